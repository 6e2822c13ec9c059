#include "../src/config.h"
#include "harness.h"

TEST(servo_arm_config_matches_hardware_yaml) {
  // robots/servo_arm/config/hardware.yaml: Revolute 1..6 on channels 0,3,6,9,12,15
  // (Revolute 7 shares Revolute 6's servo, so six servos).
  const trs::Config config = trs::servo_arm_config();
  CHECK_EQ(config.n_servos, 6);
  const int channels[6] = {0, 3, 6, 9, 12, 15};
  for (int i = 0; i < 6; ++i) {
    CHECK_EQ(static_cast<int>(config.servos[i].channel), channels[i]);
    CHECK_EQ(config.servos[i].home_cdeg, 9000);
  }
  CHECK_EQ(config.tick_ms, 80u);
  CHECK_EQ(trs::check_config(config), "");
}

TEST(check_config_names_the_problem) {
  trs::Config config = trs::servo_arm_config();
  config.n_servos = 0;
  CHECK_EQ(trs::check_config(config), "n_servos must be 1..16 (got 0)");

  config = trs::servo_arm_config();
  config.servos[1].channel = 16;
  CHECK_EQ(trs::check_config(config), "servo 2 channel must be 0..15 (got 16)");

  config = trs::servo_arm_config();
  config.servos[2].channel = 0;
  CHECK_EQ(trs::check_config(config), "servo 3 channel 0 is already used");

  config = trs::servo_arm_config();
  config.servos[0].min_us = 2500;
  CHECK_EQ(trs::check_config(config),
           "servo 1 pulse range must be two different widths in 100..3000 us (got 2500..2500)");

  config = trs::servo_arm_config();
  config.servos[5].home_cdeg = 18050;
  CHECK_EQ(trs::check_config(config), "servo 6 home must be 0..180 degrees (got 180.5)");

  config = trs::servo_arm_config();
  config.tick_ms = 0;
  CHECK_EQ(trs::check_config(config), "tick_ms must be 1..1000 (got 0)");

  config = trs::servo_arm_config();
  config.default_speed = 21;
  CHECK_EQ(trs::check_config(config), "default_speed must be 1..20 (got 21)");
}
