#include "../src/pca9685.h"
#include "harness.h"

TEST(pulse_us_maps_0_to_180_degrees_linearly) {
  CHECK_EQ(trs::pulse_us(0, 500, 2500), 500);
  CHECK_EQ(trs::pulse_us(9000, 500, 2500), 1500);
  CHECK_EQ(trs::pulse_us(18000, 500, 2500), 2500);
  CHECK_EQ(trs::pulse_us(4500, 500, 2500), 1000);
  CHECK_EQ(trs::pulse_us(1, 500, 2500), 500);     // 0.01 deg = 0.11 us
  CHECK_EQ(trs::pulse_us(5, 500, 2500), 501);     // 0.55 us rounds up
  CHECK_EQ(trs::pulse_us(9000, 600, 2400), 1500);
}

TEST(pulse_us_clamps_and_can_reverse) {
  CHECK_EQ(trs::pulse_us(-100, 500, 2500), 500);
  CHECK_EQ(trs::pulse_us(20000, 500, 2500), 2500);
  CHECK_EQ(trs::pulse_us(0, 2500, 500), 2500);
  CHECK_EQ(trs::pulse_us(18000, 2500, 500), 500);
  CHECK_EQ(trs::pulse_us(4500, 2500, 500), 2000);
}

TEST(pca9685_prescale_matches_the_datasheet_formula) {
  CHECK_EQ(trs::pca9685_prescale(25000000, 50), 121);   // datasheet: 50 Hz -> 0x79
  CHECK_EQ(trs::pca9685_prescale(25000000, 200), 30);   // datasheet: 200 Hz -> 0x1E
  CHECK_EQ(trs::pca9685_prescale(25000000, 1526), 3);   // fastest
  CHECK_EQ(trs::pca9685_prescale(25000000, 24), 253);
  CHECK_EQ(trs::pca9685_prescale(25000000, 1), 255);    // clamped
  CHECK_EQ(trs::pca9685_prescale(25000000, 100000), 3); // clamped
}

TEST(pca9685_counts_follow_the_real_period) {
  // 25 MHz, prescale 121: period = 4096 * 122 / 25e6 = 19.98848 ms, 4.88 us per count.
  CHECK_EQ(trs::pca9685_counts(1500, 25000000, 121), 307);   // 307.4
  CHECK_EQ(trs::pca9685_counts(500, 25000000, 121), 102);    // 102.46
  CHECK_EQ(trs::pca9685_counts(2500, 25000000, 121), 512);   // 512.3
  CHECK_EQ(trs::pca9685_counts(0, 25000000, 121), 0);
  CHECK_EQ(trs::pca9685_counts(30000, 25000000, 121), 4095); // clamped below full-on
  // A board whose oscillator runs at 27 MHz, with the prescale computed for it.
  CHECK_EQ(trs::pca9685_counts(1500, 27000000, trs::pca9685_prescale(27000000, 50)), 307);
}

TEST(pulse_counts_are_monotonic_over_the_angle_range) {
  const uint8_t prescale = trs::pca9685_prescale(trs::kPca9685OscillatorHz, 50);
  uint16_t previous = 0;
  for (int32_t c = 0; c <= 18000; c += 10) {
    const uint16_t counts =
        trs::pca9685_counts(trs::pulse_us(c, 500, 2500), trs::kPca9685OscillatorHz, prescale);
    CHECK(counts >= previous);
    previous = counts;
  }
  CHECK_EQ(previous, 512);
}
