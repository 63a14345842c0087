#pragma once
// A judged motion as JavaScript, for the bindings that present one judgement (the page's
// "Judge a motion" panel, web/judge_bindings.cpp; the npm package, npm/flipcheck_bindings.cpp):
// analysis::judgement_row translated, nothing computed.
#include <emscripten/val.h>

#include <string>
#include <vector>

#include "analysis/judgement.hpp"

namespace bookspin::web {

/// {columns, cells (the judgement CSV's row as the command line writes it, as text), line
/// (analysis::verdict_line), failures (one phrase each)} of `row`.
inline emscripten::val judgement_value(const analysis::JudgementRow& row) {
  const auto array = [](const std::vector<std::string>& items) {
    emscripten::val out = emscripten::val::array();
    for (const std::string& item : items) out.call<void>("push", item);
    return out;
  };
  emscripten::val out = emscripten::val::object();
  out.set("columns", array(row.columns));
  out.set("cells", array(row.cells));
  out.set("line", row.line);
  out.set("failures", array(row.failures));
  return out;
}

}  // namespace bookspin::web
