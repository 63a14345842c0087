// The CSV writer (common/csv_writer.hpp): texts written out by hand, empty cells, quoting, and
// the finiteness check naming the column.
#include "common/csv_writer.hpp"

#include <gtest/gtest.h>

#include "support/internal_error_of.hpp"

namespace bookspin {
namespace {

TEST(CsvWriter, WritesTheHeaderThenEachRowInItsCellsFormats) {
  const CsvTable table{{"model", "dt", "error", "cost", "flips"},
                       {{std::string("rigid-matrix"), CsvNumber{0.1}, CsvNumber{1.0 / 3.0, "%.6e"},
                         CsvNumber{12.345, "%.2f"}, std::string("4")},
                        {std::string("particle"), CsvNumber{1.0 / 60.0}, CsvNumber{std::nullopt},
                         CsvNumber{0.5, "%.2f"}, std::string()}}};
  // By hand: 0.1 to 17 significant digits is 0.10000000000000001, 1/60 is
  // 0.016666666666666666; 1/3 in %.6e is 3.333333e-01.
  EXPECT_EQ(csv_text(table, "test CSV"),
            "model,dt,error,cost,flips\n"
            "rigid-matrix,0.10000000000000001,3.333333e-01,12.35,4\n"
            "particle,0.016666666666666666,,0.50,\n");
  EXPECT_EQ(csv_text({{"t"}, {}}, "test CSV"), "t\n");
}

TEST(CsvWriter, QuotesATextCellThatHoldsACommaAQuoteOrALineBreak) {
  const CsvTable table{
      {"name", "a,b"},
      {{std::string("say \"hi\""), std::string("x\ny")}, {std::string("plain"), std::string("-")}}};
  EXPECT_EQ(csv_text(table, "test CSV"), "name,\"a,b\"\n\"say \"\"hi\"\"\",\"x\ny\"\nplain,-\n");
}

TEST(CsvWriter, ARowIsItsFieldsJoinedByCommasQuotedAsInATable) {
  EXPECT_EQ(csv_row({"3", "", "0.5", ""}), "3,,0.5,");
  EXPECT_EQ(csv_row({"a,b", "c\"d", "e\rf", "g"}), "\"a,b\",\"c\"\"d\",\"e\rf\",g");
  EXPECT_EQ(csv_row({}), "");
  EXPECT_EQ(csv_field("initial.angular_velocity[1]"), "initial.angular_velocity[1]");
  EXPECT_EQ(csv_field(""), "");
  // A table's cells are the same fields.
  EXPECT_EQ(csv_text({{"a,b", "c"},
                      {{std::string("x\"y"), CsvNumber{0.25, nullptr, NumberStyle::shortest}}}},
                     "test CSV"),
            "\"a,b\",c\n\"x\"\"y\",0.25\n");
}

TEST(CsvWriter, NonFiniteNumberIsAnInternalErrorNamingItsColumn) {
  const CsvTable nan{{"t", "energy"},
                     {{CsvNumber{0.5}, CsvNumber{1e-3}}, {CsvNumber{1.0}, CsvNumber{kNan}}}};
  EXPECT_EQ(internal_error_of([&] { csv_text(nan, "energy CSV"); }),
            "non-finite energy CSV column energy in an output: nan");
  const CsvTable inf{{"dt"}, {{CsvNumber{-kInf, "%.6e"}}}};
  EXPECT_EQ(internal_error_of([&] { csv_text(inf, "accuracy CSV"); }),
            "non-finite accuracy CSV column dt in an output: -inf");
  // An empty cell is no number: nothing to check.
  EXPECT_EQ(csv_text({{"dt"}, {{CsvNumber{std::nullopt}}}}, "accuracy CSV"), "dt\n\n");
}

TEST(CsvWriter, ARowThatDoesNotMatchTheColumnsIsAnInternalError) {
  const CsvTable short_row{{"a", "b"}, {{std::string("1")}}};
  EXPECT_NE(internal_error_of([&] { csv_text(short_row, "test CSV"); }), "");
}

}  // namespace
}  // namespace bookspin
