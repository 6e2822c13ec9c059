// Host stub of the few Arduino-ESP32 (3.x) declarations taskrunner_servo.ino uses, so
// `make sketch-check` can type-check the sketch without the ESP32 toolchain.
// Declarations only: nothing here is linked or run. Signatures follow arduino-esp32 3.x.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

class String {
 public:
  String();
  String(const char* text);  // NOLINT: implicit, as in Arduino
  const char* c_str() const;
  unsigned int length() const;
};

class HardwareSerial {
 public:
  void begin(unsigned long baud);
  std::size_t setRxBufferSize(std::size_t size);
  int available();
  int read();
  std::size_t write(uint8_t byte);
  std::size_t write(const uint8_t* data, std::size_t size);
  void flush();
};
extern HardwareSerial Serial;

unsigned long millis();
void delay(uint32_t ms);
