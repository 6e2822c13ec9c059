// Byte stream -> command lines, robust to noise.
//
// A line ends at CR or LF (so CR, LF, CRLF and LFCR all work; the empty line that a
// CRLF pair leaves behind is ignored, as are blank lines). Only printable ASCII and tab
// may appear in a line. A line longer than kMaxLineLength, or holding any other byte,
// is discarded up to its terminator and reported once, when the terminator arrives.
// Memory is bounded: nothing past kMaxLineLength is stored.
#pragma once

#include <cstdint>
#include <string_view>

#include "config.h"

namespace trs {

class LineReader {
 public:
  enum class Event : uint8_t {
    kNone,     // nothing complete yet (or a blank line was skipped)
    kLine,     // line() holds a complete line, trimmed of spaces and tabs
    kTooLong,  // a line exceeded kMaxLineLength bytes
    kBadByte,  // a line held a byte outside printable ASCII; see bad_byte(), bad_column()
  };

  Event feed(char byte);

  // Valid after kLine until the next feed().
  std::string_view line() const;
  // After kBadByte: the first offending byte and its 1-based column.
  uint8_t bad_byte() const { return bad_byte_; }
  std::size_t bad_column() const { return bad_column_; }

  // Drops a partial line.
  void reset();

 private:
  char buffer_[kMaxLineLength];
  std::size_t length_ = 0;     // bytes stored
  std::size_t received_ = 0;   // bytes seen in this line (including discarded)
  bool too_long_ = false;
  bool bad_ = false;
  uint8_t bad_byte_ = 0;
  std::size_t bad_column_ = 0;
  std::string_view line_;
};

// The same checks for a whole command received at once (HTTP): kLine when `text` is one
// acceptable line (line_out gets it trimmed), else kTooLong / kBadByte (with the
// offending byte and column) or kNone when it is blank.
LineReader::Event check_line(std::string_view text, std::string_view* line_out,
                             uint8_t* bad_byte, std::size_t* bad_column);

}  // namespace trs
