#include "scene/page_data.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include "physics/polhode.hpp"

namespace bookspin::scene {

namespace {

/// The members model, integrator and normalize of `m`, each name followed by `suffix` ("" for
/// the page's first method, "2" for the one it compares with).
void add_method(JsonObject& state, const physics::ModelConfig& m, const std::string& suffix) {
  state.push_back({"model" + suffix, {std::string(physics::to_string(m.kind))}});
  state.push_back({"integrator" + suffix, {std::string(physics::to_string(m.integrator))}});
  state.push_back({"normalize" + suffix, {m.normalize}});
}

/// The models the page can run: every tile but the other engines' (the page binds src/physics
/// alone, docs/engines.md), or the scene's model; the exact motion where none is left.
std::vector<physics::ModelConfig> page_models(const Scene& s) {
  std::vector<physics::ModelConfig> models;
  if (s.compare.empty()) models.push_back(s.model);
  for (const CompareTile& tile : s.compare) models.push_back(tile.model);
  std::erase_if(models, [](const physics::ModelConfig& m) { return physics::is_engine(m.kind); });
  if (models.empty()) models.push_back({physics::ModelKind::exact, physics::Integrator::euler});
  return models;
}

/// Every [[compare]] tile, in order, as the page shows it (docs/explorer.md, "Comparison"): its
/// label, model, integrator and normalize; the page steps bookspin's own models and replays the
/// other engines' (their motion, jobs::page_replays, the explorer product adds).
JsonArray tiles_data(const Scene& s) {
  JsonArray out;
  for (const CompareTile& tile : s.compare)
    out.push_back(
        {JsonObject{{"label", {tile.label}},
                    {"model", {std::string(physics::to_string(tile.model.kind))}},
                    {"integrator", {std::string(physics::to_string(tile.model.integrator))}},
                    {"normalize", {tile.model.normalize}}}});
  return out;
}

/// The entries of `m` as doubles, column by column (Eigen's order: a 3×N matrix flattened).
template <typename Matrix>
JsonValue numbers(const Matrix& m) {
  return {std::vector<double>(m.data(), m.data() + m.size())};
}

/// The scene's measured ω (measured.omega) as the page draws it: {t (time units), w (3×N
/// body-frame ω, flattened column by column), ut and u: the times and body-frame L/|L| of the
/// samples whose L = I·ω (I the scene body's principal moments) is not zero, 3×M flattened}.
JsonObject measured_data(const Scene& s) {
  const MeasuredOmega& m = s.measured;
  const physics::MomentumDirections L = physics::momentum_directions(s.body.moments, m.omega);
  std::vector<double> ut;
  for (const Eigen::Index i : L.samples) ut.push_back(m.t[static_cast<std::size_t>(i)]);
  return {{"t", {m.t}}, {"w", numbers(m.omega)}, {"ut", {std::move(ut)}}, {"u", numbers(L.u)}};
}

}  // namespace

JsonObject page_data(const Scene& s) {
  const std::vector<physics::ModelConfig> models = page_models(s);
  const physics::ModelConfig& first = models.front();
  JsonObject state{{"body", {std::string(physics::to_string(s.body.shape))}}};
  add_method(state, first, "");
  // Air drag (docs/physics.md §21) where the scene has it; the page's default is none.
  if (first.drag.active())
    state.insert(state.end(), {{"drag", {std::string(physics::to_string(first.drag.law))}},
                               {"dragRate", {first.drag.rate}}});
  state.insert(state.end(), {{"damping", {first.damping}},
                             {"k", {first.spring_constant}},
                             {"cells", {std::int64_t{first.lattice_cells}}},
                             {"dt", {s.dt}},
                             {"axis", {std::string("custom")}},
                             {"w", numbers(s.initial.omega0_body)},
                             {"jiggle", {s.initial.jiggle}},
                             {"seed", {static_cast<std::int64_t>(s.initial.seed)}},
                             {"speed", {s.dt * s.steps_per_frame * s.render.fps}},
                             {"showL", {s.render.show_angular_momentum}},
                             {"showAxes", {s.render.show_body_axes}}});
  if (models.size() >= 2) {
    // Two methods when the page compares two: the first tile with the last (e.g. Euler and exact).
    state.push_back({"compare", {true}});
    add_method(state, models.back(), "2");
  }
  // A comparison shows every tile, as its clip does (the page's `tiles`; tiles=0: two methods).
  if (!s.compare.empty()) state.push_back({"tiles", {true}});
  const physics::Body& b = s.body;
  JsonObject scene{{"name", {s.name}},
                   {"title", {s.title}},
                   {"description", {s.description}},
                   {"state", {std::move(state)}},
                   {"book", {JsonObject{{"size", numbers(b.cage.size)}, {"mass", {b.cage.mass}}}}},
                   {"duration", {(s.frames - 1) * s.dt * s.steps_per_frame}}};
  if (!s.compare.empty()) scene.push_back({"tiles", {tiles_data(s)}});
  if (!s.measured.file.empty()) scene.push_back({"measured", {measured_data(s)}});
  if (b.shape != physics::BodyShape::book) {
    scene.push_back({"body",
                     {JsonObject{{"shape", {std::string(physics::to_string(b.shape))}},
                                 {"mass", {b.cage.mass}},
                                 {"moments", numbers(b.moments)},
                                 {"cage", numbers(b.cage.size)},
                                 {"volume", {b.volume}},
                                 {"vertices", numbers(b.vertices)},
                                 {"triangles", numbers(b.triangles)},
                                 {"colours", numbers(b.face_colours)},
                                 {"smooth", {b.smooth}}}}});
  }
  return scene;
}

}  // namespace bookspin::scene
