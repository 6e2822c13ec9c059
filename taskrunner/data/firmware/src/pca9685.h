// Servo angle -> pulse width -> PCA9685 counts.
//
// The PCA9685 divides each PWM period into 4096 counts; the period is
// 4096 * (prescale + 1) / oscillator. The sketch reads the prescale the chip actually
// got (readPrescale()) so the counts match the real period, whatever the library's
// rounding of the requested 50 Hz.
#pragma once

#include <cstdint>

namespace trs {

constexpr uint32_t kPca9685OscillatorHz = 25000000;  // nominal; boards vary by a few %
constexpr uint16_t kPca9685FullOff = 4096;           // OFF register value: output fully off

// Pulse width for `centideg` (clamped to 0..180 degrees), linear from min_us (0 deg) to
// max_us (180 deg), rounded to the nearest microsecond. min_us > max_us reverses.
uint16_t pulse_us(int32_t centideg, uint16_t min_us, uint16_t max_us);

// Prescale register value for a PWM frequency, as the chip's datasheet gives it:
// round(osc / (4096 * pwm_hz)) - 1, clamped to 3..255.
uint8_t pca9685_prescale(uint32_t oscillator_hz, uint32_t pwm_hz);

// OFF count (with ON at 0) for a pulse of `us` microseconds, rounded, clamped to 0..4095.
uint16_t pca9685_counts(uint32_t us, uint32_t oscillator_hz, uint8_t prescale);

}  // namespace trs
