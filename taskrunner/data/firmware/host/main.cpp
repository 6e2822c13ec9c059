// taskrunner-servo-host: the servo firmware with simulated servos, for tests and for
// developing the Python serial/http backends without hardware.
//
// The same protocol core as the ESP32 sketch, behind a pseudo-terminal (the "serial
// port") and a loopback HTTP server, ticking in real time (or --speedup times faster).
// Single-threaded: one poll() loop serves the pty, HTTP and the tick clock.
// stdout: line 1 the pty path, line 2 the command URL; nothing else. Diagnostics go to
// stderr. SIGTERM/SIGINT/SIGHUP end the loop; the log is flushed and the link removed.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "../src/config.h"
#include "../src/numbers.h"
#include "../src/protocol.h"
#include "http_server.h"
#include "options.h"
#include "pty_port.h"

namespace {

constexpr const char* kProgram = "taskrunner-servo-host";
// Behind by more than this many ticks (a stalled machine): skip ahead instead of
// replaying them back to back. Firmware time (tick count) stays consistent either way.
constexpr int kMaxCatchUpTicks = 10;

int g_signal_pipe[2] = {-1, -1};
volatile sig_atomic_t g_signal = 0;

void on_signal(int signo) {
  g_signal = signo;
  const int saved = errno;
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(g_signal_pipe[1], &byte, 1);
  errno = saved;
}

bool install_signal_handlers(std::string* error) {
  if (::pipe(g_signal_pipe) != 0) {
    *error = std::string("pipe: ") + std::strerror(errno);
    return false;
  }
  for (int fd : g_signal_pipe) {
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    ::fcntl(fd, F_SETFD, FD_CLOEXEC);
  }
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  for (int signo : {SIGTERM, SIGINT, SIGHUP}) {
    if (::sigaction(signo, &action, nullptr) != 0) {
      *error = std::string("sigaction: ") + std::strerror(errno);
      return false;
    }
  }
  ::signal(SIGPIPE, SIG_IGN);
  return true;
}

int64_t now_ns() {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

class TickLog {
 public:
  bool open(const std::string& path, int n_servos, std::string* error) {
    if (path.empty()) return true;
    file_ = std::fopen(path.c_str(), "w");
    if (!file_) {
      *error = "cannot write log " + path + ": " + std::strerror(errno);
      return false;
    }
    std::string header = "t_ms";
    for (int i = 1; i <= n_servos; ++i) header += ",a" + std::to_string(i);
    std::fprintf(file_, "%s\n", header.c_str());
    return true;
  }
  void write(const trs::Motion& motion) {
    if (!file_) return;
    std::string row = std::to_string(static_cast<uint64_t>(motion.ticks()) * motion.tick_ms());
    for (int i = 0; i < motion.n_servos(); ++i) {
      row.push_back(',');
      trs::append_centi(&row, motion.pos()[i]);
    }
    row.push_back('\n');
    std::fputs(row.c_str(), file_);
    std::fflush(file_);  // readable while we run
  }
  ~TickLog() {
    if (file_) std::fclose(file_);
  }

 private:
  std::FILE* file_ = nullptr;
};

// Replaces `link` with a symlink to `target`, refusing to clobber anything but a symlink.
bool make_link(const std::string& link, const std::string& target, std::string* error) {
  struct stat st {};
  if (::lstat(link.c_str(), &st) == 0) {
    if (!S_ISLNK(st.st_mode)) {
      *error = "--link " + link + " exists and is not a symlink";
      return false;
    }
    ::unlink(link.c_str());
  }
  if (::symlink(target.c_str(), link.c_str()) != 0) {
    *error = "symlink " + link + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "%s: %s\n", kProgram, message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  host::Options options;
  std::string error;
  if (!host::parse_options(argc, argv, &options, &error)) {
    std::fprintf(stderr, "%s: %s\n\n%s", kProgram, error.c_str(), host::usage());
    return 2;
  }
  if (options.help) {
    std::fputs(host::usage(), stdout);
    return 0;
  }

  trs::Config config = trs::servo_arm_config();
  config.tick_ms = options.tick_ms;
  if (!options.channels.empty()) {
    config.n_servos = static_cast<int>(options.channels.size());
    for (int i = 0; i < config.n_servos; ++i) {
      config.servos[i] = config.servos[0];
      config.servos[i].channel = static_cast<uint8_t>(options.channels[i]);
    }
  }
  // The watchdog counts firmware time, which runs `speedup` times faster than the wall
  // clock the host lives by: --watchdog-ms is wall-clock time, as on the board.
  config.watchdog_ms = 0;
  if (options.watchdog_ms > 0) {
    const double firmware_ms = options.watchdog_ms * options.speedup;
    config.watchdog_ms = static_cast<uint32_t>(
        std::min<double>(trs::kWatchdogMsMax, std::max<double>(config.tick_ms, firmware_ms)));
  }
  error = trs::check_config(config);
  if (!error.empty()) return fail("bad configuration: " + error);
  trs::Protocol protocol(config);

  if (!install_signal_handlers(&error)) return fail(error);
  host::PtyPort pty;
  if (!pty.open(&error)) return fail(error);
  host::HttpServer http;
  if (!http.listen(options.http_port, &error)) return fail(error);
  TickLog log;
  if (!log.open(options.log_path, config.n_servos, &error)) return fail(error);
  if (!options.link_path.empty() && !make_link(options.link_path, pty.slave_path(), &error)) {
    return fail(error);
  }

  std::printf("%s\nhttp://127.0.0.1:%d/api/command\n", pty.slave_path().c_str(), http.port());
  std::fflush(stdout);
  std::fprintf(stderr, "%s: serial %s, http 127.0.0.1:%d, tick %u ms, speedup %g\n", kProgram,
               pty.slave_path().c_str(), http.port(), config.tick_ms, options.speedup);

  pty.send(protocol.banner() + "\n");
  log.write(protocol.motion());

  const auto period_ns = static_cast<int64_t>(config.tick_ms * 1e6 / options.speedup);
  int64_t next_tick_ns = now_ns() + period_ns;
  const host::HttpServer::Handler on_http = [&protocol](std::string_view body) {
    return protocol.http_command(body);
  };
  std::vector<pollfd> fds;
  std::string reply;

  while (g_signal == 0) {
    fds.clear();
    fds.push_back({g_signal_pipe[0], POLLIN, 0});
    fds.push_back({pty.fd(), static_cast<short>(POLLIN | (pty.wants_write() ? POLLOUT : 0)), 0});
    const std::size_t http_first = fds.size();
    http.poll_fds(&fds);

    const int64_t wait_ns = next_tick_ns - now_ns();
    const int timeout_ms = wait_ns <= 0 ? 0 : static_cast<int>((wait_ns + 999999) / 1000000);
    if (::poll(fds.data(), fds.size(), timeout_ms) < 0 && errno != EINTR) {
      return fail(std::string("poll: ") + std::strerror(errno));
    }
    if (fds[0].revents & POLLIN) break;

    if (fds[1].revents & POLLIN) {
      char buffer[512];
      while (true) {
        const ssize_t n = ::read(pty.fd(), buffer, sizeof buffer);
        if (n <= 0) break;  // EAGAIN (or EIO between clients on some systems)
        for (ssize_t i = 0; i < n; ++i) {
          if (protocol.feed(buffer[i], &reply)) pty.send(reply + "\n");
        }
      }
    }
    if (fds[1].revents & POLLOUT) pty.flush();
    http.service(fds, http_first, now_ns() / 1000000, on_http);

    const int64_t now = now_ns();
    for (int caught_up = 0; now >= next_tick_ns; ++caught_up) {
      if (caught_up == kMaxCatchUpTicks) {
        next_tick_ns = now + period_ns;
        break;
      }
      protocol.tick();
      log.write(protocol.motion());
      next_tick_ns += period_ns;
    }
  }

  if (!options.link_path.empty()) ::unlink(options.link_path.c_str());
  std::fprintf(stderr, "%s: stopped by signal %d after %u ticks\n", kProgram,
               static_cast<int>(g_signal), protocol.motion().ticks());
  return 0;
}
