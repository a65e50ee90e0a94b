#include "rtamp/serve/server.hpp"

#include <filesystem>
#include <thread>

#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "rtamp/serve/client_session.hpp"
#include "rtamp/serve/hub.hpp"
#include "rtamp/serve/origin_policy.hpp"
#include "rtamp/serve/web_root.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::serve {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
namespace fs = std::filesystem;
using tcp = net::ip::tcp;

namespace {

std::string mime_type(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".html" || ext == ".htm") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json" || ext == ".map") return "application/json";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  if (ext == ".ico") return "image/x-icon";
  if (ext == ".wasm") return "application/wasm";
  if (ext == ".woff2") return "font/woff2";
  if (ext == ".txt") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket&& socket, Server::Impl& server) : stream_(std::move(socket)), server_(server) {}
  void run() { read(); }

 private:
  void read() {
    parser_.emplace();
    parser_->body_limit(64 * 1024);
    stream_.expires_after(std::chrono::seconds(30));
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }
  void on_read(beast::error_code ec);

  template <typename Body>
  void respond(http::response<Body>&& res) {
    auto sp = std::make_shared<http::response<Body>>(std::move(res));
    http::async_write(stream_, *sp, [self = shared_from_this(), sp](beast::error_code ec, std::size_t) {
      if (ec || !sp->keep_alive()) {
        beast::error_code ignored;
        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
        return;
      }
      self->read();
    });
  }
  void text(http::status status, const std::string& body, const std::string& type = "text/plain; charset=utf-8") {
    http::response<http::string_body> res{status, parser_->get().version()};
    res.set(http::field::server, "rtamp");
    res.set(http::field::content_type, type);
    res.set(http::field::cache_control, "no-store");
    res.keep_alive(parser_->get().keep_alive());
    res.body() = body;
    res.prepare_payload();
    respond(std::move(res));
  }

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  Server::Impl& server_;
};

}  // namespace

struct Server::Impl {
  ServerOptions options;
  RequestHandler* handler = nullptr;
  net::io_context ioc{1};
  tcp::acceptor acceptor{ioc};
  std::thread thread;
  WebRoot web;
  OriginPolicy policy;

  explicit Impl(ServerOptions o)
      : options(std::move(o)), web(options.web_root), policy(options.host, options.allowed_origins) {}

  void accept() {
    acceptor.async_accept(net::make_strand(ioc), [this](beast::error_code ec, tcp::socket socket) {
      if (ec == net::error::operation_aborted || !acceptor.is_open()) return;
      if (!ec) {
        // Small messages go out at once: with Nagle's algorithm a message written
        // right after another (a log record after a reply) waited for the
        // client's delayed ACK, ~40 ms.
        beast::error_code ignored;
        socket.set_option(tcp::no_delay(true), ignored);
        std::make_shared<HttpSession>(std::move(socket), *this)->run();
      }
      accept();
    });
  }
};

namespace {

void HttpSession::on_read(beast::error_code ec) {
  if (ec == http::error::end_of_stream || ec) {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
    return;
  }
  auto& req = parser_->get();
  const std::string target(req.target());
  const auto header = [&req](http::field f) -> std::optional<std::string_view> {
    const auto it = req.find(f);
    if (it == req.end()) return std::nullopt;
    return std::string_view(it->value().data(), it->value().size());
  };
  const auto host = header(http::field::host);
  if (std::string why = server_.policy.refuse_host(host); !why.empty()) {
    text(http::status::forbidden, "rtamp serve: forbidden: " + why + "\n");
    return;
  }
  if (beast::websocket::is_upgrade(req)) {
    if (target != "/ws" || req.method() != http::verb::get) {
      text(http::status::not_found, "rtamp serve: the WebSocket is at /ws\n");
      return;
    }
    if (std::string why = server_.policy.refuse_origin(header(http::field::origin), *host); !why.empty()) {
      text(http::status::forbidden, "rtamp serve: forbidden: " + why + "\n");
      return;
    }
    stream_.expires_never();
    start_client_session(stream_.release_socket(), parser_->release(), server_.handler->hub(), *server_.handler);
    return;
  }
  if (req.method() != http::verb::get && req.method() != http::verb::head) {
    text(http::status::method_not_allowed, "rtamp serve: only GET\n");
    return;
  }
  if (target == "/api/hello") {
    text(http::status::ok, server_.handler->hub().hello(), "application/json");
    return;
  }
  const WebRoot::Lookup file = server_.web.find(target);
  const std::string& path = file.path;
  if (file.outside) {
    text(http::status::forbidden, "rtamp serve: forbidden: " + target + " leads outside the page's directory\n");
    return;
  }
  if (path.empty()) {
    if ((target == "/" || target == "/index.html") && !server_.web.has_page())
      text(http::status::not_found,
           "rtamp serve: the page is not installed (no index.html in '" + server_.options.web_root +
               "'); build it (docs/serve.md) or pass --web-root DIR. The API (/api/hello) and the WebSocket (/ws) "
               "work.\n");
    else
      text(http::status::not_found, "rtamp serve: not found: " + target + "\n");
    return;
  }
  http::file_body::value_type body;
  beast::error_code fec;
  body.open(path.c_str(), beast::file_mode::scan, fec);
  if (fec) {
    text(http::status::not_found, "rtamp serve: cannot read " + target + "\n");
    return;
  }
  const auto size = body.size();
  if (req.method() == http::verb::head) {
    http::response<http::empty_body> res{http::status::ok, req.version()};
    res.set(http::field::content_type, mime_type(path));
    res.content_length(size);
    res.keep_alive(req.keep_alive());
    respond(std::move(res));
    return;
  }
  http::response<http::file_body> res{std::piecewise_construct, std::make_tuple(std::move(body)),
                                      std::make_tuple(http::status::ok, req.version())};
  res.set(http::field::server, "rtamp");
  res.set(http::field::content_type, mime_type(path));
  res.content_length(size);
  res.keep_alive(req.keep_alive());
  respond(std::move(res));
}

}  // namespace

Server::Server(ServerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  Impl& s = *impl_;
  const std::string where = s.options.host + ":" + std::to_string(s.options.port);
  beast::error_code ec;
  const auto address = net::ip::make_address(s.options.host, ec);
  if (ec) throw Error("cannot listen on " + where + ": '" + s.options.host + "' is not an IP address");
  const tcp::endpoint ep{address, s.options.port};
  s.acceptor.open(ep.protocol(), ec);
  if (!ec) s.acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) s.acceptor.bind(ep, ec);
  if (!ec) s.acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) throw Error("cannot listen on " + where + ": " + ec.message());
}

Server::~Server() { stop(); }

unsigned short Server::port() const { return impl_->acceptor.local_endpoint().port(); }

std::string Server::address() const { return impl_->acceptor.local_endpoint().address().to_string(); }

bool Server::has_page() const { return impl_->web.has_page(); }

void Server::start() {
  if (!handler_) throw Error("Server::start(): no request handler");
  start(*handler_);
}

void Server::start(RequestHandler& handler) {
  impl_->handler = &handler;
  impl_->accept();
  impl_->thread = std::thread([this] { impl_->ioc.run(); });
}

void Server::drain(std::chrono::milliseconds timeout) {
  if (!impl_ || !impl_->handler) return;
  impl_->handler->hub().flush();
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (impl_->handler->hub().unsent() > 0 && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

void Server::stop() {
  if (!impl_) return;
  Impl& s = *impl_;
  net::post(s.ioc, [&s] {
    beast::error_code ignored;
    s.acceptor.close(ignored);
  });
  s.ioc.stop();
  if (s.thread.joinable()) s.thread.join();
  if (s.handler) s.handler->hub().clear();
  s.handler = nullptr;  // stop() again (the destructor) touches nothing of it
}

}  // namespace rtamp::serve
