// Host stub (see Arduino.h): Adafruit PWM Servo Driver Library 3.x calls the sketch uses.
#pragma once

#include <Arduino.h>
#include <Wire.h>

class Adafruit_PWMServoDriver {
 public:
  Adafruit_PWMServoDriver(const uint8_t addr = 0x40);
  Adafruit_PWMServoDriver(const uint8_t addr, TwoWire& i2c);
  bool begin(uint8_t prescale = 0);
  void setOscillatorFrequency(uint32_t freq);
  void setPWMFreq(float freq);
  uint8_t readPrescale(void);
  uint8_t setPWM(uint8_t num, uint16_t on, uint16_t off);
};
