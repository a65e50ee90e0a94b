// A live episode served for a test: the symbolic world (deterministic, inline
// planning, seed 7) run by a LiveEpisode behind a Server on 127.0.0.1 and a
// free port; the episode's thread ends before the server goes (replies may be
// on their way). temp_dir() gives each test its own scratch directory.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include "rtamp/episode/episode.hpp"
#include "rtamp/serve/live_episode.hpp"
#include "rtamp/serve/server.hpp"

namespace rtamp::serve::test {

inline std::filesystem::path temp_dir(const std::string& name) {
  const std::filesystem::path d =
      std::filesystem::temp_directory_path() / ("rtamp_serve_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::create_directories(d);
  return d;
}

inline episode::EpisodeOptions symbolic_options(const std::string& log = {}) {
  episode::EpisodeOptions o;
  o.world = "symbolic";
  o.loop.planning = exec::PlanningMode::Inline;
  o.seed = 7;
  o.loop.max_time = 300;
  o.outputs.log = log;
  return o;
}

struct Served {
  LiveEpisode episode;
  Server server;
  Served(const world::Scenario& s, LiveOptions o, ServerOptions so = {})
      : episode(s, std::move(o)), server([&so] {
          so.port = 0;
          return so;
        }(), episode) {
    server.start();
    episode.start();
  }
  ~Served() {
    episode.stop();
    episode.wait();
  }
  unsigned short port() const { return server.port(); }
};

}  // namespace rtamp::serve::test
