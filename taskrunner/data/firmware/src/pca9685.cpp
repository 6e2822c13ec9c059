#include "pca9685.h"

#include "config.h"

namespace trs {

uint16_t pulse_us(int32_t centideg, uint16_t min_us, uint16_t max_us) {
  if (centideg < kAngleMin) centideg = kAngleMin;
  if (centideg > kAngleMax) centideg = kAngleMax;
  const int64_t span = static_cast<int64_t>(max_us) - min_us;
  const int64_t scaled = span * centideg;
  const int64_t half = kAngleMax / 2;
  const int64_t offset = scaled >= 0 ? (scaled + half) / kAngleMax
                                     : -((-scaled + half) / kAngleMax);
  return static_cast<uint16_t>(min_us + offset);
}

uint8_t pca9685_prescale(uint32_t oscillator_hz, uint32_t pwm_hz) {
  if (pwm_hz == 0) return 255;
  const uint64_t denominator = 4096ull * pwm_hz;
  const uint64_t rounded = (oscillator_hz + denominator / 2) / denominator;
  if (rounded < 4) return 3;
  if (rounded > 256) return 255;
  return static_cast<uint8_t>(rounded - 1);
}

uint16_t pca9685_counts(uint32_t us, uint32_t oscillator_hz, uint8_t prescale) {
  // counts = us * 1e-6 / ((prescale + 1) / osc) = us * osc / (1e6 * (prescale + 1))
  const uint64_t numerator = static_cast<uint64_t>(us) * oscillator_hz;
  const uint64_t denominator = 1000000ull * (prescale + 1u);
  const uint64_t counts = (numerator + denominator / 2) / denominator;
  return static_cast<uint16_t>(counts > 4095 ? 4095 : counts);
}

}  // namespace trs
