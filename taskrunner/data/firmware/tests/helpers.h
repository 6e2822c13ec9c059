// Shared helpers for the core tests.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "../src/config.h"
#include "../src/protocol.h"

namespace th {

// Feeds `bytes` to the serial side of `protocol`; returns the replies, in order.
inline std::vector<std::string> send(trs::Protocol& protocol, std::string_view bytes) {
  std::vector<std::string> replies;
  std::string reply;
  for (char c : bytes) {
    if (protocol.feed(c, &reply)) replies.push_back(reply);
  }
  return replies;
}

// The single reply to one command line ("" and a test failure otherwise is up to the
// caller: returns "<N replies>" when there is not exactly one).
inline std::string ask(trs::Protocol& protocol, std::string_view line) {
  std::vector<std::string> replies = send(protocol, std::string(line) + "\n");
  if (replies.size() != 1) return "<" + std::to_string(replies.size()) + " replies>";
  return replies[0];
}

inline void tick(trs::Protocol& protocol, int n) {
  for (int i = 0; i < n; ++i) protocol.tick();
}

// "ok", "ok <printable>", or "err <1..8> <printable>"; printable ASCII only (no tab,
// CR or LF).
inline bool well_formed_reply(const std::string& reply) {
  for (char c : reply) {
    if (c < 0x20 || c > 0x7e) return false;
  }
  if (reply == "ok") return true;
  if (reply.rfind("ok ", 0) == 0) return reply.size() > 3;
  if (reply.size() < 7 || reply.rfind("err ", 0) != 0) return false;
  return reply[4] >= '1' && reply[4] <= '8' && reply[5] == ' ' && reply[6] != ' ';
}

inline trs::Angles angles6(int a, int b, int c, int d, int e, int f) {
  trs::Angles out{};
  out[0] = a; out[1] = b; out[2] = c; out[3] = d; out[4] = e; out[5] = f;
  return out;
}

inline std::string pos_text(const trs::Motion& motion) {
  std::string out;
  for (int i = 0; i < motion.n_servos(); ++i) {
    if (i) out += ",";
    out += std::to_string(motion.pos()[i]);
  }
  return out;
}

}  // namespace th
