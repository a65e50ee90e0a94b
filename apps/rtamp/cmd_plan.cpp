// rtamp plan — plan for a scenario's LTL task (plan/planner.hpp), optionally
// replanning after scripted changes, and print the plans and search
// statistics readably or as one JSON object (documented in docs/cli.md).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command.hpp"
#include "options.hpp"
#include "rtamp/world/change.hpp"
#include "rtamp/plan/planner.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

struct PlanArgs {
  std::string scenario;
  std::string algo = "astar-exp";
  std::string graph = "partial";
  std::string cost = "euclid";
  std::vector<std::string> changes;
  bool json = false;
  bool no_progress = false;
  bool transition_based = false;
  std::string generalized = "where-it-pays";
  std::size_t max_nodes = 20'000'000;
  double time_limit = 60;
  double max_memory_gib = double(plan::SearchLimits{}.max_memory_bytes) / double(1ull << 30);  // inf: none
};

nlohmann::json steps_json(plan::Planner& p, const std::vector<plan::Step>& steps) {
  const task::System& ts = p.system();
  nlohmann::json out = nlohmann::json::array();
  for (const auto& st : steps) {
    nlohmann::json j;
    j["action"] = ts.action_name(st.action);
    if (!st.action.is_stay()) {
      j["thing"] = ts.thing_name(st.action.thing);
      j["from"] = ts.location_name(ts.location(st.from, st.action.thing));
      j["to"] = ts.location_name(st.action.to);
    }
    j["cost"] = st.cost;
    j["ba_from"] = st.ba_from;
    j["ba_to"] = st.ba_to;
    j["state_after"] = ts.to_string(st.to);
    out.push_back(j);
  }
  return out;
}

nlohmann::json stats_json(const plan::SearchStats& s) {
  return {{"generated", s.generated},
          {"expanded", s.expanded},
          {"successor_generations", s.successor_generations},
          {"cycle_searches", s.cycle_searches},
          {"graph_nodes", s.graph_nodes},
          {"graph_edges", s.graph_edges},
          {"reused_nodes", s.reused_nodes},
          {"reused_path_edges", s.reused_path_edges},
          {"cache_used", s.cache_used},
          {"cache_hits", s.cache_hits},
          {"cache_misses", s.cache_misses},
          {"memory_bytes", s.memory_bytes},
          {"bytes_per_node", s.bytes_per_node()},
          {"construction_seconds", s.construction_seconds},
          {"seconds", s.seconds},
          {"diagnosis_nodes", s.diagnosis_nodes},
          {"diagnosis_seconds", s.diagnosis_seconds},
          {"hit_node_limit", s.hit_node_limit},
          {"hit_time_limit", s.hit_time_limit},
          {"hit_memory_limit", s.hit_memory_limit}};
}

std::string fmt(double v, int prec = 4) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(prec) << v;
  return o.str();
}

void print_steps(plan::Planner& p, const std::vector<plan::Step>& steps, std::ostream& out) {
  const task::System& ts = p.system();
  int i = 1;
  for (const auto& st : steps) {
    std::string a = ts.action_name(st.action);
    out << "    " << std::setw(3) << i++ << ". " << std::left << std::setw(28) << a << std::right << std::setw(9)
        << fmt(st.cost) << "   " << ts.to_string(st.to) << "\n";
  }
}

void print_result(plan::Planner& p, const plan::PlanResult& r, const std::string& title, std::ostream& out) {
  out << title << "\n";
  if (!r.found) {
    out << "  no plan (" << plan::to_string(r.reason) << "): " << r.message << "\n";
  } else {
    out << "  cost " << fmt(r.plan.cost()) << " = prefix " << fmt(r.plan.prefix_cost) << " + cycle "
        << fmt(r.plan.cycle_cost) << "\n";
    out << "  prefix (" << r.plan.prefix.size() << " steps):\n";
    print_steps(p, r.plan.prefix, out);
    out << "  cycle (" << r.plan.cycle.size() << " steps, repeated forever):\n";
    print_steps(p, r.plan.cycle, out);
  }
  const auto& s = r.stats;
  out << "  statistics: " << s.generated << " nodes generated, " << s.expanded << " expanded ("
      << s.successor_generations << " successor generations, " << s.cycle_searches << " cycle searches), "
      << s.reused_nodes << " reused, " << s.reused_path_edges << " plan edges reused; graph " << s.graph_nodes << " nodes / " << s.graph_edges << " edges; "
      << fmt(s.seconds * 1e3, 3) << " ms";
  if (s.construction_seconds > 0) out << " (construction " << fmt(s.construction_seconds * 1e3, 3) << " ms)";
  if (s.diagnosis_seconds > 0)
    out << " (capacity diagnosis " << s.diagnosis_nodes << " nodes, " << fmt(s.diagnosis_seconds * 1e3, 3) << " ms)";
  if (s.cache_used) out << "; cache " << s.cache_hits << " hits / " << s.cache_misses << " misses";
  else if (s.reused_nodes > 0 || s.reused_path_edges > 0) out << "; no cost cache (closed-form costs)";
  out << "; memory " << s.memory_bytes
      << " B (" << fmt(s.bytes_per_node(), 1) << " B/node)";
  if (s.hit_node_limit) out << "; HIT NODE LIMIT";
  if (s.hit_time_limit) out << "; HIT TIME LIMIT";
  if (s.hit_memory_limit) out << "; HIT MEMORY LIMIT";
  out << "\n";
}

// A one-line report on stderr while a query runs longer than half a second
// (SearchLimits::on_progress), rewritten in place and cleared when it ends.
struct ProgressLine {
  bool shown = false;
  void operator()(const plan::SearchProgress& p) {
    std::ostringstream line;
    line << std::fixed;
    if (std::string(p.phase) == "constructing") {
      line << "constructing the full product graph: " << p.graph_nodes << " nodes";
    } else {
      line << "searching: " << p.graph_nodes << " nodes, " << p.expanded << " expanded, ";
      if (p.best < plan::kInf) line << std::setprecision(4) << "best lasso so far " << p.best;
      else line << std::setprecision(4) << "no lasso yet, optimum >= " << p.bound;
    }
    line << std::setprecision(1) << ", " << p.seconds << " s";
    std::cerr << "\r" << line.str() << "\x1b[K" << std::flush;
    shown = true;
  }
  void clear() {
    if (shown) std::cerr << "\r\x1b[K" << std::flush;
    shown = false;
  }
};

rtamp::cli::Registrar reg{
    "plan", "Plan for a scenario's LTL task (minimum motion cost lasso), optionally replanning after changes",
    [](CLI::App& sub) -> rtamp::cli::Action {
      auto a = std::make_shared<PlanArgs>();
      rtamp::cli::add_scenario(sub, a->scenario)->required();
      rtamp::cli::add_choice(sub, "--algo", a->algo, rtamp::cli::algorithm_choices(), "Search algorithm:");
      rtamp::cli::add_choice(sub, "--graph", a->graph, rtamp::cli::choices_of(rtamp::plan::graph_constructions()),
                             "Product construction:");
      rtamp::cli::add_choice(sub, "--cost", a->cost, rtamp::cli::cost_model_choices(), "Motion-cost model:");
      sub.add_option("--change", a->changes,
                     "A change applied after the previous plan, followed by a replan (repeatable, in order): "
                     "'move OBJ LOC', 'add OBJ CLASS LOC', 'remove OBJ', 'add-container NAME CLASS REGION [CAP]', "
                     "'remove-container NAME', 'add-region NAME X Y [CAP [SX SY]]'");
      sub.add_flag("--json", a->json, "Print one JSON object (fields: docs/cli.md)");
      rtamp::cli::add_integer(sub, "--max-nodes", a->max_nodes, 1, std::numeric_limits<long long>::max(),
                              "Node limit of each search");
      rtamp::cli::add_real(sub, "--time-limit", a->time_limit, {0, std::numeric_limits<double>::max(), true, true},
                           "Time limit of each search in seconds");
      rtamp::cli::add_real(sub, "--max-memory", a->max_memory_gib, {0, std::numeric_limits<double>::max(), true, true},
                           "Memory limit of each search in GiB (the planner's estimate of its graph, search arrays, "
                           "experience and cost cache)");
      sub.add_flag("--transition-based", a->transition_based,
                   "Translate the task to a transition-based Büchi automaton and accept on the product's edges "
                   "(same costs as state-based on every task measured; docs/planning.md)");
      sub.add_option("--generalized", a->generalized,
                     "With --transition-based, when the task's automaton has several acceptance sets: "
                     "where-it-pays searches it generalized (a cycle takes every set) with --algo dijkstra where it "
                     "has fewer states than its one-set form (A*'s bounds do better on the one-set form); always; "
                     "never (one set)")
          ->check(CLI::IsMember({"where-it-pays", "always", "never"}))
          ->default_str("where-it-pays");
      sub.add_flag("--no-progress", a->no_progress,
                   "Do not show the progress line that searches longer than 0.5 s print on a terminal's stderr");
      return [a]() -> int {
        plan::PlannerOptions opt;
        opt.algorithm = plan::parse_algorithm(a->algo);
        opt.graph = parse_name(plan::graph_constructions(), a->graph, "graph");
        opt.cost = a->cost;
        opt.transition_based = a->transition_based;
        opt.generalized = a->generalized == "always"  ? plan::PlannerOptions::Generalized::Always
                          : a->generalized == "never" ? plan::PlannerOptions::Generalized::Never
                                                      : plan::PlannerOptions::Generalized::WhereItPays;
        if (a->generalized != "where-it-pays" && !a->transition_based)
          throw Error("--generalized " + a->generalized + " needs --transition-based");
        opt.limits.max_nodes = a->max_nodes;
        opt.limits.time_limit = a->time_limit;
        const double max_bytes = a->max_memory_gib * double(1ull << 30);
        opt.limits.max_memory_bytes =
            max_bytes >= double(std::numeric_limits<std::size_t>::max())
                ? 0  // inf: none
                : std::max<std::size_t>(1, static_cast<std::size_t>(max_bytes));
        auto progress = std::make_shared<ProgressLine>();
        if (!a->no_progress && ::isatty(STDERR_FILENO))
          opt.limits.on_progress = [progress](const plan::SearchProgress& p) { (*progress)(p); };
        world::Scenario scenario = world::load_scenario(a->scenario);
        task::validate_task(scenario);  // every input is checked before anything runs
        const std::vector<world::Change> changes = world::parse_changes(scenario, a->changes);
        plan::Planner planner(std::move(scenario), opt);

        nlohmann::json doc;
        doc["scenario"] = planner.scenario().name;
        doc["task"] = planner.scenario().task;
        doc["automaton_states"] = planner.automaton().num_states();
        const automata::Automaton& ba = planner.automaton();
        const bool generalized = !ba.state_based && ba.num_sets >= 2;
        doc["automaton_acceptance"] = ba.state_based ? "state" : generalized ? "generalized" : "transition";
        doc["automaton_sets"] = ba.state_based ? 1u : ba.num_sets;
        doc["algorithm"] = a->algo;
        doc["graph"] = a->graph;
        doc["cost_model"] = a->cost;
        doc["plans"] = nlohmann::json::array();
        if (!a->json) {
          std::cout << "scenario " << planner.scenario().name << ": task " << planner.scenario().task << " ("
                    << planner.automaton().num_states() << "-state "
                    << (ba.state_based ? ""
                        : generalized ? "transition-based generalized (" + std::to_string(ba.num_sets) + " sets) "
                                      : std::string("transition-based "))
                    << "Büchi automaton)\n"
                    << "algorithm " << a->algo << ", graph " << a->graph << ", cost " << a->cost << "\n\n";
        }
        bool all_found = true;
        for (std::size_t i = 0; i <= changes.size(); ++i) {
          if (i > 0) planner.apply(changes[i - 1]);
          const plan::PlanResult r = planner.plan();
          progress->clear();
          all_found = all_found && r.found;
          if (a->json) {
            nlohmann::json j;
            j["change"] = i == 0 ? nlohmann::json(nullptr) : nlohmann::json(changes[i - 1].to_string());
            j["start"] = planner.system().to_string(planner.system().initial());
            j["found"] = r.found;
            j["reason"] = plan::to_string(r.reason);
            j["message"] = r.message;
            if (r.found) {
              j["cost"] = r.plan.cost();
              j["prefix_cost"] = r.plan.prefix_cost;
              j["cycle_cost"] = r.plan.cycle_cost;
              j["prefix"] = steps_json(planner, r.plan.prefix);
              j["cycle"] = steps_json(planner, r.plan.cycle);
            }
            j["stats"] = stats_json(r.stats);
            doc["plans"].push_back(j);
          } else {
            std::string title = i == 0 ? "plan 1 (initial)" : "plan " + std::to_string(i + 1) + " after '" +
                                                                  changes[i - 1].to_string() + "'";
            title += "\n  start: " + planner.system().to_string(planner.system().initial());
            print_result(planner, r, title, std::cout);
            std::cout << "\n";
          }
        }
        if (a->json) std::cout << doc.dump(2) << "\n";
        return all_found ? 0 : 1;
      };
    }};

}  // namespace
