#include "rtamp/serve/client_session.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <string>

#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

namespace rtamp::serve {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

class WsSession final : public Client, public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(tcp::socket&& socket, Hub& hub, RequestHandler& handler, const ClientLimits& limits)
      : ws_(std::move(socket)), hub_(hub), handler_(handler), limits_(limits), tokens_(limits.burst),
        refill_(std::chrono::steady_clock::now()) {}

  void run(beast::http::request<beast::http::string_body> req) {
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.read_message_max(limits_.max_frame);
    ws_.async_accept(req, [self = shared_from_this()](beast::error_code ec) { self->on_accept(ec); });
  }

  void send(std::shared_ptr<const std::string> message, Slot slot) override {
    hub_.count_unsent(1);
    net::post(ws_.get_executor(), [self = shared_from_this(), m = std::move(message), slot]() mutable {
      self->enqueue(std::move(m), slot);
    });
  }

 private:
  struct Out {
    std::shared_ptr<const std::string> m;
    Slot slot;
  };

  void on_accept(beast::error_code ec) {
    if (ec) return;
    joined_ = true;
    hub_.join(shared_from_this());
    read();
  }

  void read() {
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t n) { self->on_read(ec, n); });
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    hub_.count_unsent(-static_cast<long>(queue_.size()));  // never written
    if (joined_) hub_.leave(this);
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
    beast::get_lowest_layer(ws_).close();
  }

  void reply(std::string text) {
    hub_.count_unsent(1);
    enqueue(std::make_shared<const std::string>(std::move(text)), Slot::None);
  }

  bool take_token() {
    const auto now = std::chrono::steady_clock::now();
    tokens_ = std::min(limits_.burst, tokens_ + std::chrono::duration<double>(now - refill_).count() * limits_.rate);
    refill_ = now;
    if (tokens_ < 1) return false;
    tokens_ -= 1;
    return true;
  }

  void on_read(beast::error_code ec, std::size_t n) {
    if (ec) {  // closed, too big (1009 sent by Beast), or broken
      close();
      return;
    }
    const bool text = ws_.got_text();
    std::string msg = beast::buffers_to_string(buffer_.data());
    buffer_.consume(n);
    if (!take_token()) {
      if (++refused_in_a_row_ > limits_.max_refused_in_a_row) {
        close();
        return;
      }
      reply(reply_message("null", false, "throttled: more than " + std::to_string(static_cast<int>(limits_.rate)) +
                                             " requests a second"));
    } else {
      refused_in_a_row_ = 0;
      if (!text) {
        reply(reply_message("null", false, "binary messages are not accepted (send JSON text)"));
      } else if (msg.size() > limits_.max_request) {
        reply(reply_message("null", false,
                            "message of " + std::to_string(msg.size()) + " bytes is over the limit of " +
                                std::to_string(limits_.max_request) + " bytes"));
      } else {
        const Request r = parse_request(msg);
        std::weak_ptr<WsSession> weak = shared_from_this();
        handler_.handle(r, [weak](std::string m) {
          if (auto self = weak.lock()) self->send(std::make_shared<const std::string>(std::move(m)), Slot::None);
        });
      }
    }
    if (!closed_) read();
  }

  void enqueue(std::shared_ptr<const std::string> m, Slot slot) {
    if (closed_) {
      hub_.count_unsent(-1);
      return;
    }
    // A frame replaces an unsent frame, a camera image an unsent one (not the one being written).
    if (slot != Slot::None) {
      for (std::size_t i = writing_ ? 1 : 0; i < queue_.size(); ++i)
        if (queue_[i].slot == slot) {
          queued_bytes_ -= queue_[i].m->size();
          queued_bytes_ += m->size();
          queue_[i].m = std::move(m);
          hub_.count_unsent(-1);  // the replaced one
          return;
        }
    }
    queued_bytes_ += m->size();
    queue_.push_back(Out{std::move(m), slot});
    if (queued_bytes_ > limits_.max_queued_bytes) {
      close();
      return;
    }
    if (!writing_) write();
  }

  void write() {
    writing_ = true;
    ws_.text(true);
    ws_.async_write(net::buffer(*queue_.front().m), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->on_write(ec);
    });
  }

  void on_write(beast::error_code ec) {
    writing_ = false;
    if (ec) {
      close();
      return;
    }
    queued_bytes_ -= queue_.front().m->size();
    queue_.pop_front();
    if (!closed_) hub_.count_unsent(-1);  // (close() counted the whole queue)
    if (!queue_.empty() && !closed_) write();
  }

  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
  Hub& hub_;
  RequestHandler& handler_;
  ClientLimits limits_;
  std::deque<Out> queue_;
  std::size_t queued_bytes_ = 0;
  bool writing_ = false, closed_ = false, joined_ = false;
  double tokens_;
  std::chrono::steady_clock::time_point refill_;
  int refused_in_a_row_ = 0;
};

}  // namespace

void start_client_session(tcp::socket socket, beast::http::request<beast::http::string_body> upgrade, Hub& hub,
                          RequestHandler& handler, const ClientLimits& limits) {
  std::make_shared<WsSession>(std::move(socket), hub, handler, limits)->run(std::move(upgrade));
}

}  // namespace rtamp::serve
