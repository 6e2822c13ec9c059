// Host stub (see Arduino.h): the WiFi access-point calls the sketch uses.
#pragma once

#include <Arduino.h>

typedef enum { WIFI_MODE_NULL = 0, WIFI_MODE_STA, WIFI_MODE_AP, WIFI_MODE_APSTA } wifi_mode_t;
#define WIFI_AP WIFI_MODE_AP

class IPAddress {
 public:
  IPAddress(uint8_t a, uint8_t b, uint8_t c, uint8_t d);
  String toString() const;
};

class WiFiClass {
 public:
  bool mode(wifi_mode_t mode);
  bool softAPConfig(IPAddress local_ip, IPAddress gateway, IPAddress subnet);
  bool softAP(const char* ssid, const char* passphrase = nullptr, int channel = 1,
              int ssid_hidden = 0, int max_connection = 4);
  IPAddress softAPIP();
};
extern WiFiClass WiFi;
