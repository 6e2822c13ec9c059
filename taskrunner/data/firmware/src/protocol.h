// The line protocol of the servo bridge (spec: firmware/PROTOCOL.md).
//
// Every command line gets exactly one reply line: "ok[ <data>]" or "err <code> <reason>",
// followed by "*XX" (checksum.h) when the command carried one.
// The same Protocol object serves the serial port (feed() byte by byte) and HTTP
// (http_command() with the POST body), so both transports behave identically.
// Plain C++17, no Arduino headers: compiled into the ESP32 sketch, the host firmware
// and the unit tests.
#pragma once

#include <string>
#include <string_view>

#include "config.h"
#include "line_reader.h"
#include "motion.h"

namespace trs {

enum class ErrorCode : int {
  kUnknownCommand = 1,
  kOutOfRange = 2,
  kWrongCount = 3,
  kSyntax = 4,
  kQueueFull = 5,
  kLineTooLong = 6,
  kBadByte = 7,
  kChecksum = 8,
};

struct HttpResponse {
  int status = 200;   // 200 with {"reply": "..."}; 400 with {"error": "..."}
  std::string body;   // JSON
};

class Protocol {
 public:
  // `config` must pass check_config().
  explicit Protocol(const Config& config);

  // Serial: feed one received byte. Returns true and sets `reply` (no line terminator)
  // when the byte completed a command line; blank lines get no reply.
  bool feed(char byte, std::string* reply);

  // One whole command (HTTP): always exactly one reply. A trailing CR/LF is tolerated;
  // a blank command gets "err 4 empty command".
  std::string execute(std::string_view command);

  // POST /api/command with `body` = {"cmd": "..."}.
  HttpResponse http_command(std::string_view body);
  // POST /api/command without a usable body: none, or sent as a form
  // (application/x-www-form-urlencoded, multipart/...), which the ESP32 WebServer parses
  // as form fields instead of handing it over. 400 with a hint to send JSON.
  static HttpResponse http_no_body();

  // One tick of the step loop; call every config().tick_ms milliseconds. Runs the
  // watchdog first: while a trajectory streams, no accepted line for
  // config().watchdog_ms stops the servos where they are (counted in STATUS).
  void tick();

  // Lines refused for a bad or malformed checksum since boot (STATUS "crc_errors").
  uint32_t crc_errors() const { return crc_errors_; }
  // Trajectories the watchdog stopped since boot (STATUS "watchdog_stops").
  uint32_t watchdog_stops() const { return watchdog_stops_; }

  const Motion& motion() const { return motion_; }
  const Config& config() const { return config_; }

  // "# taskrunner-servo 1.1.0 protocol 2 ready": printed once at boot on serial.
  std::string banner() const;
  // The JSON of STATUS and VERSION replies (without the "ok ").
  std::string status_json() const;
  std::string version_json() const;

 private:
  // A complete line: checksum checked and stripped, the command run, the reply
  // checksummed when the line was.
  std::string handle(std::string_view line);
  std::string run(std::string_view line);
  std::string parse_angles(std::string_view args, std::string_view command,
                           Angles* out) const;
  std::string cmd_move(std::string_view args, bool has_args);
  std::string cmd_speed(std::string_view args, bool has_args);
  std::string cmd_traj(std::string_view args, bool has_args);
  Angles filled(int32_t centideg) const;
  Angles home() const;

  Config config_;
  Motion motion_;
  LineReader reader_;
  uint32_t crc_errors_ = 0;
  uint32_t watchdog_stops_ = 0;
  uint32_t silent_ms_ = 0;  // firmware ms since the last accepted line (saturating)
};

// "err <code> <reason>"
std::string error_reply(ErrorCode code, std::string_view reason);

}  // namespace trs
