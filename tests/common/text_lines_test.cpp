// The pieces of a CSV's lines every reader shares (common/text_lines.hpp): the three line ends,
// the NUL byte's line, and a cell cut for a one-line message. The expected values are written
// out by hand from the bytes given.
#include "common/text_lines.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bookspin {
namespace {

std::vector<std::string> lines_of(std::string_view text) {
  std::vector<std::string> lines;
  for (std::size_t start = 0; start < text.size();) {
    const TextLine next = next_line(text, start);
    EXPECT_GT(next.next, start);  // always forward
    lines.emplace_back(next.line);
    start = next.next;
  }
  return lines;
}

TEST(TextLines, CrLfLfAndALoneCrEachEndALine) {
  const std::vector<std::string> want{"a", "b", "c", "", "d"};
  EXPECT_EQ(lines_of("a\nb\nc\n\nd"), want);
  EXPECT_EQ(lines_of("a\r\nb\r\nc\r\n\r\nd\r\n"), want);
  EXPECT_EQ(lines_of("a\rb\rc\r\rd\r"), want);
  EXPECT_EQ(lines_of("a\r\nb\rc\n\r\nd"), want);  // mixed, as a file edited twice
  EXPECT_EQ(lines_of(""), std::vector<std::string>{});
  EXPECT_EQ(lines_of("\r"), std::vector<std::string>{""});
}

// A CSV record as RFC 4180 reads it, written out by hand: quotes hold the separator, a doubled
// quote and line ends of each kind; spaces around a cell are not part of it, inside quotes
// they are; a quote inside an unquoted cell is a character; an open quote at the end says so.
TEST(TextLines, ACsvRecordIsReadAsRfc4180ReadsIt) {
  using Cells = std::vector<std::string>;
  const CsvRecord plain = next_csv_record(" a , b,,c \r\nnext", 0, ',');
  EXPECT_EQ(plain.cells, (Cells{"a", "b", "", "c"}));
  EXPECT_EQ(plain.next, 12u);
  EXPECT_EQ(plain.lines, 1);
  const CsvRecord quoted =
      next_csv_record("1,\"x, \"\"y\"\"\r\nz\rw\" , \" q \",5\"6\nrest", 0, ',');
  EXPECT_EQ(quoted.cells, (Cells{"1", "x, \"y\"\r\nz\rw", " q ", "5\"6"}));
  EXPECT_EQ(quoted.lines, 3);
  EXPECT_FALSE(quoted.unclosed);
  EXPECT_EQ(
      next_csv_record("1,\"x, \"\"y\"\"\r\nz\rw\" , \" q \",5\"6\nrest", quoted.next, ',').cells,
      Cells{"rest"});
  EXPECT_EQ(next_csv_record("a;\"1,5\";b", 0, ';').cells, (Cells{"a", "1,5", "b"}));
  EXPECT_EQ(next_csv_record("a\t\"b\tc\"", 0, '\t').cells, (Cells{"a", "b\tc"}));
  const CsvRecord open = next_csv_record("a,\"b\nc", 0, ',');
  EXPECT_TRUE(open.unclosed);
  EXPECT_EQ(open.next, 6u);  // the end of the text
  EXPECT_EQ(open.cells, (Cells{"a", "b\nc"}));
}

TEST(TextLines, ANulByteIsNamedWithItsLine) {
  EXPECT_FALSE(nul_byte_problem("t,wx\n1,2\n").has_value());
  const std::string tail = " (not a text file: a binary file, or text saved as UTF-16)";
  EXPECT_EQ(nul_byte_problem(std::string("\0a", 2)), "NUL byte at line 1" + tail);
  EXPECT_EQ(nul_byte_problem(std::string("a\nb\nc\0", 6)), "NUL byte at line 3" + tail);
  EXPECT_EQ(nul_byte_problem(std::string("a\r\nb\rc\0", 7)), "NUL byte at line 3" + tail);
  // UTF-16: "t\0" — the NUL right after the first character.
  EXPECT_EQ(nul_byte_problem(std::string("t\0,\0", 4)), "NUL byte at line 1" + tail);
}

TEST(TextLines, ACellLongerThan80CharactersIsCutWithItsLength) {
  const std::string eighty(80, '7');
  EXPECT_EQ(quoted_cell(eighty), "\"" + eighty + "\"");
  EXPECT_EQ(cut_cell(eighty), eighty);
  const std::string long_cell(2'097'152, 'x');
  EXPECT_EQ(quoted_cell(long_cell), "\"" + std::string(60, 'x') + "…\" (2097152 characters)");
  EXPECT_EQ(cut_cell(long_cell), std::string(60, 'x') + "… (2097152 characters)");
  EXPECT_EQ(quoted_cell(std::string(81, 'a')), "\"" + std::string(60, 'a') + "…\" (81 characters)");
  // Not cut inside a UTF-8 sequence: "ω" is two bytes, the 60th byte is the first of one.
  const std::string omegas = std::string(59, 'a') + "ωωωωωωωωωω" + std::string(10, 'b');
  EXPECT_EQ(cut_cell(omegas), std::string(59, 'a') + "… (89 characters)");
}

}  // namespace
}  // namespace bookspin
