#include "analysis/scenario_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "common/json_string.hpp"
#include "common/number_text.hpp"
#include "common/text_lines.hpp"

namespace bookspin::analysis {

namespace {

/// A JSON value as a scenario file's reader needs it (RFC 8259: objects, arrays, strings,
/// numbers, true, false, null).
struct Json {
  enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
  double number = 0.0;
  std::string string;
  std::vector<Json> items;
  std::vector<std::pair<std::string, Json>> members;

  /// The value of `key`; of a key given twice, the last, as JSON.parse and Python's json
  /// read it.
  const Json* member(std::string_view key) const {
    for (auto it = members.rbegin(); it != members.rend(); ++it)
      if (it->first == key) return &it->second;
    return nullptr;
  }
};

/// The type of `v` as the npm package names it in messages ("null", "an array", "a number").
std::string type_of(const Json& v) {
  switch (v.kind) {
    case Json::Kind::null:
      return "null";
    case Json::Kind::boolean:
      return "a boolean";
    case Json::Kind::number:
      return "a number";
    case Json::Kind::string:
      return "a string";
    case Json::Kind::array:
      return "an array";
    case Json::Kind::object:
      return "an object";
  }
  return "a value";
}

/// A recursive-descent reader of one JSON text; InputError "FILE: not valid JSON: WHAT at line
/// L, column C" where it stops being JSON.
class JsonReader {
 public:
  JsonReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  Json document() {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;  // a byte-order mark
    skip_space();
    Json v = value(0);
    skip_space();
    if (at_ < text_.size()) fail("more after the JSON value");
    return v;
  }

 private:
  /// " at line L, column C" of the reader's place, or ": the file ends at line L, column C".
  std::string place() const {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < at_ && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        column = 1;
      } else if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) {
        ++column;
      }
    }
    return (at_ >= text_.size() ? ": the file ends at line " : " at line ") + std::to_string(line) +
           ", column " + std::to_string(column);
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ": not valid JSON: " + what + place());
  }
  void skip_space() {
    while (at_ < text_.size() &&
           (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' || text_[at_] == '\r'))
      ++at_;
  }
  bool eat(char c) {
    skip_space();
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  std::string seen() const {
    if (at_ >= text_.size()) return "the end";
    const char c = text_[at_];
    if (static_cast<unsigned char>(c) < 0x20) return "a control character";
    return std::string("\"") + c + "\"";
  }
  Json value(int depth) {
    skip_space();
    if (at_ >= text_.size()) fail("expected a value");
    // Valid JSON, deeper than a scenario is read: said in the words the npm package's object
    // door says it in, there at a key path ("nested more than 64 deep at extra.a.a…").
    if (depth > 64) throw InputError(file_ + ": nested more than 64 deep" + place());
    const char c = text_[at_];
    Json v;
    if (c == '{') {
      ++at_;
      v.kind = Json::Kind::object;
      if (eat('}')) return v;
      do {
        skip_space();
        if (at_ >= text_.size() || text_[at_] != '"')
          fail("expected a key in double quotes, saw " + seen());
        std::string key = string();
        if (!eat(':')) fail("expected ':' after the key, saw " + seen());
        v.members.emplace_back(std::move(key), value(depth + 1));
      } while (eat(','));
      if (!eat('}')) fail("expected ',' or '}', saw " + seen());
      return v;
    }
    if (c == '[') {
      ++at_;
      v.kind = Json::Kind::array;
      if (eat(']')) return v;
      do v.items.push_back(value(depth + 1));
      while (eat(','));
      if (!eat(']')) fail("expected ',' or ']', saw " + seen());
      return v;
    }
    if (c == '"') {
      v.kind = Json::Kind::string;
      v.string = string();
      return v;
    }
    for (const auto& [word, kind, truth] : {std::tuple{"true", Json::Kind::boolean, true},
                                            std::tuple{"false", Json::Kind::boolean, false},
                                            std::tuple{"null", Json::Kind::null, false}}) {
      const std::string_view w(word);
      if (text_.substr(at_, w.size()) == w) {
        at_ += w.size();
        v.kind = kind;
        v.number = truth ? 1.0 : 0.0;
        return v;
      }
    }
    if (c == '-' || (c >= '0' && c <= '9')) return number();
    fail("unexpected " + seen());
  }
  Json number() {
    const std::size_t start = at_;
    const auto digits = [&] {
      const std::size_t from = at_;
      while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') ++at_;
      return at_ > from;
    };
    if (text_[at_] == '-') ++at_;
    if (at_ < text_.size() && text_[at_] == '0') {
      ++at_;
    } else if (!digits()) {
      fail("expected a digit, saw " + seen());
    }
    if (at_ < text_.size() && text_[at_] == '.') {
      ++at_;
      if (!digits()) fail("expected a digit after '.', saw " + seen());
    }
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      ++at_;
      if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
      if (!digits()) fail("expected a digit in the exponent, saw " + seen());
    }
    Json v;
    v.kind = Json::Kind::number;
    const std::string spelled(text_.substr(start, at_ - start));
    // Beyond the doubles: JSON.parse's ±Infinity or ±0, which the fields' checks then refuse.
    v.number = read_number(spelled).value_or(std::strtod(spelled.c_str(), nullptr));
    return v;
  }
  std::string string() {
    JsonStringRead read = read_json_string(text_, at_);
    at_ = read.end;
    if (!read.error.empty()) fail(read.error);
    return std::move(read.text);
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t at_ = 0;
};

/// A number as a message gives it: "%.15g" where it reads back, else "%.17g".
std::string plain(double value) {
  char number[32];
  std::snprintf(number, sizeof number, "%.15g", value);
  if (std::strtod(number, nullptr) != value) std::snprintf(number, sizeof number, "%.17g", value);
  return number;
}

std::string vector_text(const std::vector<double>& v) {
  std::string text = "(";
  for (std::size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + plain(v[i]);
  return text + ")";
}

const Json* field(const Json& json, const char* key, const std::string& where) {
  const Json* v = json.member(key);
  if (!v)
    throw InputError(where + ": " + key +
                     ": missing (a scenario JSON as flipcheck export writes it)");
  return v;
}

double number_field(const Json& json, const char* key, const std::string& where) {
  const Json* v = field(json, key, where);
  if (v->kind != Json::Kind::number)
    throw InputError(where + ": " + key + ": expected a number, got " + type_of(*v));
  return v->number;
}

std::vector<double> numbers_field(const Json& json, const char* key, std::size_t n,
                                  const std::string& where) {
  const Json* v = field(json, key, where);
  const std::string expected = "expected an array of " + std::to_string(n) + " numbers";
  if (v->kind != Json::Kind::array)
    throw InputError(where + ": " + key + ": " + expected + ", got " + type_of(*v));
  if (v->items.size() != n)
    throw InputError(where + ": " + key + ": " + expected + ", got " +
                     std::to_string(v->items.size()));
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (v->items[i].kind != Json::Kind::number)
      throw InputError(where + ": " + key + "[" + std::to_string(i) + "]: expected a number, got " +
                       type_of(v->items[i]));
    out.push_back(v->items[i].number);
  }
  return out;
}

JsonValue vector_json(const Eigen::Vector3d& v) { return {JsonArray{{v.x()}, {v.y()}, {v.z()}}}; }

}  // namespace

JsonValue scenario_json(const Scenario& s) {
  // q0 is the identity, so ω0 in the world frame is ω0 in the body frame.
  const Eigen::Vector3d omega0 = start_omega(s);
  JsonObject units{{"time", {std::string("time unit (any: the motion scales with 1/time)")}},
                   {"length", {std::string("length unit")}},
                   {"mass", {std::string("mass unit")}},
                   {"angle", {std::string("radian")}},
                   {"angular_velocity", {std::string("rad per time unit")}},
                   {"moments", {std::string("mass * length^2")}}};
  JsonObject object{
      {"scenario", {s.name}},
      {"units", {std::move(units), true}},
      {"mass", {s.body.cage.mass}},
      {"principal_moments", vector_json(s.body.moments)},
      {"principal_axes", {std::string("body x, y, z (the moments are about these axes)")}},
      {"q0", {JsonArray{{1.0}, {0.0}, {0.0}, {0.0}}}},
      {"q_convention", {std::string("w, x, y, z; body to world")}},
      {"omega0_body", vector_json(omega0)},
      {"omega0_world", vector_json(omega0)},
      {"dt", {JsonNumber{s.dt, NumberStyle::shortest}}},
      {"steps", {static_cast<std::int64_t>(s.steps)}},
      {"gravity", {std::string("none; no damping, no contacts")}},
      {"exact_motion", {s.name + "-exact.csv"}},
  };
  return {std::move(object), true};
}

std::string scenario_file(const Scenario& scenario) {
  const JsonValue json = scenario_json(scenario);
  return json_text(json, "flipcheck scenario", JsonLayout::indented) + "\n";
}

namespace {

/// Whether the NUL bytes of `text` say it is no text: a UTF-16 byte-order mark (FF FE, FE FF),
/// or NUL in one byte of 8 or more (UTF-16's ASCII is every other byte; a binary file's many).
bool nuls_say_no_text(std::string_view text) {
  if (text.size() >= 2 &&
      ((text[0] == '\xff' && text[1] == '\xfe') || (text[0] == '\xfe' && text[1] == '\xff')))
    return true;
  const auto nuls = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\0'));
  return nuls * 8 >= text.size();
}

}  // namespace

Scenario scenario_from_json(std::string_view text, const std::string& file) {
  // A file saved as UTF-16 (or no text at all) is said to be so, as a scene or a recording is,
  // not "a control character" where its first NUL byte stands; a NUL or two in a text (one
  // typed into a string) is the JSON reader's to name, a control character at its line and
  // column.
  if (const auto nul = nul_byte_problem(text); nul && nuls_say_no_text(text))
    throw InputError(file + ": " + *nul);
  const Json json = JsonReader(text, file).document();
  if (json.kind != Json::Kind::object)
    throw InputError(file + ": holds " +
                     (json.kind == Json::Kind::null ? "JSON null" : type_of(json)) +
                     ", not a scenario (a JSON object as flipcheck export writes it: scenario, "
                     "mass, principal_moments, omega0_body, dt, steps)");
  Scenario s;
  const Json* name = json.member("scenario");
  if (!name)
    throw InputError(file +
                     ": scenario: missing (the scenario's name, as flipcheck export writes it)");
  if (name->kind != Json::Kind::string)
    throw InputError(file + ": scenario: expected a name (a string), got " + type_of(*name));
  s.name = name->string;
  if (!scenario_name_problem(s.name).empty()) check_scenario(s);  // the name refused, printable
  const std::vector<double> moments = numbers_field(json, "principal_moments", 3, s.name);
  s.body.moments = {moments[0], moments[1], moments[2]};
  s.body.cage.mass = number_field(json, "mass", s.name);
  const bool has_body = json.member("omega0_body") != nullptr;
  const bool has_world = json.member("omega0_world") != nullptr;
  const std::vector<double> body =
      numbers_field(json, has_body || !has_world ? "omega0_body" : "omega0_world", 3, s.name);
  if (has_body && has_world) {
    const std::vector<double> world = numbers_field(json, "omega0_world", 3, s.name);
    for (int i = 0; i < 3; ++i)
      if (!(std::abs(world[i] - body[i]) <= 1e-12 * std::max(std::abs(body[i]), 1e-300)))
        throw InputError(s.name + ": omega0_world: " + vector_text(world) + " is not omega0_body " +
                         vector_text(body) +
                         ": at q0 = identity they are one vector (give them equal, or one)");
  }
  if (json.member("q0")) {
    const std::vector<double> q0 = numbers_field(json, "q0", 4, s.name);
    if (!(q0[0] != 0.0 && std::isfinite(q0[0]) && q0[1] == 0.0 && q0[2] == 0.0 && q0[3] == 0.0))
      throw InputError(s.name + ": q0: " + vector_text(q0) +
                       ": every scenario starts at the identity, q0 = (1, 0, 0, 0) (w, x, y, z)");
  }
  s.initial.omega0_body = {body[0], body[1], body[2]};
  s.initial.jiggle = 0.0;
  s.dt = number_field(json, "dt", s.name);
  const double steps = number_field(json, "steps", s.name);
  if (!(std::floor(steps) == steps))
    throw InputError(s.name + ": steps: " + plain(steps) + " is not a whole number of steps");
  if (!(steps >= 1.0 && steps <= static_cast<double>(ScenarioLimits::max_steps)))
    throw InputError(s.name + ": steps: " + plain(steps) +
                     " must be from 1 to 10^7 (the exact motion is exported at every step)");
  s.steps = static_cast<long long>(steps);
  check_scenario(s);
  return s;
}

}  // namespace bookspin::analysis
