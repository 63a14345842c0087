// embind bindings of src/physics for the browser explorer (docs/explorer.md), with the two
// measures the page shows taken from where bookspin takes them: the flip detector and the
// intermediate axis of src/analysis/motion.hpp, and the clip stage's trilinear cage
// (src/clip/body_drawing.hpp) that carries a surface with the 8 corners. Everything is compiled
// unchanged; this file only translates between Eigen and JavaScript arrays. Shapes: corners
// 3×8 and surfaces 3×V are flattened column by column (x, y, z of column 0, then column 1, …),
// body frame or world frame as stated on each method.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/motion.hpp"
#include "body_spec.hpp"
#include "clip/body_drawing.hpp"
#include "engines/engine_body.hpp"
#include "physics/body.hpp"
#include "physics/book.hpp"
#include "physics/exact_model.hpp"
#include "physics/exact_solution.hpp"
#include "physics/names.hpp"
#include "physics/polhode.hpp"
#include "physics/presets.hpp"
#include "physics/shape.hpp"
#include "physics/simulator.hpp"

namespace {

using namespace bookspin::physics;
using bookspin::analysis::FlipDetector;
using emscripten::val;

/// `value` or JavaScript null.
val optional_number(const std::optional<double>& value) {
  return value ? val(*value) : val::null();
}

/// A Float64Array copy of `n` doubles.
val f64(const double* data, std::size_t n) {
  val out = val::global("Float64Array").new_(n);
  out.call<void>("set", val(emscripten::typed_memory_view(n, data)));
  return out;
}

val f32(const float* data, std::size_t n) {
  val out = val::global("Float32Array").new_(n);
  out.call<void>("set", val(emscripten::typed_memory_view(n, data)));
  return out;
}

val i32(const int* data, std::size_t n) {
  val out = val::global("Int32Array").new_(n);
  out.call<void>("set", val(emscripten::typed_memory_view(n, data)));
  return out;
}

val vec3(const Eigen::Vector3d& v) { return f64(v.data(), 3); }

}  // namespace

// The bodies of the page's scenes (web/body_spec.hpp), shared with web/judge_bindings.cpp.
namespace bookspin::web {

using namespace bookspin::physics;
using emscripten::val;

BodyShape shape_of(const std::string& name) {
  BodyShape shape{};
  if (!parse_body_shape(name, shape) || shape == BodyShape::mesh)
    throw std::invalid_argument("unknown body '" + name +
                                "' (expected book, t-handle, tennis-racket, phone)");
  return shape;
}

/// The book of `size` (a, b, c, length units) and `mass`, or a preset of `mass` and `scale`
/// (docs/physics.md §1, §12).
Body make_body(const std::string& name, double mass, double scale, double a, double b, double c) {
  const BodyShape shape = shape_of(name);
  if (shape == BodyShape::book) {
    Book book;
    book.size = {a, b, c};
    book.mass = mass;
    return book_body(book);
  }
  return preset_body(shape, mass, scale);
}

/// `array[i]` of a JavaScript array of numbers, as `count` values (or throws).
template <typename T>
std::vector<T> numbers(const val& spec, const char* key, std::size_t count) {
  const std::vector<T> v = emscripten::vecFromJSArray<T>(spec[key]);
  if (v.size() != count)
    throw std::invalid_argument(std::string("body.") + key + ": expected " + std::to_string(count) +
                                " numbers, got " + std::to_string(v.size()));
  return v;
}

/// The Body exactly as bookspin built it (src/products/explorer.hpp, `body`): shape, mass,
/// principal moments about x, y, z, cage size, volume, the surface 3×V (principal frame) with its
/// triangles 3×N and face colours 3×N flattened column by column, smooth. Nothing is computed
/// again, so the page starts from bookspin's own doubles (a mesh body needs no mesh reader).
Body body_of(const val& spec) {
  Body body;
  const std::string shape = spec["shape"].as<std::string>();
  if (!parse_body_shape(shape, body.shape) || body.shape == BodyShape::book)
    throw std::invalid_argument("body: unknown shape '" + shape + "'");
  body.cage.mass = spec["mass"].as<double>();
  const std::vector<double> moments = numbers<double>(spec, "moments", 3);
  const std::vector<double> cage = numbers<double>(spec, "cage", 3);
  body.moments = {moments[0], moments[1], moments[2]};
  body.cage.size = {cage[0], cage[1], cage[2]};
  body.volume = spec["volume"].as<double>();
  const std::vector<double> vertices = emscripten::vecFromJSArray<double>(spec["vertices"]);
  const std::vector<int> triangles = emscripten::vecFromJSArray<int>(spec["triangles"]);
  if (vertices.size() % 3 != 0 || triangles.size() % 3 != 0 || triangles.empty())
    throw std::invalid_argument("body: vertices and triangles must be 3×V and 3×N, N > 0");
  const auto n = static_cast<Eigen::Index>(triangles.size() / 3);
  body.vertices = Eigen::Map<const Eigen::Matrix3Xd>(
      vertices.data(), 3, static_cast<Eigen::Index>(vertices.size() / 3));
  body.triangles = Eigen::Map<const Eigen::Matrix3Xi>(triangles.data(), 3, n);
  const std::vector<float> colours = numbers<float>(spec, "colours", triangles.size());
  body.face_colours = Eigen::Map<const Eigen::Matrix3Xf>(colours.data(), 3, n);
  body.smooth = spec["smooth"].as<bool>();
  for (Eigen::Index i = 0; i < body.triangles.size(); ++i) {
    if (body.triangles.data()[i] < 0 || body.triangles.data()[i] >= body.vertices.cols())
      throw std::invalid_argument("body: a triangle names a vertex that does not exist");
  }
  return body;
}

}  // namespace bookspin::web

namespace {

using bookspin::web::body_of;
using bookspin::web::make_body;

/// A rigid body whose state a JavaScript engine holds (cannon-es, Rapier, Jolt: web/src/engines/):
/// the page sets q and ω after each of the engine's steps, and corners, orientation and diagnostics
/// come from them as engines::EngineBody makes them for MuJoCo, Bullet and ODE (header only,
/// physics alone). reset() starts at the identity with ω0 = I⁻¹·L0, L0 with the jiggle
/// (docs/physics.md §5), which the page hands to the engine; step() is the engine's, not this.
class PoseBody : public bookspin::engines::EngineBody {
 public:
  explicit PoseBody(const Body& body) : EngineBody(body) {}
  void reset(const InitialState& initial) override {
    q_ = Eigen::Quaterniond::Identity();
    omega_ = initial_omega(initial);
    t_ = 0.0;
  }
  void step(double /*dt*/) override {
    throw std::logic_error("PoseBody: a JavaScript engine steps this body, not the physics");
  }
  /// The engine's state at time t: q body → world (w x y z, as stored), ω in the world frame
  /// (rad per time unit), taken to the body frame by R(q)ᵀ.
  void set(const Eigen::Quaterniond& q, const Eigen::Vector3d& omega_world, double t) {
    q_ = q;
    omega_ = q_.normalized().toRotationMatrix().transpose() * omega_world;
    t_ = t;
  }

 private:
  Eigen::Quaterniond engine_quaternion() const override { return q_; }
  Eigen::Vector3d engine_omega_body() const override { return omega_; }
  Eigen::Quaterniond q_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d omega_ = Eigen::Vector3d::Zero();
};

/// One simulator with the settings of the page: body, model, integrator, toggles.
class Session {
 public:
  Session(const std::string& body, double mass, double scale, double a, double b, double c)
      : body_(make_body(body, mass, scale, a, b, c)) {}
  /// A body given whole (body_of): a mesh scene's body as bookspin built it.
  explicit Session(const val& body) : body_(body_of(body)) {}

  /// Creates the simulator (docs/physics.md §5, §9, §10). Throws std::invalid_argument (a
  /// JavaScript exception) for an unknown name or an integrator the model does not support.
  void configure(const std::string& model, const std::string& integrator, bool normalize,
                 bool damping, double spring_constant, int lattice_cells, const std::string& drag,
                 double drag_rate) {
    ModelConfig config;
    if (!parse_model_kind(model, config.kind))
      throw std::invalid_argument("unknown model '" + model + "'");
    if (!parse_integrator(integrator, config.integrator))
      throw std::invalid_argument("unknown integrator '" + integrator + "'");
    config.normalize = normalize;
    config.damping = damping;
    config.spring_constant = spring_constant;
    config.lattice_cells = lattice_cells;
    // Air drag (docs/physics.md §21) for the models that take it; the others run without.
    if (!parse_drag_law(drag, config.drag.law))
      throw std::invalid_argument("unknown drag law '" + drag + "'");
    config.drag.rate = config.drag.law == DragLaw::none ? 0.0 : drag_rate;
    if (!supports_drag(config.kind)) config.drag = Drag{};
    simulator_ = make_simulator(body_, config);
    steps_ = 0;
  }

  /// Makes the body one a JavaScript engine steps (PoseBody): step() is refused, observe() takes
  /// the engine's state after each of its steps.
  void configure_engine() {
    simulator_ = std::make_unique<PoseBody>(body_);
    steps_ = 0;
  }

  /// One step of a JavaScript engine done: its q (body → world, w x y z) and world-frame ω
  /// (rad per time unit) after the step, at t = steps·dt. The flip detector sees it as step()
  /// feeds it (docs/physics.md §14). Returns false when the state stops being finite.
  bool observe(double qw, double qx, double qy, double qz, double wx, double wy, double wz,
               double dt) {
    auto* pose = dynamic_cast<PoseBody*>(simulator_.get());
    if (!pose) throw std::logic_error("Session: observe() needs configureEngine()");
    ++steps_;
    const double t = static_cast<double>(steps_) * dt;
    pose->set(Eigen::Quaterniond(qw, qx, qy, qz), Eigen::Vector3d(wx, wy, wz), t);
    if (!pose->finite()) return false;
    flips_.observe(t, bookspin::analysis::flip_signal(pose->diagnostics(), body_.moments));
    return true;
  }

  /// Resets to identity orientation at t = 0: body-frame ω0 (rad per time unit) and the
  /// seeded jiggle of L (docs/physics.md §5).
  void reset(double wx, double wy, double wz, double jiggle, double seed) {
    initial_ = InitialState{};
    initial_.omega0_body = {wx, wy, wz};
    initial_.jiggle = jiggle;
    initial_.seed = static_cast<std::uint64_t>(seed);
    sim().reset(initial_);
    // The motion this start would have without any method's error, for the flips' exact values
    // beside the method's (omega only: its orientation is not needed).
    exact_.emplace(body_.moments, start_omega_body(), ExactParts::omega_only);
    exact_first_ = bookspin::analysis::exact_flip_amplitude(*exact_) > FlipDetector::kMargin
                       ? bookspin::analysis::exact_first_flip(*exact_, intermediate_axis())
                       : std::nullopt;
    steps_ = 0;
    flips_ = FlipDetector();
    flips_.observe(0.0, bookspin::analysis::flip_signal(sim().diagnostics(), body_.moments));
  }
  /// The start's body-frame ω0' = I⁻¹·L0, L0 with the jiggle (docs/physics.md §5): what every
  /// model starts from.
  val start_omega() const { return vec3(start_omega_body()); }

  /// Advances `n` steps of `dt`; stops early (returns false) when the state stops being finite.
  /// The flip detector sees every step at t = steps·dt (a product), as analysis::measure_run
  /// does for `bookspin sweep` (docs/physics.md §14), so the counts agree.
  bool step(double dt, int n) {
    if (auto* exact = exact_model()) {
      // The exact motion is a closed form in t: evaluated once, at the end (docs/physics.md §8);
      // its flips are the closed form's (flips()), not sampled.
      exact->advance(dt, n);
      steps_ += n;
      return exact->finite();
    }
    for (int i = 0; i < n; ++i) {
      sim().step(dt);
      ++steps_;
      if (!sim().finite()) return false;
      flips_.observe(static_cast<double>(steps_) * dt,
                     bookspin::analysis::flip_signal(sim(), body_.moments));
    }
    return true;
  }

  /// The flips since reset (docs/physics.md §14): sign changes of cos(intermediate axis, L)
  /// seen after every step, as {count, first (time units or null), period (time units or
  /// null: fewer than two)}.
  /// The exact model's flips are those of its closed form up to its t (analysis::
  /// exact_flip_count: the zeros of ω about the intermediate axis, a wobble whose cosine stays
  /// within the detector's margin counting none), not a detector fed samples.
  val flips() const {
    val out = val::object();
    if (const auto* exact = exact_model()) {
      const int count = exact_flip_count(exact->time());
      out.set("count", count);
      out.set("first", count > 0 ? optional_number(exact_first_) : val::null());
      out.set("period", count > 1 ? val(exact_->flip_period()) : val::null());
      return out;
    }
    out.set("count", flips_.count());
    out.set("first", optional_number(flips_.first_flip()));
    out.set("period", optional_number(flips_.flip_period()));
    return out;
  }
  /// The exact motion's flips from this start up to time `t` (docs/physics.md §14), whatever the
  /// model: {count, first (null for a wobble or before any), period}: the values a method's own
  /// flips are read beside.
  val exact_flips(double t) const {
    val out = val::object();
    out.set("count", exact_flip_count(t));
    out.set("first", optional_number(exact_first_));
    out.set("period", exact_first_ ? val(exact_->flip_period()) : val::null());
    return out;
  }
  /// The body axis (0 = x, 1 = y, 2 = z) of the intermediate principal moment.
  int intermediate_axis() const { return bookspin::analysis::intermediate_axis(body_.moments); }

  /// The body-frame ω0 (rad per time unit) whose angular momentum I·ω0 points along the
  /// body-frame direction (ux, uy, uz) with magnitude `L` (mass·length²/time): ω0_d = L·u_d/I_d
  /// with u normalized, I the principal moments about body x, y, z (docs/physics.md §5, §15).
  /// Throws std::invalid_argument for a zero or non-finite direction or a negative L.
  val omega_for_momentum(double ux, double uy, double uz, double L) const {
    const Eigen::Vector3d u(ux, uy, uz);
    if (!u.allFinite() || !(u.norm() > 0.0) || !(L >= 0.0) || !std::isfinite(L))
      throw std::invalid_argument("momentum direction must be a finite non-zero vector");
    return vec3((L * u.normalized()).cwiseQuotient(body_.moments));
  }
  /// |I·ω| (mass·length²/time) for body-frame ω (rad per time unit), I the principal moments.
  double momentum_magnitude(double wx, double wy, double wz) const {
    return body_.moments.cwiseProduct(Eigen::Vector3d(wx, wy, wz)).norm();
  }

  double steps() const { return static_cast<double>(steps_); }
  bool finite() const { return simulator_ && simulator_->finite(); }
  std::string divergence_reason() const {
    return simulator_ ? simulator_->divergence_reason() : std::string();
  }

  /// Diagnostics of docs/physics.md §9 as a plain object (vectors as Float64Array(3)).
  val diagnostics() const {
    const Diagnostics d = sim().diagnostics();
    val out = val::object();
    out.set("t", d.t);
    out.set("omega_body", vec3(d.omega_body));
    out.set("L", vec3(d.L));
    out.set("energy_kinetic", d.energy_kinetic);
    out.set("energy_potential", d.energy_potential);
    out.set("energy_total", d.energy_total);
    out.set("cos_axis_L", vec3(d.cos_axis_L));
    out.set("strain_max", d.strain_max);
    out.set("orthogonality_error", d.orthogonality_error);
    out.set("quaternion_norm", d.quaternion_norm);
    out.set("cos_principal_L", vec3(d.cos_principal_L));
    out.set("momentum_direction", vec3(momentum_direction_body(d)));
    return out;
  }

  /// World corners, 3×8 column-major (24 numbers).
  val corners() const {
    const Corners c = sim().corners();
    return f64(c.data(), 24);
  }
  /// The body's surface as bookspin draws it, 3×V (world; vertex i the body's rest vertex i):
  /// the lattice's own deformed surface (docs/physics.md §13), else the rest surface carried by
  /// the moved cage corners (clip::trilinear_deform, as clip::BodyDrawing). Empty for the book.
  val surface_world() const {
    Eigen::Matrix3Xd s = sim().deformed_surface();
    if (s.cols() == 0 && body_.vertices.cols() > 0)
      s = bookspin::clip::trilinear_deform(body_.cage.body_corners(), sim().corners(),
                                           body_.vertices);
    return f64(s.data(), static_cast<std::size_t>(s.size()));
  }
  /// Body-frame points 3×N (flattened column by column) carried by the moved cage corners
  /// (clip::trilinear_deform) to world, 3×N: the book's box drawn as bookspin draws it.
  val carry(const val& points) const {
    const std::vector<double> p = emscripten::vecFromJSArray<double>(points);
    if (p.size() % 3 != 0) throw std::invalid_argument("carry: points must be 3×N");
    const Eigen::Matrix3Xd rest =
        Eigen::Map<const Eigen::Matrix3Xd>(p.data(), 3, static_cast<Eigen::Index>(p.size() / 3));
    const Eigen::Matrix3Xd world =
        bookspin::clip::trilinear_deform(body_.cage.body_corners(), sim().corners(), rest);
    return f64(world.data(), static_cast<std::size_t>(world.size()));
  }
  /// The orientation R (body→world, 3×3 column-major): Simulator::orientation().
  val orientation() const {
    const Eigen::Matrix3d r = sim().orientation();
    return f64(r.data(), 9);
  }

  /// Principal moments about body x, y, z (mass·length²).
  val moments() const { return vec3(body_.moments); }
  /// The body's mass (mass units).
  double mass() const { return body_.cage.mass; }
  /// Body axes sorted by ascending moment (Int32Array(3)).
  val principal_order() const {
    const std::array<int, 3> o = bookspin::physics::principal_order(body_.moments);
    return i32(o.data(), 3);
  }
  /// The cage's 8 body-frame corners, 3×8 column-major; the book: its own corners.
  val body_corners() const {
    const Corners c = body_.cage.body_corners();
    return f64(c.data(), 24);
  }
  val cage_size() const { return vec3(body_.cage.size); }
  /// Surface vertices 3×V (principal frame), triangles 3×N, face colours 3×N (linear RGB);
  /// empty for the book.
  val surface_vertices() const {
    return f64(body_.vertices.data(), static_cast<std::size_t>(body_.vertices.size()));
  }
  val surface_triangles() const {
    return i32(body_.triangles.data(), static_cast<std::size_t>(body_.triangles.size()));
  }
  val surface_colours() const {
    return f32(body_.face_colours.data(), static_cast<std::size_t>(body_.face_colours.size()));
  }

 private:
  Simulator& sim() const {
    if (!simulator_) throw std::logic_error("Session: configure() before use");
    return *simulator_;
  }
  ExactModel* exact_model() const { return dynamic_cast<ExactModel*>(simulator_.get()); }
  Eigen::Vector3d start_omega_body() const {
    return initial_angular_momentum(body_.moments, initial_).cwiseQuotient(body_.moments);
  }
  /// The exact motion's turn-overs from this start up to t (analysis::exact_flip_count).
  int exact_flip_count(double t) const {
    return exact_ ? bookspin::analysis::exact_flip_count(*exact_, exact_first_, t) : 0;
  }
  Body body_;
  InitialState initial_;
  std::optional<ExactRotation> exact_;  ///< this start's exact motion, ω only
  std::optional<double> exact_first_;   ///< its first flip; empty for a wobble
  std::unique_ptr<Simulator> simulator_;
  long long steps_ = 0;
  FlipDetector flips_;
};

/// The polhode family of moments (Ix, Iy, Iz) (docs/physics.md §15): an array of
/// {points: Float64Array(3·n) body frame, separatrix, pole_axis, energy_ratio}.
val polhodes(double ix, double iy, double iz, int levels, double max_step) {
  const std::vector<Polhode> family = polhode_family({ix, iy, iz}, levels, max_step);
  val out = val::array();
  for (const Polhode& p : family) {
    std::vector<double> flat;
    flat.reserve(p.points.size() * 3);
    for (const Eigen::Vector3d& u : p.points) flat.insert(flat.end(), {u.x(), u.y(), u.z()});
    val curve = val::object();
    curve.set("points", f64(flat.data(), flat.size()));
    curve.set("separatrix", p.separatrix);
    curve.set("pole_axis", p.pole_axis);
    curve.set("energy_ratio", p.energy_ratio);
    out.call<void>("push", curve);
  }
  return out;
}

/// A JavaScript array of strings.
val strings(const std::vector<std::string_view>& names) {
  val out = val::array();
  for (std::string_view name : names) out.call<void>("push", std::string(name));
  return out;
}

/// A plain JavaScript array of 3 numbers (not a typed array: the page's state compares and
/// writes its values as JSON).
val array3(const Eigen::Vector3d& v) {
  val out = val::array();
  for (int i = 0; i < 3; ++i) out.call<void>("push", v[i]);
  return out;
}

/// The names the page offers, from the physics' own tables, each list in the physics' order:
/// {models: the models of src/physics (the other engines' models, physics::is_engine, are not in
/// the page: it binds src/physics alone), integrators: every integrator one of those models
/// accepts, supports: {model: the integrators it accepts (physics::supports)}, bodies: every
/// body shape ("mesh": a mesh scene's own body)}.
val physics_names() {
  std::vector<std::string_view> models, integrators;
  val supported = val::object();
  for (ModelKind kind : model_kinds()) {
    if (is_engine(kind)) continue;
    models.push_back(to_string(kind));
    std::vector<std::string_view> own;
    for (Integrator integrator : bookspin::physics::integrators())
      if (supports(kind, integrator)) own.push_back(to_string(integrator));
    supported.set(std::string(to_string(kind)), strings(own));
  }
  for (Integrator integrator : bookspin::physics::integrators()) {
    for (ModelKind kind : model_kinds()) {
      if (!is_engine(kind) && supports(kind, integrator)) {
        integrators.push_back(to_string(integrator));
        break;
      }
    }
  }
  std::vector<std::string_view> bodies;
  for (BodyShape shape : body_shapes()) bodies.push_back(to_string(shape));
  val out = val::object();
  out.set("models", strings(models));
  out.set("integrators", strings(integrators));
  out.set("supports", supported);
  out.set("bodies", strings(bodies));
  return out;
}

/// The settings whose default the physics owns: {book: {size: [a, b, c] (length units), mass
/// (mass units)} the default book (physics::Book, docs/physics.md §1), k (force per length),
/// cells (lattice cells, 0: the default) and damping of physics::ModelConfig, w: the body-frame
/// ω0 of physics::InitialState (rad per time unit) and rate: its magnitude}.
val physics_defaults() {
  const Book book;
  const ModelConfig model;
  const InitialState initial;
  val out = val::object();
  val b = val::object();
  b.set("size", array3(book.size));
  b.set("mass", book.mass);
  out.set("book", b);
  out.set("k", model.spring_constant);
  out.set("cells", model.lattice_cells);
  out.set("damping", model.damping);
  out.set("w", array3(initial.omega0_body));
  out.set("rate", initial.omega0_body.norm());
  return out;
}

std::string error_message(std::intptr_t pointer) {
  return reinterpret_cast<const std::exception*>(pointer)->what();
}

}  // namespace

EMSCRIPTEN_BINDINGS(bookspin_physics) {
  emscripten::class_<Session>("Session")
      .constructor<std::string, double, double, double, double, double>()
      .constructor<val>()
      .function("configure", &Session::configure)
      .function("configureEngine", &Session::configure_engine)
      .function("observe", &Session::observe)
      .function("reset", &Session::reset)
      .function("startOmega", &Session::start_omega)
      .function("exactFlips", &Session::exact_flips)
      .function("step", &Session::step)
      .function("steps", &Session::steps)
      .function("finite", &Session::finite)
      .function("divergenceReason", &Session::divergence_reason)
      .function("diagnostics", &Session::diagnostics)
      .function("corners", &Session::corners)
      .function("flips", &Session::flips)
      .function("intermediateAxis", &Session::intermediate_axis)
      .function("omegaForMomentum", &Session::omega_for_momentum)
      .function("momentumMagnitude", &Session::momentum_magnitude)
      .function("surfaceWorld", &Session::surface_world)
      .function("carry", &Session::carry)
      .function("orientation", &Session::orientation)
      .function("moments", &Session::moments)
      .function("mass", &Session::mass)
      .function("principalOrder", &Session::principal_order)
      .function("bodyCorners", &Session::body_corners)
      .function("cageSize", &Session::cage_size)
      .function("surfaceVertices", &Session::surface_vertices)
      .function("surfaceTriangles", &Session::surface_triangles)
      .function("surfaceColours", &Session::surface_colours);
  emscripten::function("polhodes", &polhodes);
  emscripten::function("physicsNames", &physics_names);
  emscripten::function("physicsDefaults", &physics_defaults);
  emscripten::function("errorMessage", &error_message);
}
