// Firmware configuration: servo count, channel map, pulse widths, home angles, timing.
//
// Angles are integer centidegrees (1/100 degree) everywhere in the core: 9000 is 90
// degrees. The protocol accepts and reports degrees with up to two decimals.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace trs {

constexpr const char* kFirmwareName = "taskrunner-servo";
constexpr const char* kFirmwareVersion = "1.1.0";
constexpr int kProtocolVersion = 2;

constexpr int kMaxServos = 16;          // a PCA9685 has 16 channels
constexpr int kQueueCapacity = 64;      // TRAJ points (64 x 80 ms = 5.12 s of motion)
constexpr std::size_t kMaxLineLength = 128;  // bytes of one command, terminator excluded

constexpr int32_t kAngleMin = 0;        // centidegrees
constexpr int32_t kAngleMax = 18000;    // centidegrees
constexpr int kSpeedMin = 1;            // degrees per tick
constexpr int kSpeedMax = 20;           // degrees per tick
constexpr uint32_t kTrajDtMinMs = 1;    // shortest TRAJ segment
constexpr uint32_t kTrajDtMaxMs = 60000;  // longest TRAJ segment
constexpr uint32_t kTickMsMin = 1;
constexpr uint32_t kTickMsMax = 1000;
constexpr uint32_t kWatchdogMsMax = 600000;

using Angles = std::array<int32_t, kMaxServos>;  // centidegrees; only [0, n_servos) used

// One servo: where it is wired and how its pulse maps to 0..180 degrees.
struct ServoSpec {
  uint8_t channel = 0;      // PCA9685 output 0..15
  uint16_t min_us = 500;    // pulse width at 0 degrees
  uint16_t max_us = 2500;   // pulse width at 180 degrees
  int32_t home_cdeg = 9000; // HOME target and power-on position (centidegrees)
};

struct Config {
  int n_servos = 0;
  std::array<ServoSpec, kMaxServos> servos{};
  uint32_t tick_ms = 80;   // period of the step loop
  int default_speed = 5;   // degrees per tick after boot
  // While a trajectory streams, no accepted line for this long (firmware ms) stops the
  // servos where they are. 0: off. Must be 0 or at least one tick.
  uint32_t watchdog_ms = 300;
};

// Our arm (robots/servo_arm/config/hardware.yaml): six servos on channels
// 0, 3, 6, 9, 12, 15 (Revolute 1..6; Revolute 7 shares Revolute 6's servo),
// 500..2500 us for 0..180 degrees, home 90 degrees each, 80 ms tick, speed 5.
Config servo_arm_config();

// Empty when `config` is usable, else what is wrong with it
// (e.g. "servo 2 channel must be 0..15 (got 16)").
std::string check_config(const Config& config);

}  // namespace trs
