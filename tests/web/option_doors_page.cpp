// The explorer lab's options read as the page reads them, compiled to WebAssembly by
// tests/web/option_doors_test.mjs: the field's text and the menu's name through the functions
// web/fit_bindings.cpp's tosses_arg and drag_arg call (fit/fit_options.hpp), named as the page
// names them. Prints "ok" or the error line.
// Usage (under node): option_doors_page.js tosses|drag TEXT
#include <cstdio>
#include <string>

#include "common/errors.hpp"
#include "fit/fit_options.hpp"
#include "fit/fit_tables.hpp"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  const std::string option = argv[1], text = argv[2];
  const bookspin::fit::FitOptionNames names =
      bookspin::fit::fit_option_names(bookspin::fit::Reader::page);
  try {
    if (option == "tosses")
      bookspin::fit::parse_toss_ranges(text, names.tosses);
    else if (option == "drag")
      bookspin::fit::parse_drag_option(text, names.drag);
    else
      return 2;
  } catch (const bookspin::InputError& e) {
    std::printf("%s\n", e.what());
    return 0;
  }
  std::printf("ok\n");
  return 0;
}
