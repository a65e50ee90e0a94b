#include "rtamp/sim/session.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "rtamp/sim/action_check.hpp"
#include "rtamp/util/format.hpp"

namespace rtamp::sim {

namespace {

SessionOptions seeded(SessionOptions o, const world::Scenario& s) {
  o.perception.seed = o.seed * 2654435761u + 1;
  o.person.seed = o.seed * 40503u + 7;
  if (o.scripted_operator)
    o.person.script.insert(o.person.script.end(), s.interventions.begin(), s.interventions.end());
  return o;
}

// An action as the list syntax writes it: its text, or (built in code, no
// text) its words, so that a check's columns point into it.
SimAction written(SimAction a) {
  if (!a.text.empty()) return a;
  switch (a.kind) {
    case SimAction::Kind::Move:
      a.text = "move " + a.thing + " " + a.location;
      break;
    case SimAction::Kind::Pick:
      a.text = "pick " + a.thing;
      break;
    case SimAction::Kind::Place:
      a.text = "place " + a.location;
      break;
    case SimAction::Kind::Wait:
      a.text = "wait " + format_number(a.seconds);
      break;
  }
  return a;
}

}  // namespace

std::vector<SimAction> parse_actions(const std::string& text) {
  std::vector<SimAction> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(';', start);
    if (end == std::string::npos) end = text.size();
    // Words with their columns.
    std::vector<std::pair<std::string, int>> words;
    std::size_t i = start;
    while (i < end) {
      while (i < end && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      std::size_t j = i;
      while (j < end && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j > i) words.emplace_back(text.substr(i, j - i), static_cast<int>(i) + 1);
      i = j;
    }
    if (!words.empty()) {
      SimAction a;
      a.column = words[0].second;
      a.text = text.substr(static_cast<std::size_t>(a.column - 1), end - static_cast<std::size_t>(a.column - 1));
      while (!a.text.empty() && std::isspace(static_cast<unsigned char>(a.text.back()))) a.text.pop_back();
      const std::string& verb = words[0].first;
      auto want = [&](std::size_t n, const char* usage) {
        if (words.size() != n)
          throw Error(std::string("'") + verb + "' takes " + std::to_string(n - 1) + " argument" +
                          (n == 2 ? "" : "s") + ": " + usage,
                      {"--do", 1, a.column}, caret_line(text, a.column));
      };
      if (verb == "move") {
        want(3, "move THING LOCATION");
        a.kind = SimAction::Kind::Move, a.thing = words[1].first, a.location = words[2].first;
      } else if (verb == "pick") {
        want(2, "pick THING");
        a.kind = SimAction::Kind::Pick, a.thing = words[1].first;
      } else if (verb == "place") {
        want(2, "place LOCATION");
        a.kind = SimAction::Kind::Place, a.location = words[1].first;
      } else if (verb == "wait") {
        want(2, "wait SECONDS");
        a.kind = SimAction::Kind::Wait;
        char* e = nullptr;
        a.seconds = std::strtod(words[1].first.c_str(), &e);
        if (!e || *e || !std::isfinite(a.seconds) || a.seconds < 0 || a.seconds > 3600)
          throw Error("'" + words[1].first + "' is not a duration in seconds (0 to 3600)",
                      {"--do", 1, words[1].second}, caret_line(text, words[1].second));
      } else {
        throw Error("unknown action '" + verb + "' (expected move, pick, place or wait)", {"--do", 1, a.column},
                    caret_line(text, a.column));
      }
      out.push_back(std::move(a));
    }
    start = end + 1;
  }
  return out;
}

Session::Session(const world::Scenario& scenario, SessionOptions options)
    : options_(seeded(std::move(options), scenario)),
      sim_(scenario, options_.sim),
      controller_(sim_, options_.controller),
      runner_(sim_, controller_, options_.skills),
      perception_(sim_, options_.perception),
      truth_(sim_, {}),
      operator_(sim_),
      person_(scenario, options_.person) {
  if (!options_.video_path.empty()) {
    renderer_ = std::make_unique<Renderer>(sim_, options_.render);
    video_ = std::make_unique<VideoWriter>(options_.video_path, renderer_->width(), renderer_->height(),
                                           options_.video_fps);
  }
  on_step_ = [this] { after_step(); };
}

Session::~Session() = default;

world::Placement Session::true_placement() { return truth_.observe().placement(); }

void Session::after_step() {
  perception_.advance();
  if (person_.next_time() <= sim_.time())
    while (auto iv = person_.due(sim_.time(), true_placement())) events_.push_back(operator_.apply(*iv));
  if (video_ && sim_.time() >= next_frame_) {
    renderer_->render(frame_);
    video_->add(frame_);
    next_frame_ += 1.0 / options_.video_fps;
  }
}

world::Vocabulary Session::vocabulary() const {
  world::Vocabulary v(sim_.scenario(), options_.scripted_operator);
  for (const Thing& t : sim_.things()) {
    if (t.name.empty() || v.is_thing(t.name)) continue;
    (t.container ? v.containers : v.objects).push_back(t.name);
    auto& classes = t.container ? v.container_classes : v.object_classes;
    if (std::find(classes.begin(), classes.end(), t.cls) == classes.end()) classes.push_back(t.cls);
  }
  return v;
}

ActionResult Session::execute(const SimAction& a) {
  SimAction one = written(a);
  one.column = 1;
  check_actions({one}, vocabulary(), one.text, "action");
  return run_action(a);
}

ActionResult Session::run_action(const SimAction& a) {
  ActionResult r;
  r.action = a.text;
  r.start = sim_.time();
  auto finish = [&] {
    r.status = controller_.status();
    r.reason = controller_.reason();
    r.duration = sim_.time() - r.start;
    return r;
  };
  switch (a.kind) {
    case SimAction::Kind::Move: {
      ActionResult m = runner_.move(a.thing, a.location, on_step_);
      m.action = a.text;
      return m;
    }
    case SimAction::Kind::Pick:
      if (runner_.start_pick(a.thing)) {
        r.cost = controller_.plan().cost;
        runner_.run_controller(on_step_);
      }
      return finish();
    case SimAction::Kind::Place:
      if (runner_.start_place(a.location)) {
        r.cost = controller_.plan().cost;
        runner_.run_controller(on_step_);
      }
      return finish();
    case SimAction::Kind::Wait: {
      const int n = static_cast<int>(std::lround(a.seconds / sim_.timestep()));
      for (int k = 0; k < n; ++k) {
        sim_.step();
        after_step();
      }
      r.status = Status::Success;
      r.duration = sim_.time() - r.start;
      return r;
    }
  }
  return r;
}

SessionReport Session::run(const std::vector<SimAction>& actions,
                           const std::function<void(const ActionResult&)>& on_action) {
  // Every action checked before the first one moves, at its column in the
  // list written out again.
  {
    std::vector<SimAction> listed;
    std::string text;
    for (const SimAction& given : actions) {
      SimAction& a = listed.emplace_back(written(given));
      if (!text.empty()) text += "; ";
      a.column = static_cast<int>(text.size()) + 1;
      text += a.text;
    }
    check_actions(listed, vocabulary(), text, "actions");
  }
  SessionReport rep;
  const double t0 = sim_.time();
  const auto w0 = std::chrono::steady_clock::now();
  for (const auto& a : actions) {
    rep.actions.push_back(run_action(a));
    if (on_action) on_action(rep.actions.back());
  }
  rep.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  rep.sim_time = sim_.time() - t0;
  rep.final_percept = perception_.observe();
  rep.interventions = events_;
  rep.warnings = sim_.warnings();
  if (video_) {
    rep.video_frames = video_->frames();
    video_->close();
    video_.reset();
  }
  return rep;
}

void Session::snapshot(const std::string& png_path) {
  if (!renderer_) renderer_ = std::make_unique<Renderer>(sim_, options_.render);
  renderer_->render(frame_);
  write_png(png_path, frame_, renderer_->width(), renderer_->height());
}

}  // namespace rtamp::sim
