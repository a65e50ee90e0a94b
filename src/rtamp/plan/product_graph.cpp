#include "rtamp/plan/product_graph.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <stdexcept>
#include <string>

#include "rtamp/automata/accepting_cycles.hpp"
#include "rtamp/plan/cost_check.hpp"

namespace rtamp::plan {

namespace {
std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

ProductGraph::ProductGraph(const task::System& ts, const task::Labeling& labeling, const automata::Automaton& ba,
                           const MotionCostModel& model, MotionCostCache* cache)
    : ts_(&ts), lab_(&labeling), ba_(&ba), model_(&model), cache_(cache), words_(ts.layout().words) {
  if (!ba.state_based && ba.num_sets > kMaxProductSets)
    throw std::invalid_argument("ProductGraph: an automaton with " + std::to_string(ba.num_sets) +
                                " acceptance sets (at most " + std::to_string(kMaxProductSets) + ")");
  all_marks_ = ba.cycle_marks_all();
  if (std::popcount(all_marks_) >= 2) {
    union_ = std::make_unique<automata::Automaton>(ba);
    union_->num_sets = 1;
    for (auto& out : union_->edges)
      for (auto& e : out) e.marks = (e.marks & all_marks_) ? 1u : 0u;
  }
  useful_ = automata::useful_states(ba);
  on_accepting_cycle_ = automata::states_on_accepting_cycles(ba);
  table_.assign(1024, 0);
  std::size_t out = ba.num_states();
  for (const auto& edges : ba.edges) out = std::max(out, edges.size());
  succ_q_.reserve(out);
  succ_marks_.reserve(out);
}

std::uint64_t ProductGraph::hash(const std::uint64_t* w, std::uint32_t q) const {
  return task::hash_words(w, words_, q);
}

void ProductGraph::grow_table() {
  table_.assign(table_.size() * 2, 0);
  const std::size_t mask = table_.size() - 1;
  for (NodeId n = 0; n < size(); ++n) {
    std::size_t i = hash(&states_[std::size_t{n} * words_], q_[n]) & mask;
    while (table_[i]) i = (i + 1) & mask;
    table_[i] = n + 1;
  }
}

NodeId ProductGraph::find(const task::State& s, std::uint32_t q) const {
  const std::size_t mask = table_.size() - 1;
  std::size_t i = hash(s.words.data(), q) & mask;
  while (std::uint32_t id = table_[i]) {
    const NodeId n = id - 1;
    if (q_[n] == q && std::equal(s.words.begin(), s.words.begin() + words_, states_.begin() + std::size_t{n} * words_))
      return n;
    i = (i + 1) & mask;
  }
  return kNoNode;
}

NodeId ProductGraph::find_or_add(const task::State& s, std::uint32_t q) {
  if (!useful_[q]) return kNoNode;
  const std::size_t mask = table_.size() - 1;
  std::size_t i = hash(s.words.data(), q) & mask;
  while (std::uint32_t id = table_[i]) {
    const NodeId n = id - 1;
    if (q_[n] == q && std::equal(s.words.begin(), s.words.begin() + words_, states_.begin() + std::size_t{n} * words_))
      return n;
    i = (i + 1) & mask;
  }
  const NodeId n = static_cast<NodeId>(size());
  states_.insert(states_.end(), s.words.begin(), s.words.begin() + words_);
  q_.push_back(q);
  edge_begin_.push_back(kUnexpanded);
  edge_end_.push_back(kUnexpanded);
  labels_.push_back(0);
  table_[i] = n + 1;
  if (size() * 2 > table_.size()) grow_table();
  return n;
}

void ProductGraph::expand(NodeId n) {
  if (expanded(n)) return;
  ++expansions_;
  const task::State s = state(n);
  const automata::Letter l = lab_->label(s);
  labels_[n] = l;
  succ_q_.clear();
  succ_marks_.clear();
  const bool tb = !ba_->state_based;
  for (const auto& e : ba_->edges[q_[n]]) {
    if (!e.guard.matches(l) || !useful_[e.dst]) continue;
    const auto m = static_cast<std::uint8_t>(tb ? ba_->cycle_marks(e) : 0u);
    // Keep the maximal mark sets per destination: the first entry a superset
    // replaces takes it in place, other replaced ones go.
    std::size_t kept = succ_q_.size();
    bool dominated = false;
    for (std::size_t i = 0; i < succ_q_.size() && !dominated; ++i) {
      if (succ_q_[i] != e.dst) continue;
      if ((succ_marks_[i] & m) == m) dominated = true;
      else if ((succ_marks_[i] & m) == succ_marks_[i]) {
        if (kept == succ_q_.size()) {
          kept = i;
          succ_marks_[i] = m;
        } else {
          succ_q_[i] = kNoNode;  // replaced: erased below
        }
      }
    }
    if (dominated) continue;
    if (kept == succ_q_.size()) {
      succ_q_.push_back(e.dst);
      succ_marks_.push_back(m);
    } else if (std::find(succ_q_.begin(), succ_q_.end(), kNoNode) != succ_q_.end()) {
      std::size_t w = 0;
      for (std::size_t i = 0; i < succ_q_.size(); ++i)
        if (succ_q_[i] != kNoNode) {
          succ_q_[w] = succ_q_[i];
          succ_marks_[w++] = succ_marks_[i];
        }
      succ_q_.resize(w);
      succ_marks_.resize(w);
    }
  }
  const auto begin = static_cast<std::uint32_t>(edges_.size());
  if (!succ_q_.empty()) {
    const std::uint32_t stay = task::Action::stay().packed();
    for (std::uint32_t q2 : succ_q_) edges_.push_back({find_or_add(s, q2), stay, 0.0});
    ts_->for_each_move(s, [&](const task::Action& a) {
      const MotionQuery mq = MotionCostModel::query(*ts_, s, a);
      const double c = cache_ ? cache_->lookup(mq, *model_) : model_->cost(mq);
      if (!valid_cost(c)) [[unlikely]]
        throw_bad_cost(*model_, *ts_, s, a, c);
      if (c == kInf) {  // the model cannot do this move
        ++impossible_moves_;
        return;
      }
      const task::State s2 = ts_->canonical_successor(s, a);
      for (std::uint32_t q2 : succ_q_) edges_.push_back({find_or_add(s2, q2), a.packed(), c});
    });
    if (tb)  // the stays, then each move's edges, in succ_q_ order
      for (std::size_t i = begin; i < edges_.size(); ++i)
        edge_marks_.push_back(succ_marks_[(i - begin) % succ_q_.size()]);
  }
  edge_begin_[n] = begin;
  edge_end_[n] = static_cast<std::uint32_t>(edges_.size());
}

bool ProductGraph::expand_all(NodeId from, std::size_t max_nodes, std::int64_t deadline_ns,
                              const std::function<void(std::int64_t now_ns)>& tick, std::size_t max_bytes) {
  return expand_all(std::vector<NodeId>{from}, max_nodes, deadline_ns, tick, max_bytes);
}

bool ProductGraph::expand_all(const std::vector<NodeId>& from, std::size_t max_nodes, std::int64_t deadline_ns,
                              const std::function<void(std::int64_t now_ns)>& tick, std::size_t max_bytes) {
  std::vector<NodeId> queue;
  std::vector<bool> queued;
  queued.resize(size(), false);
  for (const NodeId n : from)
    if (n != kNoNode && !queued[n]) {
      queued[n] = true;
      queue.push_back(n);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const NodeId n = queue[head];
    expand(n);
    if (queued.size() < size()) queued.resize(size(), false);
    for (std::uint32_t e = edge_begin_[n]; e < edge_end_[n]; ++e) {
      const NodeId d = edges_[e].dst;
      if (!queued[d]) {
        queued[d] = true;
        queue.push_back(d);
      }
    }
    if (size() >= max_nodes) return false;
    if ((head & 255) != 0) continue;
    if (max_bytes && memory_bytes() + queue.capacity() * sizeof(NodeId) > max_bytes) return false;
    if (deadline_ns || tick) {
      const std::int64_t now = now_ns();
      if (deadline_ns && now > deadline_ns) return false;
      if (tick) tick(now);
    }
  }
  return true;
}

std::size_t ProductGraph::memory_bytes() const {
  return states_.capacity() * sizeof(std::uint64_t) + q_.capacity() * 4 + edge_begin_.capacity() * 4 +
         edge_end_.capacity() * 4 + labels_.capacity() * sizeof(automata::Letter) +
         edges_.capacity() * sizeof(ProductEdge) + edge_marks_.capacity() + table_.capacity() * 4;
}

}  // namespace rtamp::plan
