#include "rtamp/plan/planner.hpp"

#include <algorithm>

#include "rtamp/automata/degeneralize_tba.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/plan/canonical_replay.hpp"
#include "rtamp/plan/lasso_exists.hpp"
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
  translate();
  init();
}

void Planner::translate() {
  formula_ = ltl::parse(scenario_.task, scenario_.task_where);
  automata::TranslateOptions t;
  t.state_based = !options_.transition_based;
  // Generalized where it pays (PlannerOptions::generalized): a search
  // without a heuristic, on an automaton with fewer states than its one-set form.
  using G = PlannerOptions::Generalized;
  const bool may_generalize =
      options_.transition_based && (options_.generalized == G::Always || (options_.generalized == G::WhereItPays &&
                                                                           options_.algorithm == Algorithm::Dijkstra));
  t.one_set = options_.transition_based && !may_generalize;
  ba_ = automata::translate(formula_, t);
  if (may_generalize && ba_.num_sets >= 2) {
    t.one_set = true;
    automata::Automaton one = automata::translate(formula_, t);
    if (ba_.num_sets > kMaxProductSets || (options_.generalized == G::WhereItPays && one.num_states() <= ba_.num_states()))
      ba_ = std::move(one);
  }
}

void Planner::set_task(const world::TaskChange& change) {
  world::Scenario next = task::with_task(scenario_, change);  // throws before anything changes
  scenario_.task = std::move(next.task);
  scenario_.task_where = next.task_where;
  scenario_.task_layout = next.task_layout;
  scenario_.propositions = std::move(next.propositions);
  translate();
  ba_starts_.assign(1, ba_.initial);
  dirty_ = true;  // new atoms: the TS's labeling, the product graph and what is known of it are remade
}

Planner::Planner(world::Scenario scenario, automata::Automaton automaton, PlannerOptions options)
    : scenario_(std::move(scenario)), options_(std::move(options)), ba_(std::move(automaton)) {
  if (!ba_.state_based && ba_.num_sets > kMaxProductSets) ba_ = automata::degeneralize_tba(ba_);
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
  if (options_.symmetry && !(model_->depends() & kDependsThing)) {
    ts_->set_symmetry(lab_->symmetry_groups());
    ts_->set_container_symmetry(lab_->container_groups());
  }
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
  const std::int64_t t0 = steady_now_ns();
  const bool keep = algorithm_info(options_.algorithm).keeps_experience;
  PlanResult res = search(*ts_, *lab_, options_, keep ? Experienced::Kept : Experienced::Cold);
  // (graph_nodes > 0: the search ran, i.e. some start state could still reach acceptance.)
  if (!res.found && res.reason == NoPlanReason::NoAcceptingCycle && res.stats.graph_nodes > 0 &&
      options_.diagnose_capacity)
    diagnose(res, t0);
  return res;
}

// ---- one query, step by step -------------------------------------------------

namespace {

// The query's clock: its start, its deadline and how the result is closed.
struct QueryClock {
  std::int64_t t0 = steady_now_ns();
  std::int64_t deadline = 0;
  explicit QueryClock(double limit) {
    // No deadline for a limit <= 0, NaN, infinite or beyond ~30 years (it would overflow the clock).
    if (limit > 0 && limit < 1e9) deadline = t0 + static_cast<std::int64_t>(limit * 1e9);
  }
  double since_start(std::int64_t now) const { return double(now - t0) * 1e-9; }
  PlanResult finish(PlanResult res, NoPlanReason reason, std::string message) const {
    res.reason = reason;
    res.message = std::move(message);
    res.stats.seconds = since_start(steady_now_ns());
    return res;
  }
};

// Which limit stopped a query, if any.
struct Stopped {
  bool node = false, time = false, memory = false;
  bool any() const { return node || time || memory; }
};

// The full construction (graph "full"): every reachable node expanded before the search.
Stopped construct_full(ProductGraph& g, const std::vector<NodeId>& starts, const PlannerOptions& opt,
                       const QueryClock& clock, std::uint64_t& built, SearchStats& stats) {
  Stopped stop;
  const std::int64_t c0 = steady_now_ns();
  const std::uint64_t built0 = g.expansions();
  std::function<void(std::int64_t)> tick;
  if (opt.limits.on_progress) {
    std::int64_t next = c0 + opt.limits.progress_interval_ns();
    tick = [&, next](std::int64_t now) mutable {
      if (now < next) return;
      next = now + opt.limits.progress_interval_ns();
      SearchProgress p;
      p.phase = "constructing";
      p.graph_nodes = g.size();
      p.seconds = clock.since_start(now);
      opt.limits.on_progress(p);
    };
  }
  if (!g.expand_all(starts, opt.limits.max_nodes, clock.deadline, tick, opt.limits.max_memory_bytes)) {
    if (g.size() >= opt.limits.max_nodes) stop.node = true;
    else if (clock.deadline && steady_now_ns() > clock.deadline) stop.time = true;
    else stop.memory = true;
  }
  built = g.expansions() - built0;
  stats.construction_seconds = double(steady_now_ns() - c0) * 1e-9;
  return stop;
}

// The message of a query a limit stopped: which limit, and how far it got.
std::string limit_message(const Stopped& stop, const PlannerOptions& opt, const SearchStats& stats,
                          std::uint64_t built) {
  const bool in_construction = stats.expanded == 0 && built > 0;
  const std::string stopped = in_construction ? "the full construction stopped at its " : "the search stopped at its ";
  const std::uint64_t expansions = in_construction ? built : stats.expanded;
  const std::string after = " after " + format_count(expansions) + (expansions == 1 ? " expansion (" : " expansions (") +
                            format_count(stats.graph_nodes) + " graph nodes, " +
                            format_bytes(double(stats.memory_bytes)) + "); whether a plan exists is unknown";
  if (stop.node) return stopped + "node limit (" + format_count(opt.limits.max_nodes) + " nodes)" + after;
  if (stop.memory) return stopped + "memory limit (" + format_bytes(double(opt.limits.max_memory_bytes)) + ")" + after;
  return stopped + "time limit (" + format_number(opt.limits.time_limit) + " s)" + after;
}

NoPlanReason limit_reason(const Stopped& stop) {
  if (stop.node) return NoPlanReason::NodeLimit;
  if (stop.memory) return NoPlanReason::MemoryLimit;
  return NoPlanReason::TimeLimit;
}

// The limits a query's search runs under: the options', with progress
// reported from the query's start (the search counts from its own).
SearchLimits search_limits(const PlannerOptions& opt, const QueryClock& clock) {
  SearchLimits limits = opt.limits;
  if (limits.on_progress) {
    const double offset = clock.since_start(steady_now_ns());
    limits.on_progress = [report = opt.limits.on_progress, offset](SearchProgress p) {
      p.seconds += offset;
      report(p);
    };
  }
  return limits;
}

// The graph's share of a query's statistics, after it.
void record_graph(SearchStats& stats, const ProductGraph& g, std::size_t before, std::uint64_t expansions_before,
                  const Stopped& stop) {
  stats.successor_generations = g.expansions() - expansions_before;
  stats.generated = g.size() - before;
  stats.graph_nodes = g.size();
  stats.graph_edges = g.num_edges();
  stats.impossible_moves = g.impossible_moves();
  stats.hit_node_limit = stop.node;
  stats.hit_time_limit = stop.time;
  stats.hit_memory_limit = stop.memory;
}

}  // namespace

ProductGraph& Planner::kept_graph(task::System& ts, task::Labeling& lab, const PlannerOptions& opt) {
  // A kept graph that holds half the memory limit is dropped (experience
  // only speeds queries up), so that it cannot grow until every query stops.
  const std::size_t max_bytes = opt.limits.max_memory_bytes;
  if (graph_ && max_bytes && 2 * (graph_->memory_bytes() + experience_.memory_bytes()) > max_bytes) {
    exp_heuristic_.reset();
    graph_.reset();
    experience_.forget_graph();
  }
  if (!graph_) {
    MotionCostCache& cache = experience_.costs();
    auto graph = std::make_unique<ProductGraph>(ts, lab, ba_, *model_, model_->expensive() ? &cache : nullptr);
    exp_heuristic_ = algorithm_info(opt.algorithm).make_heuristic(*graph, experience_);  // may throw
    graph_ = std::move(graph);
  }
  return *graph_;
}

// The graph, experience, search and heuristic of one query: the kept ones, or cold ones.
struct Planner::QueryParts {
  std::unique_ptr<ProductGraph> cold_graph;
  std::unique_ptr<Experience> cold_experience;
  std::unique_ptr<LassoSearch> cold_search;
  std::unique_ptr<Heuristic> cold_heuristic;
  ProductGraph* g = nullptr;
  Experience* x = nullptr;
  LassoSearch* search = nullptr;
  Heuristic* h = nullptr;  // made when the search starts (after the full construction)
};

Planner::QueryParts Planner::query_parts(task::System& ts, task::Labeling& lab, const PlannerOptions& opt,
                                         Experienced experienced) {
  QueryParts q;
  if (experienced == Experienced::Kept) {
    q.g = &kept_graph(ts, lab, opt);
    q.x = &experience_;
    q.search = &search_;
    q.h = exp_heuristic_.get();
    experience_.costs().reset_counters();
  } else {
    q.cold_graph = std::make_unique<ProductGraph>(ts, lab, ba_, *model_, nullptr);
    q.cold_experience = std::make_unique<Experience>();
    q.cold_search = std::make_unique<LassoSearch>();
    q.g = q.cold_graph.get();
    q.x = q.cold_experience.get();
    q.search = q.cold_search.get();
  }
  return q;
}

std::vector<NodeId> Planner::start_nodes(ProductGraph& g, const task::System& ts) const {
  std::vector<NodeId> starts;
  for (const std::uint32_t q : ba_starts_)
    if (g.useful(q)) starts.push_back(g.find_or_add(ts.canonical(ts.initial()), q));
  return starts;
}

PlanResult Planner::search(task::System& ts, task::Labeling& lab, const PlannerOptions& opt, Experienced experienced) {
  PlanResult res;
  const QueryClock clock(opt.limits.time_limit);
  if (!lab.unknown_atoms().empty())
    return clock.finish(std::move(res), NoPlanReason::UnknownName,
                        "the task uses '" + lab.unknown_atoms().front() +
                            "', which is neither a proposition of the scenario nor a proposition expression");
  QueryParts q = query_parts(ts, lab, opt, experienced);
  ProductGraph& g = *q.g;
  if (ba_.num_states() == 0 || !g.useful(ba_.initial))
    return clock.finish(std::move(res), NoPlanReason::Unsatisfiable,
                        "the task is unsatisfiable: its Büchi automaton accepts no word");
  const std::size_t before = g.size();
  const std::vector<NodeId> starts = start_nodes(g, ts);
  if (starts.empty()) {
    std::string list;
    for (const std::uint32_t b : ba_starts_) list += (list.empty() ? "" : ", ") + std::to_string(b);
    return clock.finish(std::move(res), NoPlanReason::NoAcceptingCycle,
                        "no accepting lasso is possible: from none of the automaton states the run is in {" + list +
                            "} can the automaton still reach an accepting cycle");
  }
  res.stats.reused_nodes = before;
  std::uint64_t built = 0;  // nodes the full construction expanded
  Stopped stop;
  if (opt.graph == GraphConstruction::Full) stop = construct_full(g, starts, opt, clock, built, res.stats);
  LassoResult r;
  const std::uint64_t expansions_before = g.expansions();
  if (!stop.any()) {
    if (!q.h) {
      q.cold_heuristic = algorithm_info(opt.algorithm).make_heuristic(g, *q.x);
      q.h = q.cold_heuristic.get();
    }
    const LassoConfig config{opt.algorithm != Algorithm::Dijkstra, experienced == Experienced::Kept};
    const Termination termination{search_limits(opt, clock), clock.deadline};
    r = q.search->run(g, *q.x, starts, *q.h, config, termination, res.stats);
    stop = {r.hit_node_limit, r.hit_time_limit, r.hit_memory_limit};
  }
  record_graph(res.stats, g, before, expansions_before, stop);
  MotionCostCache& cache = experience_.costs();
  if (experienced == Experienced::Kept && model_->expensive()) {
    res.stats.cache_used = true;
    res.stats.cache_hits = cache.hits();
    res.stats.cache_misses = cache.misses();
  }
  res.stats.memory_bytes = g.memory_bytes() + q.x->memory_bytes() + q.search->memory_bytes() +
                           (res.stats.cache_used ? cache.bytes() : 0);
  if (r.found) {
    res.found = true;
    res.plan = replay_lasso(g, r);
    res.stats.seconds = clock.since_start(steady_now_ns());
    return res;
  }
  // A limit says nothing about whether a plan exists: the message says so,
  // and how far the query got.
  if (stop.any()) return clock.finish(std::move(res), limit_reason(stop), limit_message(stop, opt, res.stats, built));
  return clock.finish(std::move(res), NoPlanReason::NoAcceptingCycle,
                      "no accepting lasso is reachable from the current state: the task cannot be achieved from here");
}

void Planner::diagnose(PlanResult& res, std::int64_t t0) {
  // The same TS without capacities (nor rooms), forbidden moves kept: is
  // there any lasso at all? Existence only, no costs (plan/lasso_exists.hpp).
  const std::int64_t d0 = steady_now_ns();
  task::System relaxed(scenario_, placement_, hand_, task::System::Options{true});
  relaxed.forbid_moves(forbidden_);
  task::Labeling rlab(relaxed, ba_.atoms, parse_atom);
  if (options_.symmetry && !(model_->depends() & kDependsThing)) {
    relaxed.set_symmetry(rlab.symmetry_groups());
    relaxed.set_container_symmetry(rlab.container_groups());
  }
  const QueryClock clock(options_.limits.time_limit);
  const LassoExistence e =
      find_accepting_lasso(relaxed, rlab, ba_, ba_starts_, options_.limits.max_nodes, clock.deadline);
  res.stats.diagnosis_nodes = e.nodes;
  bool exists = e.exists;
  bool stopped = e.stopped;
  // The existence check asks no costs, so it cannot know the moves the model
  // prices +inf: if the search met any, a lasso it finds is confirmed by a
  // search of the capacity-free TS that does (rare: only such models pay).
  if (exists && res.stats.impossible_moves > 0) {
    PlannerOptions confirm = options_;
    confirm.graph = GraphConstruction::Partial;
    const PlanResult c = search(relaxed, rlab, confirm, Experienced::Cold);
    exists = c.found;
    stopped = c.stats.hit_node_limit || c.stats.hit_time_limit || c.stats.hit_memory_limit;
    res.stats.diagnosis_nodes += c.stats.graph_nodes;
  }
  const std::int64_t now = steady_now_ns();
  res.stats.diagnosis_seconds = double(now - d0) * 1e-9;
  res.stats.seconds = double(now - t0) * 1e-9;
  if (exists) {
    res.reason = NoPlanReason::Capacity;
    res.message = "no plan within the capacities of the locations (there is one if capacities are ignored)";
  } else if (stopped) {
    res.message += " (whether there is a plan if capacities are ignored is unknown: that check stopped at its limit)";
  }
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
