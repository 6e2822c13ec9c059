// Shared helpers for the core tests.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "../src/checksum.h"
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

// The single reply to one command line, sent as written ("" and a test failure
// otherwise is up to the caller: returns "<N replies>" when there is not exactly one).
inline std::string ask_plain(trs::Protocol& protocol, std::string_view line) {
  std::vector<std::string> replies = send(protocol, std::string(line) + "\n");
  if (replies.size() != 1) return "<" + std::to_string(replies.size()) + " replies>";
  return replies[0];
}

// As ask_plain, except that a TRAJ line without a '*' goes out with its checksum, as
// hosts send it (the firmware refuses a TRAJ without one), and the reply comes back with
// its checksum checked and removed ("<bad checksum: ...>" when it is not right).
inline std::string ask(trs::Protocol& protocol, std::string_view line) {
  const std::string_view name = line.substr(0, line.find(':'));
  const bool traj = name.size() == 4 && (name[0] | 0x20) == 't' && (name[1] | 0x20) == 'r' &&
                    (name[2] | 0x20) == 'a' && (name[3] | 0x20) == 'j';
  if (!traj || line.find('*') != std::string_view::npos) return ask_plain(protocol, line);
  const std::string reply = ask_plain(protocol, trs::with_checksum(line));
  const std::size_t star = reply.rfind('*');
  if (star == std::string::npos || trs::with_checksum(reply.substr(0, star)) != reply) {
    return "<bad checksum: " + reply + ">";
  }
  return reply.substr(0, star);
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
