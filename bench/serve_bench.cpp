// `rtamp serve`'s cost (the bars in docs/benchmarks.md):
//
//   BM_ServeOverhead/W/C   one whole episode of 3-block-tray per iteration, at
//                          speed 0 (as fast as possible: a paced episode's wall
//                          time is its world time by design), W = 0 symbolic /
//                          1 MuJoCo; C = 0: run_episode, not served (the
//                          baseline); C = 1: served, no page attached; C = 2:
//                          served with one page attached that reads every
//                          message (hello, log, tree, status, 30 frames a wall
//                          second). Real time and process CPU time (every thread:
//                          loop, server, client) per episode.
//   BM_InterventionLatency/W  a served episode at real-time speed (speed 1); a
//                          page sends a relocation every 250 ms of wall time
//                          (alternately the first block to r2 and back to r1);
//                          counters: the server-side latency from receipt of the
//                          intervene message to the intervention applied in the
//                          world (the reply's server_ms): median, p90, max (ms).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <thread>

#include "../tests/serve/ws_client.hpp"
#include "rtamp/episode/episode.hpp"
#include "rtamp/serve/live_episode.hpp"
#include "rtamp/serve/server.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;
using serve::test::json;
using serve::test::WsClient;

episode::EpisodeOptions options(int world) {
  episode::EpisodeOptions o;
  o.world = world == 0 ? "symbolic" : "mujoco";
  o.loop.planning = world == 0 ? exec::PlanningMode::Inline : exec::PlanningMode::Worker;
  o.seed = 1;
  o.loop.max_time = 200;
  return o;
}

void BM_ServeOverhead(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const int world = static_cast<int>(state.range(0)), clients = static_cast<int>(state.range(1));
  int success = 0, n = 0;
  std::size_t messages = 0;
  for (auto _ : state) {
    ++n;
    if (clients == 0) {
      success += episode::run_episode(s, options(world)).success;
      continue;
    }
    serve::LiveOptions lo;
    lo.episode = options(world);
    lo.speed = 0;
    lo.paused = clients == 2;  // resumed once the page is attached
    serve::LiveEpisode live(s, lo);
    serve::Server server(serve::ServerOptions{"127.0.0.1", 0, ""}, live);
    server.start();
    live.start();
    std::thread page;
    if (clients == 2) {
      std::atomic<bool> attached{false};
      page = std::thread([&] {
        WsClient c(server.port());
        c.read();
        attached = true;
        c.send(json{{"type", "control"}, {"id", 1}, {"action", "resume"}});
        while (true) {
          auto m = c.read(std::chrono::seconds(600));
          if (!m) break;
          ++messages;
          if ((*m)["type"] == "state" && (*m)["ended"] == true) break;
        }
      });
    }
    success += live.wait().success;
    if (page.joinable()) page.join();
  }
  state.counters["success"] = static_cast<double>(success) / n;
  if (clients == 2) state.counters["messages"] = static_cast<double>(messages) / n;
}
BENCHMARK(BM_ServeOverhead)
    ->ArgsProduct({{0}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(BM_ServeOverhead)
    ->ArgsProduct({{1}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_InterventionLatency(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  std::vector<double> ms;
  for (auto _ : state) {
    serve::LiveOptions lo;
    lo.episode = options(static_cast<int>(state.range(0)));
    lo.episode.scripted_operator = false;
    lo.speed = 1;
    serve::LiveEpisode live(s, lo);
    serve::Server server(serve::ServerOptions{"127.0.0.1", 0, ""}, live);
    server.start();
    live.start();
    WsClient c(server.port());
    c.read();
    for (int i = 0; i < 40 && !live.ended(); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
      c.send(json{{"type", "intervene"}, {"id", i}, {"kind", "relocate"}, {"subject", "o1"},
                  {"location", i % 2 ? "r1" : "r2"}});
      auto r = c.reply(i);
      if (r && r->contains("server_ms")) ms.push_back((*r)["server_ms"].get<double>());
    }
    live.stop();
    live.wait();
  }
  std::sort(ms.begin(), ms.end());
  if (!ms.empty()) {
    state.counters["n"] = static_cast<double>(ms.size());
    state.counters["median_ms"] = ms[ms.size() / 2];
    state.counters["p90_ms"] = ms[ms.size() * 9 / 10];
    state.counters["max_ms"] = ms.back();
  }
}
BENCHMARK(BM_InterventionLatency)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
