#include "pty_port.h"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace host {

PtyPort::~PtyPort() {
  if (slave_ >= 0) ::close(slave_);
  if (master_ >= 0) ::close(master_);
}

bool PtyPort::open(std::string* error) {
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master_ < 0) {
    *error = std::string("posix_openpt: ") + std::strerror(errno);
    return false;
  }
  if (::grantpt(master_) != 0 || ::unlockpt(master_) != 0) {
    *error = std::string("grantpt/unlockpt: ") + std::strerror(errno);
    return false;
  }
  const char* name = ::ptsname(master_);
  if (name == nullptr) {
    *error = std::string("ptsname: ") + std::strerror(errno);
    return false;
  }
  slave_path_ = name;
  slave_ = ::open(name, O_RDWR | O_NOCTTY);
  if (slave_ < 0) {
    *error = "open " + slave_path_ + ": " + std::strerror(errno);
    return false;
  }
  termios tio{};
  if (::tcgetattr(slave_, &tio) != 0) {
    *error = std::string("tcgetattr: ") + std::strerror(errno);
    return false;
  }
  ::cfmakeraw(&tio);
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, B115200);
  ::cfsetospeed(&tio, B115200);
  if (::tcsetattr(slave_, TCSANOW, &tio) != 0) {
    *error = std::string("tcsetattr: ") + std::strerror(errno);
    return false;
  }
  const int flags = ::fcntl(master_, F_GETFL);
  if (flags < 0 || ::fcntl(master_, F_SETFL, flags | O_NONBLOCK) != 0) {
    *error = std::string("fcntl O_NONBLOCK: ") + std::strerror(errno);
    return false;
  }
  return true;
}

void PtyPort::send(std::string_view bytes) {
  if (pending_.size() + bytes.size() > kMaxPending) return;
  pending_.append(bytes.data(), bytes.size());
  flush();
}

void PtyPort::flush() {
  while (!pending_.empty()) {
    const ssize_t n = ::write(master_, pending_.data(), pending_.size());
    if (n > 0) {
      pending_.erase(0, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      return;  // EAGAIN: the client is not reading; retry when poll() says POLLOUT
    }
  }
}

}  // namespace host
