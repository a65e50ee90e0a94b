// One page's WebSocket connection (docs/serve.md "WebSocket"). It joins the
// Hub (hello, then every message), reads requests and hands them to the
// RequestHandler, and writes what it is sent from its own queue:
//  - messages are text frames of one JSON object; a message over 64 KiB is
//    refused with a reply (over 1 MiB the connection is closed with 1009,
//    "message too big"); binary messages are refused;
//  - flooding: a token bucket (burst 200, 100 requests a second); a request
//    over it is refused ("throttled"); a client that keeps sending after 1000
//    refusals in a row is dropped;
//  - a slow page: frames waiting to be written are replaced by newer ones;
//    a client whose queue holds more than 16 MiB is dropped. Nothing a client
//    does blocks the episode or another client.
// All of its state lives on its strand; send() may be called from any thread.
#pragma once

#include <memory>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/beast/http/string_body.hpp>

#include "rtamp/serve/hub.hpp"
#include "rtamp/serve/request_handler.hpp"

namespace rtamp::serve {

struct ClientLimits {
  std::size_t max_request = 64 * 1024;         // bytes: refused with a reply above
  std::size_t max_frame = 1024 * 1024;         // bytes: the connection is closed above
  double rate = 100, burst = 200;              // requests a second, bucket size
  int max_refused_in_a_row = 1000;             // throttled requests before the client is dropped
  std::size_t max_queued_bytes = 16u << 20;    // a slower client is dropped
};

// Accepts the WebSocket `upgrade` request on `socket` and serves the client until it goes.
void start_client_session(boost::asio::ip::tcp::socket socket,
                          boost::beast::http::request<boost::beast::http::string_body> upgrade, Hub& hub,
                          RequestHandler& handler, const ClientLimits& limits = {});

}  // namespace rtamp::serve
