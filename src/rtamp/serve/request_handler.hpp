// What answers a page's requests (request.hpp) for the server: a live episode
// (live_episode.hpp) or a replay (replay.hpp). handle() is called on a server
// thread and must not block; `reply` (callable from any thread, exactly once
// per request) sends the reply message to the page that asked.
#pragma once

#include <functional>
#include <string>

#include "rtamp/serve/request.hpp"

namespace rtamp::serve {

class Hub;

class RequestHandler {
 public:
  using Reply = std::function<void(std::string message)>;
  virtual ~RequestHandler() = default;
  virtual void handle(const Request& request, Reply reply) = 0;
  virtual Hub& hub() = 0;
};

}  // namespace rtamp::serve
