#include <string>
#include <vector>

#include "../src/line_reader.h"
#include "harness.h"

using trs::LineReader;
using Event = trs::LineReader::Event;

namespace {

struct Seen {
  std::vector<std::string> lines;
  std::vector<Event> errors;
};

Seen feed_all(LineReader& reader, std::string_view bytes) {
  Seen seen;
  for (char c : bytes) {
    const Event e = reader.feed(c);
    if (e == Event::kLine) seen.lines.emplace_back(reader.line());
    if (e == Event::kTooLong || e == Event::kBadByte) seen.errors.push_back(e);
  }
  return seen;
}

}  // namespace

TEST(line_reader_accepts_lf_cr_crlf_and_lfcr_terminators) {
  for (const char* terminator : {"\n", "\r", "\r\n", "\n\r"}) {
    LineReader reader;
    const Seen seen = feed_all(reader, std::string("PING") + terminator + "STATUS" + terminator);
    CHECK_EQ(seen.lines.size(), 2u);
    CHECK(seen.errors.empty());
    if (seen.lines.size() == 2) {
      CHECK_EQ(seen.lines[0], "PING");
      CHECK_EQ(seen.lines[1], "STATUS");
    }
  }
}

TEST(line_reader_skips_blank_lines_and_trims_spaces) {
  LineReader reader;
  const Seen seen = feed_all(reader, "\n\r\n   \n\t\r  PING \t\n");
  CHECK_EQ(seen.lines.size(), 1u);
  CHECK(seen.errors.empty());
  if (!seen.lines.empty()) CHECK_EQ(seen.lines[0], "PING");
}

TEST(line_reader_takes_a_line_of_exactly_max_length) {
  LineReader reader;
  const std::string line(trs::kMaxLineLength, 'A');
  const Seen seen = feed_all(reader, line + "\n");
  CHECK_EQ(seen.lines.size(), 1u);
  if (!seen.lines.empty()) CHECK_EQ(seen.lines[0].size(), trs::kMaxLineLength);
}

TEST(line_reader_reports_an_overlong_line_once_and_recovers) {
  LineReader reader;
  const std::string line(trs::kMaxLineLength + 1, 'A');
  Seen seen = feed_all(reader, line + "\n");
  CHECK(seen.lines.empty());
  CHECK_EQ(seen.errors.size(), 1u);
  if (!seen.errors.empty()) CHECK(seen.errors[0] == Event::kTooLong);
  // 100 kB without a terminator: still one error, then back to normal.
  seen = feed_all(reader, std::string(100000, 'x') + "\r\nPING\n");
  CHECK_EQ(seen.errors.size(), 1u);
  CHECK_EQ(seen.lines.size(), 1u);
}

TEST(line_reader_reports_bad_bytes_with_column) {
  LineReader reader;
  Seen seen = feed_all(reader, std::string("PI\xffNG\n", 6));
  CHECK(seen.lines.empty());
  REQUIRE(seen.errors.size() == 1u);
  CHECK(seen.errors[0] == Event::kBadByte);
  CHECK_EQ(static_cast<int>(reader.bad_byte()), 0xff);
  CHECK_EQ(reader.bad_column(), 3u);
  seen = feed_all(reader, std::string("\0\n", 2));
  REQUIRE(seen.errors.size() == 1u);
  CHECK_EQ(static_cast<int>(reader.bad_byte()), 0);
  CHECK_EQ(reader.bad_column(), 1u);
  seen = feed_all(reader, "PING\n");
  CHECK_EQ(seen.lines.size(), 1u);
}

TEST(line_reader_allows_tabs_but_not_other_controls) {
  LineReader reader;
  CHECK_EQ(feed_all(reader, "MOVE:\t1\n").lines.size(), 1u);
  CHECK_EQ(feed_all(reader, "MO\x1bVE\n").errors.size(), 1u);
  CHECK_EQ(feed_all(reader, "MOVE\x7f\n").errors.size(), 1u);
}

TEST(line_reader_reset_drops_partial_line) {
  LineReader reader;
  feed_all(reader, "GARB");
  reader.reset();
  const Seen seen = feed_all(reader, "PING\n");
  REQUIRE(seen.lines.size() == 1u);
  CHECK_EQ(seen.lines[0], "PING");
}

TEST(check_line_validates_a_whole_command) {
  std::string_view line;
  uint8_t bad = 0;
  std::size_t column = 0;
  CHECK(trs::check_line(" PING ", &line, &bad, &column) == Event::kLine);
  CHECK_EQ(line, "PING");
  CHECK(trs::check_line("PING\r\n", &line, &bad, &column) == Event::kLine);
  CHECK_EQ(line, "PING");
  CHECK(trs::check_line("", &line, &bad, &column) == Event::kNone);
  CHECK(trs::check_line("  \n", &line, &bad, &column) == Event::kNone);
  CHECK(trs::check_line("PI\nNG", &line, &bad, &column) == Event::kBadByte);
  CHECK_EQ(column, 3u);
  CHECK(trs::check_line(std::string(trs::kMaxLineLength + 1, 'A'), &line, &bad, &column) ==
        Event::kTooLong);
  CHECK(trs::check_line(std::string(trs::kMaxLineLength, 'A'), &line, &bad, &column) ==
        Event::kLine);
}
