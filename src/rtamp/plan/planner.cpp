#include "rtamp/plan/planner.hpp"

#include <algorithm>

#include "rtamp/automata/translate.hpp"
#include "rtamp/world/change.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/propositions.hpp"

namespace rtamp::plan {

namespace {
std::optional<world::PropExpr> parse_atom(const std::string& atom) {
  try {
    return world::parse_prop_expr(atom);
  } catch (const Error&) {
    return std::nullopt;
  }
}
}  // namespace

// ---- Planner ---------------------------------------------------------------

Planner::Planner(world::Scenario scenario, PlannerOptions options)
    : scenario_(std::move(scenario)), options_(std::move(options)) {
  if (scenario_.task.empty()) throw Error("the scenario has no task", scenario_.task_where);
  task::validate_task(scenario_);  // every atom names a proposition or a valid expression
  formula_ = ltl::parse(scenario_.task, scenario_.task_where);
  ba_ = automata::translate(formula_);
  init();
}

Planner::Planner(world::Scenario scenario, automata::Automaton automaton, PlannerOptions options)
    : scenario_(std::move(scenario)), options_(std::move(options)), ba_(std::move(automaton)) {
  init();
}

Planner::~Planner() = default;

void Planner::init() {
  ba_starts_.assign(1, ba_.initial);
  model_ = options_.model ? options_.model : make_cost_model(options_.cost, scenario_);
  experience_.costs().set_depends(model_->depends());
  placement_ = world::initial_placement(scenario_);
  hand_.clear();
  rebuild();
}

void Planner::rebuild() {
  exp_heuristic_.reset();
  graph_.reset();
  experience_.forget_graph();
  lab_.reset();
  ts_ = std::make_unique<task::System>(scenario_, placement_, hand_);
  ts_->forbid_moves(forbidden_);
  lab_ = std::make_unique<task::Labeling>(*ts_, ba_.atoms, parse_atom);
  if (options_.symmetry && !(model_->depends() & kDependsThing)) ts_->set_symmetry(lab_->symmetry_groups());
  dirty_ = false;
}

const task::System& Planner::system() {
  if (dirty_) rebuild();
  return *ts_;
}

const task::Labeling& Planner::labeling() {
  if (dirty_) rebuild();
  return *lab_;
}

task::State Planner::state() {
  system();
  return ts_->encode(placement_, hand_);
}

void Planner::set_placement(world::Placement placement, std::string hand) {
  // Things added or removed by the new placement change the TS.
  bool same = placement.things.size() == placement_.things.size();
  if (same)
    for (const auto& [name, thing] : placement.things) {
      auto it = placement_.things.find(name);
      if (it == placement_.things.end() || it->second.container != thing.container) same = false;
    }
  if (!same) throw Error("set_placement: the placement names other things than the scenario (use apply())");
  placement_ = std::move(placement);
  hand_ = std::move(hand);
}

void Planner::forbid_move(const std::string& thing, const std::string& location) {
  const std::pair<std::string, std::string> m{thing, location};
  if (std::find(forbidden_.begin(), forbidden_.end(), m) != forbidden_.end()) return;
  forbidden_.push_back(m);
  dirty_ = true;
}

void Planner::clear_forbidden_moves() {
  if (forbidden_.empty()) return;
  forbidden_.clear();
  dirty_ = true;
}

void Planner::set_automaton_states(std::vector<std::uint32_t> states) {
  for (const std::uint32_t q : states)
    if (q >= ba_.num_states())
      throw Error("set_automaton_states: automaton state " + std::to_string(q) + " does not exist (the automaton has " +
                  std::to_string(ba_.num_states()) + " states)");
  std::sort(states.begin(), states.end());
  states.erase(std::unique(states.begin(), states.end()), states.end());
  ba_starts_ = std::move(states);
}

void Planner::execute(const task::Action& a) {
  system();
  const task::State next = ts_->successor(ts_->encode(placement_, hand_), a);
  placement_ = ts_->describe(next);
  hand_ = ts_->hand_name(next);
  if (hand_ == "home") hand_.clear();
}

void Planner::apply(const world::Change& c, ChangeOrigin origin) {
  using Kind = world::Change::Kind;
  world::check_change(c, scenario_);
  if (origin == ChangeOrigin::Proposed) world::check_change_room(c, scenario_, placement_);
  if (c.kind == Kind::Remove || c.kind == Kind::RemoveContainer)
    if (ts_)
      if (int t = ts_->find_thing(c.subject); t >= 0) experience_.costs().forget_thing(ts_->thing_uid(static_cast<unsigned>(t)));
  world::apply_change(c, scenario_, placement_, hand_);
  // A relocation leaves the TS unchanged: the product graph and all experience stay valid.
  if (c.kind != Kind::Relocate) dirty_ = true;
}

PlanResult Planner::plan() {
  if (dirty_) rebuild();
  ts_->set_initial(ts_->encode(placement_, hand_));
  return search(*ts_, *lab_, options_.diagnose_capacity);
}

PlanResult Planner::search(task::System& ts, task::Labeling& lab, bool allow_diagnosis) {
  PlanResult res;
  const std::int64_t t0 = steady_now_ns();
  const bool exp = algorithm_info(options_.algorithm).keeps_experience && &ts == ts_.get();
  // No deadline for a limit <= 0, NaN, infinite or beyond ~30 years (it would overflow the clock).
  const double limit = options_.limits.time_limit;
  std::int64_t deadline = limit > 0 && limit < 1e9 ? t0 + static_cast<std::int64_t>(limit * 1e9) : 0;
  auto finish = [&](NoPlanReason reason, std::string message) {
    res.reason = reason;
    res.message = std::move(message);
    res.stats.seconds = double(steady_now_ns() - t0) * 1e-9;
    return res;
  };
  if (!lab.unknown_atoms().empty())
    return finish(NoPlanReason::UnknownName, "the task uses '" + lab.unknown_atoms().front() +
                                                 "', which is neither a proposition of the scenario nor a "
                                                 "proposition expression");
  std::unique_ptr<ProductGraph> cold_graph;
  std::unique_ptr<Experience> cold_experience;
  std::unique_ptr<LassoSearch> cold_search;
  ProductGraph* g = nullptr;
  Experience* x = nullptr;
  LassoSearch* ls = nullptr;
  MotionCostCache& cache = experience_.costs();
  if (exp) {
    // A kept graph that holds half the memory limit is dropped (experience
    // only speeds queries up), so that it cannot grow until every query stops.
    const std::size_t max_bytes = options_.limits.max_memory_bytes;
    if (graph_ && max_bytes && 2 * (graph_->memory_bytes() + experience_.memory_bytes()) > max_bytes) {
      exp_heuristic_.reset();
      graph_.reset();
      experience_.forget_graph();
    }
    if (!graph_) {
      auto graph = std::make_unique<ProductGraph>(ts, lab, ba_, *model_, model_->expensive() ? &cache : nullptr);
      exp_heuristic_ = algorithm_info(options_.algorithm).make_heuristic(*graph, experience_);  // may throw
      graph_ = std::move(graph);
    }
    g = graph_.get();
    x = &experience_;
    ls = &search_;
    cache.reset_counters();
  } else {
    cold_graph = std::make_unique<ProductGraph>(ts, lab, ba_, *model_, nullptr);
    cold_experience = std::make_unique<Experience>();
    cold_search = std::make_unique<LassoSearch>();
    g = cold_graph.get();
    x = cold_experience.get();
    ls = cold_search.get();
  }
  if (ba_.num_states() == 0 || !g->useful(ba_.initial))
    return finish(NoPlanReason::Unsatisfiable, "the task is unsatisfiable: its Büchi automaton accepts no word");
  const std::size_t before = g->size();
  std::vector<NodeId> starts;
  for (const std::uint32_t q : ba_starts_)
    if (g->useful(q)) starts.push_back(g->find_or_add(ts.canonical(ts.initial()), q));
  if (starts.empty()) {
    std::string list;
    for (const std::uint32_t q : ba_starts_) list += (list.empty() ? "" : ", ") + std::to_string(q);
    return finish(NoPlanReason::NoAcceptingCycle,
                  "no accepting lasso is possible: from none of the automaton states the run is in {" + list +
                      "} can the automaton still reach an accepting cycle");
  }
  res.stats.reused_nodes = before;
  bool hit_node = false, hit_time = false, hit_memory = false;
  std::uint64_t built = 0;  // nodes the full construction expanded
  if (options_.graph == GraphConstruction::Full) {
    const std::int64_t c0 = steady_now_ns();
    const std::uint64_t built0 = g->expansions();
    std::function<void(std::int64_t)> tick;
    if (options_.limits.on_progress) {
      std::int64_t next = c0 + options_.limits.progress_interval_ns();
      tick = [&, next](std::int64_t now) mutable {
        if (now < next) return;
        next = now + options_.limits.progress_interval_ns();
        SearchProgress p;
        p.phase = "constructing";
        p.graph_nodes = g->size();
        p.seconds = double(now - t0) * 1e-9;
        options_.limits.on_progress(p);
      };
    }
    if (!g->expand_all(starts, options_.limits.max_nodes, deadline, tick, options_.limits.max_memory_bytes)) {
      if (g->size() >= options_.limits.max_nodes) hit_node = true;
      else if (deadline && steady_now_ns() > deadline) hit_time = true;
      else hit_memory = true;
    }
    built = g->expansions() - built0;
    res.stats.construction_seconds = double(steady_now_ns() - c0) * 1e-9;
  }
  LassoResult r;
  const std::uint64_t exp0 = g->expansions();
  if (!hit_node && !hit_time && !hit_memory) {
    std::unique_ptr<Heuristic> h;
    Heuristic* hp = nullptr;
    if (exp) {
      hp = exp_heuristic_.get();
    } else {
      h = algorithm_info(options_.algorithm).make_heuristic(*g, *x);
      hp = h.get();
    }
    const bool astar = options_.algorithm != Algorithm::Dijkstra;
    SearchLimits limits = options_.limits;
    if (limits.on_progress) {  // the search counts from its own start; report from the query's
      const double offset = double(steady_now_ns() - t0) * 1e-9;
      limits.on_progress = [this, offset](SearchProgress p) {
        p.seconds += offset;
        options_.limits.on_progress(p);
      };
    }
    r = ls->run(*g, *x, starts, *hp, LassoConfig{astar, exp}, Termination{limits, deadline}, res.stats);
    hit_node = r.hit_node_limit;
    hit_time = r.hit_time_limit;
    hit_memory = r.hit_memory_limit;
  }
  res.stats.successor_generations = g->expansions() - exp0;
  res.stats.generated = g->size() - before;
  res.stats.graph_nodes = g->size();
  res.stats.graph_edges = g->num_edges();
  res.stats.hit_node_limit = hit_node;
  res.stats.hit_time_limit = hit_time;
  res.stats.hit_memory_limit = hit_memory;
  if (exp && model_->expensive()) {
    res.stats.cache_used = true;
    res.stats.cache_hits = cache.hits();
    res.stats.cache_misses = cache.misses();
  }
  res.stats.memory_bytes =
      g->memory_bytes() + x->memory_bytes() + ls->memory_bytes() + (res.stats.cache_used ? cache.bytes() : 0);
  if (r.found) {
    res.found = true;
    Plan& p = res.plan;
    // Replay the (canonical) path on concrete states: a move of a group
    // member at location a becomes a move of the lowest-numbered member of
    // that group that is at a in the concrete state.
    task::State concrete = ts.initial();
    auto add_steps = [&](NodeId cur, const std::vector<std::uint32_t>& edges, std::vector<Step>& out) {
      for (std::uint32_t e : edges) {
        const ProductEdge& pe = g->edge(e);
        task::Action a = task::Action::unpack(pe.action);
        if (!a.is_stay() && ts.group_of(a.thing) >= 0) {
          const std::uint32_t at = ts.location(g->state(cur), a.thing);
          for (unsigned t = 0; t < ts.num_things(); ++t)
            if (ts.group_of(t) == ts.group_of(a.thing) && ts.location(concrete, t) == at) {
              a.thing = static_cast<std::uint16_t>(t);
              break;
            }
        }
        Step st;
        st.action = a;
        st.from = concrete;
        concrete = ts.successor(concrete, a);
        st.to = concrete;
        st.ba_from = g->ba_state(cur);
        st.ba_to = g->ba_state(pe.dst);
        st.cost = pe.cost;
        st.label = g->label(cur);
        out.push_back(st);
        cur = pe.dst;
      }
    };
    p.prefix.reserve(r.prefix_edges.size());
    p.cycle.reserve(r.cycle_edges.size());
    add_steps(r.start, r.prefix_edges, p.prefix);
    add_steps(r.cycle_start, r.cycle_edges, p.cycle);
    p.prefix_cost = r.prefix_cost;
    p.cycle_cost = r.cycle_cost;
    res.stats.seconds = double(steady_now_ns() - t0) * 1e-9;
    return res;
  }
  // A limit says nothing about whether a plan exists: the message says so,
  // and how far the query got.
  const bool in_construction = res.stats.expanded == 0 && built > 0;
  const std::string stopped = in_construction ? "the full construction stopped at its " : "the search stopped at its ";
  const std::uint64_t expansions = in_construction ? built : res.stats.expanded;
  const std::string after = " after " + format_count(expansions) + (expansions == 1 ? " expansion (" : " expansions (") +
                            format_count(res.stats.graph_nodes) + " graph nodes, " +
                            format_bytes(double(res.stats.memory_bytes)) + "); whether a plan exists is unknown";
  if (hit_node)
    return finish(NoPlanReason::NodeLimit,
                  stopped + "node limit (" + format_count(options_.limits.max_nodes) + " nodes)" + after);
  if (hit_memory)
    return finish(NoPlanReason::MemoryLimit,
                  stopped + "memory limit (" + format_bytes(double(options_.limits.max_memory_bytes)) + ")" + after);
  if (hit_time)
    return finish(NoPlanReason::TimeLimit, stopped + "time limit (" + format_number(options_.limits.time_limit) +
                                               " s)" + after);
  if (allow_diagnosis) {
    task::System relaxed(scenario_, placement_, hand_, task::System::Options{true});
    task::Labeling rlab(relaxed, ba_.atoms, parse_atom);
    if (options_.symmetry && !(model_->depends() & kDependsThing)) relaxed.set_symmetry(rlab.symmetry_groups());
    PlannerOptions saved = options_;
    options_.algorithm = Algorithm::AStar;
    options_.graph = GraphConstruction::Partial;
    PlanResult rr;
    try {
      rr = search(relaxed, rlab, false);
    } catch (...) {  // e.g. a cost model's bad value: the options stay the user's
      options_ = std::move(saved);
      throw;
    }
    options_ = std::move(saved);
    if (rr.found)
      return finish(NoPlanReason::Capacity,
                    "no plan within the capacities of the locations (there is one if capacities are ignored)");
  }
  return finish(NoPlanReason::NoAcceptingCycle,
                "no accepting lasso is reachable from the current state: the task cannot be achieved from here");
}

const char* to_string(NoPlanReason r) {
  switch (r) {
    case NoPlanReason::None: return "none";
    case NoPlanReason::Unsatisfiable: return "unsatisfiable";
    case NoPlanReason::NoAcceptingCycle: return "no-accepting-cycle";
    case NoPlanReason::Capacity: return "capacity";
    case NoPlanReason::UnknownName: return "unknown-name";
    case NoPlanReason::NodeLimit: return "node-limit";
    case NoPlanReason::TimeLimit: return "time-limit";
    case NoPlanReason::MemoryLimit: return "memory-limit";
  }
  return "?";
}

}  // namespace rtamp::plan
