// rtamp gen — write a generated scenario (world/generator.hpp) as YAML, for the
// planning benchmarks: e.g. `rtamp gen --regions 5 --objects 6 --layout random --seed 3`.
#include <fstream>
#include <iostream>

#include "command.hpp"
#include "rtamp/util/output_file.hpp"
#include "options.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

struct GenArgs {
  int regions = 2;
  int objects = 3;
  int containers = 0;
  std::string layout = "line";
  std::uint64_t seed = 1;
  std::string task;
  std::vector<std::string> props;
  std::string output;
};

rtamp::cli::Registrar reg{
    "gen", "Generate a scenario (regions r1..rM, objects o1..oN in r1) and print it as YAML",
    [](CLI::App& sub) -> rtamp::cli::Action {
      auto args = std::make_shared<GenArgs>();
      rtamp::cli::add_integer(sub, "--regions,-m", args->regions, 1, 64, "Number of regions M");
      rtamp::cli::add_integer(sub, "--objects,-n", args->objects, 1, 256, "Number of objects N, all starting in r1");
      sub.add_option("--layout", args->layout, "Region layout: line (0.5 m apart) or random (1 m square)")
          ->check(CLI::IsMember({"line", "random"}))
          ->capture_default_str();
      rtamp::cli::add_seed(sub, "--seed", args->seed, "Seed of the random layout");
      sub.add_option("--task", args->task, "LTL task (default: F G all_in_r2, all_in_r2 = \"all block in r2\")");
      rtamp::cli::add_integer(sub, "--containers,-c", args->containers, 0, 64,
                              "Number of trays t1..tC, one per region rM, rM-1, ...");
      sub.add_option("--prop", args->props, "Extra proposition NAME=EXPR, e.g. --prop 'o1_in_r3=o1 in r3' (repeatable)");
      sub.add_option("--output,-o", args->output, "Write to this file instead of standard output");
      return [args]() -> int {
        rtamp::world::GeneratorOptions o;
        o.regions = args->regions;
        o.objects = args->objects;
        o.containers = args->containers;
        o.layout = rtamp::world::parse_layout(args->layout);
        o.seed = args->seed;
        o.task = args->task;
        o.task_where = {"--task", 1, 1};
        for (std::size_t i = 0; i < args->props.size(); ++i) {
          const std::string& p = args->props[i];
          const std::string where = "--prop #" + std::to_string(i + 1);
          const auto eq = p.find('=');
          if (eq == std::string::npos || eq == 0)
            throw rtamp::Error("must be NAME=EXPRESSION, e.g. 'o1_in_r3=o1 in r3'", {where, 1, 1},
                               rtamp::caret_at(p, eq == 0 ? 0 : p.size()));
          o.propositions.emplace_back(p.substr(0, eq), p.substr(eq + 1));
          o.proposition_where.push_back({where, 1, static_cast<int>(eq) + 2});
        }
        // The scenario is checked as a file of it would be (the task too) before anything is written.
        const rtamp::world::Scenario scenario = rtamp::world::generate_scenario(o);
        rtamp::task::validate_task(scenario);
        if (!args->output.empty()) rtamp::cli::check_output_file("--output", args->output);
        const std::string yaml = rtamp::world::to_yaml(scenario);
        if (args->output.empty()) {
          std::cout << yaml;
          std::cout.flush();
          if (!std::cout) throw rtamp::Error("cannot write to standard output");
        } else {
          rtamp::write_output_file(args->output, "--output", yaml);
        }
        return 0;
      };
    }};

}  // namespace
