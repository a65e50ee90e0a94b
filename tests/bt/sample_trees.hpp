// A sample tree for the export/import tests: every node kind of the engine,
// names that need XML escaping, a port only one instance has, empty controls.
#pragma once

#include <chrono>
#include <memory>

#include "probes.hpp"
#include "rtamp/bt/bt.hpp"

namespace rtamp::bt::testing {

// A tree using every node type, with names that need escaping.
inline std::unique_ptr<Node> every_node_type(Probe& p) {
  auto root = std::make_unique<ReactiveSequence>("root <&> \"quoted\"");
  auto chooser = std::make_unique<Chooser>("o1: r1 -> r2");
  auto post = std::make_unique<Sequence>("post");
  auto at = std::make_unique<Condition>(
      "o1 in r2", [] { return false; }, "ObjectAt");
  at->set_port("object", "o1", "the object");
  at->set_port("region", "r2");
  post->add(std::move(at));
  auto pre = std::make_unique<Sequence>("pre+act");
  auto at2 = std::make_unique<Condition>(
      "o1 in r1", [] { return true; }, "ObjectAt");
  at2->set_port("object", "o1");
  at2->set_port("region", "r1");
  at2->set_port("tolerance", "0.01");  // a port only this instance has
  pre->add(std::move(at2));
  auto move = probe_action("move o1", p, "MoveObject");
  move->set_port("object", "o1");
  move->set_port("from", "r1");
  move->set_port("to", "r2");
  auto update = std::make_unique<StateUpdate>(
      "update", [](Node&) {}, std::move(move));
  update->set_port("effect", "o1@r2");
  pre->add(std::make_unique<Timeout>("limit", std::chrono::milliseconds(1500),
                                     std::make_unique<Retry>("again", 3, std::move(update))));
  chooser->add(std::move(post));
  chooser->add(std::move(pre));
  root->add(std::move(chooser));
  auto par = std::make_unique<Parallel>("watch", 2, -1);
  par->add(std::make_unique<Inverter>(probe_action("i", p)));
  par->add(make<Fallback>("fb", probe_action("x", p)));
  par->add(std::make_unique<ReactiveFallback>("empty rf"));
  root->add(std::move(par));
  root->add(std::make_unique<Sequence>("empty seq"));
  return root;
}

}  // namespace rtamp::bt::testing
