#include "../src/numbers.h"
#include "harness.h"

using trs::format_centi;
using trs::parse_centi;
using trs::parse_uint;

namespace {
bool centi_is(std::string_view text, int64_t expected) {
  const trs::ParsedNumber n = parse_centi(text);
  return n.ok && n.value == expected;
}
bool centi_rejects(std::string_view text) { return !parse_centi(text).ok; }
}  // namespace

TEST(parse_centi_reads_integers_and_decimals) {
  CHECK(centi_is("0", 0));
  CHECK(centi_is("90", 9000));
  CHECK(centi_is("180", 18000));
  CHECK(centi_is("+90", 9000));
  CHECK(centi_is("-5", -500));
  CHECK(centi_is("-0", 0));
  CHECK(centi_is("90.5", 9050));
  CHECK(centi_is("90.25", 9025));
  CHECK(centi_is("007.10", 710));
  CHECK(centi_is(".5", 50));
  CHECK(centi_is("12.", 1200));
}

TEST(parse_centi_rounds_beyond_two_decimals_half_away_from_zero) {
  CHECK(centi_is("0.004", 0));
  CHECK(centi_is("0.005", 1));
  CHECK(centi_is("89.999", 9000));
  CHECK(centi_is("179.995", 18000));
  CHECK(centi_is("-1.235", -124));
  CHECK(centi_is("1.23499999", 123));
}

TEST(parse_centi_rejects_non_numbers) {
  CHECK(centi_rejects(""));
  CHECK(centi_rejects("+"));
  CHECK(centi_rejects("-"));
  CHECK(centi_rejects("."));
  CHECK(centi_rejects("abc"));
  CHECK(centi_rejects("9O"));
  CHECK(centi_rejects("1e2"));
  CHECK(centi_rejects("nan"));
  CHECK(centi_rejects("inf"));
  CHECK(centi_rejects("1.2.3"));
  CHECK(centi_rejects("1 2"));
  CHECK(centi_rejects("--1"));
  CHECK(centi_rejects("0x10"));
}

TEST(parse_centi_saturates_huge_values_so_they_stay_out_of_range) {
  const trs::ParsedNumber big = parse_centi("99999999999999999999999999");
  CHECK(big.ok);
  CHECK_EQ(big.value, trs::kParseSaturation);
  const trs::ParsedNumber negative = parse_centi("-99999999999999999999.99");
  CHECK(negative.ok);
  CHECK_EQ(negative.value, -trs::kParseSaturation);
}

TEST(parse_uint_accepts_digits_only) {
  CHECK(parse_uint("80").ok);
  CHECK_EQ(parse_uint("80").value, 80);
  CHECK_EQ(parse_uint("007").value, 7);
  CHECK(!parse_uint("").ok);
  CHECK(!parse_uint("-1").ok);
  CHECK(!parse_uint("+1").ok);
  CHECK(!parse_uint("1.0").ok);
  CHECK(!parse_uint(" 1").ok);
  CHECK_EQ(parse_uint("123456789012345678901234567890").value, trs::kParseSaturation);
}

TEST(format_centi_prints_shortest_exact_decimal) {
  CHECK_EQ(format_centi(0), "0");
  CHECK_EQ(format_centi(9000), "90");
  CHECK_EQ(format_centi(9050), "90.5");
  CHECK_EQ(format_centi(9025), "90.25");
  CHECK_EQ(format_centi(1), "0.01");
  CHECK_EQ(format_centi(10), "0.1");
  CHECK_EQ(format_centi(18000), "180");
  CHECK_EQ(format_centi(-150), "-1.5");
}

TEST(format_and_parse_round_trip_every_angle) {
  for (int32_t c = 0; c <= 18000; ++c) {
    const trs::ParsedNumber n = parse_centi(format_centi(c));
    if (!n.ok || n.value != c) {
      CHECK_EQ(n.value, c);
      return;
    }
  }
}

TEST(trim_and_iequals) {
  CHECK_EQ(trs::trim("  a b\t "), "a b");
  CHECK_EQ(trs::trim("\t\t"), "");
  CHECK(trs::iequals("status", "STATUS"));
  CHECK(trs::iequals("StAtUs", "STATUS"));
  CHECK(!trs::iequals("STATU", "STATUS"));
  CHECK(!trs::iequals("STATUs1", "STATUS"));
}
