#include <string>
#include <vector>

#include "../src/json.h"
#include "../src/protocol.h"
#include "harness.h"
#include "helpers.h"

using th::ask;
using th::send;
using th::tick;
using trs::Protocol;

namespace {
// The watchdog off: these tests tick through trajectories without sending lines
// (test_link.cpp tests the watchdog).
Protocol make() {
  trs::Config config = trs::servo_arm_config();
  config.watchdog_ms = 0;
  return Protocol(config);
}
bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}
}  // namespace

// --- the seed's commands -------------------------------------------------------------

TEST(status_reports_json_after_ok) {
  Protocol p = make();
  const std::string reply = ask(p, "STATUS");
  CHECK_EQ(reply,
           "ok {\"status\":\"ok\",\"mode\":\"idle\",\"moving\":false,\"powered\":false,"
           "\"pos\":[90,90,90,90,90,90],\"target\":[90,90,90,90,90,90],\"speed\":5,"
           "\"queued\":0,\"buffered_ms\":0,\"tick\":0,\"crc_errors\":0,\"watchdog_stops\":0}");
  CHECK(trs::json_valid(reply.substr(3)));
}

TEST(move_replies_ok_and_status_shows_the_motion) {
  Protocol p = make();
  CHECK_EQ(ask(p, "MOVE:100,80,90,90.5,0,180"), "ok");
  std::string status = ask(p, "STATUS");
  CHECK(status.find("\"mode\":\"move\",\"moving\":true,\"powered\":true") != std::string::npos);
  CHECK(status.find("\"pos\":[90,90,90,90,90,90]") != std::string::npos);
  CHECK(status.find("\"target\":[100,80,90,90.5,0,180]") != std::string::npos);
  tick(p, 1);
  status = ask(p, "STATUS");
  CHECK(status.find("\"pos\":[95,85,90,90.5,85,95]") != std::string::npos);
  CHECK(status.find("\"tick\":1") != std::string::npos);
  tick(p, 17);
  status = ask(p, "STATUS");
  CHECK(status.find("\"mode\":\"idle\",\"moving\":false") != std::string::npos);
  CHECK(status.find("\"pos\":[100,80,90,90.5,0,180]") != std::string::npos);
}

TEST(zero_sends_every_servo_to_0_degrees) {
  Protocol p = make();
  CHECK_EQ(ask(p, "ZERO"), "ok");
  CHECK(ask(p, "STATUS").find("\"target\":[0,0,0,0,0,0]") != std::string::npos);
  tick(p, 18);
  CHECK(ask(p, "STATUS").find("\"pos\":[0,0,0,0,0,0]") != std::string::npos);
}

TEST(home_sends_every_servo_to_its_home_angle) {
  trs::Config config = trs::servo_arm_config();
  config.servos[0].home_cdeg = 4500;
  Protocol p(config);
  CHECK_EQ(ask(p, "ZERO"), "ok");
  tick(p, 20);
  CHECK_EQ(ask(p, "HOME"), "ok");
  CHECK(ask(p, "STATUS").find("\"target\":[45,90,90,90,90,90]") != std::string::npos);
  tick(p, 20);
  CHECK(ask(p, "STATUS").find("\"pos\":[45,90,90,90,90,90]") != std::string::npos);
}

TEST(home_at_boot_powers_the_servos_without_moving) {
  Protocol p = make();
  CHECK_EQ(ask(p, "HOME"), "ok");
  CHECK(ask(p, "STATUS").find("\"mode\":\"idle\",\"moving\":false,\"powered\":true") !=
        std::string::npos);
}

TEST(speed_sets_degrees_per_tick) {
  Protocol p = make();
  CHECK_EQ(ask(p, "SPEED:20"), "ok");
  CHECK(ask(p, "STATUS").find("\"speed\":20") != std::string::npos);
  CHECK_EQ(ask(p, "MOVE:180,180,180,180,180,180"), "ok");
  tick(p, 1);
  CHECK(ask(p, "STATUS").find("\"pos\":[110,110,110,110,110,110]") != std::string::npos);
  CHECK_EQ(ask(p, "SPEED:1"), "ok");
  tick(p, 1);
  CHECK(ask(p, "STATUS").find("\"pos\":[111,111,111,111,111,111]") != std::string::npos);
}

// --- extensions ----------------------------------------------------------------------

TEST(ping_answers_pong) {
  Protocol p = make();
  CHECK_EQ(ask(p, "PING"), "ok pong");
}

TEST(version_reports_firmware_and_limits_as_json) {
  Protocol p = make();
  const std::string reply = ask(p, "VERSION");
  CHECK_EQ(reply,
           "ok {\"firmware\":\"taskrunner-servo\",\"version\":\"1.1.0\",\"protocol\":2,"
           "\"servos\":6,\"channels\":[0,3,6,9,12,15],\"home\":[90,90,90,90,90,90],"
           "\"tick_ms\":80,\"speed_range\":[1,20],\"queue\":64,\"max_line\":128,"
           "\"checksum\":\"crc8\",\"watchdog_ms\":0}");
  CHECK(trs::json_valid(reply.substr(3)));
}

TEST(banner_names_firmware_and_protocol) {
  Protocol p = make();
  CHECK_EQ(p.banner(), "# taskrunner-servo 1.1.0 protocol 2 ready");
}

TEST(traj_replies_queue_length_and_buffered_time) {
  Protocol p = make();
  CHECK_EQ(ask(p, "TRAJ:80:91,90,90,90,90,90"), "ok 1 80");
  CHECK_EQ(ask(p, "TRAJ:80:92,90,90,90,90,90"), "ok 2 160");
  CHECK_EQ(ask(p, "TRAJ:40:93.5,90,90,90,90,90"), "ok 3 200");
  const std::string status = ask(p, "STATUS");
  CHECK(status.find("\"mode\":\"traj\",\"moving\":true,\"powered\":true") != std::string::npos);
  CHECK(status.find("\"target\":[93.5,90,90,90,90,90]") != std::string::npos);
  CHECK(status.find("\"queued\":3,\"buffered_ms\":200") != std::string::npos);
  tick(p, 1);
  CHECK(ask(p, "STATUS").find("\"pos\":[91,90,90,90,90,90]") != std::string::npos);
  tick(p, 2);
  const std::string done = ask(p, "STATUS");
  CHECK(done.find("\"mode\":\"idle\",\"moving\":false") != std::string::npos);
  CHECK(done.find("\"pos\":[93.5,90,90,90,90,90]") != std::string::npos);
  CHECK(done.find("\"queued\":0,\"buffered_ms\":0") != std::string::npos);
}

TEST(traj_queue_full_is_error_5_and_the_queue_is_unchanged) {
  Protocol p = make();
  for (int k = 0; k < trs::kQueueCapacity; ++k) {
    CHECK(starts_with(ask(p, "TRAJ:80:90,90,90,90,90,90"), "ok "));
  }
  CHECK_EQ(ask(p, "TRAJ:80:0,0,0,0,0,0"),
           "err 5 queue full (64 points): wait for it to drain, then resend this point");
  CHECK(ask(p, "STATUS").find("\"queued\":64,\"buffered_ms\":5120") != std::string::npos);
  tick(p, 1);
  CHECK_EQ(ask(p, "TRAJ:80:0,0,0,0,0,0"), "ok 64 5120");
}

TEST(stop_halts_mid_motion_and_clears_the_queue) {
  Protocol p = make();
  CHECK_EQ(ask(p, "MOVE:180,180,180,180,180,180"), "ok");
  tick(p, 3);
  CHECK_EQ(ask(p, "STOP"), "ok");
  tick(p, 10);
  std::string status = ask(p, "STATUS");
  CHECK(status.find("\"mode\":\"idle\",\"moving\":false") != std::string::npos);
  CHECK(status.find("\"pos\":[105,105,105,105,105,105],\"target\":[105,105,105,105,105,105]") !=
        std::string::npos);

  CHECK_EQ(ask(p, "TRAJ:800:25,25,25,25,25,25"), "ok 1 800");
  CHECK_EQ(ask(p, "TRAJ:800:105,105,105,105,105,105"), "ok 2 1600");
  tick(p, 5);  // halfway through the first segment
  CHECK_EQ(ask(p, "STOP"), "ok");
  tick(p, 5);
  status = ask(p, "STATUS");
  CHECK(status.find("\"pos\":[65,65,65,65,65,65]") != std::string::npos);
  CHECK(status.find("\"queued\":0,\"buffered_ms\":0") != std::string::npos);
}

TEST(commands_are_case_insensitive_and_tolerate_spaces) {
  Protocol p = make();
  CHECK_EQ(ask(p, "ping"), "ok pong");
  CHECK_EQ(ask(p, "  Status  ").substr(0, 3), "ok ");
  CHECK_EQ(ask(p, "move : 90 , 91,92 ,93, 94,95"), "ok");
  CHECK(ask(p, "STATUS").find("\"target\":[90,91,92,93,94,95]") != std::string::npos);
  CHECK_EQ(ask(p, "speed: 7"), "ok");
  CHECK_EQ(ask(p, "traj: 80 : 90,90,90,90,90,90"), "ok 1 80");
}

// --- every error ---------------------------------------------------------------------

TEST(unknown_command_is_error_1) {
  Protocol p = make();
  CHECK_EQ(ask(p, "FOO"),
           "err 1 unknown command 'FOO' (commands: STATUS HOME ZERO MOVE SPEED TRAJ STOP PING "
           "VERSION)");
  CHECK(starts_with(ask(p, "FOO:1,2"), "err 1 unknown command 'FOO' "));
  CHECK(starts_with(ask(p, ":90"), "err 1 unknown command '' "));
  CHECK(starts_with(ask(p, "MOVEX:90"), "err 1 unknown command 'MOVEX' "));
  CHECK(starts_with(ask(p, "ok"), "err 1 "));  // a reply echoed back is not a command
  CHECK(starts_with(ask(p, std::string(60, 'Z')),
                    "err 1 unknown command 'ZZZZZZZZZZZZZZZZZZZZZZZZ...' "));
}

TEST(angle_out_of_range_is_error_2) {
  Protocol p = make();
  CHECK_EQ(ask(p, "MOVE:90,90,200,90,90,90"), "err 2 angle 3 out of range 0..180 (got 200)");
  CHECK_EQ(ask(p, "MOVE:-1,90,90,90,90,90"), "err 2 angle 1 out of range 0..180 (got -1)");
  CHECK_EQ(ask(p, "MOVE:90,90,90,90,90,180.01"),
           "err 2 angle 6 out of range 0..180 (got 180.01)");
  CHECK_EQ(ask(p, "TRAJ:80:90,90,90,90,999999999999,90"),
           "err 2 angle 5 out of range 0..180 (got 999999999999)");
  CHECK_EQ(ask(p, "MOVE:0,0,0,0,0,180.004"), "ok");  // rounds to 180.00
}

TEST(speed_and_time_out_of_range_are_error_2) {
  Protocol p = make();
  CHECK_EQ(ask(p, "SPEED:0"), "err 2 speed out of range 1..20 (got 0)");
  CHECK_EQ(ask(p, "SPEED:21"), "err 2 speed out of range 1..20 (got 21)");
  CHECK_EQ(ask(p, "SPEED:-3"), "err 2 speed out of range 1..20 (got -3)");
  CHECK_EQ(ask(p, "TRAJ:0:90,90,90,90,90,90"), "err 2 dt_ms out of range 1..60000 (got 0)");
  CHECK_EQ(ask(p, "TRAJ:60001:90,90,90,90,90,90"),
           "err 2 dt_ms out of range 1..60000 (got 60001)");
  CHECK_EQ(ask(p, "TRAJ:60000:90,90,90,90,90,90"), "ok 1 60000");
}

TEST(wrong_angle_count_is_error_3) {
  Protocol p = make();
  CHECK_EQ(ask(p, "MOVE:90,90,90,90,90"), "err 3 MOVE needs 6 angles (got 5)");
  CHECK_EQ(ask(p, "MOVE:90,90,90,90,90,90,90"), "err 3 MOVE needs 6 angles (got 7)");
  CHECK_EQ(ask(p, "MOVE:90"), "err 3 MOVE needs 6 angles (got 1)");
  CHECK_EQ(ask(p, "TRAJ:80:90,90"), "err 3 TRAJ needs 6 angles (got 2)");
}

TEST(malformed_arguments_are_error_4) {
  Protocol p = make();
  CHECK_EQ(ask(p, "MOVE"), "err 4 MOVE needs 6 angles: MOVE:a1,...,a6");
  CHECK_EQ(ask(p, "MOVE:"), "err 4 MOVE needs 6 angles: MOVE:a1,...,a6");
  CHECK_EQ(ask(p, "MOVE:90,,90,90,90,90"), "err 4 angle 2 is empty");
  CHECK_EQ(ask(p, "MOVE:90,abc,90,90,90,90"),
           "err 4 angle 2 must be a number of degrees (got 'abc')");
  CHECK_EQ(ask(p, "MOVE:90,90,90,90,90,1e2"),
           "err 4 angle 6 must be a number of degrees (got '1e2')");
  CHECK_EQ(ask(p, "SPEED"), "err 4 SPEED needs a value: SPEED:n with n in 1..20 (degrees per tick)");
  CHECK_EQ(ask(p, "SPEED:fast"), "err 4 speed must be an integer 1..20 (got 'fast')");
  CHECK_EQ(ask(p, "SPEED:2.5"), "err 4 speed must be an integer 1..20 (got '2.5')");
  CHECK_EQ(ask(p, "SPEED:3.0"), "err 4 speed must be an integer 1..20 (got '3.0')");
  CHECK_EQ(ask(p, "TRAJ"), "err 4 TRAJ needs a time step and 6 angles: TRAJ:dt_ms:a1,...,a6");
  CHECK_EQ(ask(p, "TRAJ:90,90,90,90,90,90"),
           "err 4 TRAJ needs a time step and 6 angles: TRAJ:dt_ms:a1,...,a6");
  CHECK_EQ(ask(p, "TRAJ:80:"), "err 4 TRAJ needs 6 angles: TRAJ:dt_ms:a1,...,a6");
  CHECK_EQ(ask(p, "TRAJ:x:90,90,90,90,90,90"),
           "err 4 dt_ms must be an integer 1..60000 (got 'x')");
  CHECK_EQ(ask(p, "TRAJ:80.5:90,90,90,90,90,90"),
           "err 4 dt_ms must be an integer 1..60000 (got '80.5')");
  CHECK_EQ(ask(p, "TRAJ:80:90,90,90,90,90,90:5"),
           "err 4 angle 6 must be a number of degrees (got '90:5')");
  for (const char* command : {"STATUS", "HOME", "ZERO", "STOP", "PING", "VERSION"}) {
    CHECK_EQ(ask(p, std::string(command) + ":1"),
             "err 4 " + std::string(command) + " takes no arguments (got '1')");
  }
  CHECK_EQ(ask(p, "STATUS:"), "err 4 STATUS takes no arguments (got '')");
}

TEST(overlong_line_is_error_6) {
  Protocol p = make();
  CHECK_EQ(ask(p, std::string(200, 'A')), "err 6 line too long (max 128 bytes)");
  CHECK_EQ(ask(p, "PING"), "ok pong");
}

TEST(invalid_byte_is_error_7) {
  Protocol p = make();
  CHECK_EQ(ask(p, std::string("PI\x80NG")),
           "err 7 invalid byte 0x80 at column 3 (printable ASCII only)");
  CHECK_EQ(ask(p, "PING"), "ok pong");
}

TEST(errors_change_nothing) {
  Protocol p = make();
  CHECK_EQ(ask(p, "MOVE:100,100,100,100,100,100"), "ok");
  tick(p, 1);
  const std::string before = ask(p, "STATUS");
  for (const char* bad : {"MOVE:90,90,200,90,90,90", "MOVE:1,2", "SPEED:99", "TRAJ:0:1,1,1,1,1,1",
                          "TRAJ:80:1,1,1,1,1,x", "FOO", "HOME:1", "STOP:now"}) {
    CHECK(starts_with(ask(p, bad), "err "));
  }
  CHECK_EQ(ask(p, "STATUS"), before);
}

// --- framing and reply format --------------------------------------------------------

TEST(one_reply_per_command_line) {
  Protocol p = make();
  const std::vector<std::string> replies =
      send(p, "PING\r\nSTATUS\nFOO\r\n\r\n\n   \nMOVE:1,2\rSPEED:5\n\rVERSION\n");
  REQUIRE(replies.size() == 6u);
  CHECK_EQ(replies[0], "ok pong");
  CHECK(starts_with(replies[1], "ok {"));
  CHECK(starts_with(replies[2], "err 1 "));
  CHECK(starts_with(replies[3], "err 3 "));
  CHECK_EQ(replies[4], "ok");
  CHECK(starts_with(replies[5], "ok {\"firmware\""));
  for (const std::string& reply : replies) CHECK(th::well_formed_reply(reply));
}

TEST(a_partial_line_waits_for_its_terminator) {
  Protocol p = make();
  CHECK(send(p, "PI").empty());
  tick(p, 3);
  const std::vector<std::string> replies = send(p, "NG\n");
  REQUIRE(replies.size() == 1u);
  CHECK_EQ(replies[0], "ok pong");
}

TEST(status_json_is_valid_in_every_mode) {
  Protocol p = make();
  CHECK(trs::json_valid(p.status_json()));
  ask(p, "MOVE:0,30.5,60,120,150,180");
  CHECK(trs::json_valid(p.status_json()));
  ask(p, "TRAJ:123:0.01,1,2,3,4,179.99");
  tick(p, 1);
  CHECK(trs::json_valid(p.status_json()));
  CHECK(trs::json_valid(p.version_json()));
}

// --- HTTP ----------------------------------------------------------------------------

TEST(http_command_wraps_the_reply_in_json) {
  Protocol p = make();
  trs::HttpResponse r = p.http_command(R"({"cmd": "PING"})");
  CHECK_EQ(r.status, 200);
  CHECK_EQ(r.body, "{\"reply\":\"ok pong\"}");
  r = p.http_command(R"({"cmd": "STATUS"})");
  CHECK_EQ(r.status, 200);
  CHECK(starts_with(r.body, "{\"reply\":\"ok {\\\"status\\\":\\\"ok\\\","));
  CHECK(trs::json_valid(r.body));
  r = p.http_command(R"({"cmd": "MOVE:90,90,200,90,90,90"})");
  CHECK_EQ(r.body, "{\"reply\":\"err 2 angle 3 out of range 0..180 (got 200)\"}");
  r = p.http_command(R"({"cmd": "PING\n"})");
  CHECK_EQ(r.body, "{\"reply\":\"ok pong\"}");
}

TEST(http_command_rejects_bad_bodies_with_400) {
  Protocol p = make();
  trs::HttpResponse r = p.http_command("MOVE:90,90,90,90,90,90");
  CHECK_EQ(r.status, 400);
  CHECK(starts_with(r.body, "{\"error\":\"body must be a JSON object"));
  CHECK(trs::json_valid(r.body));
  r = p.http_command(R"({"cmd": 1})");
  CHECK_EQ(r.status, 400);
  CHECK_EQ(r.body, "{\"error\":\"'cmd' must be a string (got number)\"}");
}

TEST(http_no_body_asks_for_json) {
  const trs::HttpResponse r = Protocol::http_no_body();
  CHECK_EQ(r.status, 400);
  CHECK_EQ(r.body,
           "{\"error\":\"no JSON body: POST {\\\"cmd\\\": \\\"...\\\"} with Content-Type: "
           "application/json\"}");
  CHECK(trs::json_valid(r.body));
}

TEST(http_command_gives_one_reply_even_for_odd_commands) {
  Protocol p = make();
  CHECK_EQ(p.http_command(R"({"cmd": ""})").body, "{\"reply\":\"err 4 empty command\"}");
  CHECK_EQ(p.http_command(R"({"cmd": "PING\nPING"})").body,
           "{\"reply\":\"err 7 invalid byte 0x0a at column 5 (printable ASCII only)\"}");
  const std::string long_cmd = "{\"cmd\": \"" + std::string(129, 'A') + "\"}";
  CHECK_EQ(p.http_command(long_cmd).body, "{\"reply\":\"err 6 line too long (max 128 bytes)\"}");
  CHECK_EQ(p.http_command(R"({"cmd": "\u00e9"})").body,
           "{\"reply\":\"err 7 invalid byte 0xc3 at column 1 (printable ASCII only)\"}");
}

TEST(serial_and_http_share_one_state) {
  Protocol p = make();
  CHECK_EQ(p.http_command(R"({"cmd": "MOVE:0,0,0,0,0,0"})").body, "{\"reply\":\"ok\"}");
  CHECK(ask(p, "STATUS").find("\"target\":[0,0,0,0,0,0]") != std::string::npos);
}

TEST(protocol_handles_other_servo_counts) {
  trs::Config config = trs::servo_arm_config();
  config.n_servos = 2;
  Protocol p(config);
  CHECK_EQ(ask(p, "MOVE:1,2"), "ok");
  CHECK_EQ(ask(p, "MOVE:1,2,3"), "err 3 MOVE needs 2 angles (got 3)");
  CHECK_EQ(ask(p, "TRAJ"), "err 4 TRAJ needs a time step and 2 angles: TRAJ:dt_ms:a1,...,a2");
  CHECK(ask(p, "VERSION").find("\"servos\":2,\"channels\":[0,3],\"home\":[90,90]") !=
        std::string::npos);
}

TEST(protocol_survives_an_invalid_config) {
  trs::Config config = trs::servo_arm_config();
  config.n_servos = 40;  // check_config rejects this; nothing may overflow anyway
  Protocol p(config);
  std::string move = "MOVE:";
  for (int i = 0; i < 40; ++i) move += i ? ",1" : "1";
  CHECK_EQ(ask(p, move), "err 3 MOVE needs 16 angles (got 40)");
  CHECK(trs::json_valid(p.status_json()));
}
