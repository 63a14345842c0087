// The one number formatter (common/number_text.hpp): each style against texts written out by
// hand, and the closing check naming the field (docs/outputs.md, "Numbers").
#include "common/number_text.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include "support/internal_error_of.hpp"

namespace bookspin {
namespace {

TEST(FiniteNumber, PassesFiniteNumbersInShortestRoundTripForm) {
  EXPECT_EQ(finite(0.1, "x"), 0.1);
  EXPECT_EQ(finite_text(0.1, "x"), "0.1");
  EXPECT_EQ(finite_text(1e300, "x"), "1e+300");
  EXPECT_EQ(finite_text(std::numeric_limits<double>::denorm_min(), "x"), "5e-324");
  EXPECT_EQ(finite_text(std::optional<double>(), "x"), "");
  EXPECT_EQ(finite_text(std::optional<double>(-2.5), "x"), "-2.5");
}

TEST(FiniteNumber, EachStyleHasItsOwnSpelling) {
  // Written out by hand: %g drops trailing zeros and switches to an exponent below 1e-4;
  // to_chars takes the shorter of the two forms.
  EXPECT_EQ(finite_text(0.0001, "x", NumberStyle::shortest), "1e-04");
  EXPECT_EQ(finite_text(0.0001, "x", NumberStyle::digits17), "0.0001");
  EXPECT_EQ(finite_text(0.0001, "x", NumberStyle::fewest_g), "0.0001");
  EXPECT_EQ(finite_text(2.0 / 3.0, "x", NumberStyle::shortest), "0.6666666666666666");
  EXPECT_EQ(finite_text(2.0 / 3.0, "x", NumberStyle::digits17), "0.66666666666666663");
  EXPECT_EQ(finite_text(2.0 / 3.0, "x", NumberStyle::fewest_g), "0.6666666666666666");
  EXPECT_EQ(finite_text(0.1, "x", NumberStyle::digits17), "0.10000000000000001");
  EXPECT_EQ(finite_text(0.1, "x", NumberStyle::fewest_g), "0.1");
  EXPECT_EQ(finite_text(1e21, "x", NumberStyle::fewest_g), "1e+21");
  EXPECT_EQ(finite_text(std::numeric_limits<double>::denorm_min(), "x", NumberStyle::fewest_g),
            "4.94065645841247e-324");
  EXPECT_EQ(finite_text(12345.678, "x", "%.6e"), "1.234568e+04");
  EXPECT_EQ(finite_text(2.5, "x", "%.2f"), "2.50");
  EXPECT_EQ(finite_text(std::optional<double>(0.1), "x", NumberStyle::digits17),
            "0.10000000000000001");
}

TEST(FiniteNumber, NonFiniteIsAnInternalErrorNamingTheField) {
  EXPECT_EQ(internal_error_of([] { finite(kNan, "CSV column a"); }),
            "non-finite CSV column a in an output: nan");
  EXPECT_EQ(internal_error_of([] { finite_text(kInf, "JSON field b"); }),
            "non-finite JSON field b in an output: inf");
  EXPECT_EQ(internal_error_of([] { finite_text(std::optional<double>(-kInf), "c"); }),
            "non-finite c in an output: -inf");
  EXPECT_EQ(internal_error_of([] { finite_text(kNan, "d", NumberStyle::fewest_g); }),
            "non-finite d in an output: nan");
  EXPECT_EQ(internal_error_of([] { finite_text(kInf, "e", "%.6e"); }),
            "non-finite e in an output: inf");
}

}  // namespace
}  // namespace bookspin

// read_number() reads what std::from_chars reads (libstdc++'s, an independent implementation;
// emscripten's libc++ has none for doubles, so the explorer page relies on this reader): the
// same value to the bit, or nothing where from_chars stops early or is out of range.
TEST(ReadNumber, ReadsWhatFromCharsReads) {
  const char* cases[] = {"0",
                         "-0",
                         "1",
                         "-2.5",
                         "1e5",
                         "1E-5",
                         ".5",
                         "5.",
                         "-.5e+3",
                         "007",
                         "0.1",
                         "1e",
                         "1e+",
                         "e5",
                         ".",
                         "-",
                         "",
                         "+1",
                         "--1",
                         " 1",
                         "1 ",
                         "0x10",
                         "1,5",
                         "nan",
                         "NaN",
                         "-nan",
                         "inf",
                         "-INF",
                         "infinity",
                         "Infinity",
                         "infin",
                         "1e400",
                         "-1e400",
                         "1e-400",
                         "4.9e-324",
                         "2e-324",
                         "1e-310",
                         "0e500",
                         "0.000e-999",
                         "1.7976931348623157e308",
                         "123456789012345678901234567890",
                         "0.30000000000000004"};
  for (const char* text : cases) {
    const std::string_view s(text);
    double expected = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), expected);
    const bool whole = ec == std::errc() && end == s.data() + s.size();
    const std::optional<double> got = bookspin::read_number(s);
    ASSERT_EQ(got.has_value(), whole) << '"' << text << '"';
    if (!whole) continue;
    if (std::isnan(expected)) {
      EXPECT_TRUE(std::isnan(*got)) << text;
      EXPECT_EQ(std::signbit(*got), std::signbit(expected)) << text;
    } else {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(*got), std::bit_cast<std::uint64_t>(expected)) << text;
    }
  }
}

namespace bookspin {
namespace {

// A value ± σ for a person (number_text.hpp, plus_minus): σ to two significant digits, the
// value to σ's last place; the expected texts worked by hand.
TEST(PlusMinus, TheValueStopsAtSigmasSecondSignificantDigit) {
  EXPECT_EQ(plus_minus(0.3482571, 0.0000269191), "0.348257 ± 0.000027");
  EXPECT_EQ(plus_minus(0.170234567, 0.000123), "0.17023 ± 0.00012");
  EXPECT_EQ(plus_minus(1.23456, 0.0996), "1.23 ± 0.10");  // σ rounds up a place: 0.10
  EXPECT_EQ(plus_minus(171.4, 12.3), "171 ± 12");
  EXPECT_EQ(plus_minus(1714.0, 123.0), "1710 ± 120");     // σ above 100: tens
  EXPECT_EQ(plus_minus(-0.0001, 0.01), "0.000 ± 0.010");  // no "-0.000"
  EXPECT_EQ(plus_minus(-0.25, 0.031), "-0.250 ± 0.031");
  // No σ to round to: four significant digits, and a σ of 0 said.
  EXPECT_EQ(plus_minus(5.0, 0.0), "5 ± 0");
  EXPECT_EQ(plus_minus(0.123456, std::nan("")), "0.1235");
}

}  // namespace
}  // namespace bookspin
