// runtime/json.hpp writes what nlohmann::json's dump writes for the same document, so trace.json and
// stats.json keep their layout while the model needs no JSON library. One deliberate difference:
// a decimal is printed as its own digits, where nlohmann's Grisu2 printing of the parsed double
// sometimes adds a tail that reads back as the same double ("0.81744" -> 0.8174400000000001).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "runtime/json.hpp"

using namespace vbim;

TEST(Json, QuoteEscapesLikeNlohmann) {
  std::string all;
  for (int c = 1; c < 128; ++c) all += static_cast<char>(c);
  all += "caf\xc3\xa9 \xe2\x86\x92";
  EXPECT_EQ(json::quote(all), nlohmann::json(all).dump());
  EXPECT_EQ(json::quote(""), nlohmann::json("").dump());
}

// Damaged text (a descriptor from a scratched disc) may hold any bytes: quote() keeps well-formed
// UTF-8 and replaces every other byte with U+FFFD, so nlohmann's strict parser reads every result;
// isUtf8() says exactly when nlohmann's strict writer would refuse the text.
TEST(Json, QuoteKeepsEveryDocumentValidUtf8) {
  std::mt19937 rng(29);
  for (int round = 0; round < 20000; ++round) {
    std::string s(rng() % 12, '\0');
    for (char& c : s) {
      // mostly bytes that start or continue multi-byte sequences, where the edge cases are
      const unsigned r = rng();
      c = static_cast<char>((r & 3) == 0 ? (r >> 8) % 0x80 : 0x80 + (r >> 8) % 0x80);
    }
    bool strictWrites = true;
    try {
      (void)nlohmann::json(s).dump();
    } catch (const nlohmann::json::type_error&) {
      strictWrites = false;
    }
    ASSERT_EQ(json::isUtf8(s), strictWrites) << round;
    const std::string quoted = json::quote(s);
    nlohmann::json back;
    ASSERT_NO_THROW(back = nlohmann::json::parse(quoted)) << quoted;
    ASSERT_NO_THROW((void)back.dump()) << quoted;  // what it parsed is well-formed UTF-8 again
    if (strictWrites) {
      ASSERT_EQ(back.get<std::string>(), s);
    }
  }
  EXPECT_EQ(json::quote("a\x28\xff("), "\"a(\\ufffd(\"");
  EXPECT_EQ(json::quote("\xed\xa0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");  // a surrogate, CESU-style
  EXPECT_EQ(json::quote("\xf0\x9f\x98\x80"), "\"\xf0\x9f\x98\x80\"");   // U+1F600 kept
}

// Ours reads back as the same double as nlohmann's text, and is never longer; where Grisu2 found the
// shortest form (almost always), the two are identical.
void expectSameDouble(const std::string& text) {
  const std::string ours = json::Value::decimal(text).dump(2);
  const std::string theirs = nlohmann::json::parse(text).dump(2);
  ASSERT_EQ(nlohmann::json::parse(ours).get<double>(), nlohmann::json::parse(theirs).get<double>()) << text;
  ASSERT_LE(ours.size(), theirs.size()) << text;
  if (ours.size() == theirs.size()) {
    ASSERT_EQ(ours, theirs) << text;
  }
}

TEST(Json, DecimalsPrintAsTheParsedDouble) {
  const char* cases[] = {"0",        "7",         "-3",       "12.500000", "600.000000", "0.0000",  "0.0123",
                         "1.0000",   "0.000016",  "0.000100", "0.001000",  "123456.789", "-0.5000", "99999.999999",
                         "0.000001", "1000000.0", "42.000001"};
  for (const char* c : cases) expectSameDouble(c);
  EXPECT_EQ(json::Value::decimal("0.81744").dump(2), "0.81744");
  std::mt19937_64 rng(5);
  for (int i = 0; i < 20'000; ++i) {
    const std::uint64_t whole = rng() % 10'000'000;
    const std::uint64_t frac = rng() % 1'000'000;
    std::string f = std::to_string(frac);
    const std::string text = std::to_string(whole) + "." + std::string(6 - f.size(), '0') + f;
    expectSameDouble(text);
    expectSameDouble("0." + std::string(rng() % 6, '0') + std::to_string(rng() % 100'000));
  }
}

TEST(Json, DocumentsDumpLikeNlohmann) {
  json::Value v;
  v["b"] = json::object({{"z", 1}, {"a", true}, {"m", json::Value()}});
  v["a"] = std::uint64_t{18'446'744'073'709'551'615u};
  v["c"] = json::Value::array();
  json::Value arr = json::Value::array();
  arr.push(std::int64_t{-5});
  arr.push("x\ny");
  arr.push(json::Value::object());
  v["d"] = arr;
  v["e"] = json::Value::decimal("3.250000");
  nlohmann::json n;
  n["b"] = {{"z", 1}, {"a", true}, {"m", nullptr}};
  n["a"] = std::uint64_t{18'446'744'073'709'551'615u};
  n["c"] = nlohmann::json::array();
  n["d"] = {-5, "x\ny", nlohmann::json::object()};
  n["e"] = nlohmann::json::parse("3.250000");
  EXPECT_EQ(v.dump(2), n.dump(2));
  EXPECT_EQ(v.dump(0), n.dump(0));
}

TEST(Json, RejectsWhatIsNotADecimal) {
  EXPECT_THROW(json::Value::decimal("1e5"), std::invalid_argument);
  EXPECT_THROW(json::Value::decimal("1.2.3"), std::invalid_argument);
  EXPECT_THROW(json::Value::decimal(""), std::invalid_argument);
  EXPECT_THROW(json::Value::decimal("1234567890.1234567"), std::invalid_argument);
}
