// A scene's run as a table (jobs::diagnostics_table, the Python module's simulate): the very
// numbers of the CSV write_diagnostics_rows writes, every column in its order, an empty cell
// NaN; a comparison scene refused.
#include "jobs/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "output/diagnostics_csv.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {
namespace {

scene::Scene scene_of(const std::string& text) { return scene::parse_scene_text(text, "t.toml"); }

void expect_table_is_the_csv(const scene::Scene& s) {
  std::ostringstream csv;
  const SimulationResult written = write_diagnostics_rows(s, csv);
  const DiagnosticsTable table = diagnostics_table(s);
  EXPECT_EQ(table.result.rows, written.rows);
  EXPECT_EQ(table.columns, output::diagnostics_columns());
  std::istringstream lines(csv.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, csv_row(table.columns));
  int frame = 0;
  for (; std::getline(lines, line); ++frame) {
    const std::vector<std::string> cells = csv_cells(line);
    ASSERT_EQ(cells.size(), table.columns.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const double value = table.values[c].at(static_cast<std::size_t>(frame));
      if (cells[c].empty()) {
        EXPECT_TRUE(std::isnan(value)) << table.columns[c];
      } else {
        EXPECT_EQ(value, read_number(cells[c]).value()) << table.columns[c] << " " << frame;
      }
    }
  }
  EXPECT_EQ(frame, written.rows);
  for (const std::vector<double>& column : table.values) EXPECT_EQ(column.size(), frame);
}

TEST(Simulation, TheTableIsTheCsvsNumbers) {
  expect_table_is_the_csv(
      scene_of("[model]\nkind = \"rigid-quaternion\"\nintegrator = \"rk4\"\n[initial]\n"
               "angular_velocity = [0.2, 1.0, 0.01]\njiggle = 0.001\n[time]\nframes = 40\n"));
  expect_table_is_the_csv(scene_of("[model]\nkind = \"particle\"\n[time]\nframes = 12\n"));
  // At rest: the cosines with L are empty cells, NaN in the table.
  expect_table_is_the_csv(scene_of(
      "[initial]\nangular_velocity = [0.0, 0.0, 0.0]\njiggle = 0.0\n[time]\nframes = 3\n"));
}

TEST(Simulation, AComparisonSceneIsRefusedWithItsFile) {
  const scene::Scene s =
      scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/compare-methods-x.toml");
  try {
    require_one_run(s);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compare-methods-x.toml: a comparison scene"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(require_one_run(scene_of("[time]\nframes = 2\n")));
}

}  // namespace
}  // namespace bookspin::jobs
