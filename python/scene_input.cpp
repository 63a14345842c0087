// A scene from Python (docs/python.md): a path or TOML text, and the overrides as a dict that
// becomes the command line's `--set KEY=VALUE`, each value spelled in TOML.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "common/errors.hpp"
#include "common/json_string.hpp"

namespace bookspin::python {

namespace {

/// A Python value spelled in TOML: bool, int, float (repr: 0.1, 1e-05, inf, nan), str, and
/// lists or tuples of them; InputError naming `key` for anything else.
std::string toml_value(const py::handle& value, const std::string& key) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (PyIndex_Check(value.ptr()) && !PyFloat_Check(value.ptr()))
    return std::string(py::str(py::int_(py::reinterpret_borrow<py::object>(value))));
  if (PyFloat_Check(value.ptr()) ||
      py::isinstance(value, py::module_::import("numbers").attr("Real")))
    return std::string(py::repr(py::float_(py::reinterpret_borrow<py::object>(value))));
  // A JSON string (common/json_string.hpp: quote, backslash and control characters escaped
  // as \uXXXX) is a TOML basic string too.
  if (py::isinstance<py::str>(value)) return json_string(unicode_arg(value, "--set " + key));
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string out = "[";
    bool first = true;
    for (const py::handle item : value) {
      out += (first ? "" : ", ") + toml_value(item, key);
      first = false;
    }
    return out + "]";
  }
  throw InputError("--set " + key + ": a Python " +
                   std::string(py::str(py::type::handle_of(value).attr("__name__"))) +
                   " is no scene value (give a bool, a number, a str or a list of them)");
}

std::vector<std::string> override_args(const py::handle& overrides) {
  std::vector<std::string> args;
  if (overrides.is_none()) return args;
  if (!py::isinstance<py::dict>(overrides))
    throw InputError("overrides: expected a dict such as {\"time.frames\": 120}, got " +
                     std::string(py::str(py::type::handle_of(overrides).attr("__name__"))));
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(overrides)) {
    if (!py::isinstance<py::str>(key))
      throw InputError("overrides: a key is not a str: " + std::string(py::repr(key)));
    const std::string name = unicode_arg(key, "overrides");
    args.push_back(name + "=" + toml_value(value, name));
  }
  return args;
}

}  // namespace

namespace {

/// InputError naming `argument` at the first lone surrogate of the str `text` (with `escaped`
/// false, the first outside U+DC80 … U+DCFF: those are bytes that are no UTF-8, as os.listdir
/// gives them, which a file's name may hold).
[[noreturn]] void refuse_lone_surrogate(const py::handle& text, const std::string& argument,
                                        bool escaped) {
  PyErr_Clear();
  const Py_ssize_t n = PyUnicode_GetLength(text.ptr());
  for (Py_ssize_t i = 0; i < n; ++i) {
    const Py_UCS4 c = PyUnicode_ReadChar(text.ptr(), i);
    if (c < 0xd800 || c > 0xdfff || (!escaped && c >= 0xdc80 && c <= 0xdcff)) continue;
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(c));
    // json.dumps writes the surrogate as \udXXX, as JavaScript's JSON.stringify does.
    const std::string quoted = py::str(py::module_::import("json").attr("dumps")(text));
    throw InputError(argument + ": " + quoted + " holds a lone surrogate (" + code +
                     ") at character " + std::to_string(i + 1) + ": no UTF-8 text holds one");
  }
  throw InputError(argument + ": not text the file system can name");
}

}  // namespace

std::string unicode_arg(const py::handle& text, const std::string& argument) {
  Py_ssize_t size = 0;
  const char* bytes = PyUnicode_AsUTF8AndSize(text.ptr(), &size);
  if (bytes == nullptr) refuse_lone_surrogate(text, argument, true);
  return std::string(bytes, static_cast<std::size_t>(size));
}

std::string text_arg(const py::handle& value, const std::string& argument) {
  if (!py::isinstance<py::str>(value))
    throw InputError(argument + ": expected a str, got " +
                     py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
  return unicode_arg(value, argument);
}

std::string path_text(const py::handle& value, bool& ok, const std::string& argument) {
  ok = py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
  if (!ok) return {};
  const py::object path = py::module_::import("os").attr("fspath")(value);
  if (!py::isinstance<py::str>(path)) {
    ok = false;  // a bytes path
    return {};
  }
  // os.fsencode: the file system's encoding with surrogateescape.
  const py::object bytes = py::reinterpret_steal<py::object>(PyUnicode_EncodeFSDefault(path.ptr()));
  if (!bytes) refuse_lone_surrogate(path, argument, false);
  return std::string(PyBytes_AS_STRING(bytes.ptr()),
                     static_cast<std::size_t>(PyBytes_GET_SIZE(bytes.ptr())));
}

std::string path_arg(const py::handle& value, bool& ok, const std::string& argument) {
  std::string text = path_text(value, ok, argument);
  if (const std::size_t nul = text.find('\0'); ok && nul != std::string::npos)
    throw InputError(argument + ": holds a NUL byte at character " + std::to_string(nul + 1) +
                     " (no file's name holds one)");
  return text;
}

scene::Scene scene_arg(const py::handle& scene, const py::handle& overrides) {
  bool ok = false;
  const std::string text = path_text(scene, ok, "scene");
  if (!ok)
    throw InputError("scene: expected a path or TOML text (str), got " +
                     std::string(py::str(py::type::handle_of(scene).attr("__name__"))));
  const std::vector<std::string> args = override_args(overrides);
  const bool path_like = !py::isinstance<py::str>(scene);
  std::error_code ec;
  const bool names_a_file = std::filesystem::is_regular_file(text, ec);
  if (path_like || names_a_file || text.find_first_of("\n=") == std::string::npos)
    return scene::parse_scene(text, args);
  return scene::parse_scene_text(text, "scene-text.toml", args);
}

}  // namespace bookspin::python
