#include "common/json_writer.hpp"

#include <charconv>

#include "common/json_string.hpp"

namespace bookspin {

namespace {

struct Writer {
  std::string out;
  std::string_view what;
  bool spaced = false;  ///< ", " and ": " (the indented layout), else "," and ":"

  /// `path` names the value for the finiteness check's message ("state.dt"); `indent` is the
  /// indent of the line the value starts on (the indented layout).
  void value(const JsonValue& v, const std::string& path, int indent) {
    const bool lines = spaced && v.lines;
    std::visit([&](const auto& x) { write(x, path, indent, lines); }, v.value);
  }

  /// "WHAT PATH": what finite_text names in its message.
  std::string named(const std::string& path) const {
    return path.empty() ? std::string(what) : std::string(what) + " " + path;
  }

  const char* comma() const { return spaced ? ", " : ","; }

  void write(double x, const std::string& path, int, bool) { out += finite_text(x, named(path)); }
  void write(const JsonNumber& x, const std::string& path, int, bool) {
    out += finite_text(x.value, named(path), x.style);
  }
  void write(const std::vector<double>& numbers, const std::string& path, int, bool) {
    const std::string name = named(path);
    out += '[';
    for (std::size_t i = 0; i < numbers.size(); ++i)
      out.append(i ? comma() : "").append(finite_text(numbers[i], name));
    out += ']';
  }
  void write(bool x, const std::string&, int, bool) { out += x ? "true" : "false"; }
  void write(std::int64_t x, const std::string&, int, bool) {
    char buffer[24];
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  }
  void write(const std::string& text, const std::string&, int, bool) { out += json_string(text); }
  void write(const JsonArray& array, const std::string& path, int indent, bool lines) {
    out += '[';
    for (std::size_t i = 0; i < array.size(); ++i) {
      separate(i, indent, lines);
      value(array[i], path + "[" + std::to_string(i) + "]", indent + 2);
    }
    close(']', indent, lines);
  }
  void write(const JsonObject& object, const std::string& path, int indent, bool lines) {
    out += '{';
    for (std::size_t i = 0; i < object.size(); ++i) {
      separate(i, indent, lines);
      member(object[i], path, indent + 2);
    }
    close('}', indent, lines);
  }

  /// `"key": value`, the value on a line indented by `indent`.
  void member(const JsonMember& m, const std::string& path, int indent) {
    out.append(json_string(m.key)).append(spaced ? ": " : ":");
    value(m.value, path.empty() ? m.key : path + "." + m.key, indent);
  }

  /// Before the i-th item of a container opened on a line indented by `indent`.
  void separate(std::size_t i, int indent, bool lines) {
    if (lines)
      out.append(i ? ",\n" : "\n").append(static_cast<std::size_t>(indent) + 2, ' ');
    else if (i)
      out += comma();
  }

  /// After the items: "\n" and the indent before a broken container's bracket ("{\n  }" when
  /// empty).
  void close(char bracket, int indent, bool lines) {
    if (lines) out.append("\n").append(static_cast<std::size_t>(indent), ' ');
    out += bracket;
  }

  /// The explorer's list: "[\n" a ",\n" b "]", every element on a line of its own.
  void element_lines(const JsonArray& array) {
    out += '[';
    for (std::size_t i = 0; i < array.size(); ++i) {
      out.append(i ? ",\n" : "\n");
      value(array[i], std::string(1, '[').append(std::to_string(i)).append("]"), 0);
    }
    out += ']';
  }
};

}  // namespace

std::string json_text(const JsonValue& value, std::string_view what, JsonLayout layout) {
  Writer writer{{}, what, layout == JsonLayout::indented};
  const auto* array = std::get_if<JsonArray>(&value.value);
  if (layout == JsonLayout::element_per_line && array)
    writer.element_lines(*array);
  else
    writer.value(value, "", 0);
  return std::move(writer.out);
}

std::string json_member_lines(const JsonObject& members, std::string_view what, int indent,
                              bool last) {
  Writer writer{{}, what, true};
  for (std::size_t i = 0; i < members.size(); ++i) {
    writer.out.append(static_cast<std::size_t>(indent), ' ');
    writer.member(members[i], "", indent);
    writer.out += (last && i + 1 == members.size()) ? "\n" : ",\n";
  }
  return std::move(writer.out);
}

}  // namespace bookspin
