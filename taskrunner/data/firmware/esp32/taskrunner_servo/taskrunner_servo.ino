// taskrunner servo bridge: ESP32 + PCA9685 servo board.
//
// A thin shell around the protocol core (firmware/src, copied into src/trs/ by
// `make -C firmware sketch`): serial at 115200 baud, a WiFi access point serving
// POST /api/command, the 80 ms tick, and the PCA9685 outputs. Every command, reply and
// motion rule lives in the core and is specified in firmware/PROTOCOL.md.
//
// Build (arduino-esp32 3.x: the core needs C++17; 2.x compiles with gnu++11):
//   make -C firmware sketch
//   arduino-cli lib install "Adafruit PWM Servo Driver Library"
//   arduino-cli compile --fqbn esp32:esp32:esp32 firmware/esp32/taskrunner_servo
//   arduino-cli upload -p /dev/ttyUSB0 --fqbn esp32:esp32:esp32 firmware/esp32/taskrunner_servo
//
// Wiring: PCA9685 SDA -> GPIO 21, SCL -> GPIO 22, VCC -> 3.3 V, V+ -> a separate 5-6 V
// servo supply (not USB), grounds joined. Servos on the channels below.

#if !__has_include("src/trs/protocol.h")
#error "The protocol core is missing: run `make -C firmware sketch` (copies firmware/src into src/trs/)."
#endif

#include <Adafruit_PWMServoDriver.h>
#include <Arduino.h>
#include <WebServer.h>
#include <WiFi.h>
#include <Wire.h>

#include <string>
#include <string_view>

#include "src/trs/config.h"
#include "src/trs/pca9685.h"
#include "src/trs/protocol.h"

// ---- Settings ------------------------------------------------------------------------

constexpr uint32_t kSerialBaud = 115200;
constexpr const char* kApSsid = "taskrunner-arm";
constexpr const char* kApPassword = "taskrunner";  // 8+ characters (WPA2), or nullptr: open
const IPAddress kApAddress(10, 10, 10, 1);         // the host posts to http://10.10.10.1/api/command
const IPAddress kApNetmask(255, 255, 255, 0);
constexpr uint8_t kPca9685Address = 0x40;
// The PCA9685's internal oscillator is 25 MHz nominal but boards measure 23-27 MHz;
// measure yours (Adafruit's "oscillator" example) for accurate pulse widths.
constexpr uint32_t kPca9685OscillatorHz = trs::kPca9685OscillatorHz;
constexpr float kServoPwmHz = 50.0f;

// The servos in MOVE/TRAJ order: robots/servo_arm/config/hardware.yaml, Revolute 1..6
// (Revolute 7 shares Revolute 6's servo). Pulse widths for 0 and 180 degrees: measure
// each servo (drive it to either end and stop just before it buzzes against its stop).
// Home: where HOME sends each servo, and the assumed position at power-on.
// {channel, min_us, max_us, home_centidegrees}
const trs::ServoSpec kServos[] = {
    {0, 500, 2500, 9000},   // Revolute 1: base yaw (MG996R)
    {3, 500, 2500, 9000},   // Revolute 2: shoulder (MG996R)
    {6, 500, 2500, 9000},   // Revolute 3: elbow (MG996R)
    {9, 500, 2500, 9000},   // Revolute 4: wrist pitch (MG90S)
    {12, 500, 2500, 9000},  // Revolute 5: wrist roll (MG90S)
    {15, 500, 2500, 9000},  // Revolute 6: gripper, both fingers (SG90)
};
constexpr uint32_t kTickMs = 80;
constexpr int kDefaultSpeed = 5;  // degrees per tick
// While a trajectory streams, this long without a line from the host (a cable pulled, a
// hung host) stops the servos where they are; 0 turns it off. The host sends a line at
// least every ~80 ms while streaming.
constexpr uint32_t kWatchdogMs = 300;
// After a stall (a slow HTTP client can hold handleClient() for seconds), run at most
// this many missed ticks back to back and drop the rest: the motion is delayed (the
// PCA9685 holds the last pulses meanwhile) rather than rushed in a jump.
constexpr int kMaxCatchUpTicks = 1;

// ---- State ---------------------------------------------------------------------------

trs::Config make_config() {
  trs::Config config;
  config.n_servos = static_cast<int>(sizeof kServos / sizeof kServos[0]);
  for (int i = 0; i < config.n_servos && i < trs::kMaxServos; ++i) config.servos[i] = kServos[i];
  config.tick_ms = kTickMs;
  config.default_speed = kDefaultSpeed;
  config.watchdog_ms = kWatchdogMs;
  return config;
}

const trs::Config g_config = make_config();
std::string g_config_error;  // non-empty: refuse to drive anything
trs::Protocol g_protocol(g_config);
Adafruit_PWMServoDriver g_pwm(kPca9685Address);
WebServer g_server(80);
uint8_t g_prescale = 121;
uint16_t g_written[trs::kMaxServos];  // last OFF count per servo, to skip redundant I2C writes
unsigned long g_last_tick_ms = 0;
std::string g_reply;

// ---- Helpers -------------------------------------------------------------------------

void send_line(const std::string& line) {
  Serial.write(reinterpret_cast<const uint8_t*>(line.data()), line.size());
  Serial.write(static_cast<uint8_t>('\n'));
}

// Drives the PCA9685 from the core's positions: full off while unpowered (servos limp
// until the first motion command), else the pulse for each commanded angle.
void write_outputs() {
  const trs::Motion& motion = g_protocol.motion();
  for (int i = 0; i < g_config.n_servos; ++i) {
    const trs::ServoSpec& servo = g_config.servos[i];
    uint16_t off = trs::kPca9685FullOff;
    if (motion.powered()) {
      const uint16_t us = trs::pulse_us(motion.pos()[i], servo.min_us, servo.max_us);
      off = trs::pca9685_counts(us, kPca9685OscillatorHz, g_prescale);
    }
    if (off != g_written[i]) {
      g_pwm.setPWM(servo.channel, 0, off);
      g_written[i] = off;
    }
  }
}

void handle_command() {
  // The WebServer hands over a JSON (or text/plain) body as the argument "plain"; a body
  // sent as a form (urlencoded / multipart) is parsed into fields and is not there.
  if (!g_server.hasArg("plain")) {
    const trs::HttpResponse response = trs::Protocol::http_no_body();
    g_server.send(response.status, "application/json", response.body.c_str());
    return;
  }
  const String body = g_server.arg("plain");
  const trs::HttpResponse response =
      g_protocol.http_command(std::string_view(body.c_str(), body.length()));
  g_server.send(response.status, "application/json", response.body.c_str());
}

void handle_not_found() {
  g_server.send(404, "application/json",
                "{\"error\":\"not found: the only endpoint is POST /api/command\"}");
}

// ---- Arduino entry points ------------------------------------------------------------

void setup() {
  Serial.setRxBufferSize(1024);  // room for ~20 TRAJ lines while WiFi work holds the loop
  Serial.begin(kSerialBaud);

  g_config_error = trs::check_config(g_config);
  if (!g_config_error.empty()) return;  // loop() keeps reporting it

  Wire.begin();
  Wire.setClock(400000);
  Wire.beginTransmission(kPca9685Address);
  const bool pca_found = Wire.endTransmission() == 0;
  g_pwm.begin();
  g_pwm.setOscillatorFrequency(kPca9685OscillatorHz);
  g_pwm.setPWMFreq(kServoPwmHz);
  g_prescale = g_pwm.readPrescale();  // what the chip got, so counts match its real period
  for (uint16_t& written : g_written) written = 0xffff;
  write_outputs();  // all channels full off until the first motion command

  // softAPConfig() configures the running access point, so it comes after softAP().
  WiFi.mode(WIFI_AP);
  const bool ap_up = WiFi.softAP(kApSsid, kApPassword) &&
                     WiFi.softAPConfig(kApAddress, kApAddress, kApNetmask);
  g_server.on("/api/command", HTTP_POST, handle_command);
  g_server.onNotFound(handle_not_found);
  g_server.begin();

  // Lines starting with '#' are information, never replies (PROTOCOL.md, "Framing").
  send_line(g_protocol.banner());
  if (!pca_found) send_line("# warning: no PCA9685 answers at I2C address 0x40");
  if (ap_up) {
    send_line(std::string("# wifi: access point ") + kApSsid + ", http://" +
              WiFi.softAPIP().toString().c_str() + "/api/command");
  } else {
    send_line("# warning: WiFi access point failed to start; serial only");
  }
  g_last_tick_ms = millis();
}

void loop() {
  if (!g_config_error.empty()) {
    send_line("# config error: " + g_config_error);
    delay(2000);
    return;
  }

  while (Serial.available() > 0) {
    const int byte = Serial.read();
    if (byte < 0) break;
    if (g_protocol.feed(static_cast<char>(byte), &g_reply)) send_line(g_reply);
  }

  g_server.handleClient();

  const unsigned long now = millis();
  int ticks = 0;
  while (now - g_last_tick_ms >= g_config.tick_ms) {
    if (ticks == kMaxCatchUpTicks) {
      g_last_tick_ms = now;  // too far behind: resume from now rather than rush
      break;
    }
    g_protocol.tick();
    g_last_tick_ms += g_config.tick_ms;
    ++ticks;
  }
  if (ticks > 0) write_outputs();
}
