// Checksummed lines (PROTOCOL.md "Checksums") and the link watchdog ("Watchdog").
#include <string>

#include "../src/checksum.h"
#include "../src/json.h"
#include "../src/protocol.h"
#include "harness.h"
#include "helpers.h"

using th::ask;
using th::tick;
using trs::Protocol;

namespace {

Protocol make(uint32_t watchdog_ms) {
  trs::Config config = trs::servo_arm_config();
  config.watchdog_ms = watchdog_ms;
  return Protocol(config);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The reply's body when it carries a correct checksum, else "<bad checksum: ...>".
std::string checked(const std::string& reply) {
  std::string_view body;
  uint8_t received = 0;
  uint8_t computed = 0;
  if (trs::check_checksum(reply, &body, &received, &computed) != trs::ChecksumResult::kOk) {
    return "<bad checksum: " + reply + ">";
  }
  return std::string(body);
}

}  // namespace

TEST(crc8_is_the_smbus_crc) {
  CHECK_EQ(static_cast<int>(trs::crc8("123456789")), 0xF4);
  CHECK_EQ(static_cast<int>(trs::crc8("")), 0);
  CHECK_EQ(trs::with_checksum("PING"), "PING" + trs::checksum_suffix("PING"));
  CHECK_EQ(trs::checksum_suffix("123456789"), "*F4");
}

TEST(crc8_catches_every_single_digit_change_and_transposition_of_a_traj_line) {
  const std::string line = "TRAJ:80:92.5,90,87.25,90,90,112.9";
  const uint8_t crc = trs::crc8(line);
  int caught = 0;
  int changes = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    for (char c = 0x20; c <= 0x7e; ++c) {
      if (c == line[i]) continue;
      std::string changed = line;
      changed[i] = c;
      ++changes;
      caught += trs::crc8(changed) != crc ? 1 : 0;
    }
    if (i + 1 < line.size() && line[i] != line[i + 1]) {
      std::string swapped = line;
      std::swap(swapped[i], swapped[i + 1]);
      ++changes;
      caught += trs::crc8(swapped) != crc ? 1 : 0;
    }
  }
  CHECK_EQ(caught, changes);
}

TEST(checksummed_command_gets_a_checksummed_reply) {
  Protocol p = make(0);
  CHECK_EQ(ask(p, trs::with_checksum("PING")), trs::with_checksum("ok pong"));
  CHECK_EQ(ask(p, "PING*" + trs::checksum_suffix("PING").substr(1)), "ok pong*" +
           trs::checksum_suffix("ok pong").substr(1));
  // Lower-case hex digits are accepted too.
  std::string lower = trs::with_checksum("STATUS");
  for (std::size_t i = lower.size() - 2; i < lower.size(); ++i) {
    if (lower[i] >= 'A' && lower[i] <= 'F') lower[i] = static_cast<char>(lower[i] - 'A' + 'a');
  }
  const std::string status = checked(ask(p, lower));
  CHECK(status.rfind("ok {", 0) == 0);
  CHECK(trs::json_valid(status.substr(3)));
  // An error to a checksummed command is checksummed as well.
  CHECK_EQ(checked(ask(p, trs::with_checksum("SPEED:99"))),
           "err 2 speed out of range 1..20 (got 99)");
  CHECK_EQ(checked(ask(p, trs::with_checksum(""))), "err 4 empty command");
}

TEST(plain_commands_typed_in_a_terminal_still_work_without_checksum) {
  Protocol p = make(0);
  CHECK_EQ(ask(p, "PING"), "ok pong");
  CHECK_EQ(ask(p, "MOVE:90,90,90,90,90,91"), "ok");
  CHECK(contains(ask(p, "STATUS"), "\"crc_errors\":0"));
}

TEST(corrupted_line_is_refused_with_err_8_and_counted) {
  Protocol p = make(0);
  std::string line = trs::with_checksum("TRAJ:80:100,90,90,90,90,90");
  line[9] = '9';  // one digit: 100 -> 190
  const std::string reply = checked(ask(p, line));
  CHECK(reply.rfind("err 8 checksum mismatch: line says 0x", 0) == 0);
  CHECK(contains(reply, "(line refused, 1 so far)"));
  const std::string status = ask(p, "STATUS");
  CHECK(contains(status, "\"mode\":\"idle\""));  // nothing was queued
  CHECK(contains(status, "\"crc_errors\":1"));
  // A corrupted checksum digit, a '*' in the middle, a short checksum: malformed.
  std::string bad_digit = trs::with_checksum("PING");
  bad_digit.back() = 'G';
  CHECK(checked(ask(p, bad_digit)).rfind("err 8 malformed checksum", 0) == 0);
  CHECK(checked(ask(p, "PI*NG")).rfind("err 8 malformed checksum", 0) == 0);
  CHECK(checked(ask(p, "PI*NG*00")).rfind("err 8 checksum mismatch", 0) == 0);
  CHECK(checked(ask(p, "PING*0")).rfind("err 8 malformed checksum", 0) == 0);
  CHECK(contains(ask(p, "STATUS"), "\"crc_errors\":5"));
  CHECK(th::well_formed_reply(checked(ask(p, "PING*0"))));
}

TEST(a_traj_line_without_its_checksum_is_refused_and_nothing_moves) {
  // Hosts stream TRAJ points with a checksum; one without it lost its '*XX' (a '*'
  // corrupted into another byte, a cut line) and must not run unchecked.
  Protocol p = make(0);
  const std::string stripped = "TRAJ:80:100,90,90,90,90,90";
  const std::string reply = th::ask_plain(p, stripped);
  CHECK_EQ(reply, "err 8 TRAJ needs a checksum: 'TRAJ:dt_ms:a1,...,a6*XX' (line refused, 1 so far)");
  CHECK(th::well_formed_reply(reply));
  CHECK_EQ(th::ask_plain(p, " traj : 80:100,90,90,90,90,90").substr(0, 6), "err 8 ");
  CHECK_EQ(th::ask_plain(p, "TRAJ").substr(0, 6), "err 8 ");
  std::string status = th::ask_plain(p, "STATUS");
  CHECK(contains(status, "\"mode\":\"idle\""));  // nothing was queued
  CHECK(contains(status, "\"queued\":0"));
  CHECK(contains(status, "\"crc_errors\":3"));
  // The same point with its checksum runs; over HTTP the rule is the same.
  CHECK_EQ(checked(th::ask_plain(p, trs::with_checksum(stripped))), "ok 1 80");
  const trs::HttpResponse http = p.http_command("{\"cmd\": \"" + stripped + "\"}");
  CHECK(contains(http.body, "err 8 TRAJ needs a checksum"));
  status = th::ask_plain(p, "STATUS");
  CHECK(contains(status, "\"queued\":1"));  // the checked point only (no tick since)
  CHECK(contains(status, "\"crc_errors\":4"));
}

TEST(checksums_work_over_http_too) {
  Protocol p = make(0);
  const trs::HttpResponse ok = p.http_command("{\"cmd\": \"" + trs::with_checksum("PING") + "\"}");
  CHECK_EQ(ok.status, 200);
  CHECK_EQ(ok.body, "{\"reply\":\"" + trs::with_checksum("ok pong") + "\"}");
  const trs::HttpResponse bad = p.http_command("{\"cmd\": \"PING*00\"}");
  CHECK(contains(bad.body, "err 8 checksum mismatch"));
}

TEST(watchdog_stops_a_streamed_trajectory_when_the_host_goes_silent) {
  Protocol p = make(240);  // 3 ticks
  CHECK_EQ(ask(p, "TRAJ:800:10,90,90,90,90,90"), "ok 1 800");
  CHECK_EQ(ask(p, "TRAJ:800:170,90,90,90,90,90"), "ok 2 1600");
  tick(p, 2);  // 160 ms without a line: still streaming
  std::string status = ask(p, "STATUS");  // a line: the watchdog starts again
  CHECK(contains(status, "\"mode\":\"traj\""));
  CHECK(contains(status, "\"pos\":[74,90,90,90,90,90]"));
  tick(p, 2);
  CHECK(contains(ask(p, "STATUS"), "\"mode\":\"traj\""));
  tick(p, 3);  // 240 ms of silence: stopped where it was at the last tick before
  status = ask(p, "STATUS");
  CHECK(contains(status, "\"mode\":\"idle\",\"moving\":false"));
  CHECK(contains(status, "\"pos\":[42,90,90,90,90,90],\"target\":[42,90,90,90,90,90]"));
  CHECK(contains(status, "\"queued\":0,\"buffered_ms\":0"));
  CHECK(contains(status, "\"watchdog_stops\":1"));
  tick(p, 10);  // held: nothing moves any more
  CHECK(contains(ask(p, "STATUS"), "\"pos\":[42,90,90,90,90,90]"));
}

TEST(watchdog_leaves_step_moves_idle_servos_and_a_talking_host_alone) {
  Protocol p = make(240);
  CHECK_EQ(ask(p, "MOVE:180,90,90,90,90,90"), "ok");
  tick(p, 20);  // MOVE is not streamed: it finishes
  CHECK(contains(ask(p, "STATUS"), "\"pos\":[180,90,90,90,90,90]"));
  for (int i = 0; i < 20; ++i) {  // a host sending a point every tick is never stopped
    CHECK_EQ(ask(p, trs::with_checksum("TRAJ:80:170,90,90,90,90,90")).substr(0, 3), "ok ");
    tick(p, 1);
  }
  tick(p, 1);
  const std::string status = ask(p, "STATUS");
  CHECK(contains(status, "\"watchdog_stops\":0"));
  CHECK(contains(status, "\"pos\":[170,90,90,90,90,90]"));
}

TEST(a_corrupted_line_does_not_feed_the_watchdog) {
  Protocol p = make(240);
  CHECK_EQ(ask(p, "TRAJ:800:10,90,90,90,90,90"), "ok 1 800");
  for (int i = 0; i < 3; ++i) {
    CHECK(checked(ask(p, "PING*00")).rfind("err 8", 0) == 0);
    tick(p, 1);
  }
  CHECK(contains(ask(p, "STATUS"), "\"watchdog_stops\":1"));
}

TEST(config_rejects_a_watchdog_shorter_than_a_tick) {
  trs::Config config = trs::servo_arm_config();
  config.watchdog_ms = 40;
  CHECK_EQ(trs::check_config(config), "watchdog_ms must be 0 (off) or 80..600000 (got 40)");
  config.watchdog_ms = 0;
  CHECK_EQ(trs::check_config(config), "");
}
