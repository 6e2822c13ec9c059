#include "config.h"

#include "numbers.h"

namespace trs {

Config servo_arm_config() {
  Config config;
  config.n_servos = 6;
  const uint8_t channels[6] = {0, 3, 6, 9, 12, 15};
  for (int i = 0; i < config.n_servos; ++i) {
    config.servos[i].channel = channels[i];
    config.servos[i].min_us = 500;
    config.servos[i].max_us = 2500;
    config.servos[i].home_cdeg = 9000;
  }
  config.tick_ms = 80;
  config.default_speed = 5;
  config.watchdog_ms = 300;
  return config;
}

std::string check_config(const Config& config) {
  if (config.n_servos < 1 || config.n_servos > kMaxServos) {
    return "n_servos must be 1.." + std::to_string(kMaxServos) + " (got " +
           std::to_string(config.n_servos) + ")";
  }
  bool used[kMaxServos] = {};
  for (int i = 0; i < config.n_servos; ++i) {
    const ServoSpec& s = config.servos[i];
    const std::string name = "servo " + std::to_string(i + 1);
    if (s.channel >= kMaxServos) {
      return name + " channel must be 0..15 (got " + std::to_string(s.channel) + ")";
    }
    if (used[s.channel]) {
      return name + " channel " + std::to_string(s.channel) + " is already used";
    }
    used[s.channel] = true;
    if (s.min_us < 100 || s.min_us > 3000 || s.max_us < 100 || s.max_us > 3000 ||
        s.min_us == s.max_us) {
      return name + " pulse range must be two different widths in 100..3000 us (got " +
             std::to_string(s.min_us) + ".." + std::to_string(s.max_us) + ")";
    }
    if (s.home_cdeg < kAngleMin || s.home_cdeg > kAngleMax) {
      return name + " home must be 0..180 degrees (got " + format_centi(s.home_cdeg) + ")";
    }
  }
  if (config.tick_ms < kTickMsMin || config.tick_ms > kTickMsMax) {
    return "tick_ms must be " + std::to_string(kTickMsMin) + ".." +
           std::to_string(kTickMsMax) + " (got " + std::to_string(config.tick_ms) + ")";
  }
  if (config.watchdog_ms != 0 &&
      (config.watchdog_ms < config.tick_ms || config.watchdog_ms > kWatchdogMsMax)) {
    return "watchdog_ms must be 0 (off) or " + std::to_string(config.tick_ms) + ".." +
           std::to_string(kWatchdogMsMax) + " (got " + std::to_string(config.watchdog_ms) + ")";
  }
  if (config.default_speed < kSpeedMin || config.default_speed > kSpeedMax) {
    return "default_speed must be 1..20 (got " + std::to_string(config.default_speed) + ")";
  }
  return "";
}

}  // namespace trs
