#include "options.hpp"

#include "rtamp/util/output_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "rtamp/plan/registry.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::cli {

namespace {

std::string shown(std::string_view text) { return world::quoted(escape_text(text)); }

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// CLI11 calls option callbacks with the option's text; errors become ValidationErrors.
template <typename F>
void as_validation(const std::string& name, F&& f) {
  try {
    f();
  } catch (const Error& e) {
    throw CLI::ValidationError(name, e.what());
  }
}

std::string choice_help(const std::string& description, const std::vector<Choice>& choices) {
  std::string out = description;
  bool described = false;
  for (const auto& c : choices) described = described || !c.description.empty();
  if (!described) {
    out += " (";
    for (std::size_t i = 0; i < choices.size(); ++i) out += (i ? ", " : "") + choices[i].name;
    return out + ")";
  }
  for (const auto& c : choices) out += "\n  " + c.name + (c.description.empty() ? "" : ": " + c.description);
  return out;
}

CLI::Validator choice_validator(const std::vector<Choice>& choices) {
  std::vector<std::string> names;
  for (const auto& c : choices) names.push_back(c.name);
  return CLI::Validator(
      [names](std::string& value) -> std::string {
        if (std::find(names.begin(), names.end(), value) != names.end()) return {};
        return "unknown value " + shown(value) + world::suggestion(escape_text(value), names);
      },
      "");  // the help text lists the names
}

}  // namespace

std::string RealRange::text() const {
  std::string out;
  const bool no_max = max >= std::numeric_limits<double>::max();
  if (no_max) {
    out = (min_open ? "> " : ">= ") + format_number(min);
  } else {
    out = (min_open ? "in (" : "in [") + format_number(min) + ", " + format_number(max) + "]";
  }
  if (allow_inf) out += std::string(" or inf (") + inf_means + ")";
  return out;
}

double parse_real(std::string_view text, const RealRange& range) {
  const std::string l = lower(text);
  double v = 0;
  if (l == "inf" || l == "+inf" || l == "infinity" || l == "+infinity") {
    if (!range.allow_inf) throw Error("must be a finite number " + range.text() + ", found " + shown(text));
    return std::numeric_limits<double>::infinity();
  }
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+') ++b;
  const auto [p, ec] = std::from_chars(b, e, v);
  if (b == e || ec == std::errc::invalid_argument || p != e || std::isnan(v) || std::isinf(v))
    throw Error("expected a number " + range.text() + ", found " + shown(text));
  if (ec == std::errc::result_out_of_range)
    throw Error("number out of range: " + shown(text) + " (expected " + range.text() + ")");
  const bool below = range.min_open ? !(v > range.min) : !(v >= range.min);
  if (below || v > range.max) throw Error("must be " + range.text() + ", found " + shown(text));
  return v;
}

std::string integer_range(long long min, long long max) {
  if (max == std::numeric_limits<long long>::max()) return ">= " + std::to_string(min);
  return "in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
}

long long parse_integer(std::string_view text, long long min, long long max) {
  const std::string range = integer_range(min, max);
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+') ++b;
  long long v = 0;
  const auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc::result_out_of_range) throw Error("must be an integer " + range + ", found " + shown(text));
  if (b == e || ec != std::errc() || p != e) throw Error("expected an integer " + range + ", found " + shown(text));
  if (v < min || v > max) throw Error("must be an integer " + range + ", found " + shown(text));
  return v;
}

std::uint64_t parse_seed(std::string_view text) {
  const char* b = text.data();
  const char* e = b + text.size();
  std::uint64_t v = 0;
  const bool digits = b != e && std::all_of(b, e, [](char c) { return c >= '0' && c <= '9'; });
  const auto [p, ec] = std::from_chars(b, e, v);
  if (!digits || ec != std::errc() || p != e)
    throw Error("a seed is an integer in [0, 18446744073709551615], found " + shown(text));
  return v;
}

CLI::Option* add_real(CLI::App& app, const std::string& name, double& target, const RealRange& range,
                      const std::string& description) {
  const std::string key = name.substr(0, name.find(','));
  auto* opt = app.add_option_function<std::string>(
      name, [&target, range, key](const std::string& s) { as_validation(key, [&] { target = parse_real(s, range); }); },
      description + ", " + range.text());
  opt->type_name("NUMBER")->default_str(format_number(target));
  return opt;
}

CLI::Option* add_integer_with(CLI::App& app, const std::string& name, std::function<void(long long)> store,
                              long long min, long long max, const std::string& default_text,
                              const std::string& description) {
  const std::string key = name.substr(0, name.find(','));
  const std::string range = integer_range(min, max);
  auto* opt = app.add_option_function<std::string>(
      name,
      [store = std::move(store), min, max, key](const std::string& s) {
        as_validation(key, [&] { store(parse_integer(s, min, max)); });
      },
      description + ", an integer " + range);
  opt->type_name("INT")->default_str(default_text);
  return opt;
}

world::TaskChange parse_new_task(std::string_view text, int occurrence) {
  const std::size_t at = text.find('@');
  if (at == std::string_view::npos)
    throw Error("expected TIME@LTL, a new task at a world time (e.g. '12@F G all_in_r3'), found " + shown(text));
  world::TaskChange c;
  try {
    c.time = parse_real(text.substr(0, at), RealRange{});
  } catch (const Error& e) {
    throw Error("the time before '@': " + e.message());
  }
  c.task = std::string(text.substr(at + 1));
  if (c.task.find_first_not_of(" \t\r\n") == std::string::npos)
    throw Error("no formula after '@' (e.g. '12@F G all_in_r3')");
  const std::string option = "--new-task #" + std::to_string(occurrence);
  c.task_where = SourceLocation{option, 1, static_cast<int>(at) + 2};
  c.where = SourceLocation{option, 1, 1};
  c.by = "command line";
  return c;
}

CLI::Option* add_new_task(CLI::App& app, std::vector<world::TaskChange>& target) {
  auto* opt = app.add_option_function<std::vector<std::string>>(
      "--new-task",
      [&target](const std::vector<std::string>& v) {
        for (const std::string& s : v)
          as_validation("--new-task", [&] { target.push_back(parse_new_task(s, static_cast<int>(target.size()) + 1)); });
      },
      "A new task at world time TIME (repeatable): from then on the episode works towards LTL instead, its "
      "propositions the scenario's or quoted expressions (docs/exec.md \"A new task\")");
  opt->type_name("TIME@LTL")->allow_extra_args(false);
  return opt;
}

CLI::Option* add_seed(CLI::App& app, const std::string& name, std::uint64_t& target, const std::string& description) {
  const std::string key = name.substr(0, name.find(','));
  auto* opt = app.add_option_function<std::string>(
      name, [&target, key](const std::string& s) { as_validation(key, [&] { target = parse_seed(s); }); },
      description + ", unsigned 64-bit");
  opt->type_name("SEED")->default_str(std::to_string(target));
  return opt;
}

std::vector<Choice> algorithm_choices() {
  std::vector<Choice> out;
  for (const auto& a : plan::algorithms()) out.push_back({a.name, a.description});
  return out;
}

std::vector<Choice> cost_model_choices() {
  std::vector<Choice> out;
  for (const auto& c : plan::cost_models()) out.push_back({c.name, c.description});
  return out;
}

CLI::Option* add_choice(CLI::App& app, const std::string& name, std::string& target, const std::vector<Choice>& choices,
                        const std::string& description) {
  auto* opt = app.add_option(name, target, choice_help(description, choices));
  opt->check(choice_validator(choices))->type_name("NAME")->default_str(target);
  return opt;
}

CLI::Option* add_choice_with(CLI::App& app, const std::string& name, const std::vector<Choice>& choices,
                             const std::string& default_name, std::function<void(const std::string&)> store,
                             const std::string& description) {
  const std::string key = name.substr(0, name.find(','));
  auto* opt = app.add_option_function<std::string>(
      name, [store = std::move(store), key](const std::string& s) { as_validation(key, [&] { store(s); }); },
      choice_help(description, choices));
  opt->check(choice_validator(choices))->type_name("NAME")->default_str(default_name);
  return opt;
}

CLI::Option* add_choices(CLI::App& app, const std::string& name, std::vector<std::string>& target,
                         const std::vector<Choice>& choices, const std::string& description) {
  auto* opt = app.add_option(name, target, choice_help(description, choices));
  opt->check(choice_validator(choices))->type_name("NAME");
  return opt;
}

CLI::Option* add_scenario(CLI::App& app, std::string& target) {
  std::string names;
  std::vector<std::string> builtins = world::builtin_scenario_names();
  std::sort(builtins.begin(), builtins.end());
  for (const auto& n : builtins) names += (names.empty() ? "" : ", ") + n;
  return app.add_option("scenario", target, "A scenario YAML file or a built-in scenario: " + names)
      ->type_name("SCENARIO");
}

void check_output_file(const std::string& option, const std::string& path) { rtamp::check_output(path, option); }

void check_output_dir(const std::string& option, const std::string& dir) {
  namespace fs = std::filesystem;
  auto fail = [&](const std::string& why) {
    throw Error(option + ": cannot write into " + shown(dir) + ": " + why);
  };
  if (dir.empty()) fail("empty path");
  std::error_code ec;
  fs::path p = fs::absolute(fs::path(dir), ec);
  if (ec) fail(ec.message());
  // The nearest part of the path that exists must be a directory we may write into.
  while (!fs::exists(fs::symlink_status(p, ec)) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec)) fail(shown(p.string()) + " is not a directory");
  if (::access(p.c_str(), W_OK | X_OK) != 0) fail(std::error_code(errno, std::generic_category()).message());
}

std::vector<Choice> mcap_profile_choices() {
  return {{"json", "JSON messages with JSON Schemas, Foxglove's conventions (default)"},
          {"ros2", "the MCAP ros2 profile: CDR messages, ros2msg schemas, ROS 2's topics (ros2 bag play)"}};
}

std::vector<Choice> mcap_compression_choices() {
  return {{"zstd", "Zstandard (default)"}, {"lz4", "LZ4 frames"}, {"none", "uncompressed chunks"}};
}

}  // namespace rtamp::cli
