#include "checksum.h"

namespace trs {
namespace {

constexpr char kHex[] = "0123456789ABCDEF";

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

uint8_t crc8(std::string_view bytes) {
  uint8_t crc = 0;
  for (char c : bytes) {
    crc ^= static_cast<uint8_t>(c);
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x80) ? static_cast<uint8_t>((crc << 1) ^ 0x07) : static_cast<uint8_t>(crc << 1);
    }
  }
  return crc;
}

std::string checksum_suffix(std::string_view bytes) {
  const uint8_t crc = crc8(bytes);
  std::string out = "*";
  out.push_back(kHex[crc >> 4]);
  out.push_back(kHex[crc & 0x0f]);
  return out;
}

std::string with_checksum(std::string_view line) {
  std::string out(line);
  out += checksum_suffix(line);
  return out;
}

ChecksumResult check_checksum(std::string_view line, std::string_view* body,
                              uint8_t* received, uint8_t* computed) {
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos) return ChecksumResult::kNone;
  if (star + 3 != line.size()) return ChecksumResult::kMalformed;
  const int high = hex_value(line[star + 1]);
  const int low = hex_value(line[star + 2]);
  if (high < 0 || low < 0) return ChecksumResult::kMalformed;
  *body = line.substr(0, star);
  *received = static_cast<uint8_t>(high * 16 + low);
  *computed = crc8(*body);
  return *received == *computed ? ChecksumResult::kOk : ChecksumResult::kMismatch;
}

}  // namespace trs
