// Host stub (see Arduino.h): the WebServer calls the sketch uses.
#pragma once

#include <Arduino.h>

#include <functional>

enum HTTPMethod { HTTP_DELETE = 0, HTTP_GET = 1, HTTP_HEAD = 2, HTTP_POST = 3, HTTP_PUT = 4,
                  HTTP_ANY = 100 };

class WebServer {
 public:
  typedef std::function<void(void)> THandlerFunction;
  explicit WebServer(int port = 80);
  void begin();
  void handleClient();
  WebServer& on(const String& uri, HTTPMethod method, THandlerFunction fn);
  void onNotFound(THandlerFunction fn);
  String arg(const String& name);
  bool hasArg(const String& name) const;
  void send(int code, const char* content_type = nullptr, const String& content = String());
};
