#include "line_reader.h"

#include "numbers.h"

namespace trs {
namespace {

bool is_line_byte(uint8_t byte) { return byte == '\t' || (byte >= 0x20 && byte <= 0x7e); }

}  // namespace

void LineReader::reset() {
  length_ = 0;
  received_ = 0;
  too_long_ = false;
  bad_ = false;
  bad_byte_ = 0;
  bad_column_ = 0;
}

std::string_view LineReader::line() const { return line_; }

LineReader::Event LineReader::feed(char c) {
  const auto byte = static_cast<uint8_t>(c);
  if (byte == '\r' || byte == '\n') {
    Event event = Event::kNone;
    if (too_long_) {
      event = Event::kTooLong;
    } else if (bad_) {
      event = Event::kBadByte;
    } else {
      line_ = trim(std::string_view(buffer_, length_));
      if (!line_.empty()) event = Event::kLine;
    }
    const uint8_t bad_byte = bad_byte_;
    const std::size_t bad_column = bad_column_;
    reset();
    bad_byte_ = bad_byte;
    bad_column_ = bad_column;
    return event;
  }
  ++received_;
  if (!bad_ && !is_line_byte(byte)) {
    bad_ = true;
    bad_byte_ = byte;
    bad_column_ = received_;
  }
  if (length_ < kMaxLineLength) {
    buffer_[length_++] = c;
  } else {
    too_long_ = true;
  }
  return Event::kNone;
}

LineReader::Event check_line(std::string_view text, std::string_view* line_out,
                             uint8_t* bad_byte, std::size_t* bad_column) {
  // A trailing terminator is tolerated (people paste serial commands with "\n").
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
  if (text.size() > kMaxLineLength) return LineReader::Event::kTooLong;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<uint8_t>(text[i]);
    if (!is_line_byte(byte)) {
      *bad_byte = byte;
      *bad_column = i + 1;
      return LineReader::Event::kBadByte;
    }
  }
  *line_out = trim(text);
  return line_out->empty() ? LineReader::Event::kNone : LineReader::Event::kLine;
}

}  // namespace trs
