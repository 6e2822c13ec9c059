// Command line of the host firmware (taskrunner-servo-host --help).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace host {

struct Options {
  uint32_t tick_ms = 80;     // firmware tick (--tick-ms)
  double speedup = 1.0;      // wall clock runs this many times faster (--speedup)
  std::string log_path;      // CSV of every tick's angles (--log)
  int http_port = 0;         // 0: any free port (--http-port)
  std::string link_path;     // symlink to the pty slave (--link)
  uint32_t watchdog_ms = 300;  // wall-clock ms of host silence that stop a stream; 0: off
  std::vector<int> channels;   // PCA9685 channel of each servo; empty: our arm's six
  bool help = false;
};

// False with `error` set on bad usage.
bool parse_options(int argc, char** argv, Options* options, std::string* error);

const char* usage();

}  // namespace host
