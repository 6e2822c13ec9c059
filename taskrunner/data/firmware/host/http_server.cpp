#include "http_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "../src/json.h"

namespace host {
namespace {

bool set_nonblocking(int fd) {
  const int flags = ::fcntl(fd, F_GETFL);
  return flags >= 0 && ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

const char* reason_phrase(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 411: return "Length Required";
    case 408: return "Request Timeout";
    case 413: return "Payload Too Large";
    case 431: return "Request Header Fields Too Large";
    case 501: return "Not Implemented";
    default: return "Error";
  }
}

std::string error_json(const std::string& message) {
  return "{\"error\":" + trs::json_quote(message) + "}";
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

std::string_view strip(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return text;
}

}  // namespace

HttpServer::~HttpServer() {
  for (Connection& c : connections_) ::close(c.fd);
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

bool HttpServer::listen(int port, std::string* error) {
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
  if (listen_fd_ < 0) {
    *error = std::string("socket: ") + std::strerror(errno);
    return false;
  }
  const int one = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(static_cast<uint16_t>(port));
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    *error = "bind 127.0.0.1:" + std::to_string(port) + ": " + std::strerror(errno);
    return false;
  }
  if (::listen(listen_fd_, 16) != 0 || !set_nonblocking(listen_fd_)) {
    *error = std::string("listen: ") + std::strerror(errno);
    return false;
  }
  socklen_t len = sizeof addr;
  if (::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    *error = std::string("getsockname: ") + std::strerror(errno);
    return false;
  }
  port_ = ntohs(addr.sin_port);
  return true;
}

void HttpServer::poll_fds(std::vector<pollfd>* fds) const {
  // While full, new clients wait in the listen backlog.
  fds->push_back({listen_fd_, static_cast<short>(connections_.size() < kMaxConnections ? POLLIN : 0), 0});
  for (const Connection& c : connections_) {
    fds->push_back({c.fd, static_cast<short>(c.responding ? POLLOUT : POLLIN), 0});
  }
}

void HttpServer::accept_all(int64_t now_ms) {
  while (connections_.size() < kMaxConnections) {
    const int fd = ::accept(listen_fd_, nullptr, nullptr);
    if (fd < 0) return;  // EAGAIN or a transient error: try again on the next poll
    if (!set_nonblocking(fd)) {
      ::close(fd);
      continue;
    }
    Connection c;
    c.fd = fd;
    c.deadline_ms = now_ms + kTimeoutMs;
    connections_.push_back(std::move(c));
  }
}

void HttpServer::respond(Connection* c, int status, const std::string& json,
                         const char* extra_headers) {
  c->out = "HTTP/1.1 " + std::to_string(status) + " " + reason_phrase(status) +
           "\r\nContent-Type: application/json\r\nContent-Length: " +
           std::to_string(json.size()) + "\r\nConnection: close\r\n" + extra_headers + "\r\n" +
           json;
  c->sent = 0;
  c->responding = true;
}

void HttpServer::read_request(Connection* c, const Handler& handler) {
  char buffer[2048];
  bool peer_closed = false;
  while (c->in.size() <= kMaxHeader + kMaxBody) {
    const ssize_t n = ::recv(c->fd, buffer, sizeof buffer, 0);
    if (n > 0) {
      c->in.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0) {
      peer_closed = true;  // a client may half-close after its request
      break;
    } else if (errno == EINTR) {
      continue;
    } else if (errno == EAGAIN || errno == EWOULDBLOCK) {
      break;
    } else {
      c->deadline_ms = 0;
      return;
    }
  }
  if (!answer(c, handler) && peer_closed) {
    give_up(c, 400, "incomplete request: the connection closed before the whole body arrived");
  }
}

void HttpServer::give_up(Connection* c, int status, const std::string& message) {
  // Best effort, one non-blocking send: the client may be gone or not reading.
  respond(c, status, error_json(message));
  [[maybe_unused]] const ssize_t n = ::send(c->fd, c->out.data(), c->out.size(), MSG_NOSIGNAL);
  c->out.clear();
  c->responding = false;
  c->deadline_ms = 0;
}

bool HttpServer::answer(Connection* c, const Handler& handler) {
  const std::size_t header_end = c->in.find("\r\n\r\n");
  if (header_end == std::string::npos) {
    if (c->in.size() <= kMaxHeader) return false;  // wait for more
    respond(c, 431, error_json("request headers too large"));
    return true;
  }
  if (header_end > kMaxHeader) {
    respond(c, 431, error_json("request headers too large"));
    return true;
  }
  const std::string_view head(c->in.data(), header_end);
  const std::size_t body_start = header_end + 4;

  const std::size_t line_end = head.find("\r\n");
  const std::string_view request_line = head.substr(0, line_end);
  const std::size_t sp1 = request_line.find(' ');
  const std::size_t sp2 = request_line.find(' ', sp1 == std::string_view::npos ? 0 : sp1 + 1);
  if (sp1 == std::string_view::npos || sp2 == std::string_view::npos ||
      request_line.substr(sp2 + 1).rfind("HTTP/1.", 0) != 0) {
    respond(c, 400, error_json("malformed request line"));
    return true;
  }
  const std::string_view method = request_line.substr(0, sp1);
  std::string_view path = request_line.substr(sp1 + 1, sp2 - sp1 - 1);
  path = path.substr(0, path.find('?'));

  long content_length = -1;
  bool form_body = false;
  std::string_view rest =
      line_end == std::string_view::npos ? std::string_view() : head.substr(line_end + 2);
  while (!rest.empty()) {
    const std::size_t eol = rest.find("\r\n");
    const std::string_view line = rest.substr(0, eol);
    rest = eol == std::string_view::npos ? std::string_view() : rest.substr(eol + 2);
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string name = lower(strip(line.substr(0, colon)));
    const std::string_view value = strip(line.substr(colon + 1));
    if (name == "content-length") {
      if (value.empty() || value.size() > 9 ||
          !std::all_of(value.begin(), value.end(), [](char ch) { return ch >= '0' && ch <= '9'; })) {
        respond(c, 400, error_json("bad Content-Length"));
        return true;
      }
      content_length = std::stol(std::string(value));
    } else if (name == "content-type") {
      // Like the ESP32 WebServer: a form body is parsed as fields, not passed on as JSON.
      const std::string type = lower(value);
      form_body = type.rfind("application/x-www-form-urlencoded", 0) == 0 ||
                  type.rfind("multipart/", 0) == 0;
    } else if (name == "transfer-encoding" && lower(value) != "identity") {
      respond(c, 501, error_json("chunked bodies are not supported: send Content-Length"));
      return true;
    }
  }

  if (path != "/api/command") {
    respond(c, 404, error_json("not found: the only endpoint is POST /api/command"));
    return true;
  }
  if (method != "POST") {
    respond(c, 405, error_json("use POST /api/command with {\"cmd\": \"...\"}"),
            "Allow: POST\r\n");
    return true;
  }
  if (content_length < 0) {
    respond(c, 411, error_json("POST needs a Content-Length"));
    return true;
  }
  if (static_cast<std::size_t>(content_length) > kMaxBody) {
    respond(c, 413, error_json("body too large (max " + std::to_string(kMaxBody) + " bytes)"));
    return true;
  }
  if (c->in.size() < body_start + static_cast<std::size_t>(content_length)) return false;
  const std::string_view body(c->in.data() + body_start, static_cast<std::size_t>(content_length));
  const trs::HttpResponse response =
      body.empty() || form_body ? trs::Protocol::http_no_body() : handler(body);
  respond(c, response.status, response.body);
  return true;
}

void HttpServer::service(const std::vector<pollfd>& fds, std::size_t first, int64_t now_ms,
                         const Handler& handler) {
  if (first >= fds.size()) return;
  // fds[first] is the listener, then one entry per connection in order.
  for (std::size_t i = 0; i < connections_.size() && first + 1 + i < fds.size(); ++i) {
    Connection& c = connections_[i];
    const short revents = fds[first + 1 + i].revents;
    if (revents == 0) continue;
    if (!c.responding && (revents & (POLLIN | POLLHUP | POLLERR))) read_request(&c, handler);
    if (c.responding) {
      while (c.sent < c.out.size()) {
        const ssize_t n = ::send(c.fd, c.out.data() + c.sent, c.out.size() - c.sent, MSG_NOSIGNAL);
        if (n > 0) {
          c.sent += static_cast<std::size_t>(n);
        } else if (n < 0 && errno == EINTR) {
          continue;
        } else {
          if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) c.deadline_ms = 0;
          break;
        }
      }
      if (c.sent >= c.out.size()) {
        ::shutdown(c.fd, SHUT_WR);
        c.deadline_ms = 0;  // done: close below
      }
    }
  }
  // Time out slow clients, then close finished connections (deadline 0 = finished).
  for (Connection& c : connections_) {
    if (c.deadline_ms != 0 && now_ms >= c.deadline_ms) {
      if (c.responding) {
        c.deadline_ms = 0;  // not reading its answer: drop it
      } else {
        give_up(&c, 408, "request not complete within " + std::to_string(kTimeoutMs) + " ms");
      }
    }
  }
  connections_.erase(std::remove_if(connections_.begin(), connections_.end(),
                                    [](const Connection& c) {
                                      if (c.deadline_ms == 0) {
                                        ::close(c.fd);
                                        return true;
                                      }
                                      return false;
                                    }),
                     connections_.end());
  if (fds[first].revents & POLLIN) accept_all(now_ms);
}

}  // namespace host
