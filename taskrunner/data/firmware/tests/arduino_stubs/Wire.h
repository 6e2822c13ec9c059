// Host stub (see Arduino.h): the TwoWire calls the sketch uses.
#pragma once

#include <Arduino.h>

class TwoWire {
 public:
  bool begin();
  bool setClock(uint32_t frequency);
  void beginTransmission(uint8_t address);
  uint8_t endTransmission(bool send_stop = true);
};
extern TwoWire Wire;
