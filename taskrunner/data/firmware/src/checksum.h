// Line checksums (PROTOCOL.md, "Checksums"): an optional "*XX" suffix, NMEA style.
//
// XX is the CRC-8 (polynomial 0x07, initial value 0, no reflection, no final XOR: the
// SMBus CRC-8, check value 0xF4 for "123456789") of every byte of the line before the
// '*', as two hexadecimal digits. It catches every single-bit and single-byte error,
// every burst up to 8 bits and transposed digits, which an XOR does not.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace trs {

uint8_t crc8(std::string_view bytes);

// "*XX" with upper-case hex digits.
std::string checksum_suffix(std::string_view bytes);

// `line` + "*XX".
std::string with_checksum(std::string_view line);

enum class ChecksumResult : uint8_t {
  kNone,       // no '*' in the line: a plain command (typed in a terminal)
  kOk,         // "*XX" at the end and it matches; *body gets the line before the '*'
  kMalformed,  // the last '*' is not followed by exactly two hex digits ending the line
  kMismatch,   // well formed, but the CRC of the bytes before it differs
};

// Splits and checks `line`'s checksum; the last '*' is the one that counts (a reply may
// echo a '*' of its command). On kMismatch, `*received` and `*computed` get the
// two values.
ChecksumResult check_checksum(std::string_view line, std::string_view* body,
                              uint8_t* received, uint8_t* computed);

}  // namespace trs
