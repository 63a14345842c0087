#include "scene/model_reader.hpp"

#include <cctype>

#include "physics/model_modes.hpp"

namespace bookspin::scene {

namespace {

/// "compare[i]." — built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + string.
std::string entry_prefix(std::size_t index) {
  std::string prefix("compare[");
  prefix.append(std::to_string(index)).append("].");
  return prefix;
}

/// Reads one [[compare]] entry with its own reader, so that unknown keys inside it are
/// reported with its line and as compare[i].key.
CompareTile read_tile(const toml::table& entry, std::size_t index, const std::string& origin,
                      const std::set<std::string>& overridden, const physics::ModelConfig& base) {
  TomlReader r(entry, origin, overridden, entry_prefix(index), &entry);
  CompareTile panel;
  if (!r.has("label")) r.fail("label", "missing (every [[compare]] entry needs a label)");
  panel.label = r.string("label", "");
  panel.name = label_to_name(panel.label);
  if (panel.name.empty()) r.fail("label", "must contain a letter or digit");
  panel.model = read_model(r, base);
  r.reject_unknown_keys();
  return panel;
}

/// " (expected …)": an engine's modes (physics::model_modes()), for its unsupported-integrator
/// error; empty for bookspin's own models.
std::string engine_modes(physics::ModelKind kind) {
  if (!physics::is_engine(kind)) return {};
  std::string modes;
  for (const physics::ModelMode& mode : physics::model_modes())
    if (mode.kind == kind)
      modes.append(modes.empty() ? "" : ", ").append(physics::to_string(mode.integrator));
  return " (expected " + modes + ")";
}

/// "a, b, c": the names of `values`, in their order.
template <typename Enum>
std::string names(const std::vector<Enum>& values) {
  std::string text;
  for (Enum value : values) text.append(text.empty() ? "" : ", ").append(physics::to_string(value));
  return text;
}

/// model.drag and model.drag_rate (docs/physics.md §21): a law with its rate, both named or
/// both inherited; only the rigid and exact models take drag (a particle tile of a drag scene
/// inherits none).
void read_drag(TomlReader& r, physics::ModelConfig& m, const physics::ModelConfig& fallback) {
  const bool takes = physics::supports_drag(m.kind);
  const physics::Drag inherited = takes ? fallback.drag : physics::Drag{};
  const std::string law = r.string("model.drag", std::string(physics::to_string(inherited.law)));
  if (!physics::parse_drag_law(law, m.drag.law))
    r.fail("model.drag", "unknown drag law '" + law + "' (expected none, linear, quadratic)");
  m.drag.rate = r.number(limit("model.drag_rate"), inherited.rate);
  if (m.drag.law != physics::DragLaw::none && !takes)
    r.fail("model.drag", "model '" + std::string(physics::to_string(m.kind)) +
                             "' takes no drag (only rigid-matrix, rigid-quaternion and exact)");
  if (m.drag.law == physics::DragLaw::none && r.has("model.drag_rate"))
    r.fail("model.drag_rate",
           "needs model.drag = \"linear\" or \"quadratic\" (the law it is the rate of)");
  if (m.drag.law != physics::DragLaw::none && r.has("model.drag") && !r.has("model.drag_rate"))
    r.fail("model.drag", "needs model.drag_rate (the initial loss of |L| per time unit, 1/time)");
  if (m.drag.law == physics::DragLaw::none) m.drag.rate = 0.0;
}

}  // namespace

physics::ModelConfig read_model(TomlReader& r, const physics::ModelConfig& fallback) {
  physics::ModelConfig m;
  const std::string kind = r.string("model.kind", std::string(physics::to_string(fallback.kind)));
  if (!physics::parse_model_kind(kind, m.kind)) {
    r.fail("model.kind",
           "unknown model '" + kind + "' (expected " + names(physics::model_kinds()) + ")");
  }
  // A tile takes only the keys that apply to its model: when the integrator is not named here
  // and the model changes to or from an engine, or to a model without the inherited integrator
  // (an exact or particle tile in an rk4 scene), the model's own default integrator.
  const bool engine = physics::is_engine(m.kind);
  const physics::Integrator fallback_integrator =
      m.kind != fallback.kind && (engine || physics::is_engine(fallback.kind) ||
                                  !physics::supports(m.kind, fallback.integrator))
          ? physics::default_integrator(m.kind)
          : fallback.integrator;
  const std::string integrator =
      r.string("model.integrator", std::string(physics::to_string(fallback_integrator)));
  if (!physics::parse_integrator(integrator, m.integrator)) {
    r.fail("model.integrator", "unknown integrator '" + integrator + "' (expected " +
                                   names(physics::integrators()) + ")");
  }
  if (!physics::supports(m.kind, m.integrator)) {
    r.fail("model.integrator", "model '" + kind + "' does not support integrator '" + integrator +
                                   "'" + engine_modes(m.kind));
  }
  if (engine) {
    // The engines' models have no such settings (docs/engines.md): refused, never ignored.
    for (const char* key :
         {"model.normalize", "model.normalize_every", "model.damping", "model.spring_constant",
          "model.lattice_cells", "model.drag", "model.drag_rate"}) {
      if (r.has(key)) r.fail(key, "model '" + kind + "' (another engine) has no such setting");
    }
    return m;
  }
  m.normalize = r.boolean("model.normalize", fallback.normalize);
  m.normalize_every =
      static_cast<int>(r.integer(limit("model.normalize_every"), fallback.normalize_every));
  // An interval means nothing without the normalization it spaces (docs/physics.md §18).
  if (r.has("model.normalize_every") && !m.normalize)
    r.fail("model.normalize_every",
           "needs model.normalize = true (it says how often to normalize)");
  m.damping = r.boolean("model.damping", fallback.damping);
  m.spring_constant = r.number(limit("model.spring_constant"), fallback.spring_constant);
  m.lattice_cells =
      static_cast<int>(r.integer(limit("model.lattice_cells"), fallback.lattice_cells));
  read_drag(r, m, fallback);
  return m;
}

std::vector<CompareTile> read_compare(TomlReader& r, const std::string& origin,
                                      const std::set<std::string>& overridden,
                                      const physics::ModelConfig& base) {
  const auto view = r.node("compare");
  if (!view) return {};
  const toml::array* array = view.as_array();
  if (!array || !array->is_array_of_tables()) {
    r.fail("compare", "expected an array of tables ([[compare]] entries)");
  }
  if (array->empty() || array->size() > static_cast<std::size_t>(kMaxCompareTiles)) {
    r.fail("compare", "expected 1 to " + std::to_string(kMaxCompareTiles) +
                          " [[compare]] entries, got " + std::to_string(array->size()));
  }
  std::vector<CompareTile> panels;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::table& entry = *array->get(i)->as_table();
    panels.push_back(read_tile(entry, i + 1, origin, overridden, base));
    for (std::size_t j = 0; j < i; ++j) {
      if (panels[j].name != panels.back().name) continue;
      TomlReader(entry, origin, overridden, entry_prefix(i + 1), &entry)
          .fail("label", "'" + panels.back().label + "' has the same file name as compare[" +
                             std::to_string(j + 1) + "] ('" + panels[j].label + "')");
    }
  }
  return panels;
}

std::string label_to_name(const std::string& label) {
  std::string name;
  for (unsigned char c : label) {
    if (std::isalnum(c)) {
      name += static_cast<char>(std::tolower(c));
    } else if (!name.empty() && name.back() != '-') {
      name += '-';
    }
  }
  while (!name.empty() && name.back() == '-') name.pop_back();
  return name;
}

}  // namespace bookspin::scene
