#include "output/json_writer.hpp"

#include <charconv>

#include "common/json_string.hpp"
#include "output/finite_number.hpp"

namespace bookspin::output {

namespace {

struct Writer {
  std::string out;
  std::string_view what;

  /// `path` names the value for the finiteness check's message ("state.dt").
  void value(const JsonValue& v, const std::string& path) {
    std::visit([&](const auto& x) { write(x, path); }, v.value);
  }

  /// "WHAT PATH": what finite_text names in its message.
  std::string named(const std::string& path) const {
    return path.empty() ? std::string(what) : std::string(what) + " " + path;
  }

  void write(double x, const std::string& path) { out += finite_text(x, named(path)); }
  void write(const std::vector<double>& numbers, const std::string& path) {
    const std::string name = named(path);
    out += '[';
    for (std::size_t i = 0; i < numbers.size(); ++i)
      out.append(i ? "," : "").append(finite_text(numbers[i], name));
    out += ']';
  }
  void write(bool x, const std::string&) { out += x ? "true" : "false"; }
  void write(std::int64_t x, const std::string&) {
    char buffer[24];
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  }
  void write(const std::string& text, const std::string&) { out += json_string(text); }
  void write(const JsonArray& array, const std::string& path) { elements(array, path, false); }
  void write(const JsonObject& object, const std::string& path) {
    out += '{';
    for (std::size_t i = 0; i < object.size(); ++i) {
      out.append(i ? "," : "").append(json_string(object[i].key)).append(":");
      value(object[i].value, path.empty() ? object[i].key : path + "." + object[i].key);
    }
    out += '}';
  }

  /// `per_line`: "[\n" a ",\n" b "]", every element on a line of its own.
  void elements(const JsonArray& array, const std::string& path, bool per_line) {
    out += '[';
    for (std::size_t i = 0; i < array.size(); ++i) {
      out.append(i ? (per_line ? ",\n" : ",") : (per_line ? "\n" : ""));
      value(array[i], path + "[" + std::to_string(i) + "]");
    }
    out += ']';
  }
};

}  // namespace

std::string json_text(const JsonValue& value, std::string_view what, JsonLayout layout) {
  Writer writer{{}, what};
  const auto* array = std::get_if<JsonArray>(&value.value);
  if (layout == JsonLayout::element_per_line && array)
    writer.elements(*array, "", true);
  else
    writer.value(value, "");
  return std::move(writer.out);
}

}  // namespace bookspin::output
