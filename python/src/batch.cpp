// The C++ half of rtamp.batch (python/rtamp/batch.py): the
// trial grid of `rtamp batch` (batch/trials.hpp: algorithms x changes x BT
// variants x trials, seeds by trial index), running a list of trials (each an
// independent episode, batch::run_batch, without the GIL) to CSV rows, and
// merging CSV slices into the canonical CSV `rtamp batch` writes
// (batch/csv.hpp). Trials cross process boundaries as plain tuples
// (algorithm, change, bt, index, seed), so Dask can ship them anywhere.
#include <sstream>

#include "bindings.hpp"
#include "choices.hpp"
#include "rtamp/batch/csv.hpp"
#include "rtamp/batch/record.hpp"
#include "rtamp/batch/runner.hpp"
#include "rtamp/batch/trials.hpp"

namespace rtamp::python {

namespace {

using TrialTuple = std::tuple<std::string, std::string, std::string, int, std::uint64_t>;

TrialTuple to_tuple(const batch::Trial& t) {
  return {plan::to_string(t.algorithm), batch::to_string(t.change), batch::to_string(t.bt), t.index, t.seed};
}

batch::Trial from_tuple(const TrialTuple& t) {
  batch::Trial x;
  x.algorithm = plan::parse_algorithm(std::get<0>(t));
  x.change = batch::parse_change_kind(std::get<1>(t));
  x.bt = batch::parse_bt_variant(std::get<2>(t));
  x.index = std::get<3>(t);
  x.seed = std::get<4>(t);
  return x;
}

template <class T, class F>
std::vector<T> parse_all(const std::vector<std::string>& names, F parse) {
  std::vector<T> out;
  for (const auto& n : names) out.push_back(parse(n));
  return out;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def("make_trials",
        [](const std::vector<std::string>& algorithms, const std::vector<std::string>& changes,
           const std::vector<std::string>& bts, int trials, std::uint64_t seed, const std::string& shard) {
          batch::Grid g;
          g.algorithms = parse_all<plan::Algorithm>(algorithms, plan::parse_algorithm);
          g.changes = parse_all<batch::ChangeKind>(changes, batch::parse_change_kind);
          g.bt_variants = parse_all<batch::BtVariant>(bts, batch::parse_bt_variant);
          g.trials = trials;
          g.base_seed = seed;
          auto list = batch::make_trials(g);
          if (!shard.empty()) list = batch::select_shard(list, batch::parse_shard(shard));
          std::vector<TrialTuple> out;
          for (const auto& t : list) out.push_back(to_tuple(t));
          return out;
        },
        py::kw_only(), py::arg("algorithms"), py::arg("changes"), py::arg("bts"), py::arg("trials") = 30,
        py::arg("seed") = 1, py::arg("shard") = "",
        "The trial grid of `rtamp batch`, trial-major, as tuples (algorithm, change, bt, trial, seed);\n"
        "shard 'K/N' keeps the K-th of N interleaved slices.");
  m.def("run_trials",
        [](const world::Scenario& s, const std::vector<TrialTuple>& trials, const std::string& world, int jobs,
           double max_time, const std::string& cost, bool randomize_initial, bool scripted_operator) {
          std::vector<batch::Trial> list;
          for (const auto& t : trials) list.push_back(from_tuple(t));
          batch::BatchOptions o;
          o.jobs = jobs;
          o.episode = batch::batch_episode_defaults(world);
          o.episode.loop.max_time = max_time;
          o.episode.loop.planner.cost = cost;
          o.episode.randomize_initial = randomize_initial;
          o.episode.scripted_operator = scripted_operator;
          std::vector<batch::EpisodeRecord> records;
          {
            py::gil_scoped_release release;
            records = batch::run_batch(s, list, o);
          }
          std::ostringstream out;
          for (const auto& r : records) batch::write_record(out, r);
          return out.str();
        },
        py::arg("scenario"), py::arg("trials"), py::kw_only(), py::arg("world") = "symbolic", py::arg("jobs") = 1,
        py::arg("max_time") = 900.0, py::arg("cost") = "euclid", py::arg("randomize_initial") = true,
        py::arg("scripted_operator") = false,
        "Runs trials (tuples from make_trials) as `rtamp batch` does and returns their CSV rows (no\n"
        "header), in the order given. The GIL is released while they run.");
  m.def("csv_columns", &batch::csv_columns, "The columns of the batch CSV, in order.");
  m.def("merge_csv",
        [](const std::vector<std::string>& slices) {
          std::ostringstream header;
          batch::write_header(header);
          std::vector<batch::EpisodeRecord> all;
          for (std::size_t i = 0; i < slices.size(); ++i) {
            auto rows = batch::read_csv(header.str() + slices[i], "slice " + std::to_string(i + 1));
            all.insert(all.end(), rows.begin(), rows.end());
          }
          batch::sort_canonical(all);
          for (std::size_t i = 1; i < all.size(); ++i)
            if (all[i - 1].key() == all[i].key()) throw Error("two rows for " + batch::describe_key(all[i]));
          std::ostringstream out;
          batch::write_csv(out, all);
          return out.str();
        },
        py::arg("slices"),
        "The batch CSV (header and rows in canonical order, as `rtamp batch` writes it) from CSV row\n"
        "slices without header (run_trials output). Two rows for one trial are an rtamp.Error.");
}

}  // namespace rtamp::python
