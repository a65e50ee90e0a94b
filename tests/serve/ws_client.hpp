// A WebSocket test client on Boost.Beast (the server's own library, used as a
// client): connect to 127.0.0.1:PORT/ws, send text, read JSON messages with a
// generous deadline (a missing message fails the test instead of hanging it).
// A `log` message (a batch of records) is handed on as one message per record,
// {"type":"log","record":...}, so that tests look for single records; log_messages
// counts the batches as they came. The handshake may carry an Origin and a
// Host of the test's choosing (Handshake); declined() reads a refusal.
// http_request() sends one plain HTTP request (the API, the page's files).
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <optional>
#include <utility>
#include <string>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

namespace rtamp::serve::test {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using nlohmann::json;

// What the handshake says besides the path: an Origin (none, as a program
// sends; a browser always sends its page's), a Host (default ADDRESS:PORT).
struct Handshake {
  std::optional<std::string> origin, host;
};

struct HttpAnswer {
  int status = 0;
  std::string body;
};

// One HTTP/1.1 request to 127.0.0.1:PORT with this Host header (nullopt: none).
inline HttpAnswer http_request(unsigned short port, beast::http::verb verb, const std::string& target,
                               const std::optional<std::string>& host = "127.0.0.1") {
  net::io_context ioc;
  beast::tcp_stream stream(ioc);
  stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
  beast::http::request<beast::http::string_body> req{verb, target, 11};
  if (host) req.set(beast::http::field::host, *host);
  req.prepare_payload();
  beast::http::write(stream, req);
  beast::flat_buffer b;
  beast::http::response<beast::http::string_body> res;
  beast::http::read(stream, b, res);
  return {static_cast<int>(res.result_int()), res.body()};
}

class WsClient {
 public:
  explicit WsClient(unsigned short port, const std::string& host = "127.0.0.1", const Handshake& h = {}) {
    beast::get_lowest_layer(ws_).connect(tcp::endpoint(net::ip::make_address(host), port));
    if (h.origin)
      ws_.set_option(websocket::stream_base::decorator(
          [origin = *h.origin](websocket::request_type& req) { req.set(beast::http::field::origin, origin); }));
    ws_.handshake(h.host.value_or(host + ":" + std::to_string(port)), "/ws");
  }

  // The server's answer to a handshake it declines: its status (101 if it
  // accepted it) and body. (A plain HTTP upgrade request: Beast's client does
  // not hand on a declining response.)
  static std::pair<int, std::string> declined(unsigned short port, const Handshake& h) {
    net::io_context ioc;
    beast::tcp_stream stream(ioc);
    stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
    beast::http::request<beast::http::empty_body> req{beast::http::verb::get, "/ws", 11};
    req.set(beast::http::field::host, h.host.value_or("127.0.0.1:" + std::to_string(port)));
    if (h.origin) req.set(beast::http::field::origin, *h.origin);
    req.set(beast::http::field::connection, "Upgrade");
    req.set(beast::http::field::upgrade, "websocket");
    req.set(beast::http::field::sec_websocket_version, "13");
    req.set(beast::http::field::sec_websocket_key, "dGhlIHNhbXBsZSBub25jZQ==");
    beast::http::write(stream, req);
    beast::flat_buffer b;
    beast::http::response_parser<beast::http::string_body> res;
    beast::http::read_header(stream, b, res);
    if (res.get().result() == beast::http::status::switching_protocols) return {101, ""};
    beast::http::read(stream, b, res);
    return {static_cast<int>(res.get().result_int()), res.get().body()};
  }

  // False once the connection is gone (the server dropped this client).
  bool send(const std::string& text) {
    beast::error_code ec;
    ws_.text(true);
    ws_.write(net::buffer(text), ec);
    if (ec) closed_ = true;
    return !ec;
  }
  bool send(const json& j) { return send(j.dump()); }

  // The next message, or nullopt after `deadline` (or when the connection ends).
  std::optional<json> read(std::chrono::milliseconds deadline = std::chrono::seconds(60)) {
    if (!records_.empty()) {
      json m = std::move(records_.front());
      records_.pop_front();
      return m;
    }
    beast::flat_buffer b;
    beast::error_code ec;
    bool done = false;
    ws_.async_read(b, [&](beast::error_code e, std::size_t) {
      ec = e;
      done = true;
    });
    ioc_.restart();
    ioc_.run_for(deadline);
    if (!done) {
      beast::get_lowest_layer(ws_).cancel();
      ioc_.restart();
      ioc_.run();
      return std::nullopt;
    }
    if (ec) {
      closed_ = true;
      return std::nullopt;
    }
    json m = json::parse(beast::buffers_to_string(b.data()));
    if (m.value("type", "") != "log" || !m.contains("records")) return m;
    ++log_messages;
    for (auto& r : m["records"]) records_.push_back(json{{"type", "log"}, {"record", std::move(r)}});
    if (records_.empty()) return json{{"type", "log"}, {"record", nullptr}};  // (never sent)
    json first = std::move(records_.front());
    records_.pop_front();
    return first;
  }

  // Reads until `pred` holds for a message (returned), or nullopt.
  std::optional<json> read_until(const std::function<bool(const json&)>& pred,
                                 std::chrono::milliseconds deadline = std::chrono::seconds(60)) {
    const auto end = std::chrono::steady_clock::now() + deadline;
    for (;;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      if (left.count() <= 0) return std::nullopt;
      auto m = read(left);
      if (!m) return std::nullopt;
      seen.push_back(*m);
      if (pred(*m)) return m;
    }
  }

  // The reply to request `id`.
  std::optional<json> reply(int id) {
    return read_until([id](const json& m) { return m.value("type", "") == "reply" && m["id"] == id; });
  }

  bool closed() const { return closed_; }
  void drop() { beast::get_lowest_layer(ws_).close(); }

  std::vector<json> seen;  // every message read_until has read
  int log_messages = 0;    // `log` messages read (each a batch of records)

 private:
  net::io_context ioc_;
  websocket::stream<beast::tcp_stream> ws_{ioc_};
  bool closed_ = false;
  std::deque<json> records_;  // the rest of the last `log` message's records
};

}  // namespace rtamp::serve::test
