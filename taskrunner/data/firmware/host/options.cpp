#include "options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace host {
namespace {

bool parse_int(const std::string& text, long min, long max, long* out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || value < min || value > max) return false;
  *out = value;
  return true;
}

bool parse_double(const std::string& text, double min, double max, double* out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (errno != 0 || *end != '\0' || !std::isfinite(value) || value < min || value > max) {
    return false;
  }
  *out = value;
  return true;
}

}  // namespace

const char* usage() {
  return "usage: taskrunner-servo-host [--tick-ms N] [--speedup X] [--log FILE]\n"
         "                             [--http-port N] [--link PATH] [--watchdog-ms N]\n"
         "                             [--channels C1,C2,...]\n"
         "\n"
         "The taskrunner servo firmware with simulated servos. Speaks the line protocol\n"
         "(firmware/PROTOCOL.md) on a pseudo-terminal and over HTTP on 127.0.0.1.\n"
         "stdout line 1: the pty path (open it like a serial port, any baud rate);\n"
         "stdout line 2: the URL for POST {\"cmd\": \"...\"}. SIGTERM or SIGINT: clean exit.\n"
         "\n"
         "  --tick-ms N     firmware tick in ms, 1..1000 (default 80)\n"
         "  --speedup X     run the tick clock X times faster than real time, 0.01..1000\n"
         "                  (default 1); firmware time in STATUS and the log is unscaled\n"
         "  --log FILE      write 't_ms,a1,...,a6' for t = 0 and after every tick (degrees)\n"
         "  --http-port N   TCP port on 127.0.0.1, 0 = any free port (default 0)\n"
         "  --link PATH     also make PATH a symlink to the pty (removed on exit)\n"
         "  --watchdog-ms N stop a streamed trajectory after N ms (wall clock) without a\n"
         "                  line from the host, 0 = off (default 300)\n"
         "  --channels LIST the servos' PCA9685 channels, in MOVE/TRAJ order (default\n"
         "                  0,3,6,9,12,15: one arm; 0,1,2,3,4,5,8,9,10,11,12,13: the pair)\n"
         "  -h, --help      this text\n";
}

bool parse_options(int argc, char** argv, Options* options, std::string* error) {
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      options->help = true;
      continue;
    }
    std::string value;
    const std::size_t eq = arg.find('=');
    if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
    } else if (arg == "--tick-ms" || arg == "--speedup" || arg == "--log" ||
               arg == "--http-port" || arg == "--link" || arg == "--watchdog-ms" ||
               arg == "--channels") {
      if (i + 1 >= argc) {
        *error = "'" + arg + "' needs a value";
        return false;
      }
      value = argv[++i];
    }
    if (arg == "--tick-ms") {
      long v = 0;
      if (!parse_int(value, 1, 1000, &v)) {
        *error = "'--tick-ms' must be an integer 1..1000 (got '" + value + "')";
        return false;
      }
      options->tick_ms = static_cast<uint32_t>(v);
    } else if (arg == "--speedup") {
      if (!parse_double(value, 0.01, 1000.0, &options->speedup)) {
        *error = "'--speedup' must be a number 0.01..1000 (got '" + value + "')";
        return false;
      }
    } else if (arg == "--log") {
      if (value.empty()) {
        *error = "'--log' must be a file path (got '')";
        return false;
      }
      options->log_path = value;
    } else if (arg == "--http-port") {
      long v = 0;
      if (!parse_int(value, 0, 65535, &v)) {
        *error = "'--http-port' must be an integer 0..65535 (got '" + value + "')";
        return false;
      }
      options->http_port = static_cast<int>(v);
    } else if (arg == "--link") {
      if (value.empty()) {
        *error = "'--link' must be a path (got '')";
        return false;
      }
      options->link_path = value;
    } else if (arg == "--watchdog-ms") {
      long v = 0;
      if (!parse_int(value, 0, 60000, &v)) {
        *error = "'--watchdog-ms' must be an integer 0..60000 (got '" + value + "')";
        return false;
      }
      options->watchdog_ms = static_cast<uint32_t>(v);
    } else if (arg == "--channels") {
      options->channels.clear();
      std::size_t start = 0;
      while (true) {
        const std::size_t comma = value.find(',', start);
        const std::string item =
            value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        long v = 0;
        if (!parse_int(item, 0, 15, &v) || options->channels.size() >= 16) {
          *error = "'--channels' must be 1..16 comma-separated channels 0..15 (got '" + value +
                   "')";
          return false;
        }
        options->channels.push_back(static_cast<int>(v));
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
    } else {
      *error = "unknown option '" + arg + "'";
      return false;
    }
  }
  return true;
}

}  // namespace host
