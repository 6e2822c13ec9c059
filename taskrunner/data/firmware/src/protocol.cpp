#include "protocol.h"

#include <cstdint>
#include <cstdio>

#include "checksum.h"
#include "json.h"
#include "numbers.h"

namespace trs {
namespace {

constexpr const char* kCommandList = "STATUS HOME ZERO MOVE SPEED TRAJ STOP PING VERSION";

// A token from the input for an error message: at most 24 bytes, tabs as spaces, so a
// reply is printable ASCII without tabs (the input was checked to be printable or tab).
std::string shown(std::string_view token) {
  constexpr std::size_t kMax = 24;
  std::string out(token.substr(0, kMax));
  for (char& c : out) {
    if (c == '\t') c = ' ';
  }
  if (token.size() > kMax) out += "...";
  return out;
}

std::string quoted(std::string_view token) { return "'" + shown(token) + "'"; }

std::string hex_byte(uint8_t byte) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02x", byte);
  return text;
}

std::string line_error(LineReader::Event event, uint8_t bad_byte, std::size_t column) {
  if (event == LineReader::Event::kTooLong) {
    return error_reply(ErrorCode::kLineTooLong,
                       "line too long (max " + std::to_string(kMaxLineLength) + " bytes)");
  }
  return error_reply(ErrorCode::kBadByte,
                     "invalid byte " + hex_byte(bad_byte) + " at column " +
                         std::to_string(column) + " (printable ASCII only)");
}

void append_angles(std::string* out, const Angles& angles, int n) {
  out->push_back('[');
  for (int i = 0; i < n; ++i) {
    if (i) out->push_back(',');
    append_centi(out, angles[i]);
  }
  out->push_back(']');
}

}  // namespace

std::string error_reply(ErrorCode code, std::string_view reason) {
  std::string reply = "err ";
  reply += std::to_string(static_cast<int>(code));
  reply.push_back(' ');
  reply += reason;
  return reply;
}

Protocol::Protocol(const Config& config) : config_(config), motion_(config) {}

void Protocol::tick() {
  const uint32_t tick_ms = motion_.tick_ms();
  silent_ms_ = silent_ms_ > UINT32_MAX - tick_ms ? UINT32_MAX : silent_ms_ + tick_ms;
  if (config_.watchdog_ms > 0 && motion_.mode() == Mode::kTraj &&
      silent_ms_ >= config_.watchdog_ms) {
    motion_.stop();  // hold where the servos are now; the host must start afresh
    ++watchdog_stops_;
  }
  motion_.tick();
}

std::string Protocol::handle(std::string_view line) {
  std::string_view body;
  uint8_t received = 0;
  uint8_t computed = 0;
  switch (check_checksum(line, &body, &received, &computed)) {
    case ChecksumResult::kNone: {
      // A plain line is one typed in a terminal, except a TRAJ point: hosts stream those,
      // always with a checksum, so a TRAJ without one lost its '*XX' on the way (a
      // corrupted '*', a cut line) and is never run unchecked.
      const std::string_view name = trim(line.substr(0, line.find(':')));
      if (iequals(name, "TRAJ")) {
        ++crc_errors_;
        return error_reply(ErrorCode::kChecksum,
                           "TRAJ needs a checksum: 'TRAJ:dt_ms:a1,...,a6*XX' (line refused, " +
                               std::to_string(crc_errors_) + " so far)");
      }
      silent_ms_ = 0;
      return run(line);
    }
    case ChecksumResult::kOk: {
      silent_ms_ = 0;
      body = trim(body);
      const std::string reply =
          body.empty() ? error_reply(ErrorCode::kSyntax, "empty command") : run(body);
      return with_checksum(reply);
    }
    case ChecksumResult::kMalformed:
      ++crc_errors_;
      return with_checksum(error_reply(
          ErrorCode::kChecksum,
          "malformed checksum: '*' must end the line followed by two hex digits (line " +
              quoted(line.substr(line.size() > 24 ? line.size() - 24 : 0)) + ")"));
    case ChecksumResult::kMismatch:
      ++crc_errors_;
      return with_checksum(error_reply(
          ErrorCode::kChecksum, "checksum mismatch: line says " + hex_byte(received) +
                                    ", its bytes give " + hex_byte(computed) +
                                    " (line refused, " + std::to_string(crc_errors_) +
                                    " so far)"));
  }
  return run(line);
}

bool Protocol::feed(char byte, std::string* reply) {
  const LineReader::Event event = reader_.feed(byte);
  switch (event) {
    case LineReader::Event::kNone: return false;
    case LineReader::Event::kLine: *reply = handle(reader_.line()); return true;
    case LineReader::Event::kTooLong:
    case LineReader::Event::kBadByte:
      *reply = line_error(event, reader_.bad_byte(), reader_.bad_column());
      return true;
  }
  return false;
}

std::string Protocol::execute(std::string_view command) {
  std::string_view line;
  uint8_t bad_byte = 0;
  std::size_t column = 0;
  const LineReader::Event event = check_line(command, &line, &bad_byte, &column);
  switch (event) {
    case LineReader::Event::kLine: return handle(line);
    case LineReader::Event::kNone: return error_reply(ErrorCode::kSyntax, "empty command");
    case LineReader::Event::kTooLong:
    case LineReader::Event::kBadByte: return line_error(event, bad_byte, column);
  }
  return error_reply(ErrorCode::kSyntax, "empty command");
}

HttpResponse Protocol::http_command(std::string_view body) {
  HttpResponse response;
  std::string cmd;
  std::string error;
  if (!json_extract_cmd(body, &cmd, &error)) {
    response.status = 400;
    response.body = "{\"error\":" + json_quote(error) + "}";
    return response;
  }
  response.body = "{\"reply\":" + json_quote(execute(cmd)) + "}";
  return response;
}

HttpResponse Protocol::http_no_body() {
  HttpResponse response;
  response.status = 400;
  response.body = "{\"error\":" +
                  json_quote("no JSON body: POST {\"cmd\": \"...\"} with Content-Type: "
                             "application/json") +
                  "}";
  return response;
}

std::string Protocol::banner() const {
  return std::string("# ") + kFirmwareName + " " + kFirmwareVersion + " protocol " +
         std::to_string(kProtocolVersion) + " ready";
}

std::string Protocol::status_json() const {
  const int n = motion_.n_servos();
  std::string out;
  out.reserve(96 + 16 * n);
  out += "{\"status\":\"ok\",\"mode\":\"";
  out += mode_name(motion_.mode());
  out += "\",\"moving\":";
  out += motion_.moving() ? "true" : "false";
  out += ",\"powered\":";
  out += motion_.powered() ? "true" : "false";
  out += ",\"pos\":";
  append_angles(&out, motion_.pos(), n);
  out += ",\"target\":";
  append_angles(&out, motion_.target(), n);
  out += ",\"speed\":" + std::to_string(motion_.speed());
  out += ",\"queued\":" + std::to_string(motion_.queued());
  out += ",\"buffered_ms\":" + std::to_string(motion_.buffered_ms());
  out += ",\"tick\":" + std::to_string(motion_.ticks());
  out += ",\"crc_errors\":" + std::to_string(crc_errors_);
  out += ",\"watchdog_stops\":" + std::to_string(watchdog_stops_);
  out += "}";
  return out;
}

std::string Protocol::version_json() const {
  const int n = motion_.n_servos();
  std::string out = "{\"firmware\":\"";
  out += kFirmwareName;
  out += "\",\"version\":\"";
  out += kFirmwareVersion;
  out += "\",\"protocol\":" + std::to_string(kProtocolVersion);
  out += ",\"servos\":" + std::to_string(n);
  out += ",\"channels\":[";
  for (int i = 0; i < n; ++i) {
    if (i) out.push_back(',');
    out += std::to_string(config_.servos[i].channel);
  }
  out += "],\"home\":";
  append_angles(&out, home(), n);
  out += ",\"tick_ms\":" + std::to_string(config_.tick_ms);
  out += ",\"speed_range\":[" + std::to_string(kSpeedMin) + "," + std::to_string(kSpeedMax) + "]";
  out += ",\"queue\":" + std::to_string(kQueueCapacity);
  out += ",\"max_line\":" + std::to_string(kMaxLineLength);
  out += ",\"checksum\":\"crc8\"";
  out += ",\"watchdog_ms\":" + std::to_string(config_.watchdog_ms);
  out += "}";
  return out;
}

Angles Protocol::filled(int32_t centideg) const {
  Angles angles{};
  for (int i = 0; i < motion_.n_servos(); ++i) angles[i] = centideg;
  return angles;
}

Angles Protocol::home() const {
  Angles angles{};
  for (int i = 0; i < motion_.n_servos(); ++i) angles[i] = config_.servos[i].home_cdeg;
  return angles;
}

std::string Protocol::run(std::string_view line) {
  const std::size_t colon = line.find(':');
  const bool has_args = colon != std::string_view::npos;
  const std::string_view name = trim(line.substr(0, colon));
  const std::string_view args = has_args ? trim(line.substr(colon + 1)) : std::string_view();

  const auto no_args = [&](std::string_view command) -> std::string {
    return error_reply(ErrorCode::kSyntax,
                       std::string(command) + " takes no arguments (got " +
                           quoted(line.substr(colon + 1)) + ")");
  };

  if (iequals(name, "STATUS")) {
    if (has_args) return no_args("STATUS");
    return "ok " + status_json();
  }
  if (iequals(name, "PING")) {
    if (has_args) return no_args("PING");
    return "ok pong";
  }
  if (iequals(name, "VERSION")) {
    if (has_args) return no_args("VERSION");
    return "ok " + version_json();
  }
  if (iequals(name, "HOME")) {
    if (has_args) return no_args("HOME");
    motion_.move_to(home());
    return "ok";
  }
  if (iequals(name, "ZERO")) {
    if (has_args) return no_args("ZERO");
    motion_.move_to(filled(0));
    return "ok";
  }
  if (iequals(name, "STOP")) {
    if (has_args) return no_args("STOP");
    motion_.stop();
    return "ok";
  }
  if (iequals(name, "MOVE")) return cmd_move(args, has_args);
  if (iequals(name, "SPEED")) return cmd_speed(args, has_args);
  if (iequals(name, "TRAJ")) return cmd_traj(args, has_args);
  return error_reply(ErrorCode::kUnknownCommand,
                     "unknown command " + quoted(name) + " (commands: " + kCommandList + ")");
}

std::string Protocol::parse_angles(std::string_view args, std::string_view command,
                                   Angles* out) const {
  const int n = motion_.n_servos();
  int fields = 1;
  for (char c : args) fields += c == ',' ? 1 : 0;
  if (fields != n) {
    return error_reply(ErrorCode::kWrongCount,
                       std::string(command) + " needs " + std::to_string(n) +
                           " angles (got " + std::to_string(fields) + ")");
  }
  std::size_t start = 0;
  for (int i = 0; i < n; ++i) {
    std::size_t end = args.find(',', start);
    if (end == std::string_view::npos) end = args.size();
    const std::string_view token = trim(args.substr(start, end - start));
    start = end + 1;
    const std::string label = "angle " + std::to_string(i + 1);
    if (token.empty()) return error_reply(ErrorCode::kSyntax, label + " is empty");
    const ParsedNumber number = parse_centi(token);
    if (!number.ok) {
      return error_reply(ErrorCode::kSyntax,
                         label + " must be a number of degrees (got " + quoted(token) + ")");
    }
    if (number.value < kAngleMin || number.value > kAngleMax) {
      return error_reply(ErrorCode::kOutOfRange,
                         label + " out of range 0..180 (got " + shown(token) + ")");
    }
    (*out)[i] = static_cast<int32_t>(number.value);
  }
  return "";
}

std::string Protocol::cmd_move(std::string_view args, bool has_args) {
  const std::string usage = "MOVE:a1,...,a" + std::to_string(motion_.n_servos());
  if (!has_args || args.empty()) {
    return error_reply(ErrorCode::kSyntax, "MOVE needs " + std::to_string(motion_.n_servos()) +
                                               " angles: " + usage);
  }
  Angles target{};
  std::string error = parse_angles(args, "MOVE", &target);
  if (!error.empty()) return error;
  motion_.move_to(target);
  return "ok";
}

std::string Protocol::cmd_speed(std::string_view args, bool has_args) {
  const std::string range = std::to_string(kSpeedMin) + ".." + std::to_string(kSpeedMax);
  if (!has_args || args.empty()) {
    return error_reply(ErrorCode::kSyntax, "SPEED needs a value: SPEED:n with n in " + range +
                                               " (degrees per tick)");
  }
  const ParsedNumber number = parse_uint(args);
  if (!number.ok) {
    // "-3" is a number, just not a speed: report it as out of range.
    const ParsedNumber signed_number = parse_centi(args);
    if (signed_number.ok && signed_number.value < 0 && signed_number.value % 100 == 0) {
      return error_reply(ErrorCode::kOutOfRange,
                         "speed out of range " + range + " (got " + shown(args) + ")");
    }
    return error_reply(ErrorCode::kSyntax,
                       "speed must be an integer " + range + " (got " + quoted(args) + ")");
  }
  if (number.value < kSpeedMin || number.value > kSpeedMax) {
    return error_reply(ErrorCode::kOutOfRange,
                       "speed out of range " + range + " (got " + shown(args) + ")");
  }
  motion_.set_speed(static_cast<int>(number.value));
  return "ok";
}

std::string Protocol::cmd_traj(std::string_view args, bool has_args) {
  const std::string usage =
      "TRAJ:dt_ms:a1,...,a" + std::to_string(motion_.n_servos());
  const std::size_t colon = args.find(':');
  if (!has_args || colon == std::string_view::npos) {
    return error_reply(ErrorCode::kSyntax, "TRAJ needs a time step and " +
                                               std::to_string(motion_.n_servos()) +
                                               " angles: " + usage);
  }
  const std::string_view dt_text = trim(args.substr(0, colon));
  const std::string_view angle_text = trim(args.substr(colon + 1));
  const std::string dt_range =
      std::to_string(kTrajDtMinMs) + ".." + std::to_string(kTrajDtMaxMs);
  const ParsedNumber dt = parse_uint(dt_text);
  if (!dt.ok) {
    return error_reply(ErrorCode::kSyntax, "dt_ms must be an integer " + dt_range +
                                               " (got " + quoted(dt_text) + ")");
  }
  if (dt.value < static_cast<int64_t>(kTrajDtMinMs) ||
      dt.value > static_cast<int64_t>(kTrajDtMaxMs)) {
    return error_reply(ErrorCode::kOutOfRange,
                       "dt_ms out of range " + dt_range + " (got " + shown(dt_text) + ")");
  }
  if (angle_text.empty()) {
    return error_reply(ErrorCode::kSyntax, "TRAJ needs " + std::to_string(motion_.n_servos()) +
                                               " angles: " + usage);
  }
  Angles point{};
  std::string error = parse_angles(angle_text, "TRAJ", &point);
  if (!error.empty()) return error;
  if (!motion_.push_point(static_cast<uint32_t>(dt.value), point)) {
    return error_reply(ErrorCode::kQueueFull,
                       "queue full (" + std::to_string(kQueueCapacity) +
                           " points): wait for it to drain, then resend this point");
  }
  return "ok " + std::to_string(motion_.queued()) + " " + std::to_string(motion_.buffered_ms());
}

}  // namespace trs
