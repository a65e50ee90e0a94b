// rtamp ltl2ba — translate LTL formulas to Büchi automata (paper Section II:
// the automaton A_φ of the specification), printed as HOA, DOT, a spin never
// claim or one line of statistics per formula. Formulas come from the command
// line or, one per line, from files (-F), like Spot's ltl2tgba.
#include <chrono>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>

#include "command.hpp"
#include "rtamp/automata/dot_writer.hpp"
#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/hoa_writer.hpp"
#include "rtamp/automata/never_claim_writer.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/text_file.hpp"

namespace {

struct Ltl2baArgs {
  std::vector<std::string> formulas;
  std::vector<std::string> files;
  std::string format = "hoa";
  bool gba = false;
  bool tba = false;
  bool no_simplify = false;
  bool no_reduce = false;
  bool no_split = false;
};

struct Job {
  std::string text;
  rtamp::SourceLocation origin;  // where the text starts (for error locations)
};

const char* kFooter = R"(FORMULA SYNTAX (Spot's and spin/ltl2ba's, mixed freely)
  constants    true false 1 0
  atoms        [a-z_][a-zA-Z0-9_.]*, or "double quoted" (any text, e.g. "o1 in r2";
               \" and \\ escape)
  unary        ! ~ (not)   X (next)   F <> (eventually)   G [] (always)
  binary       & && /\ (and)   | || \/ (or)   xor ^   -> => (implies)
               <-> <=> (equivalent)   U (until)   R V (release)
               W (weak until)   M (strong release)
  Upper-case X F G U R V W M are always operators ("GFa" is G F a).
  Precedence, loosest first: -> <-> (right assoc.) < | < xor < & < U R W M
  (right assoc.) < unary operators. Parentheses group.
  Examples: 'G(req -> F grant)'  '[]<>a && []<>b'  'F G "o1 in r2"'

INPUT
  Formulas given as arguments are translated in order. With -F FILE (repeatable;
  '-' is standard input) each line is a formula; blank lines and lines whose
  first non-blank character is '#' are skipped. One automaton is printed per
  formula, in input order. A formula that does not parse is reported on stderr
  as FILE:LINE:COLUMN with a caret, the others are still translated, and the
  exit code is then 2.

OUTPUT FORMATS (--format)
  hoa     HOA v1 (Hanoi Omega-Automata), readable by Spot's autfilt and Owl.
          Default: state-based Büchi (acc-name: Buchi, state-acc); with --gba a
          transition-based generalized Büchi automaton (marks on edges); with
          --tba a transition-based Büchi automaton (acc-name: Buchi, trans-acc,
          one set on edges: what `rtamp plan --transition-based` searches).
          Labels use AP indices: [0&!1]. The formula is the name: header.
  dot     Graphviz: accepting states are double circles, TGBA edges show their
          acceptance sets in braces. Render with: | dot -Tsvg > a.svg
  never   a spin never claim (state-based only; atoms must be identifiers).
  stats   a header line, then one tab-separated line per formula:
          states edges sets time_us status formula
          (time_us: translation time in microseconds, parsing excluded;
          status: satisfiable or unsatisfiable — an unsatisfiable formula
          gives the empty automaton, one state without edges).

EXIT STATUS
  0 success, 2 bad input (bad formula, unreadable file, bad option).)";

std::vector<Job> read_formula_file(const std::string& path) {
  std::string text;
  const std::string name = path == "-" ? "<stdin>" : path;
  if (path == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  } else {
    text = rtamp::read_text_file(path, "the formula file (-F)");
  }
  std::vector<Job> jobs;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    jobs.push_back({line, rtamp::SourceLocation{name, number, 1}});
  }
  return jobs;
}

int run(const Ltl2baArgs& args) {
  using namespace rtamp;
  if (args.gba && args.tba) throw Error("--gba and --tba exclude each other: choose one acceptance form");
  if (args.format == "never" && (args.gba || args.tba))
    throw Error(std::string("--format never needs a state-based Büchi automaton: drop ") +
                (args.gba ? "--gba" : "--tba"));
  if (args.formulas.empty() && args.files.empty())
    throw Error("no formula: give one as an argument or use -F FILE (see rtamp ltl2ba --help)");
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < args.formulas.size(); ++i) {
    const std::string name = args.formulas.size() == 1 ? "<formula>" : "<formula " + std::to_string(i + 1) + ">";
    jobs.push_back({args.formulas[i], SourceLocation{name, 1, 1}});
  }
  for (const std::string& f : args.files) {
    std::vector<Job> more = read_formula_file(f);
    jobs.insert(jobs.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
  }
  automata::TranslateOptions opt;
  opt.state_based = !args.gba && !args.tba;
  opt.one_set = args.tba;
  opt.simplify = !args.no_simplify;
  opt.reduce = !args.no_reduce;
  if (args.no_split) opt.splitting = automata::Splitting::Never;
  bool failed = false;
  std::ostringstream out;
  if (args.format == "stats") out << "states\tedges\tsets\ttime_us\tstatus\tformula\n";
  for (const Job& job : jobs) {
    try {
      const ltl::Formula f = ltl::parse(job.text, job.origin);
      automata::Automaton a;
      try {
        const auto t0 = std::chrono::steady_clock::now();
        a = automata::translate(f, opt);
        const auto t1 = std::chrono::steady_clock::now();
        if (args.format == "stats") {
          const auto us = std::chrono::duration_cast<std::chrono::microseconds>(t1 - t0).count();
          out << a.num_states() << '\t' << a.num_edges() << '\t' << (a.state_based ? 1u : a.num_sets) << '\t' << us
              << '\t' << (automata::is_empty(a) ? "unsatisfiable" : "satisfiable") << '\t' << ltl::to_string(f)
              << '\n';
        } else if (args.format == "hoa") {
          automata::write_hoa(out, a);
        } else if (args.format == "dot") {
          automata::write_dot(out, a);
        } else {
          automata::write_never_claim(out, a);
        }
      } catch (const Error& e) {
        // Translation/output errors carry no position: name the formula's.
        throw Error(e.message(), job.origin, e.detail());
      }
    } catch (const Error& e) {
      rtamp::cli::report_error(e);
      failed = true;
    }
    // Stream large batches instead of holding every automaton in memory.
    if (out.tellp() > (1 << 16)) {
      std::cout << out.str();
      out.str({});
    }
  }
  std::cout << out.str();
  std::cout.flush();
  if (!std::cout) throw Error("cannot write to standard output");
  return failed ? 2 : 0;
}

rtamp::cli::Registrar reg{
    "ltl2ba", "Translate LTL formulas to Büchi automata (HOA, DOT, never claim or statistics)",
    [](CLI::App& sub) -> rtamp::cli::Action {
      auto args = std::make_shared<Ltl2baArgs>();
      sub.add_option("formula", args->formulas, "LTL formula(s), e.g. 'G(a -> F b)'");
      sub.add_option("-F,--file", args->files, "Read formulas from FILE, one per line ('-': standard input)");
      sub.add_option("--format", args->format, "Output format: hoa, dot, never or stats")
          ->check(CLI::IsMember({"hoa", "dot", "never", "stats"}))
          ->capture_default_str();
      sub.add_flag("--gba", args->gba, "Transition-based generalized Büchi automaton instead of a state-based BA");
      sub.add_flag("--tba", args->tba,
                   "Transition-based Büchi automaton (one acceptance set, on edges) instead of a state-based BA");
      sub.add_flag("--no-simplify", args->no_simplify, "Do not simplify the formula before translating");
      sub.add_flag("--no-reduce", args->no_reduce, "Do not reduce the automaton (simulation, merging) after translating");
      sub.add_flag("--no-split", args->no_split, "Do not translate the parts of a top-level & or | separately");
      sub.footer(kFooter);
      return [args]() -> int { return run(*args); };
    }};

}  // namespace
