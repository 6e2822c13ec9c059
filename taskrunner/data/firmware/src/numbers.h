// Text <-> number helpers for the line protocol (no locale, no exceptions, no allocation
// when parsing).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace trs {

struct ParsedNumber {
  bool ok = false;     // false: not a number of the expected form
  int64_t value = 0;   // saturated at +-kParseSaturation, so huge inputs stay "out of range"
};

constexpr int64_t kParseSaturation = 1000000000;

// A decimal number of degrees ("90", "+90", "-5", "90.5", "90.25", ".5", "12.")
// as centidegrees, rounded half away from zero beyond two decimals ("0.005" -> 1).
// No exponent, no inf/nan, no spaces.
ParsedNumber parse_centi(std::string_view text);

// Unsigned decimal integer ("80", "007"): digits only, no sign.
ParsedNumber parse_uint(std::string_view text);

// Centidegrees as the shortest exact decimal: 9000 -> "90", 9050 -> "90.5", 1 -> "0.01".
std::string format_centi(int32_t centi);
void append_centi(std::string* out, int32_t centi);

// Without leading/trailing spaces and tabs.
std::string_view trim(std::string_view text);

// ASCII case-insensitive equality.
bool iequals(std::string_view a, std::string_view b);

}  // namespace trs
