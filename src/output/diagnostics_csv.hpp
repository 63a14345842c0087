#pragma once
// The diagnostics CSV sink: one row per frame, columns fixed (docs/physics.md §9).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "output/atomic_output.hpp"
#include "physics/simulator.hpp"

namespace bookspin::output {

/// The header line (no newline): frame,t,omega_x,…,quaternion_norm, then (added last, so the
/// earlier columns keep their places) cos_smallest_L,cos_intermediate_L,cos_largest_L, then
/// the pose: q_w,q_x,q_y,q_z (the unit quaternion of the orientation R, body→world, scalar
/// first, q_w >= 0; best-fit rotation of the particles for the deforming models) and
/// com_x,com_y,com_z (centre of mass, world) (docs/outputs.md, "The pose in the CSV").
const std::string& diagnostics_csv_header();

/// The header's column names, in order (frame, t, omega_x, …, com_z).
const std::vector<std::string>& diagnostics_columns();

/// One row's values, a value per column of diagnostics_columns(): the numbers the CSV row
/// spells (the frame as a double, q with q_w >= 0 and no −0), nullopt where the CSV has an
/// empty cell (the cos_*_L cells at rest). Not checked finite: diagnostics_csv_row() does that.
std::vector<std::optional<double>> diagnostics_values(int frame, const physics::Diagnostics& d);

/// One row (no newline, common/csv_writer.hpp's csv_row) for `frame`; numbers in shortest
/// round-trip form (NumberStyle::shortest), so
/// the same state always gives the same bytes. Frames: omega body, L world (docs/physics.md §9).
/// The six cos_*_L cells are empty when L = 0 (at rest: no direction); any other number that
/// is not finite throws InternalError naming its column (common/number_text.hpp).
std::string diagnostics_csv_row(int frame, const physics::Diagnostics& d);

/// The unit quaternion (w, x, y, z) of rotation `orientation` (3×3, body→world), with
/// w >= 0: v_world = q ⊗ v_body ⊗ q⁻¹. Used for the CSV's q_w…q_z and the glTF animation.
Eigen::Vector4d pose_quaternion(const Eigen::Matrix3d& orientation);

/// A diagnostics CSV written row by row under a temporary name (its folder made if missing)
/// and put in place by commit(); without commit() nothing is left behind. Throws
/// OutputError naming the path.
class DiagnosticsCsvFile {
 public:
  explicit DiagnosticsCsvFile(const std::filesystem::path& path);
  void add(int frame, const physics::Diagnostics& d);
  /// Closes the file and checks every write (idempotent); commit() does it too.
  void close() { file_.close(); }
  void commit() { file_.commit(); }
  /// Closes the file and adds it to `set`, which puts it in place with the run's outputs.
  void finish(OutputSet& set) { file_.finish(set); }

 private:
  AtomicTextFile file_;
};

}  // namespace bookspin::output
