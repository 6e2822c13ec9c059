// A tiny HTTP/1.1 server on 127.0.0.1 for the host firmware: POST /api/command only.
//
// Non-blocking and single-threaded: the main loop polls the descriptors from
// poll_fds() together with the pty and hands the results to service(). One request per
// connection (the response says Connection: close); bodies need Content-Length (no
// chunked encoding); headers up to 8 KiB, bodies up to 4 KiB; a connection that has not
// sent a whole request within 5 s gets 408 and is closed. At most 16 connections at once
// (more wait in the listen backlog). Every error answer is JSON {"error": ...}.
#pragma once

#include <poll.h>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "../src/protocol.h"

namespace host {

class HttpServer {
 public:
  using Handler = std::function<trs::HttpResponse(std::string_view body)>;

  HttpServer() = default;
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;
  ~HttpServer();

  // Listens on 127.0.0.1:port (0 = any free port).
  bool listen(int port, std::string* error);
  int port() const { return port_; }

  // Appends this server's descriptors to `fds`.
  void poll_fds(std::vector<pollfd>* fds) const;
  // Handles what poll() reported for the descriptors added at fds[first..]; `now_ms` is
  // a monotonic clock.
  void service(const std::vector<pollfd>& fds, std::size_t first, int64_t now_ms,
               const Handler& handler);

 private:
  struct Connection {
    int fd = -1;
    int64_t deadline_ms = 0;
    std::string in;
    std::string out;
    std::size_t sent = 0;
    bool responding = false;
  };

  void accept_all(int64_t now_ms);
  void read_request(Connection* c, const Handler& handler);
  // Parses c->in; true once a response is queued, false while the request is incomplete.
  bool answer(Connection* c, const Handler& handler);
  void respond(Connection* c, int status, const std::string& json,
               const char* extra_headers = "");
  // Sends an error answer if the socket takes it at once, then marks `c` for closing.
  void give_up(Connection* c, int status, const std::string& message);

  static constexpr std::size_t kMaxConnections = 16;
  static constexpr std::size_t kMaxHeader = 8192;
  static constexpr std::size_t kMaxBody = 4096;
  static constexpr int64_t kTimeoutMs = 5000;

  int listen_fd_ = -1;
  int port_ = 0;
  std::vector<Connection> connections_;
};

}  // namespace host
