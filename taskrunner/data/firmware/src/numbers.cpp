#include "numbers.h"

namespace trs {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

int64_t saturating_push_digit(int64_t value, char digit) {
  if (value >= kParseSaturation) return kParseSaturation;
  value = value * 10 + (digit - '0');
  return value > kParseSaturation ? kParseSaturation : value;
}

}  // namespace

ParsedNumber parse_centi(std::string_view text) {
  ParsedNumber result;
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    negative = text[i] == '-';
    ++i;
  }
  int64_t whole = 0;
  int digits = 0;
  while (i < text.size() && is_digit(text[i])) {
    whole = saturating_push_digit(whole, text[i]);
    ++i;
    ++digits;
  }
  int64_t fraction = 0;  // hundredths
  bool round_up = false;
  if (i < text.size() && text[i] == '.') {
    ++i;
    int fraction_digits = 0;
    while (i < text.size() && is_digit(text[i])) {
      if (fraction_digits < 2) {
        fraction = fraction * 10 + (text[i] - '0');
      } else if (fraction_digits == 2) {
        round_up = text[i] >= '5';
      }
      ++fraction_digits;
      ++digits;
      ++i;
    }
    for (; fraction_digits < 2; ++fraction_digits) fraction *= 10;
  }
  if (digits == 0 || i != text.size()) return result;
  int64_t magnitude = whole >= kParseSaturation ? kParseSaturation
                                                : whole * 100 + fraction + (round_up ? 1 : 0);
  if (magnitude > kParseSaturation) magnitude = kParseSaturation;
  result.ok = true;
  result.value = negative ? -magnitude : magnitude;
  return result;
}

ParsedNumber parse_uint(std::string_view text) {
  ParsedNumber result;
  if (text.empty()) return result;
  int64_t value = 0;
  for (char c : text) {
    if (!is_digit(c)) return result;
    value = saturating_push_digit(value, c);
  }
  result.ok = true;
  result.value = value;
  return result;
}

void append_centi(std::string* out, int32_t centi) {
  int64_t v = centi;
  if (v < 0) {
    out->push_back('-');
    v = -v;
  }
  *out += std::to_string(v / 100);
  const int frac = static_cast<int>(v % 100);
  if (frac != 0) {
    out->push_back('.');
    out->push_back(static_cast<char>('0' + frac / 10));
    if (frac % 10 != 0) out->push_back(static_cast<char>('0' + frac % 10));
  }
}

std::string format_centi(int32_t centi) {
  std::string out;
  append_centi(&out, centi);
  return out;
}

std::string_view trim(std::string_view text) {
  std::size_t begin = 0;
  std::size_t end = text.size();
  while (begin < end && (text[begin] == ' ' || text[begin] == '\t')) ++begin;
  while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  return text.substr(begin, end - begin);
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i];
    char y = b[i];
    if (x >= 'a' && x <= 'z') x = static_cast<char>(x - 'a' + 'A');
    if (y >= 'a' && y <= 'z') y = static_cast<char>(y - 'a' + 'A');
    if (x != y) return false;
  }
  return true;
}

}  // namespace trs
