// Existence of an accepting lasso by reachability and Tarjan's SCCs
// (plan/lasso_exists.hpp has the definition and why dropping the hand is exact).
#include "rtamp/plan/lasso_exists.hpp"

#include <algorithm>

#include "rtamp/plan/termination.hpp"

namespace rtamp::plan {

namespace {

struct Key {
  task::State s;
  std::uint32_t q = 0;
  friend bool operator==(const Key&, const Key&) = default;
};


constexpr std::uint32_t kUnvisited = 0xffffffffu;

class Explorer {
 public:
  Explorer(const task::System& ts, const task::Labeling& lab, const automata::Automaton& ba)
      : ts_(ts), lab_(lab), ba_(ba), words_(ts.layout().words), table_(1024, kUnvisited) {}

  // The id of (s, q), added if new (s without its hand).
  std::uint32_t node(task::State s, std::uint32_t q) {
    ts_.layout().set(s, ts_.hand_field(), 0);
    const Key k{s, q};
    std::size_t mask = table_.size() - 1;
    std::size_t i = task::hash_words(s.words.data(), words_, q) & mask;
    for (; table_[i] != kUnvisited; i = (i + 1) & mask)
      if (keys_[table_[i]] == k) return table_[i];
    const auto id = static_cast<std::uint32_t>(keys_.size());
    keys_.push_back(k);
    index_.push_back(kUnvisited);
    scc_of_.push_back(kUnvisited);
    low_.push_back(0);
    on_stack_.push_back(false);
    table_[i] = id;
    if (2 * keys_.size() > table_.size()) grow();
    return id;
  }

  // Successor ids of n into succ (stay, then moves; every BA successor).
  void successors(std::uint32_t n, std::vector<std::uint32_t>& succ) {
    succ.clear();
    const Key k = keys_[n];
    const automata::Letter l = lab_.label(k.s);
    qs_.clear();
    for (const auto& e : ba_.edges[k.q])
      if (e.guard.matches(l) && std::find(qs_.begin(), qs_.end(), e.dst) == qs_.end()) qs_.push_back(e.dst);
    if (qs_.empty()) return;
    for (const std::uint32_t q2 : qs_) succ.push_back(node(k.s, q2));
    ts_.for_each_move(k.s, [&](const task::Action& a) {
      const task::State s2 = ts_.canonical_successor(k.s, a);
      for (const std::uint32_t q2 : qs_) succ.push_back(node(s2, q2));
    });
  }

  // The sets the edges inside the SCC of `root` (its members in members_,
  // scc_of_ set) carry between them; every successor of a member is known.
  automata::Marks inside_marks(std::uint32_t root) {
    automata::Marks inside = 0;
    for (const std::uint32_t v : members_) {
      const Key k = keys_[v];
      const automata::Letter l = lab_.label(k.s);
      for (const auto& e : ba_.edges[k.q]) {
        if (!e.guard.matches(l)) continue;
        const automata::Marks em = ba_.cycle_marks(e);
        if ((inside & em) == em) continue;
        if (scc_of_[node(k.s, e.dst)] == root) inside |= em;
        ts_.for_each_move(k.s, [&](const task::Action& a) {
          if (scc_of_[node(ts_.canonical_successor(k.s, a), e.dst)] == root) inside |= em;
        });
      }
    }
    return inside;
  }

  LassoExistence run(const std::vector<std::uint32_t>& starts, std::size_t max_nodes, std::int64_t deadline_ns) {
    LassoExistence r;
    const task::State s0 = ts_.canonical(ts_.initial());
    std::vector<std::uint32_t> roots;
    for (const std::uint32_t q : starts)
      if (q < ba_.num_states()) roots.push_back(node(s0, q));
    struct Frame {
      std::uint32_t n;
      std::uint32_t next;  // index into its successor list
      bool self_loop;
    };
    std::vector<Frame> frames;
    std::vector<std::vector<std::uint32_t>> succ_of;  // per frame depth, reused
    std::vector<std::uint32_t> scc_stack;
    std::uint32_t counter = 0;
    std::uint64_t steps = 0;
    auto push = [&](std::uint32_t n) {
      index_[n] = low_[n] = counter++;
      scc_stack.push_back(n);
      on_stack_[n] = true;
      if (succ_of.size() <= frames.size()) succ_of.emplace_back();
      successors(n, succ_of[frames.size()]);
      ++r.expansions;
      frames.push_back({n, 0, false});
    };
    for (const std::uint32_t root : roots) {
      if (index_[root] != kUnvisited) continue;
      push(root);
      while (!frames.empty()) {
        if ((++steps & 4095) == 0 &&
            ((max_nodes && keys_.size() >= max_nodes) || (deadline_ns && steady_now_ns() > deadline_ns))) {
          r.stopped = true;
          r.nodes = keys_.size();
          return r;
        }
        Frame& f = frames.back();
        const std::vector<std::uint32_t>& succ = succ_of[frames.size() - 1];
        if (f.next < succ.size()) {
          const std::uint32_t m = succ[f.next++];
          if (m == f.n) f.self_loop = true;
          if (index_[m] == kUnvisited) {
            push(m);  // invalidates f
          } else if (on_stack_[m]) {
            low_[f.n] = std::min(low_[f.n], index_[m]);
          }
          continue;
        }
        // All successors done: close n.
        const std::uint32_t n = f.n;
        const bool self_loop = f.self_loop;
        frames.pop_back();
        if (!frames.empty()) low_[frames.back().n] = std::min(low_[frames.back().n], low_[n]);
        if (low_[n] != index_[n]) continue;
        bool accepting = false, cyclic = self_loop;
        members_.clear();
        std::uint32_t m;
        do {
          m = scc_stack.back();
          scc_stack.pop_back();
          on_stack_[m] = false;
          scc_of_[m] = n;
          accepting = accepting || ba_.is_accepting_state(keys_[m].q);
          members_.push_back(m);
        } while (m != n);
        if (members_.size() > 1) cyclic = true;
        if (cyclic && !ba_.state_based) accepting = inside_marks(n) == ba_.cycle_marks_all();
        if (accepting && cyclic) {
          r.exists = true;
          r.nodes = keys_.size();
          return r;
        }
      }
    }
    r.nodes = keys_.size();
    return r;
  }

 private:
  // Doubles the open-addressing table of ids (load <= 1/2, linear probing).
  void grow() {
    table_.assign(table_.size() * 2, kUnvisited);
    const std::size_t mask = table_.size() - 1;
    for (std::uint32_t id = 0; id < keys_.size(); ++id) {
      std::size_t i = task::hash_words(keys_[id].s.words.data(), words_, keys_[id].q) & mask;
      while (table_[i] != kUnvisited) i = (i + 1) & mask;
      table_[i] = id;
    }
  }

  const task::System& ts_;
  const task::Labeling& lab_;
  const automata::Automaton& ba_;
  unsigned words_;
  std::vector<std::uint32_t> table_;  // node ids, kUnvisited: empty
  std::vector<Key> keys_;
  std::vector<std::uint32_t> index_, low_;
  std::vector<bool> on_stack_;
  std::vector<std::uint32_t> scc_of_;  // the root of a closed node's SCC
  std::vector<std::uint32_t> members_;  // the SCC being closed
  std::vector<std::uint32_t> qs_;
};

}  // namespace

LassoExistence find_accepting_lasso(const task::System& ts, const task::Labeling& lab, const automata::Automaton& ba,
                                    const std::vector<std::uint32_t>& starts, std::size_t max_nodes,
                                    std::int64_t deadline_ns) {
  Explorer e(ts, lab, ba);
  return e.run(starts, max_nodes, deadline_ns);
}

}  // namespace rtamp::plan
