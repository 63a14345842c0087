// The one table of models and their modes (physics::model_modes()) against scenes/README.md's
// rows of model.kind and model.integrator, which a user reads: every model named there in the
// table's order, every model's integrators there as the table has them, an engine's default
// (its first row) marked "(its default)".
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "physics/model_modes.hpp"

namespace bookspin::scene {
namespace {

/// The description cell of the key table's row of `key` in scenes/README.md.
std::string readme_cell(const std::string& key) {
  std::ifstream readme(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/README.md");
  const std::string start = "| `" + key + "` |";
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind(start, 0) != 0) continue;
    const auto last = line.rfind(" |");
    const auto before = line.rfind(" | ", last - 1);
    return line.substr(before + 3, last - before - 3);
  }
  ADD_FAILURE() << key << " has no row in scenes/README.md";
  return {};
}

/// The `names` of `text`, in order.
std::vector<std::string> quoted_names(const std::string& text) {
  std::vector<std::string> names;
  for (auto at = text.find('`'); at != std::string::npos; at = text.find('`', at)) {
    const auto end = text.find('`', at + 1);
    names.push_back(text.substr(at + 1, end - at - 1));
    at = end + 1;
  }
  return names;
}

TEST(ModelModesDoc, TheReadmeNamesEveryModelInTheTablesOrder) {
  const std::string cell = readme_cell("model.kind");
  std::vector<std::string> table;
  for (physics::ModelKind kind : physics::model_kinds())
    table.emplace_back(physics::to_string(kind));
  EXPECT_EQ(quoted_names(cell.substr(0, cell.find(" ("))), table) << cell;
}

TEST(ModelModesDoc, TheReadmeListsEveryModelsIntegratorsAsTheTableHasThem) {
  std::string cell = readme_cell("model.integrator");
  cell = cell.substr(0, cell.find(". "));  // the groups, before the sentence that follows them
  std::map<std::string, std::vector<std::string>> documented;
  std::map<std::string, std::string> defaults;
  for (std::size_t at = 0; at < cell.size();) {
    const auto end = std::min(cell.find("; ", at), cell.size());
    const std::string group = cell.substr(at, end - at);
    at = end + 2;
    const auto colon = group.find(": ");
    ASSERT_NE(colon, std::string::npos) << group;
    const std::string label = group.substr(0, colon);
    const std::vector<std::string> names = quoted_names(group.substr(colon));
    // "rigid" stands for both rigid models.
    for (const std::string& model :
         label == "rigid" ? std::vector<std::string>{"rigid-matrix", "rigid-quaternion"}
                          : std::vector<std::string>{label}) {
      documented[model] = names;
      const auto marked = group.find(" (its default)");
      if (marked != std::string::npos)
        defaults[model] = quoted_names(group.substr(0, marked)).back();
    }
  }
  std::map<std::string, std::vector<std::string>> table;
  for (const physics::ModelMode& m : physics::model_modes())
    table[std::string(physics::to_string(m.kind))].emplace_back(physics::to_string(m.integrator));
  EXPECT_EQ(documented, table);
  for (physics::ModelKind kind : physics::model_kinds()) {
    const std::string model(physics::to_string(kind));
    if (physics::is_engine(kind))
      EXPECT_EQ(defaults[model], physics::to_string(physics::default_integrator(kind))) << model;
    else
      EXPECT_EQ(defaults.count(model), 0u) << model << ": its default is the key's, euler";
  }
}

}  // namespace
}  // namespace bookspin::scene
