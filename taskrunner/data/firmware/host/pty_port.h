// A pseudo-terminal standing in for the ESP32's USB serial port.
//
// The master side is ours; clients open slave_path() like /dev/ttyUSB0. We keep a slave
// descriptor open ourselves so the master never sees a hangup between clients, and set
// the line raw (no echo, no CR/LF translation) so a client that does not configure the
// terminal (plain os.open) still gets the bytes as sent.
#pragma once

#include <string>
#include <string_view>

namespace host {

class PtyPort {
 public:
  PtyPort() = default;
  PtyPort(const PtyPort&) = delete;
  PtyPort& operator=(const PtyPort&) = delete;
  ~PtyPort();

  bool open(std::string* error);
  int fd() const { return master_; }
  const std::string& slave_path() const { return slave_path_; }

  // Queues bytes for the client; what the pty cannot take now waits for flush().
  // Like a UART with nobody listening, output beyond kMaxPending bytes is dropped.
  void send(std::string_view bytes);
  void flush();
  bool wants_write() const { return !pending_.empty(); }

 private:
  static constexpr std::size_t kMaxPending = 64 * 1024;
  int master_ = -1;
  int slave_ = -1;
  std::string slave_path_;
  std::string pending_;
};

}  // namespace host
