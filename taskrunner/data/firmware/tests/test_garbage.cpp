// Resilience: random bytes, overlong lines and mixed terminators never crash the parser
// (the tests run under ASan/UBSan), every reply stays one well-formed line, nothing
// moves on garbage, and a valid command right after the garbage works.
#include <random>
#include <string>
#include <vector>

#include "../src/json.h"
#include "../src/protocol.h"
#include "harness.h"
#include "helpers.h"

using th::ask;
using th::send;
using trs::Protocol;

namespace {

std::string random_bytes(std::mt19937& rng, std::size_t n) {
  std::uniform_int_distribution<int> byte(0, 255);
  std::string out(n, '\0');
  for (char& c : out) c = static_cast<char>(byte(rng));
  return out;
}

// Printable noise with command-like pieces, so the parser's deeper paths get exercised.
std::string random_commandish(std::mt19937& rng) {
  static const char* kPieces[] = {"MOVE", "TRAJ", "SPEED", "STATUS", "HOME", "ZERO", "STOP",
                                  "PING", "VERSION", ":", ",", ".", "-", "+", " ", "\t",
                                  "0", "9", "90", "180", "181", "80", "1e3", "x", "\r", "\n",
                                  "\r\n", "99999999999999999999", ",,", "::"};
  std::uniform_int_distribution<std::size_t> pick(0, sizeof kPieces / sizeof kPieces[0] - 1);
  std::uniform_int_distribution<int> count(1, 20);
  std::string out;
  const int n = count(rng);
  for (int i = 0; i < n; ++i) out += kPieces[pick(rng)];
  return out;
}

}  // namespace

TEST(random_bytes_give_only_well_formed_replies_and_then_recover) {
  for (unsigned seed = 1; seed <= 200; ++seed) {
    std::mt19937 rng(seed);
    Protocol p(trs::servo_arm_config());
    const std::vector<std::string> replies = send(p, random_bytes(rng, 2000));
    for (const std::string& reply : replies) {
      if (!th::well_formed_reply(reply)) {
        CHECK_EQ(reply, "<well-formed reply>");
        return;
      }
    }
    // A fresh line after the garbage is understood. (The first "\n" ends the garbage's
    // last partial line, which may get its own error reply.)
    const std::vector<std::string> after = send(p, "\nPING\n");
    if (after.empty() || after.size() > 2 || after.back() != "ok pong") {
      CHECK_EQ(after.empty() ? std::string("<none>") : after.back(), "ok pong");
      return;
    }
  }
}

TEST(random_bytes_never_move_the_servos_with_out_of_range_angles) {
  for (unsigned seed = 1; seed <= 50; ++seed) {
    std::mt19937 rng(seed);
    Protocol p(trs::servo_arm_config());
    for (int round = 0; round < 20; ++round) {
      send(p, random_bytes(rng, 200));
      p.tick();
      for (int i = 0; i < 6; ++i) {
        const int32_t a = p.motion().pos()[i];
        const int32_t t = p.motion().target()[i];
        if (a < 0 || a > 18000 || t < 0 || t > 18000) {
          CHECK(false);
          return;
        }
      }
    }
  }
}

TEST(commandlike_noise_gives_one_well_formed_reply_per_line) {
  std::mt19937 rng(7);
  Protocol p(trs::servo_arm_config());
  for (int i = 0; i < 5000; ++i) {
    const std::string text = random_commandish(rng);
    for (const std::string& reply : send(p, text)) {
      if (!th::well_formed_reply(reply)) {
        CHECK_EQ(reply, "<well-formed reply>");
        return;
      }
    }
    if (i % 7 == 0) p.tick();
  }
  send(p, "\n");
  CHECK_EQ(ask(p, "PING"), "ok pong");
  CHECK(trs::json_valid(p.status_json()));
}

TEST(execute_gives_exactly_one_well_formed_reply_for_any_input) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<std::size_t> length(0, 300);
  Protocol p(trs::servo_arm_config());
  for (int i = 0; i < 3000; ++i) {
    const std::string text = i % 2 ? random_bytes(rng, length(rng)) : random_commandish(rng);
    const std::string reply = p.execute(text);
    if (!th::well_formed_reply(reply)) {
      CHECK_EQ(reply, "<well-formed reply>");
      return;
    }
  }
}

TEST(http_bodies_of_random_bytes_get_400_or_a_reply) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::size_t> length(0, 200);
  Protocol p(trs::servo_arm_config());
  for (int i = 0; i < 3000; ++i) {
    std::string body = random_bytes(rng, length(rng));
    if (i % 3 == 0) body = "{\"cmd\": \"" + random_commandish(rng) + "\"}";
    const trs::HttpResponse r = p.http_command(body);
    if ((r.status != 200 && r.status != 400) || !trs::json_valid(r.body)) {
      CHECK_EQ(r.body, "<valid JSON>");
      return;
    }
  }
}

TEST(overlong_lines_of_every_length_around_the_limit) {
  Protocol p(trs::servo_arm_config());
  for (std::size_t n = trs::kMaxLineLength - 3; n <= trs::kMaxLineLength + 3; ++n) {
    const std::string line = "PING" + std::string(n - 4, ' ');
    const std::string reply = ask(p, line);
    if (n <= trs::kMaxLineLength) {
      CHECK_EQ(reply, "ok pong");
    } else {
      CHECK_EQ(reply, "err 6 line too long (max 128 bytes)");
    }
  }
  // A megabyte with no terminator costs no memory and gives one error.
  CHECK(send(p, std::string(1 << 20, 'M')).empty());
  const std::vector<std::string> replies = send(p, "\r\nPING\r\n");
  REQUIRE(replies.size() == 2u);
  CHECK_EQ(replies[0], "err 6 line too long (max 128 bytes)");
  CHECK_EQ(replies[1], "ok pong");
}

TEST(terminator_variants_between_commands) {
  Protocol p(trs::servo_arm_config());
  const std::vector<std::string> replies =
      send(p, "PING\rPING\nPING\r\nPING\n\rPING\r\r\n\nPING\n");
  CHECK_EQ(replies.size(), 6u);
  for (const std::string& reply : replies) CHECK_EQ(reply, "ok pong");
}

TEST(nul_bytes_and_high_bytes_are_reported_not_executed) {
  Protocol p(trs::servo_arm_config());
  static const char kBytes[] = "ZERO\0\n\xff\xfeZERO\nMOVE:0,0,0,0,0,0\x01\n";
  const std::vector<std::string> replies = send(p, std::string(kBytes, sizeof kBytes - 1));
  REQUIRE(replies.size() == 3u);
  CHECK_EQ(replies[0], "err 7 invalid byte 0x00 at column 5 (printable ASCII only)");
  CHECK_EQ(replies[1], "err 7 invalid byte 0xff at column 1 (printable ASCII only)");
  CHECK_EQ(replies[2], "err 7 invalid byte 0x01 at column 17 (printable ASCII only)");
  CHECK(!p.motion().moving());
  CHECK(!p.motion().powered());
}
