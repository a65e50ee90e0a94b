// The HTTP and WebSocket server of `rtamp serve` (docs/serve.md), on
// Boost.Beast and Boost.Asio, one I/O thread:
//  - every request first: its Host must name this server, a WebSocket
//    handshake's Origin must be the page's own or an allowed one
//    (origin_policy.hpp); others get 403 with the reason;
//  - GET / and GET /<path>: the page's files under `web_root` (web_root.hpp:
//    index.html for a directory; nothing that resolves outside it, 403); without
//    a page there, a plain-text 404 that says so (the API and the WebSocket still work);
//  - GET /api/hello: the hello message as JSON;
//  - GET /ws with an upgrade: a WebSocket client (client_session.hpp);
//  - any other method: 405; any other path: 404.
// It listens on `host` (127.0.0.1 by default: loopback only) and `port` (0:
// any free port; port() tells which). Connections never touch the episode:
// they read the Hub and hand requests to the RequestHandler.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "rtamp/serve/origin_policy.hpp"
#include "rtamp/serve/request_handler.hpp"

namespace rtamp::serve {

struct ServerOptions {
  std::string host = "127.0.0.1";
  unsigned short port = 8080;
  std::string web_root;  // the page's files ("" or missing: no page)
  std::vector<Origin> allowed_origins;  // pages of other origins that may use the WebSocket (--allow-origin)
};

class Server {
 public:
  // Binds and listens (rtamp::Error "cannot listen on HOST:PORT: WHY"), before
  // anything else starts; start() serves `handler`.
  explicit Server(ServerOptions options);
  Server(ServerOptions options, RequestHandler& handler) : Server(std::move(options)) { handler_ = &handler; }
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  unsigned short port() const;
  std::string address() const;  // the address listened on
  // Whether web_root holds the page (index.html).
  bool has_page() const;
  void start();  // the I/O thread (the handler given to the constructor)
  void start(RequestHandler& handler);
  // Waits (at most `timeout`) until every message the clients were handed is
  // written to its socket (or dropped): before stop(), so that pages get the
  // episode's last messages (`--exit-at-end`).
  void drain(std::chrono::milliseconds timeout);
  void stop();   // closes every connection and joins the thread

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  RequestHandler* handler_ = nullptr;
};

}  // namespace rtamp::serve
