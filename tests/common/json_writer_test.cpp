// The JSON writer (common/json_writer.hpp): texts written out by hand, the escaping of the one
// escaper (common/json_string.hpp), and the finiteness check naming where the number sits.
#include "common/json_writer.hpp"

#include <gtest/gtest.h>

#include "support/internal_error_of.hpp"

namespace bookspin {
namespace {

TEST(JsonWriter, WritesEveryKindOfValueCompactlyInTheOrderGiven) {
  const JsonObject inner{{"w", {std::vector<double>{0.1, -2.0, 1e-7}}}, {"n", {std::int64_t{-42}}}};
  const JsonValue value{JsonObject{{"name", {std::string("book")}},
                                   {"on", {true}},
                                   {"off", {false}},
                                   {"dt", {1.0 / 60.0}},
                                   {"seed", {std::int64_t{9223372036854775807}}},
                                   {"list", {JsonArray{{1.5}, {std::string("x")}, {JsonArray{}}}}},
                                   {"inner", {inner}},
                                   {"empty", {JsonObject{}}}}};
  // Written out by hand: 1/60 in shortest round-trip form is 0.016666666666666666 (17 digits).
  EXPECT_EQ(json_text(value, "test"),
            "{\"name\":\"book\",\"on\":true,\"off\":false,\"dt\":0.016666666666666666,"
            "\"seed\":9223372036854775807,\"list\":[1.5,\"x\",[]],"
            "\"inner\":{\"w\":[0.1,-2,1e-07],\"n\":-42},\"empty\":{}}");
}

TEST(JsonWriter, EscapesKeysAndStringsWithTheOneEscaper) {
  const JsonValue value{JsonObject{{"a\"b", {std::string("back\\slash\nline\x01 \xc3\xa9")}}}};
  EXPECT_EQ(json_text(value, "test"), "{\"a\\\"b\":\"back\\\\slash\\u000aline\\u0001 \xc3\xa9\"}");
}

TEST(JsonWriter, ElementPerLinePutsEachElementOfTheTopArrayOnItsOwnLine) {
  const JsonValue list{JsonArray{{JsonObject{{"a", {1.0}}}}, {JsonArray{{2.0}, {3.0}}}}};
  EXPECT_EQ(json_text(list, "test", JsonLayout::element_per_line), "[\n{\"a\":1},\n[2,3]]");
  EXPECT_EQ(json_text(list, "test"), "[{\"a\":1},[2,3]]");
  EXPECT_EQ(json_text({JsonArray{}}, "test", JsonLayout::element_per_line), "[]");
  // Only an array has elements: anything else is written as it is.
  EXPECT_EQ(json_text({2.5}, "test", JsonLayout::element_per_line), "2.5");
}

TEST(JsonWriter, IndentedBreaksTheMarkedContainersAndKeepsTheOthersOnOneLine) {
  // A manifest's shape: the top object and "options" broken, "bookspin" and the vector inline,
  // "empty" broken but with nothing in it, "none" inline and empty.
  const JsonValue value{
      JsonObject{{"manifest", {std::int64_t{1}}},
                 {"bookspin", {JsonObject{{"version", {std::string("1.0")}}, {"ok", {true}}}}},
                 {"options",
                  {JsonObject{{"dt", {JsonNumber{0.1, NumberStyle::digits17}}},
                              {"v", {JsonArray{{1.5}, {std::string("x")}}}},
                              {"w", {std::vector<double>{2.0, 1e-7}}}},
                   true}},
                 {"list", {JsonArray{{JsonObject{{"path", {std::string("a.csv")}}}}, {2.0}}, true}},
                 {"empty", {JsonObject{}, true}},
                 {"none", {JsonArray{}}}},
      true};
  EXPECT_EQ(json_text(value, "test", JsonLayout::indented),
            "{\n"
            "  \"manifest\": 1,\n"
            "  \"bookspin\": {\"version\": \"1.0\", \"ok\": true},\n"
            "  \"options\": {\n"
            "    \"dt\": 0.10000000000000001,\n"
            "    \"v\": [1.5, \"x\"],\n"
            "    \"w\": [2, 1e-07]\n"
            "  },\n"
            "  \"list\": [\n"
            "    {\"path\": \"a.csv\"},\n"
            "    2\n"
            "  ],\n"
            "  \"empty\": {\n"
            "  },\n"
            "  \"none\": []\n"
            "}");
  // The other layouts ignore the marks and the number styles keep their own spelling.
  EXPECT_EQ(json_text(value, "test"),
            "{\"manifest\":1,\"bookspin\":{\"version\":\"1.0\",\"ok\":true},"
            "\"options\":{\"dt\":0.10000000000000001,\"v\":[1.5,\"x\"],\"w\":[2,1e-07]},"
            "\"list\":[{\"path\":\"a.csv\"},2],\"empty\":{},\"none\":[]}");
}

TEST(JsonWriter, MemberLinesAreTheLinesOfAnIndentedObjectsMembers) {
  const JsonObject members{{"a", {std::int64_t{-3}}},
                           {"b", {JsonObject{{"c", {std::string("d")}}}, true}},
                           {"e", {JsonNumber{1.0 / 3.0, NumberStyle::fewest_g}}}};
  EXPECT_EQ(json_member_lines(members, "test", 2, false),
            "  \"a\": -3,\n"
            "  \"b\": {\n"
            "    \"c\": \"d\"\n"
            "  },\n"
            "  \"e\": 0.3333333333333333,\n");
  EXPECT_EQ(json_member_lines(members, "test", 0, true),
            "\"a\": -3,\n"
            "\"b\": {\n"
            "  \"c\": \"d\"\n"
            "},\n"
            "\"e\": 0.3333333333333333\n");
  EXPECT_EQ(json_member_lines({}, "test", 2, true), "");
  EXPECT_EQ(internal_error_of([] {
              json_member_lines({{"x", {JsonArray{{1.0}, {JsonNumber{kNan}}}}}}, "head", 2, true);
            }),
            "non-finite head x[1] in an output: nan");
}

TEST(JsonWriter, NonFiniteNumberIsAnInternalErrorNamingItsPlace) {
  const JsonValue scenes{JsonArray{{JsonObject{{"state", {JsonObject{{"dt", {0.5}}}}}}},
                                   {JsonObject{{"state", {JsonObject{{"dt", {kNan}}}}}}}}};
  EXPECT_EQ(internal_error_of([&] { json_text(scenes, "page scene"); }),
            "non-finite page scene [1].state.dt in an output: nan");
  const JsonValue body{JsonObject{{"vertices", {std::vector<double>{0.0, -kInf}}}}};
  EXPECT_EQ(internal_error_of([&] { json_text(body, "page"); }),
            "non-finite page vertices in an output: -inf");
  EXPECT_EQ(internal_error_of([&] { json_text({kInf}, "page"); }),
            "non-finite page in an output: inf");
}

}  // namespace
}  // namespace bookspin
