#include "rtamp/exec/episode_log.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "rtamp/automata/dot_writer.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/json_text.hpp"

namespace rtamp::exec {

namespace {

using nlohmann::json;

json placement_json(const world::Placement& p) {
  json j = json::object();
  for (const auto& [name, thing] : p.things) j[name] = thing.location;
  return j;
}

json tasks_json(const std::vector<TaskOutcome>& tasks) {
  json out = json::array();
  for (const TaskOutcome& t : tasks)
    out.push_back({{"time", t.time},
                   {"task", t.task},
                   {"by", t.by},
                   {"automaton_states", t.automaton_states},
                   {"cycles", t.cycles},
                   {"outcome", t.outcome}});
  return out;
}

json automaton_value(const automata::Automaton& ba) {
  json states = json::array();
  for (std::uint32_t q = 0; q < ba.num_states(); ++q)
    states.push_back({{"id", q}, {"initial", q == ba.initial}, {"accepting", ba.is_accepting_state(q)}});
  json edges = json::array();
  for (std::uint32_t q = 0; q < ba.num_states(); ++q)
    for (const auto& e : ba.edges[q])
      edges.push_back({{"from", q},
                       {"to", e.dst},
                       {"label", automata::cube_to_string(e.guard, ba.atoms)},
                       {"accepting", !ba.state_based && e.marks == ba.all_marks()}});
  return {{"states", states}, {"edges", edges}, {"state_based", ba.state_based}};
}

json metrics_json(const EpisodeMetrics& m) {
  return {{"success", m.success},
          {"end", to_string(m.end)},
          {"reason", m.reason},
          {"first_plan_seconds", m.first_plan_seconds},
          {"replan_seconds", m.replan_seconds},
          {"replans", m.replans},
          {"tree_changes", m.tree_changes},
          {"completion_time", m.completion_time ? json(*m.completion_time) : json(nullptr)},
          {"motion_cost", m.motion_cost},
          {"interventions", m.interventions},
          {"interventions_applied", m.interventions_applied},
          {"interventions_refused", m.interventions_refused},
          {"actions_succeeded", m.actions_succeeded},
          {"actions_failed", m.actions_failed},
          {"cycles", m.cycles},
          {"tasks", tasks_json(m.tasks)},
          {"run_length", m.run_length},
          {"world_time", m.world_time},
          {"wall_seconds", m.wall_seconds},
          {"real_time_factor", m.real_time_factor},
          {"seed", m.seed}};
}

}  // namespace

std::string to_json(const EpisodeMetrics& m, int indent) { return metrics_json(m).dump(indent); }

std::string automaton_json(const automata::Automaton& ba) {
  return automaton_value(ba).dump(-1, ' ', false, json::error_handler_t::replace);
}

EpisodeLog::EpisodeLog(const std::string& path, const std::string& what) : out_(path, what) {}

void EpisodeLog::close() {
  if (!lost_.empty()) throw OutputError(lost_);
  try {
    out_.close();
  } catch (const OutputError& e) {
    lost_ = e.message();
    throw;
  }
}

void EpisodeLog::write(double t, const std::string& object) {
  // `object` is "{...}": add the time as the last member.
  std::string line = object.substr(0, object.size() - 1);
  line += object.size() > 2 ? ",\"t\":" : "\"t\":";
  line += json(std::round(t * 1e4) / 1e4).dump();
  line += '}';
  if (out_.is_open() && lost_.empty()) {
    try {
      out_.write(line + '\n');
    } catch (const OutputError& e) {
      lost_ = e.message();  // the episode goes on; close() reports it
    }
  }
  for (const auto& sink : sinks_) sink(line);
}

void EpisodeLog::on_begin(const EpisodeInfo& i) {
  json j{{"ev", "episode"},
         {"version", kEpisodeLogVersion},
         {"scenario", i.scenario},
         {"task", i.task},
         {"algorithm", i.algorithm},
         {"conditions", i.conditions},
         {"reconfiguration", i.reconfiguration},
         {"world", i.world},
         {"seed", i.seed}};
  // The first task's automaton, as a `task` record has a new one's.
  if (i.automaton) {
    j["automaton_states"] = i.automaton->num_states();
    j["automaton"] = automaton_value(*i.automaton);
  }
  write(0, j.dump(-1, ' ', false, json::error_handler_t::replace));
}

void EpisodeLog::on_action(double t, const char* what, const std::string& action, const std::string& why) {
  write(t, json{{"ev", "action"}, {"what", what}, {"action", action}, {"reason", why}}.dump());
}

void EpisodeLog::on_intervention(const WorldEvent& e) {
  using K = world::Change::Kind;
  json j{{"ev", "intervention"},    {"kind", to_string(e.what.kind)}, {"subject", e.what.subject},
         {"location", e.what.location}, {"applied", e.applied},         {"detail", e.detail}};
  // What an added thing is (a replay draws it so): its class, "" meaning the default.
  if (e.what.kind == K::Add || e.what.kind == K::AddContainer)
    j["class"] = !e.what.cls.empty() ? e.what.cls : e.what.kind == K::AddContainer ? "tray" : "block";
  write(e.time, j.dump());
}

void EpisodeLog::on_perceived(double t, const world::Placement& seen, const world::Placement&) {
  write(t, json{{"ev", "perceived"}, {"placement", placement_json(seen)}}.dump());
}

void EpisodeLog::on_things_changed(double t, const std::vector<std::string>& added,
                                   const std::vector<std::string>& removed) {
  write(t, json{{"ev", "things"}, {"added", added}, {"removed", removed}}.dump());
}

void EpisodeLog::on_progress(double t, const world::Placement& state, const std::vector<std::uint32_t>& states) {
  write(t, json{{"ev", "run"}, {"state", placement_json(state)}, {"automaton_states", states}}.dump());
}

void EpisodeLog::on_handled_by_tree(double t, const std::string& by) {
  write(t, json{{"ev", "handled_by_tree"}, {"by", by}}.dump());
}

void EpisodeLog::on_replan_request(double t, const std::string& why) {
  write(t, json{{"ev", "replan"}, {"why", why}}.dump());
}

void EpisodeLog::on_plan(double t, const PlanEvent& e) {
  json actions = json::array(), costs = json::array(), in_cycle = json::array();
  for (const auto& tu : e.tuples) {
    actions.push_back(tu.action);
    costs.push_back(tu.cost);
    in_cycle.push_back(tu.in_cycle);
  }
  const auto& s = e.result.stats;
  write(t, json{{"ev", "plan"},
                {"first", e.first},
                {"cost", e.result.plan.cost()},
                {"actions", actions},
                {"costs", costs},
                {"in_cycle", in_cycle},
                {"automaton_states", e.automaton_states},
                {"start", placement_json(e.start)},
                {"hand", e.hand.empty() ? "home" : e.hand},
                {"seconds", s.seconds},
                {"expanded", s.expanded},
                {"generated", s.generated},
                {"cache_used", s.cache_used},
                {"cache_hits", s.cache_hits},
                {"cache_misses", s.cache_misses}}
               .dump());
}

void EpisodeLog::on_tree_change(double t, const ReconfigurationReport& r, const PlanTree& tree, bool deferred) {
  json j{{"ev", "tree"},        {"applied", r.applied}, {"inserted", r.inserted},
         {"removed", r.removed}, {"updated", r.updated}, {"changes", tree.changes()}};
  if (deferred) j["deferred"] = true;
  write(t, j.dump());
}

void EpisodeLog::on_cycle(double t, int completed) {
  write(t, json{{"ev", "cycle"}, {"completed", completed}}.dump());
}

void EpisodeLog::on_task(double t, const TaskEvent& e) {
  json j{{"ev", "task"}, {"task", e.change.task}, {"by", e.change.by}, {"applied", e.applied}};
  if (!e.change.propositions.empty()) {
    json props = json::object();
    for (const world::Proposition& p : e.change.propositions) props[p.name] = p.text;
    j["propositions"] = props;
  }
  if (e.applied && e.automaton) {
    j["automaton_states"] = e.automaton->num_states();
    j["automaton"] = automaton_value(*e.automaton);
  } else {
    j["refused"] = e.refused;
  }
  write(t, j.dump(-1, ' ', false, json::error_handler_t::replace));
}

void EpisodeLog::on_redirect(double t, const std::string& action, const std::string& rule) {
  write(t, json{{"ev", "redirect"}, {"action", action}, {"rule", rule}}.dump());
}

void EpisodeLog::on_tick(double t, bt::Status status, const std::string& running) {
  if (!ticks) return;
  // The most frequent record (one a tick): written directly, the text nlohmann would dump.
  std::string r = "{\"ev\":\"tick\",\"running\":";
  json_text::append_string(r, running);
  r += ",\"status\":\"";
  r += bt::to_string(status);
  r += "\"}";
  write(t, r);
}

void EpisodeLog::on_end(double t, const EpisodeMetrics& m, const world::Placement& p) {
  json j{{"ev", "end"},
         {"success", m.success},
         {"end", to_string(m.end)},
         {"reason", m.reason},
         {"metrics", metrics_json(m)},
         {"placement", placement_json(p)}};
  for (const auto& [key, value] : end_fields_) j[key] = value();
  for (const auto& [key, value] : end_texts_) j[key] = value();
  if (truth_) j["truth"] = placement_json(truth_());
  write(t, j.dump());
}

}  // namespace rtamp::exec
