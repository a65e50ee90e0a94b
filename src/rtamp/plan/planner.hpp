// The planning facade (OMPL SimpleSetup style): everything the paper's
// high-level layer does (Sections II-III.C, Algorithm 1 lines 9-14) behind a
// few calls:
//
//   rtamp::plan::Planner planner(rtamp::world::load_scenario("3-block-tray"));
//   auto r = planner.plan();                       // first plan
//   planner.apply(world::Change::relocate("b1", "r3"));  // a person moved b1
//   auto r2 = planner.plan();                      // replan from the observed state
//   auto tuples = planner.action_tuples(r2.plan);  // for the behavior tree
//
// The planner owns the scenario, the current symbolic state (where every thing
// and the hand are), the Büchi automaton of the task (translated once, and
// again for a new task: set_task), the TS and labeling (rebuilt when
// things or regions are added or removed; names stay the identity), and the
// experience (plan/experience.hpp): the motion-cost cache (for models whose
// costs are expensive(), e.g. ik) and, while the TS is unchanged, the product
// graph with its learned bounds, solved paths and cycle table. Each plan() starts the product at the
// current state and every automaton state of automaton_states() (default:
// the initial state, i.e. (s, q_b0) of Algorithm 1 line 12; the executor sets
// the states consistent with the run so far, plan/task_progress.hpp) and
// returns the cheapest lasso from any of them.
// Algorithms dijkstra and astar plan cold every time (new graph, no cache);
// astar-exp keeps and reuses all experience.
// Errors a user can cause (unknown names in a change, a bad task, a cost
// model's NaN or negative value: plan/cost_check.hpp) are rtamp::Error; a task
// that cannot be achieved, or a query stopped by a limit (SearchLimits), is a
// PlanResult with a reason.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/ltl/formula.hpp"
#include "rtamp/plan/action_tuple.hpp"
#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/motion_cost.hpp"
#include "rtamp/plan/motion_cost_cache.hpp"
#include "rtamp/plan/plan.hpp"
#include "rtamp/plan/product_graph.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/plan/algorithm.hpp"
#include "rtamp/plan/lasso_search.hpp"
#include "rtamp/task/labeling.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::plan {

struct PlannerOptions {
  Algorithm algorithm = Algorithm::AStarExperience;
  GraphConstruction graph = GraphConstruction::Partial;
  std::string cost = "euclid";                 // a registered name (plan/registry.hpp); ignored if `model` is set
  std::shared_ptr<MotionCostModel> model;      // e.g. the robot layer's ik model
  SearchLimits limits;
  bool diagnose_capacity = true;               // on failure, check for a lasso without capacities to tell "capacity"
  bool symmetry = true;                        // search the quotient by interchangeable objects
                                               // (task::System::set_symmetry; costs are unchanged)
  // Translate the task to a transition-based Büchi automaton and accept on
  // the product's edges, instead of a state-based BA (docs/planning.md
  // "Acceptance on transitions"). An automaton given to the constructor is
  // searched in the form it has (degeneralized to one set if it has more
  // than kMaxProductSets).
  bool transition_based = false;
  // With transition_based, when the task's generalized automaton has 2 to
  // kMaxProductSets acceptance sets, whether to search it (a cycle then takes
  // every set) or its one-set (degeneralized) form. WhereItPays: where the
  // generalized one has fewer states and the search has no heuristic
  // (Dijkstra: the product is smaller and nothing else changes); A*'s bounds
  // read the order of the sets that the one-set form's states carry, and
  // expand many times fewer nodes with it (docs/planning.md "Generalized
  // acceptance").
  enum class Generalized { WhereItPays, Never, Always };
  Generalized generalized = Generalized::WhereItPays;
};

class Planner {
 public:
  // Parses and translates scenario.task. Throws rtamp::Error on a bad task or
  // a scenario whose initial state cannot be read.
  explicit Planner(world::Scenario scenario, PlannerOptions options = {});
  // With an automaton built elsewhere (its atoms name propositions).
  Planner(world::Scenario scenario, automata::Automaton automaton, PlannerOptions options = {});
  ~Planner();
  Planner(const Planner&) = delete;
  Planner& operator=(const Planner&) = delete;

  PlanResult plan();
  // How apply() checks a change. Proposed: its names against the current
  // scenario and the rule book of space where it puts things (capacity, fit,
  // room: world::check_change_room). Observed: names only — what a world
  // showed has happened is taken as it is, even a region fuller than the
  // rules allow (the reactive loop's case).
  enum class ChangeOrigin { Proposed, Observed };
  // A change of the world between plans (world/change.hpp), checked as
  // `origin` says (rtamp::Error naming the word that does not fit), then
  // applied. A relocation keeps the product graph and all experience; other
  // kinds rebuild the TS (the motion-cost cache is kept, minus a removed
  // thing's entries).
  void apply(const world::Change& change, ChangeOrigin origin = ChangeOrigin::Proposed);
  // A new task (the paper's "new temporal logic specifications"; docs/exec.md
  // "A new task"): task::with_task checks it (rtamp::Error, nothing changed),
  // then the task is translated and the automaton states reset to its
  // initial state. Kept: the scenario, the current state, forbidden moves and
  // the motion-cost cache (costs do not depend on the task); the TS is
  // relabelled and the product graph with its learned bounds, cycle table and
  // solved paths is made anew (they are the old automaton's).
  void set_task(const world::TaskChange& change);
  // The robot executed `a` (the state advances; experience is kept).
  void execute(const task::Action& a);
  // Replace the current state (e.g. from perception).
  void set_placement(world::Placement placement, std::string hand = {});
  // The automaton states plan() starts from: every (current state, q) with q
  // in the set is a start node at cost 0 (multi-source), and the plan's first
  // step (prefix, or cycle if the prefix is empty) has ba_from = the state it
  // used. States from which no accepting cycle is reachable are skipped; if
  // none is left, plan() is not found with NoAcceptingCycle. Default
  // {automaton().initial}; kept until changed (apply(), execute() and
  // set_placement() keep it). Stored sorted, without duplicates. Throws
  // rtamp::Error for a state >= automaton().num_states().
  void set_automaton_states(std::vector<std::uint32_t> states);
  const std::vector<std::uint32_t>& automaton_states() const { return ba_starts_; }
  // Moves that failed physically (e.g. the arm found no free spot), fed back
  // by the executor: move(thing, location) is in no plan until
  // clear_forbidden_moves(). Kept by name across TS rebuilds (a name the TS
  // does not know, e.g. a removed thing, is ignored while it is unknown);
  // listed once each, in the order forbidden. A new entry or a clear marks the
  // TS dirty: the next plan() rebuilds the TS and the product graph (the
  // motion-cost cache is kept).
  void forbid_move(const std::string& thing, const std::string& location);
  void clear_forbidden_moves();
  const std::vector<std::pair<std::string, std::string>>& forbidden_moves() const { return forbidden_; }

  const world::Scenario& scenario() const { return scenario_; }
  const task::System& system();
  const task::Labeling& labeling();
  const automata::Automaton& automaton() const { return ba_; }
  const ltl::Formula& formula() const { return formula_; }  // null if built from an automaton
  const world::Placement& placement() const { return placement_; }
  const std::string& hand() const { return hand_; }
  task::State state();
  const PlannerOptions& options() const { return options_; }
  const MotionCostModel& model() const { return *model_; }
  std::vector<ActionTuple> action_tuples(const Plan& p) { return to_action_tuples(system(), p); }
  // "move(o1, r2)" etc.
  std::string describe(const task::Action& a) { return system().action_name(a); }
  // What astar-exp reuses across plans (plan/experience.hpp); its cost cache is cache().
  const Experience& experience() const { return experience_; }
  const MotionCostCache& cache() const { return experience_.costs(); }

 private:
  void init();
  void translate();  // formula_ and ba_ from scenario_.task, in the form the options ask
  void rebuild();  // TS, labeling, graph from scenario_ + placement_ + hand_
  // How a query treats experience: the planner's kept graph, experience and
  // search (astar-exp), or cold ones made for the query and dropped after it.
  enum class Experienced { Kept, Cold };
  // One query on `ts` (its initial state is the start) with the options
  // `opt`: the graph, the start nodes, the full construction if asked, the
  // lasso search, the statistics, the plan replayed on concrete states.
  PlanResult search(task::System& ts, task::Labeling& lab, const PlannerOptions& opt, Experienced experienced);
  struct QueryParts;
  QueryParts query_parts(task::System& ts, task::Labeling& lab, const PlannerOptions& opt, Experienced experienced);
  // The product nodes (initial state, q) for the automaton states the run may be in, where useful.
  std::vector<NodeId> start_nodes(ProductGraph& g, const task::System& ts) const;
  // The kept product graph for `ts` (made, or dropped and remade when it holds
  // half the memory limit).
  ProductGraph& kept_graph(task::System& ts, task::Labeling& lab, const PlannerOptions& opt);
  // A query found no lasso: is that because of capacities? Sets reason
  // Capacity if a lasso exists without them (docs/planning.md "Capacity
  // diagnosis"); adds its work to the statistics. `t0`: the query's start.
  void diagnose(PlanResult& res, std::int64_t t0);

  world::Scenario scenario_;
  PlannerOptions options_;
  ltl::Formula formula_;
  automata::Automaton ba_;
  std::vector<std::uint32_t> ba_starts_;  // sorted, unique; see set_automaton_states
  std::shared_ptr<MotionCostModel> model_;
  world::Placement placement_;
  std::string hand_;
  bool dirty_ = true;  // TS must be rebuilt
  std::vector<std::pair<std::string, std::string>> forbidden_;  // (thing, location) by name
  std::unique_ptr<task::System> ts_;
  std::unique_ptr<task::Labeling> lab_;
  std::unique_ptr<ProductGraph> graph_;  // astar-exp: kept while the TS is unchanged
  Experience experience_;                // astar-exp: the cost cache, and what is known about graph_
  std::unique_ptr<Heuristic> exp_heuristic_;  // astar-exp: lives with graph_
  LassoSearch search_;
};

}  // namespace rtamp::plan
