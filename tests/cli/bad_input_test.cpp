// A table of bad inputs for every entry point of the rtamp binary (the checks of
// "How it is checked"): scenario files (malformed, hostile and wrong YAML;
// operator scripts), the LTL task and its quoted atoms through plan, run,
// batch and sim, `plan --change`, `sim --do`, `gen --task` / `--prop`, and
// hostile LTL for ltl2ba, outputs (one that is an input or another output, a
// locked file, a FIFO without a reader, an unwritable --log-dir, --resume of
// another batch) and logs `log to-mcap` must refuse. For every case the
// binary must exit with status 2 (not a signal, not a crash), say `rtamp:
// error: WHERE: WHAT` on stderr with the expected location (file:line:col, or
// option #occurrence:1:col) as its first line (further lines only the input
// and its caret), print nothing on stdout, create none of the output files it
// was given (so nothing was written and no episode started: an episode's log
// would exist), and change no existing file it names (kind and contents
// hashed before and after).
//
// The binary runs through fork/exec with an argument vector (no shell), so
// arguments carry control bytes and quotes as they are; a child that runs
// longer than 120 s is killed (a hang fails the case instead of the suite).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "run_cli.hpp"

namespace rtamp::cli::testing {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  bool exited = false;
  int code = -1;
  int signal = 0;
  std::string out, err;
};

Outcome run_argv(const std::vector<std::string>& args) {
  const fs::path dir = scratch();
  const std::string out = (dir / "bad.out").string(), err = (dir / "bad.err").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in = ::open("/dev/null", O_RDONLY);
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || o < 0 || e < 0) ::_exit(127);
    ::dup2(in, 0);
    ::dup2(o, 1);
    ::dup2(e, 2);
    ::chdir(dir.c_str());
    ::alarm(120);  // a hang ends in SIGALRM: the case fails, the suite goes on
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(RTAMP_BIN));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(RTAMP_BIN, argv.data());
    ::_exit(127);
  }
  Outcome r;
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) != pid) return r;
  r.exited = WIFEXITED(status);
  if (r.exited) r.code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

struct Case {
  std::string group;
  std::vector<std::string> args;
  std::string where;  // in the first line of stderr, e.g. "c3.yaml:13:12:" or "--change #2:1:14:"
  std::string what;   // in the first line too (optional)
  std::vector<std::string> not_created;  // names in the scratch directory that must not exist afterwards
  std::vector<std::string> unchanged;    // paths whose kind and contents must be the same afterwards
};

// What a path is, for "no existing file changed": its type and its contents' hash.
std::string fingerprint(const std::string& path) {
  struct stat st{};
  if (::lstat(path.c_str(), &st) != 0) return "absent";
  if (!S_ISREG(st.st_mode)) return "mode " + std::to_string(st.st_mode) + " rdev " + std::to_string(st.st_rdev);
  return "file " + std::to_string(std::hash<std::string>{}(slurp(path))) + " size " + std::to_string(st.st_size);
}

// ---------------------------------------------------------------- inputs

int g_files = 0;

// Writes `text` to a new file in the scratch directory; returns its path.
std::string file(const std::string& text, const std::string& ext = ".yaml") {
  const fs::path p = scratch() / ("in" + std::to_string(++g_files) + ext);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}
std::string name_of(const std::string& path) { return fs::path(path).filename().string(); }

// A valid scenario (the 3-block-tray scene, flow style); the task is on line 13
// and its text starts at column 7; `tail` goes after it (e.g. an operator).
const char* kHead =
    "name: t\n"                                                                                          // 1
    "regions:\n"                                                                                         // 2
    "  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 4}\n"                         // 3
    "  - {name: r2, center: [0.40, -0.32, 0], size: [0.36, 0.36], capacity: 4}\n"                        // 4
    "containers:\n"                                                                                      // 5
    "  - {name: r3, class: tray, position: [0.40, 0.25, 0], size: [0.30, 0.16, 0.03], capacity: 3}\n"    // 6
    "objects:\n"                                                                                         // 7
    "  - {name: o1, class: block, position: [0.32, 0.40, 0], size: [0.04, 0.04, 0.04]}\n"                // 8
    "  - {name: o2, class: block, position: [0.40, 0.40, 0], size: [0.04, 0.04, 0.04]}\n"                // 9
    "  - {name: o3, class: block, position: [0.48, 0.40, 0], size: [0.04, 0.04, 0.04]}\n"                // 10
    "propositions:\n"                                                                                    // 11
    "  all_in_r2: \"all block in r2\"\n";                                                                // 12
constexpr int kTaskLine = 13;

std::string scenario(const std::string& task = "F G all_in_r2", const std::string& tail = "") {
  return std::string(kHead) + "task: " + task + "\n" + tail;
}

// The base scenario with line `line` (1-based) replaced by `text`.
std::string with_line(int line, const std::string& text) {
  std::string s = scenario();
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = s.find('\n', start) + 1;
  const std::size_t end = s.find('\n', start);
  return s.substr(0, start) + text + s.substr(end);
}

// "FILE:LINE:COL:" of the first `word` (from `from`) in line `line` of `text` written to `path`.
std::string at(const std::string& path, const std::string& text, int line, const std::string& word,
               std::size_t from = 0) {
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  const std::string l = text.substr(start, text.find('\n', start) - start);
  const std::size_t col = l.find(word, from);
  EXPECT_NE(col, std::string::npos) << word << " not in " << l;
  return name_of(path) + ":" + std::to_string(line) + ":" + std::to_string(col + 1) + ":";
}

// ---------------------------------------------------------------- the table

void yaml_cases(std::vector<Case>& t) {
  auto add = [&](const std::string& text, int line, const std::string& word, const std::string& what) {
    const std::string p = file(text);
    t.push_back({"yaml", {"plan", p}, at(p, text, line, word), what});
  };
  auto add_file = [&](const std::string& text, const std::string& where, const std::string& what) {
    const std::string p = file(text);
    t.push_back({"yaml", {"plan", p}, name_of(p) + where, what});
  };
  add_file("", ":1:1:", "empty");
  add_file("# only a comment\n\n", ":1:1:", "empty");
  add_file("---\n...\n", ":1:1:", "empty");
  {
    std::string garbage;
    for (int i = 0; i < 512; ++i) garbage += static_cast<char>((i * 131 + 7) % 256);
    add_file(garbage, ":", "");
  }
  add_file(std::string("name: t\0x\n", 10), ":", "");
  add_file(std::string(100000, '['), ":", "");
  add_file(std::string(100000, '{'), ":", "");
  add_file("- a\n- b\n", ":1:1:", "a scenario must be a mapping");
  add_file(scenario() + "---\nname: u\n", ":14:1:", "more than one YAML document");
  {  // a billion laughs: aliases that would expand to 10^9 nodes
    std::string s = "a: &a [x, x, x, x, x, x, x, x, x, x]\n";
    for (char c = 'b'; c <= 'i'; ++c)
      s += std::string(1, c) + ": &" + c + " [*" + char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) + ", *" +
           char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) + ", *" + char(c - 1) +
           ", *" + char(c - 1) + ", *" + char(c - 1) + "]\n";
    add_file(s, ":1:1:", "unknown key 'a' in scenario");
  }
  add_file(std::string(17u << 20, ' '), ":", "too large");
  add(with_line(3, "  - {name: r1, center: [1e400, 0.32, 0], size: [0.36, 0.36], capacity: 4}"), 3, "1e400",
      "must be a number");
  add(with_line(3, "  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: \"6\"}"), 3, "\"6\"",
      "must be an integer");
  add(with_line(3, "  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 99999999999}"), 3,
      "99999999999", "out of range");
  add(with_line(3, "  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 0}"), 3, "0}",
      "at least 1");
  add(with_line(3, "  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36], capasity: 4}"), 3, "capasity",
      "did you mean 'capacity'?");
  add(with_line(3, "  - {name: r1, name: r5, center: [0.40, 0.32, 0], size: [0.36, 0.36]}"), 3, "name: r5",
      "duplicate key");
  add(with_line(3, "  - {name: in, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 4}"), 3, "in,",
      "reserved word");
  add(with_line(3, "  - {name: none, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 4}"), 3, "none",
      "reserved word");
  add(with_line(8, "  - {name: o1, class: object, position: [0.32, 0.40, 0]}"), 8, "object,", "reserved");
  add(with_line(8, "  - {name: o1, class: tray, position: [0.32, 0.40, 0]}"), 6, "tray", "is also the class of objects");
  add(with_line(4, "  - {name: r2, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 4}"), 4, "{",
      "overlaps region 'r1'");
  add(with_line(8, "  - {name: o1, class: block, position: [0.9, 0.9, 0]}"), 8, "[0.9", "outside every region");
  add(with_line(8, "  - {name: " + std::string(10000, 'x') + ", class: block, position: [0.32, 0.40, 0]}"), 8,
      "xxx", "not an identifier");
  add(with_line(8, "  - {name: \"o 1\", class: block, position: [0.32, 0.40, 0]}"), 8, "\"o 1\"",
      "not an identifier");
  add(with_line(8, "  - {name: o2, class: block, position: [0.32, 0.40, 0]}"), 9, "o2", "duplicate name 'o2'");
  add(with_line(8, "  - {name: \"o\\x07\", class: block, position: [0.32, 0.40, 0]}"), 8, "\"o", "not an identifier");
  add(with_line(12, "  all_in_r2: \"all blok in r2\""), 12, "blok", "did you mean 'block'?");
  add(with_line(12, "  all_in_r2: \"all block in (\""), 12, "(\"", "expected a location name");
  {  // the text starts at column 15; the 201st '(' is too deep
    const std::string p = file(with_line(12, "  all_in_r2: \"" + std::string(300, '(') + "o1 in r2" + std::string(300, ')') + "\""));
    t.push_back({"yaml", {"plan", p}, name_of(p) + ":12:215:", "nested too deeply"});
  }
  add(with_line(12, "  All_in_r2: \"all block in r2\""), 12, "All", "not a valid atom");
  add(with_line(12, "  o1: \"all block in r2\""), 12, "o1", "has the name of an object");
  add(with_line(12, "  all_in_r2: \"o1 in r9\""), 12, "r9", "unknown location 'r9'");
  add(with_line(12, "  all_in_r2: \"count block in r2 >= 99999999\""), 12, "99999999", "too large");
  add(with_line(1, "name: t\nrobot: {model: ur10}"), 2, "ur10", "unknown robot model");
  add(with_line(3, "  - {name: r1, center: [0.40, 0.32, 0], size: [-0.36, 0.36], capacity: 4}"), 3, "[-0.36",
      "must be positive");
  add(with_line(3, "  - {name: r1, center: [1e6, 0.32, 0], size: [0.36, 0.36], capacity: 4}"), 3, "[1e6",
      "out of range");
  add(with_line(3, "  - {name: r1, center: \"here\", size: [0.36, 0.36], capacity: 4}"), 3, "\"here\"",
      "must be a list");
  add(with_line(8, "  - {name: o1, class: block, position: [0.32, 0.40, 0], size: [0.04, 0.04]}"), 8, "[0.04, 0.04]",
      "must be a list [x, y, z]");
  add_file("name: t\nregions: 5\nobjects: []\ntask: F G p\n", ":2:10:", "must be a list");
  add(with_line(8, "  - {name: o1, class: block, position: [0.32, 0.40, 0], colour: red}"), 8, "colour",
      "unknown key 'colour'");
  add(with_line(8, "  - {name: o1, class: block}"), 8, "{", "missing the required key 'position'");
  add(with_line(8, "  - {[a]: 1, name: o1, class: block, position: [0.32, 0.40, 0]}"), 8, "[a]", "must be words");
  add_file(with_line(8, "\t- {name: o1, class: block, position: [0.32, 0.40, 0]}"), ":8:", "invalid YAML");
  add(with_line(1, "name: t\ndescription: \"\xff\xfe bad\""), 2, "\"", "UTF-8");
  {
    add_file(scenario("\"\""), ":13:8:", "the task is empty");
  }
  {
    const std::string s = scenario("{a: 1}");
    add(s, kTaskLine, "{", "must be text");
  }
  // Operator scripts.
  auto op = [&](const std::string& action, const std::string& word, const std::string& what) {
    const std::string s = scenario("F G all_in_r2", "operator:\n  - " + action + "\n");
    add(s, kTaskLine + 2, word, what);
  };
  op("{time: 5, action: relocat, object: o1, to: r2}", "relocat", "did you mean 'relocate'?");
  op("{time: -1, action: relocate, object: o1, to: r2}", "-1", "time must be a finite number");
  op("{time: .nan, action: relocate, object: o1, to: r2}", ".nan", "");
  op("{time: 5, action: take_from_gripper, object: o1, to: r2}", "object:", "unknown key 'object'");
  op("{time: 5, action: relocate, object: o1, to: r9}", "r9", "unknown location 'r9'");
  op("{time: 5, action: relocate, object: o9, to: r2}", "o9", "unknown object or container 'o9'");
  op("{time: 5, action: add, object: o9, class: object, to: r2}", "object,", "reserved");
  op("{time: 5, action: add, object: in, to: r2}", "in,", "reserved word");
  op("{time: 5, action: remove, object: o9}", "o9", "unknown object 'o9'");
  op("{time: 5, action: remove, object: r3}", "r3", "use remove_container");
  op("{time: 5, action: add, object: o1, to: r2}", "o1", "already exists");
  op("{time: 5, action: add_container, container: t2, to: r3}", "r3", "do not nest");
  op("{time: 5, action: relocate, object: o1, to: r2, position: [0.4, 0.32, 0]}", "[0.4", "not inside region 'r2'");
  op("{time: 5, action: relocate, object: o1, position: [3, 0.32, 0]}", "[3", "position [3, 0.32, 0] is off the table");
  op("{time: 5, action: add, object: o9, class: block, position: [0.4, 0.32, -3]}", "[0.4", "is below the table top");
  op("{time: 5, action: add, object: o9, class: block, position: [0.4, 0.32, 3]}", "[0.4", "is 3 m above the table top");
  op("{time: 5, action: relocate, object: o1, to: r2, speed: 3}", "speed", "unknown key 'speed'");
}

struct TaskError {
  std::string task, word, what;
};

const std::vector<TaskError>& task_errors() {
  static const std::vector<TaskError> t = {
      {"F G \"all blocks in r2\"", "blocks", "unknown class 'blocks' (did you mean 'block'?)"},
      {"F G \"o1 in r9\"", "r9", "unknown location 'r9'"},
      {"F G \"o1 in (\"", "(", "expected a location name"},
      {"F G \"o9 in r2\"", "o9", "unknown object 'o9'"},
      {"F G all_in_r3", "all_in_r3", "did you mean 'all_in_r2'?"},
      {"F G o1", "o1", "'o1' is an object"},
      {"F G (all_in_r2", "(", "missing ')'"},
      {"F G \"r1 in r2\"", "r1", "'r1' is a region"},
      {"F G \"o1 in o2\"", "o2", "'o2' is an object, not a location"},
      {"F G \"count block in r2 >= 99999999\"", "99999999", "too large"},
      {"F G \"\"", "\"", "empty quoted atomic proposition"},
      {"F G \"o1 in r2", "\"", "unterminated"},
      {"F G all_in_r2 & F nothing", "nothing", "not a proposition of the scenario"},
      {"F G \"all block in r2\" & G !\"o1 in r9\"", "r9", "unknown location 'r9'"},
      {"F G All", "All", "unexpected 'A'"},
      {"F G 2", "2", "the only numbers"},
      {"F G \"all_in_r2 | o1 in r2\"", "|", "expected 'in' after 'all_in_r2'"},
      {"F G \"any blocks in r2\" | F \"all block in r2\"", "blocks", "unknown class 'blocks'"},
      {"G (\"o1 in r2\" -> F \"o1 in r7\")", "r7", "unknown location 'r7'"},
      {"F G \"all tray in r9\"", "r9", "unknown location 'r9'"},
  };
  return t;
}

void task_cases(std::vector<Case>& t) {
  // Each task error through every command that reads the scenario.
  for (const TaskError& e : task_errors()) {
    const std::string s = scenario(e.task);
    const std::string p = file(s);
    const std::string where = at(p, s, kTaskLine, e.word, 6);
    t.push_back({"task/plan", {"plan", p}, where, e.what});
    t.push_back({"task/plan", {"plan", p, "--json", "--change", "move o1 r2"}, where, e.what});
    t.push_back({"task/run", {"run", p, "--world", "symbolic", "--log", "ep.jsonl", "--trees", "trees"}, where,
                 e.what, {"ep.jsonl", "trees"}});
    t.push_back({"task/batch", {"batch", p, "--trials", "1", "--world", "symbolic", "-o", "b.csv"}, where, e.what,
                 {"b.csv"}});
    t.push_back({"task/sim", {"sim", p, "--do", "move o1 r2", "--mjcf", "m.xml"}, where, e.what, {"m.xml"}});
    t.push_back({"task/serve", {"serve", p, "--world", "symbolic", "--port", "0", "--log", "sv.jsonl"}, where, e.what,
                 {"sv.jsonl"}});
  }
  // The MuJoCo world: refused before MuJoCo starts, no video, no log.
  {
    const std::string s = scenario("F G \"all blocks in r2\"");
    const std::string p = file(s);
    t.push_back({"task/run", {"run", p, "--log", "mj.jsonl"}, at(p, s, kTaskLine, "blocks"), "unknown class",
                 {"mj.jsonl"}});
  }
  // A task over several lines: the line of the atom.
  {
    const std::string s = std::string(kHead) + "task: |\n  F G all_in_r2 &\n  G \"o1 in r9\"\n";
    const std::string p = file(s);
    t.push_back({"task/plan", {"plan", p}, name_of(p) + ":15:", "unknown location 'r9'"});
  }
  // Block scalars (| and >, indented 2 or 4, explicit indentation, blank
  // lines, chomping): the column in the file counts the indentation, the line
  // is the file's line even where > folds the line breaks into spaces.
  {
    struct Block {
      std::string task;  // after "task: "
      int line;          // of the error, in the file
      std::string word;  // the error's word on that line (its first occurrence from `from`)
      std::string what;
      std::size_t from = 0;
    };
    const std::vector<Block> blocks = {
        {"|\n  F G all_in_r2 &\n  G \"o1 in r9\"\n", 15, "r9", "unknown location 'r9'"},
        {"|\n    F G all_in_r2 &\n    G \"o1 in r9\"\n", 15, "r9", "unknown location 'r9'"},
        {">\n  F G all_in_r2 &\n  G \"o1 in r9\"\n", 15, "r9", "unknown location 'r9'"},
        {">\n    F G all_in_r2 &\n    G \"o1 in r9\"\n", 15, "r9", "unknown location 'r9'"},
        {">-\n    F G all_in_r2\n\n    & G \"all blocks in r2\"\n", 16, "blocks", "unknown class 'blocks'"},
        {"|4\n    F G all_in_r2 &\n      G \"o9 in r2\"\n", 15, "o9", "unknown object 'o9'"},
        {"|\n  F G all_in_r2 &\n  G all_in_r9\n", 15, "all_in_r9", "not a proposition"},
        {">\n    F G all_in_r2 &\n    G all_in_r9\n", 15, "all_in_r9", "not a proposition"},
        {"|\n  F G all_in_r2\n  & & all_in_r2\n", 15, "& all", ""},
        {">\n    F G all_in_r2\n    & & all_in_r2\n", 15, "& all", ""},
        {"|+\n    F G all_in_r2 &\n    G \"o1 in\"\n\n", 15, "\"", "expected a location name", 7},
    };
    for (const Block& b : blocks) {
      const std::string s = std::string(kHead) + "task: " + b.task;
      const std::string p = file(s);
      t.push_back({"task/block", {"plan", p}, at(p, s, b.line, b.word, b.from), b.what});
    }
    // Through run, which refuses it before the episode starts.
    const std::string s = std::string(kHead) + "task: >\n    F G all_in_r2 &\n    G \"o1 in r9\"\n";
    const std::string p = file(s);
    t.push_back({"task/block", {"run", p, "--world", "symbolic", "--log", "blk.jsonl"}, at(p, s, 15, "r9"),
                 "unknown location 'r9'", {"blk.jsonl"}});
    // A proposition written as a block scalar: its names and its syntax.
    const std::string head = std::string(kHead).substr(0, std::string(kHead).rfind("  all_in_r2:"));
    for (const std::string& indent : {std::string("  "), std::string("    ")}) {
      for (const char* style : {"|", ">"}) {
        const std::string names = head + "  all_in_r2: " + style + "\n  " + indent + "all block in r2 &\n  " + indent +
                                  "o1 in r9\ntask: F G all_in_r2\n";
        const std::string pn = file(names);
        t.push_back({"prop/block", {"plan", pn}, at(pn, names, 14, "r9"), "unknown location 'r9'"});
        const std::string syntax = head + "  all_in_r2: " + style + "\n  " + indent + "all block in r2 &\n  " + indent +
                                   "o1 r2\ntask: F G all_in_r2\n";
        const std::string ps = file(syntax);
        t.push_back({"prop/block", {"plan", ps}, at(ps, syntax, 14, "r2"), "expected"});
      }
    }
  }
  // The task in YAML quotes: the column counts from the quote.
  {
    const std::string s = scenario("'F G \"all blocks in r2\"'");
    const std::string p = file(s);
    t.push_back({"task/plan", {"plan", p}, at(p, s, kTaskLine, "blocks"), "unknown class"});
  }
  // Hostile tasks.
  {
    const std::string s = scenario(std::string(5000, '(') + "all_in_r2" + std::string(5000, ')'));
    const std::string p = file(s);
    t.push_back({"task/plan", {"plan", p}, name_of(p) + ":13:", "too deeply nested"});
  }
  {
    std::string task = "F G all_in_r2";
    for (int i = 0; i < 20000; ++i) task += " & all_in_r2";
    task += " & \"o1 in r9\"";
    const std::string s = scenario(task);
    const std::string p = file(s);
    t.push_back({"task/plan", {"plan", p}, at(p, s, kTaskLine, "r9"), "unknown location 'r9'"});
  }
  {
    const std::string s = scenario("\"F G \\x01 all_in_r2\"");
    const std::string p = file(s);
    t.push_back({"task/plan", {"plan", p}, name_of(p) + ":13:", "0x01"});
  }
}

// New tasks (--new-task TIME@LTL, the operator's new_task): refused before
// anything runs, located in the option's text or the scenario file.
void new_task_cases(std::vector<Case>& t) {
  const std::vector<std::string> run = {"run", "3-block", "--world", "symbolic", "--log", "nt.jsonl"};
  auto add = [&](std::vector<std::string> extra, const std::string& where, const std::string& what) {
    std::vector<std::string> args = run;
    args.insert(args.end(), extra.begin(), extra.end());
    t.push_back({"new-task/run", args, where, what, {"nt.jsonl"}});
  };
  add({"--new-task", "3@F G nope"}, "--new-task #1:1:7:", "not a proposition of the scenario");
  add({"--new-task", "3@F G all_in_r2", "--new-task", "5@F G \"o1 in r9\""}, "--new-task #2:1:14:",
      "unknown location 'r9'");
  add({"--new-task", "3@F G (all_in_r2"}, "--new-task #1:1:7:", "missing ')'");
  add({"--new-task", "3 F G all_in_r2"}, "--new-task:", "expected TIME@LTL");
  add({"--new-task", "soon@F G all_in_r2"}, "--new-task:", "the time before '@'");
  add({"--new-task", "nan@F G all_in_r2"}, "--new-task:", "the time before '@'");
  add({"--new-task", "-2@F G all_in_r2"}, "--new-task:", "the time before '@'");
  add({"--new-task", "3@  "}, "--new-task:", "no formula after '@'");
  add({"--new-task", "1000@F G all_in_r2", "--max-time", "60"}, "--new-task #1:1:1:", "the episode ends before it");
  t.push_back({"new-task/batch",
               {"batch", "3-block", "--trials", "1", "--world", "symbolic", "-o", "nt.csv", "--new-task", "3@F G nope"},
               "--new-task #1:1:7:", "not a proposition", {"nt.csv"}});
  t.push_back({"new-task/serve",
               {"serve", "3-block", "--world", "symbolic", "--port", "0", "--log", "nt.jsonl", "--new-task",
                "3@F G nope"},
               "--new-task #1:1:7:", "not a proposition", {"nt.jsonl"}});
  // The operator script's new_task: its task, and a proposition that redefines one.
  {
    const std::string s = scenario("F G all_in_r2", "operator:\n  - {time: 4, action: new_task, task: \"F G nope\"}\n");
    const std::string p = file(s);
    t.push_back({"new-task/script", {"run", p, "--world", "symbolic", "--log", "nt.jsonl"},
                 at(p, s, kTaskLine + 2, "nope"), "new task at t = 4 s: the task uses 'nope'", {"nt.jsonl"}});
  }
  {
    const std::string s = scenario("F G all_in_r2", "operator:\n  - {time: 4, action: new_task, task: \"F G all_in_r2\", "
                                                     "propositions: {all_in_r2: \"all block in r1\"}}\n");
    const std::string p = file(s);
    t.push_back({"new-task/script", {"run", p, "--world", "symbolic", "--log", "nt.jsonl"},
                 at(p, s, kTaskLine + 2, "all block in r1"), "already defined", {"nt.jsonl"}});
  }
  {
    const std::string s = scenario("F G all_in_r2", "operator:\n  - {time: 4, action: new_task, task: \"F G all_in_r2\", "
                                                     "object: o1}\n");
    const std::string p = file(s);
    t.push_back({"new-task/script", {"run", p, "--world", "symbolic", "--log", "nt.jsonl"},
                 at(p, s, kTaskLine + 2, "object"), "unknown key 'object' in operator action 'new_task'",
                 {"nt.jsonl"}});
  }
}

void change_cases(std::vector<Case>& t) {
  auto add = [&](std::vector<std::string> changes, const std::string& where, const std::string& what) {
    std::vector<std::string> args = {"plan", "3-block-tray"};
    for (const std::string& c : changes) {
      args.push_back("--change");
      args.push_back(c);
    }
    t.push_back({"change", args, where, what});
  };
  add({"add in block r1"}, "--change #1:1:5:", "reserved word");
  add({"add o9 object r1"}, "--change #1:1:8:", "class 'object' is reserved");
  add({"add-region r9 0.40 0.32"}, "--change #1:1:15:", "overlaps region 'r1'");
  add({"add-region r9 0.40 -0.32"}, "--change #1:1:15:", "overlaps region 'r2'");
  add({"add-container t9 tray r1 99999999999"}, "--change #1:1:26:", "out of range");
  add({"add-container t9 tray r1 1e10"}, "--change #1:1:26:", "must be an integer");
  add({"add-container t9 tray r1 0"}, "--change #1:1:26:", "at least 1");
  add({"add-container t9 tray r1 -3"}, "--change #1:1:26:", "at least 1");
  add({"add-container t9 tray r1 4.5"}, "--change #1:1:26:", "must be an integer");
  add({"move o1 r2", "add o9 block r9"}, "--change #2:1:14:", "unknown location 'r9'");
  add({"mov o1 r2"}, "--change #1:1:1:", "did you mean 'move'?");
  add({"move o1"}, "--change #1:1:8:", "takes 2 arguments");
  add({"move o1 r2 r1"}, "--change #1:1:12:", "takes 2 arguments");
  add({""}, "--change #1:1:1:", "empty");
  add({"   "}, "--change #1:1:1:", "empty");
  add({"move o9 r2"}, "--change #1:1:6:", "unknown object or container 'o9'");
  add({"move o1 r9"}, "--change #1:1:9:", "unknown location 'r9'");
  add({"move o1 o2"}, "--change #1:1:9:", "'o2' is an object, not a location");
  add({"move r1 r2"}, "--change #1:1:6:", "'r1' is a region");
  add({"move r3 r3"}, "--change #1:1:9:", "cannot be placed in itself");
  add({"move r3 o1"}, "--change #1:1:9:", "is an object");
  add({"add-container t2 tray r3"}, "--change #1:1:23:", "containers do not nest");
  add({"add o9 tray r1"}, "--change #1:1:8:", "is the class of containers");
  add({"add-container t2 block r1"}, "--change #1:1:18:", "is the class of objects");
  add({"add-container t2 object r1"}, "--change #1:1:18:", "class 'object' is reserved");
  add({"remove r3"}, "--change #1:1:8:", "use remove-container");
  add({"remove o9"}, "--change #1:1:8:", "unknown object 'o9'");
  add({"remove-container o1"}, "--change #1:1:18:", "use remove");
  add({"remove-container r1"}, "--change #1:1:18:", "unknown container 'r1'");
  add({"add o1 block r1"}, "--change #1:1:5:", "already used by an object");
  add({"add r1 block r2"}, "--change #1:1:5:", "already used by a region");
  add({"add all_in_r2 block r1"}, "--change #1:1:5:", "already used by a proposition");
  add({"add-region r9 nan 0"}, "--change #1:1:15:", "out of range");
  add({"add-region r9 inf 0"}, "--change #1:1:15:", "out of range");
  add({"add-region r9 1e400 0"}, "--change #1:1:15:", "out of range");
  add({"add-region r9 abc 0"}, "--change #1:1:15:", "must be a number");
  add({"add-region r9 5000 0"}, "--change #1:1:15:", "out of range");
  add({"add-region r9 2 0x10"}, "--change #1:1:17:", "must be a number");
  add({"add-region 9r 3 3"}, "--change #1:1:12:", "not an identifier");
  add({"add-region none 3 3"}, "--change #1:1:12:", "reserved word");
  add({"add-region r9 3 3 0"}, "--change #1:1:19:", "at least 1");
  add({"add-region r9 3 3 4.5"}, "--change #1:1:19:", "must be an integer");
  add({"add-region r9 3"}, "--change #1:1:16:", "takes 3, 4 or 6 arguments");
  add({"add-region r9 3 3 2 0.5"}, "--change #1:1:24:", "takes 3, 4 or 6 arguments");
  add({"add-region r9 3 3 2 0 0.3"}, "--change #1:1:21:", "size x '0' is out of range");
  add({"add-region r9 3 3 2 0.3 abc"}, "--change #1:1:25:", "size y must be a number");
  add({"add-region r9 3 3 2 0.3 1e9"}, "--change #1:1:25:", "size y '1e9' is out of range");
  add({"add-region r9 2 2 1 0.5 0.5", "add-region r8 2.3 2 1"}, "--change #2:1:15:", "overlaps region 'r9'");
  add({"add-container t9 tray"}, "--change #1:1:22:", "takes 3 or 4 arguments");
  add({"add o9 block r1 r2"}, "--change #1:1:17:", "takes 3 arguments");
  add({"add o9 block o1"}, "--change #1:1:14:", "is an object, not a location");
  add({"add " + std::string(5000, 'x') + " block r1"}, "--change #1:1:5:", "not an identifier");
  add({"move o1\x01 r2"}, "--change #1:1:6:", "unknown object or container");
  add({"remove o1", "move o1 r2"}, "--change #2:1:6:", "unknown object or container 'o1'");
  add({"remove-container r3", "move o1 r3"}, "--change #2:1:9:", "unknown location 'r3'");
  add({"add-region r9 2 2", "add-region r8 2 2.05"}, "--change #2:1:15:", "overlaps region 'r9'");
  add({"move o1 r2", "move o2 r2", "move o3 r9"}, "--change #3:1:9:", "unknown location 'r9'");
  // The rules of space (world/space_rules.hpp): a change that would overfill a location.
  add({"add o4 block r1"}, "--change #1:1:14:", "cannot put 'o4' in 'r1': r1 has no room (capacity 4)");
  add({"add-container t9 tray r1"}, "--change #1:1:23:", "cannot put 't9' in 'r1': r1 has no room (capacity 4)");
  add({"move o1 r3", "move o2 r3", "move o3 r3", "add o4 block r3"}, "--change #4:1:14:",
      "r3 has no room (capacity 3)");
  add({"move r3 r2", "add o4 block r2", "add o5 block r2", "add o6 block r2", "move o1 r3", "move o2 r3",
       "remove-container r3"},
      "--change #7:1:18:", "cannot put 'o2' in 'r2': r2 has no room (capacity 4)");
  t.push_back({"change",
               {"plan", "3-block-tray", "--json", "--change", "add-region r9 0.40 0.32"},
               "--change #1:1:15:",
               "overlaps"});
}

void sim_cases(std::vector<Case>& t) {
  auto add = [&](const std::string& actions, const std::string& where, const std::string& what) {
    t.push_back({"sim --do", {"sim", "3-block-tray", "--do", actions, "--mjcf", "sim.xml"}, where, what, {"sim.xml"}});
  };
  add("move o1 r9", "--do:1:9:", "unknown location 'r9'");
  add("move o9 r2", "--do:1:6:", "unknown object or container 'o9'");
  add("pick r1", "--do:1:6:", "'r1' is a region");
  add("place r9", "--do:1:7:", "unknown location 'r9'");
  add("place o1", "--do:1:7:", "is an object, not a location");
  add("move o1 r2; move o2 r8", "--do:1:21:", "unknown location 'r8'");
  add("move r3 r3", "--do:1:9:", "cannot be placed in itself");
  add("move r3 o1", "--do:1:9:", "is an object, not a location");
  add("fly o1", "--do:1:1:", "unknown action 'fly'");
  add("wait -1", "--do:1:6:", "not a duration");
  add("wait nan", "--do:1:6:", "not a duration");
  add("wait 1e9", "--do:1:6:", "not a duration");
  add("wait x", "--do:1:6:", "not a duration");
  add("move o1", "--do:1:1:", "takes 2 arguments");
  add("move o1 r2 r1", "--do:1:1:", "takes 2 arguments");
  add("move o1\x02 r2", "--do:1:6:", "unknown object or container");
  add("move " + std::string(5000, 'y') + " r2", "--do:1:6:", "unknown object or container");
  add("pick o1; place o9", "--do:1:16:", "unknown location 'o9'");
  add(";;;move o1 r9", "--do:1:12:", "unknown location 'r9'");
  add("move o1 r2;   pick o7", "--do:1:20:", "unknown object or container 'o7'");
  add("wait 1; move o1 r2; move r2 r1", "--do:1:26:", "'r2' is a region");
  // An object the scripted operator adds exists only with --operator.
  {
    const std::string s = scenario("F G all_in_r2", "operator:\n  - {time: 1, action: add, object: o4, to: r2}\n");
    const std::string p = file(s);
    t.push_back({"sim --do", {"sim", p, "--do", "wait 2; move o4 r1"}, "--do:1:14:", "unknown object or container 'o4'"});
  }
}

// Cameras of the scenario (line 14 after the task) and `sim --camera`.
void camera_cases(std::vector<Case>& t) {
  auto add = [&](const std::string& camera, const std::string& word, const std::string& what, int line = kTaskLine + 2) {
    const std::string text = scenario("F G all_in_r2", "cameras:\n" + camera + "\n");
    const std::string p = file(text);
    t.push_back({"camera", {"sim", p, "--camera", "c", "--snapshot", "c.png"}, at(p, text, line, word), what,
                 {"c.png"}});
  };
  const std::string c = "  - {name: c, position: [0.4, 0, 1.5], look_at: [0.4, 0, 0]";
  add(c + ", resolution: [8, 480]}", "[8, 480]", "resolution 8x480 is out of range");
  add(c + ", resolution: [640, 5000]}", "[640, 5000]", "is out of range (16 to 4096");
  add(c + ", rate: 0}", "0}", "rate 0 Hz is out of range");
  add(c + ", rate: 5000}", "5000}", "rate 5000 Hz is out of range");
  add(c + ", fov: 180}", "180}", "field of view 180 is outside (0, 180)");
  add(c + ", fov: 0}", "0}", "field of view 0 is outside (0, 180)");
  add(c + ", range: [2, 1]}", "[2, 1]", "range [2, 1] must be");
  add("  - {name: c, position: [0.4, 0, -0.1], look_at: [0.4, 0, 0]}", "[0.4, 0, -0.1]",
      "is inside or below the table");
  add("  - {name: c, position: [0.4, 0, 1.5], look_at: [0.4, 0, 3]}", "[0.4, 0, 3]", "sees no region");
  add("  - {name: c, position: [5, 5, 0.2], look_at: [9, 9, 0.2]}", "[9, 9, 0.2]", "sees no region");
  add(c + ", mount: head}", "head", "unknown mount 'head'");
  add(c + ", noise: {a: 0.001, c: 1}}", "c: 1", "unknown key 'c'");
  add("  - {name: c, mount: wrist, look_at: [0, 0, 0]}", "[0, 0, 0]", "no look_at");
  add("  - {name: c, look_at: [0.4, 0, 0]}", "{name", "missing the required key 'position'");
  add(c + "}\n" + c + "}", "c,", "duplicate camera name 'c'", kTaskLine + 3);
  t.push_back({"camera", {"sim", "3-block-tray", "--camera", "ceiling", "--snapshot", "c.png"}, "--camera:1:1:",
               "unknown camera 'ceiling' (cameras: overhead, wrist)", {"c.png"}});
  // Perceiving cameras: unknown (at its column), repeated, or without camera perception.
  t.push_back({"camera", {"run", "3-block-tray", "--perception", "camera", "--perception-cameras", "overhead,ceiling",
                          "--log", "c1.jsonl"},
               "--perception-cameras:1:10:", "unknown camera 'ceiling' (cameras: overhead, wrist)", {"c1.jsonl"}});
  t.push_back({"camera", {"batch", "3-block-tray", "--perception", "camera", "--perception-cameras", "ceiling",
                          "--trials", "1", "-o", "c2.csv"},
               "--perception-cameras:1:1:", "unknown camera 'ceiling'", {"c2.csv"}});
  t.push_back({"camera", {"sim", "3-block-tray", "--perception", "camera", "--perception-cameras", "wrist,wrist",
                          "--snapshot", "c3.png"},
               "--perception-cameras:1:7:", "camera 'wrist' is listed twice", {"c3.png"}});
  t.push_back({"camera", {"serve", "3-block-tray", "--perception-cameras", "wrist", "--port", "0", "--log", "c4.jsonl"},
               "--perception-cameras:1:1:", "only with --perception camera", {"c4.jsonl"}});
  // Camera perception: an unknown source (in any world), noise asked of a camera.
  t.push_back({"perception", {"sim", "3-block", "--perception", "eyes", "--snapshot", "p0.png"}, "--perception", "",
               {"p0.png"}});
  t.push_back({"perception", {"sim", "3-block", "--perception", "camera", "--noise", "0.1", "--snapshot", "p1.png"},
               "position noise and misses", "for truth perception", {"p1.png"}});
  t.push_back({"perception", {"run", "3-block", "--world", "symbolic", "--perception", "sonar", "--log", "p2.jsonl"},
               "--perception", "sonar", {"p2.jsonl"}});
  t.push_back({"perception", {"batch", "3-block", "--world", "symbolic", "--perception", "sonar", "--trials", "1", "-o",
                              "p3.csv"},
               "--perception", "sonar", {"p3.csv"}});
}

// Colours of classes (line 15, after `colours:`): malformed, unknown, and (with the
// camera) two classes the colour segmentation cannot tell apart.
void colour_cases(std::vector<Case>& t) {
  auto add = [&](const std::string& entry, const std::string& word, const std::string& what,
                 std::vector<std::string> args = {"plan"}, int line = kTaskLine + 2) {
    const std::string text = scenario("F G all_in_r2", "colours:\n" + entry + "\n");
    const std::string p = file(text);
    std::vector<std::string> not_created;
    if (args.size() > 1) not_created.push_back(args.back());
    args.insert(args.begin() + 1, p);
    t.push_back({"colours", args, at(p, text, line, word), what, not_created});
  };
  add("  cup: [1, 0, 0]", "cup", "colours: unknown class 'cup'");
  add("  block: [1.5, 0, 0]", "1.5", "each channel lies in [0, 1]");
  add("  block: [1, 0]", "[1, 0]", "must be a list [r, g, b]");
  add("  block: red", "red", "must be a list [r, g, b]");
  // The blocks and the trays painted alike by the user: refused before anything runs,
  // with the camera only, at the later entry (a default colour would move instead).
  add("  tray: [0.55, 0.36, 0.2]\n  block: [0.56, 0.37, 0.2]", "block", "look alike to the camera",
      {"sim", "--perception", "camera", "--snapshot", "k.png"}, kTaskLine + 3);
  add("  block: [0.85, 0.15, 0.12]\n  tray: [0.8, 0.1, 0.1]", "tray", "look alike to the camera",
      {"run", "--perception", "camera", "--log", "k.jsonl"}, kTaskLine + 3);
  add("  block: [0.5, 0.5, 0.52]", "block", "too grey for the camera",
      {"sim", "--perception", "camera", "--snapshot", "k.png"});
}

void serve_cases(std::vector<Case>& t) {
  auto add = [&](std::vector<std::string> args, const std::string& where, const std::string& what) {
    args.insert(args.begin(), {"serve", "3-block-tray", "--world", "symbolic", "--log", "sv.jsonl"});
    t.push_back({"serve", args, where, what, {"sv.jsonl"}});
  };
  add({"--port", "65536"}, "--port:", "in [0, 65535]");
  add({"--port", "-1"}, "--port:", "in [0, 65535]");
  add({"--port", "80x"}, "--port:", "");
  add({"--speed", "-1"}, "--speed:", "in [0, 1000]");
  add({"--speed", "nan"}, "--speed:", "");
  add({"--mcap-image-period", "-1"}, "--mcap-image-period:", ">= 0 or inf (no images)");
  add({"--mcap-image-period", "nan"}, "--mcap-image-period:", "");
  add({"--mcap-image-period", "1x"}, "--mcap-image-period:", "");
  add({"--mcap", "sv.mcap", "--mcap-profile", "ros1"}, "--mcap-profile:", "unknown value 'ros1' (did you mean 'ros2'?)");
  add({"--world", "lego"}, "--world:", "lego");
  add({"--host", "localhost.invalid"}, "cannot listen on localhost.invalid:", "not an IP address");
  add({"--host", "203.0.113.7", "--port", "0"}, "cannot listen on 203.0.113.7:0:", "");
  add({"--web-root", "no-such-dir"}, "--web-root:", "not a directory");
  add({"--allow-origin", "lab.example"}, "--allow-origin: 'lab.example' is not an origin:", "no scheme");
  add({"--allow-origin", "null"}, "--allow-origin: 'null' is not an origin:", "no scheme");
  add({"--allow-origin", "file:///home"}, "--allow-origin: 'file:///home' is not an origin:", "not http or https");
  add({"--allow-origin", "http://lab.example/page"}, "--allow-origin:", "an origin has no path");
  add({"--allow-origin", "http://lab.example:99999"}, "--allow-origin:", "a port in 1-65535");
  add({"--allow-origin", "http://127.0.0.1:8080", "--allow-origin", "*"}, "--allow-origin: '*'", "no scheme");
  add({"--allow-origin", "http://" + std::string(5000, 'a')}, "--allow-origin: 'http://aaa", "...' (5007 bytes)");
  add({"--replay", "no-such.jsonl"}, "--replay:", "cannot read 'no-such.jsonl'");
  add({"--algo", "bfs"}, "--algo:", "unknown");
  {
    const std::string p = file("{\"ev\":\"episode\",\"t\":0}\nnot json\n", ".jsonl");
    add({"--replay", p}, "--replay: " + p + ":2:", "not a JSON object");
  }
  {
    const std::string p = file("{\"ev\":\"episode\",\"scenario\":\"3-block\",\"t\":0}\n", ".jsonl");
    add({"--replay", p}, "--replay: " + p + ":1:", "the log is of scenario '3-block'");
  }
  {
    const std::string p = file("{\"ev\":\"episode\",\"t\":0}\n{\"ev\":\"replan\",\"why\":\"x\",\"t\":2}\n"
                               "{\"ev\":\"replan\",\"why\":\"x\",\"t\":1}\n", ".jsonl");
    add({"--replay", p}, "--replay: " + p + ":3:", "out of time order");
  }
  {
    const std::string p = file("{\"ev\":\"episode\",\"t\":0}\n" + std::string(100000, '[') + "\n", ".jsonl");
    add({"--replay", p}, "--replay: " + p + ":2:", "nested deeper than 16 levels");
  }
  {
    const std::string p = file("{\"ev\":\"episode\",\"t\":0}\n{\"ev\":\"frame\",\"q\":[0,0,0],\"tool\":[0,0,0],"
                               "\"things\":[],\"t\":0.5}\n", ".jsonl");
    add({"--replay", p}, "--replay: " + p + ":2:", "\"q\" must be 6 numbers");
  }
  t.push_back({"serve", {"serve", "3-block-tray", "--log", "no-such-dir/sv.jsonl"}, "--log:", "cannot write", {}});
}

void gen_cases(std::vector<Case>& t) {
  auto add = [&](std::vector<std::string> args, const std::string& where, const std::string& what) {
    args.insert(args.begin(), "gen");
    args.push_back("-o");
    args.push_back("gen.yaml");
    t.push_back({"gen", args, where, what, {"gen.yaml"}});
  };
  add({"--task", "F G \"all blocks in r2\""}, "--task:1:10:", "did you mean 'block'?");
  add({"--task", "F G all_in_r3"}, "--task:1:5:", "did you mean 'all_in_r2'?");
  add({"--task", "F G ("}, "--task:1:6:", "unexpected end of formula");
  add({"--task", "F G all_in_r2 & G !(o1 in r3)"}, "--task:1:24:", "before 'in'");
  add({"--task", "F G \"o1 in r3\""}, "--task:1:12:", "unknown location 'r3'");
  add({"--task", "F G \"o1 in r3\"", "-m", "2"}, "--task:1:12:", "did you mean");
  add({"--task", " "}, "--task:1:1:", "the task is empty");
  add({"--prop", "p=o9 in r1"}, "--prop #1:1:3:", "unknown object 'o9'");
  add({"--prop", "p=o1 in ("}, "--prop #1:1:9:", "expected a location name");
  add({"--prop", "=o1 in r1"}, "--prop #1:1:1:", "NAME=EXPRESSION");
  add({"--prop", "noeq"}, "--prop #1:1:", "NAME=EXPRESSION");
  // A proposition's name is at column 1 of its --prop.
  add({"--prop", "P=o1 in r1"}, "--prop #1:1:1:", "not a valid atom");
  add({"--prop", "all_in_r2=o1 in r1"}, "--prop #1:1:1:", "duplicate proposition");
  add({"--prop", "o1=o1 in r1"}, "--prop #1:1:1:", "has the name of an object");
  add({"--prop", "q=o1 in r1", "--prop", "Q2=o1 in r2"}, "--prop #2:1:1:", "not a valid atom");
  add({"--prop", "q=o1 in r1", "--prop", "p=all blok in r2"}, "--prop #2:1:7:", "did you mean 'block'?");
  add({"--prop", "p=" + std::string(300, '(') + "o1 in r1" + std::string(300, ')')}, "--prop #1:1:",
      "nested too deeply");
  add({"--prop", "p=o1 in r1", "--task", "F G p & F \"o1 in r2\" & F q"}, "--task:1:26:", "not a proposition");
}

void ltl_cases(std::vector<Case>& t) {
  auto add = [&](const std::string& formula, const std::string& where, const std::string& what) {
    t.push_back({"ltl", {"ltl2ba", formula}, where, what});
  };
  add("G (a -> ", "<formula>:1:9:", "unexpected end of formula");
  add(std::string(100000, '('), "<formula>:1:", "too deeply nested");
  add(std::string(100000, '!') + "a", "<formula>:1:", "too deeply nested");
  add("a \x01 b", "<formula>:1:3:", "0x01");
  add("", "<formula>:1:1:", "empty formula");
  add("F G All", "<formula>:1:5:", "unexpected 'A'");
  add("\"unterminated", "<formula>:1:1:", "unterminated");
  add("a U", "<formula>:1:4:", "unexpected end of formula");
  add("()", "<formula>:1:2:", "expected a formula before ')'");
  add("a b", "<formula>:1:3:", "expected an operator");
  add("a \xff b", "<formula>:1:3:", "0xff");
  {
    std::string garbage;
    for (int i = 0; i < 300; ++i) garbage += static_cast<char>(11 + (i * 77) % 245);  // one line: no '\n'
    garbage[0] = '\x01';
    const std::string p = file(garbage, ".ltl");
    t.push_back({"ltl", {"ltl2ba", "-F", p}, name_of(p) + ":1:", ""});
  }
}

// Output paths, named by their option, and the argument parser's errors.
void option_cases(std::vector<Case>& t) {
  const fs::path dir = scratch();
  const std::string a_file = file("not a directory\n", ".txt");
  fs::create_directories(dir / "a_dir");
  const std::vector<std::string> run = {"run", "3-block", "--world", "symbolic"};
  auto with = [&](std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  t.push_back({"options", with(run, {"--log", "no_dir/ep.jsonl", "--trees", "tr"}), "--log: cannot write",
               "no directory", {"no_dir", "tr"}});
  t.push_back({"options", with(run, {"--log", (dir / "a_dir").string(), "--trees", "tr"}), "--log: cannot write",
               "it is a directory", {"tr"}});
  t.push_back({"options", with(run, {"--log", "ep2.jsonl", "--trees", a_file}), "--trees: cannot write into",
               "is not a directory", {"ep2.jsonl"}});
  t.push_back({"options", with(run, {"--log", "ep3.jsonl", "--trees", a_file + "/below"}),
               "--trees: cannot write into", "is not a directory", {"ep3.jsonl"}});
  // An MCAP profile that is not one, on every command that writes MCAP: nothing written.
  t.push_back({"options", with(run, {"--mcap", "p.mcap", "--mcap-profile", "cdr"}), "--mcap-profile:",
               "unknown value 'cdr'", {"p.mcap"}});
  t.push_back({"options", {"batch", "3-block", "--world", "symbolic", "--log-dir", "pl", "--mcap", "--mcap-profile", "JSON"},
               "--mcap-profile:", "unknown value 'JSON'", {"pl"}});
  t.push_back({"options", {"log", "to-mcap", a_file, "pt.mcap", "--mcap-profile", "ros"}, "--mcap-profile:",
               "unknown value 'ros'", {"pt.mcap"}});
  // A directory given where a file is read: said so, not a parser's "empty input".
  const std::string d = (dir / "a_dir").string();
  t.push_back({"options", {"plan", d}, d + ": cannot read scenario:", "it is a directory"});
  t.push_back({"options", {"bt", "check", d}, d + ": cannot read the behavior-tree file:", "it is a directory"});
  t.push_back({"options", {"batch", "--merge", d}, d + ": cannot read the CSV file:", "it is a directory"});
  // Several unexpected arguments: the first unknown option of the command line.
  t.push_back({"options", {"plan", "3-block", "--seed", "1e3"}, "unknown option '--seed'", ""});
  t.push_back({"options", {"plan", "3-block", "--bogus", "x", "--worse"}, "unknown option '--bogus'", ""});
  t.push_back({"options", {"plan", "3-block", "extra", "more"}, "unexpected argument 'extra' (and 1 more)", ""});
}

// Behavior-tree files that BehaviorTree.CPP itself would refuse.
void bt_cases(std::vector<Case>& t) {
  auto add = [&](const std::string& xml, int line, const std::string& word, const std::string& what) {
    const std::string p = file(xml, ".xml");
    t.push_back({"bt", {"bt", "check", p}, at(p, xml, line, word), what});
  };
  const std::string head = "<root BTCPP_format=\"4\">\n<BehaviorTree ID=\"T\"><Go/></BehaviorTree>\n<TreeNodesModel>\n";
  add("<root BTCPP_format=\"4\">\n<BehaviorTree ID=\"T\">\n  <Parallel success_count=\"5\"><Go/><Go/></Parallel>\n"
      "</BehaviorTree>\n<TreeNodesModel><Action ID=\"Go\"/></TreeNodesModel>\n</root>\n",
      3, "<Parallel", "more than its 2 children");
  add(head + "<Action ID=\"Go\"/>\n<Condition ID=\"Go\"/>\n</TreeNodesModel>\n</root>\n", 5, "<Condition",
      "'Go' is declared twice in <TreeNodesModel>");
  add(head + "<Action ID=\"Go\"><input_port name=\"bad name\"/></Action>\n</TreeNodesModel>\n</root>\n", 4, "<input_port",
      "port name 'bad name' in the model of 'Go' is not allowed");
  add("<?xml version=\"1.0\" encoding=\"UTF-16\"?>\n" + head + "<Action ID=\"Go\"/>\n</TreeNodesModel>\n</root>\n", 1,
      "<?xml", "names encoding \"UTF-16\"");
}

// A log rtamp wrote (the 3-block scenario, symbolic), line by line, to break.
std::vector<std::string> good_log() {
  static const std::vector<std::string> lines = [] {
    const fs::path p = scratch() / "good.jsonl";
    const std::string cmd = std::string("'") + RTAMP_BIN + "' run 3-block --world symbolic --quiet --log '" +
                            p.string() + "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    std::vector<std::string> out;
    std::ifstream in(p);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    EXPECT_GE(out.size(), 5u);
    return out;
  }();
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

// Outputs that are inputs or other outputs, held by another writer, a FIFO
// without a reader, and logs `log to-mcap` must refuse (the check of serve --replay).
void output_cases(std::vector<Case>& t) {
  const fs::path dir = scratch();
  const std::vector<std::string> log = good_log();
  const std::string ep = file(joined(log), ".jsonl");
  const std::string mcap_name = "out.mcap";
  // The same file twice, by name, by a hard link, by another spelling.
  t.push_back({"outputs", {"log", "to-mcap", ep, ep}, "OUT: cannot write", "it is also the input LOG", {}, {ep}});
  const std::string link = (dir / "hard.jsonl").string();
  fs::remove(link);
  fs::create_hard_link(ep, link);
  t.push_back({"outputs", {"log", "to-mcap", ep, link}, "OUT: cannot write", "it is also the input LOG", {}, {ep}});
  t.push_back({"outputs", {"log", "to-mcap", ep, (dir / "." / name_of(ep)).string()}, "OUT: cannot write",
               "it is also the input LOG", {}, {ep}});
  // The arguments swapped: an MCAP file is no log, and the log given as OUT is kept.
  const std::string an_mcap = file("\x89MCAP0\r\n not a log", ".mcap");
  t.push_back({"outputs", {"log", "to-mcap", an_mcap, ep}, name_of(an_mcap) + ":1:", "not a JSON object", {},
               {ep, an_mcap}});
  const std::vector<std::string> run = {"run", "3-block", "--world", "symbolic", "--quiet"};
  auto with = [&](std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  t.push_back({"outputs", with(run, {"--log", "same.x", "--mcap", "same.x"}), "--mcap: cannot write",
               "it is also the output --log", {"same.x"}});
  t.push_back({"outputs", with(run, {"--log", ep, "--mcap", link}), "--mcap: cannot write",
               "it is also the output --log", {}, {ep}});
  {
    const std::string yaml = file(scenario());
    t.push_back({"outputs", {"run", yaml, "--world", "symbolic", "--log", yaml}, "--log: cannot write",
                 "it is also the input SCENARIO", {}, {yaml}});
    t.push_back({"outputs", {"batch", yaml, "--world", "symbolic", "-o", yaml}, "--output: cannot write",
                 "it is also the input SCENARIO", {}, {yaml}});
  }
  // A log another process is writing (this test holds its lock).
  {
    static int held = -1;
    const std::string locked = file("{\"another\":\"writer\"}\n", ".jsonl");
    held = ::open(locked.c_str(), O_RDONLY | O_CLOEXEC);
    EXPECT_EQ(::flock(held, LOCK_EX | LOCK_NB), 0);
    t.push_back({"outputs", with(run, {"--log", locked}), "--log: cannot write",
                 "being written by another process", {}, {locked}});
    t.push_back({"outputs", {"log", "to-mcap", ep, locked}, "OUT: cannot write", "being written by another process",
                 {}, {locked, ep}});
    t.push_back({"outputs", {"batch", "3-block", "--world", "symbolic", "--trials", "1", "-o", locked},
                 "--output: cannot write", "being written by another process", {}, {locked}});
  }
  // A FIFO nobody reads: refused, not waited on, and still a FIFO.
  {
    const std::string fifo = (dir / "nobody.fifo").string();
    fs::remove(fifo);
    EXPECT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    t.push_back({"outputs", with(run, {"--log", fifo}), "--log: cannot write", "a FIFO with no reader", {}, {fifo}});
    t.push_back({"outputs", {"log", "to-mcap", ep, fifo}, "OUT: cannot write", "a FIFO with no reader", {}, {fifo, ep}});
  }
  // batch: an unwritable --log-dir is refused before a CSV exists; --merge into one of its inputs.
  {
    const std::string a_file = file("a file, not a directory\n", ".txt");
    t.push_back({"outputs",
                 {"batch", "3-block", "--world", "symbolic", "--trials", "1", "-o", "b1.csv", "--log-dir",
                  a_file + "/logs"},
                 "--log-dir: cannot write into", "is not a directory", {"b1.csv"}, {a_file}});
    const std::string csv = file("scenario,algorithm,bt,change,trial,seed,success,reason,first_plan_s,replan_s,"
                                 "replans,tree_changes,completion_s,motion_cost,interventions,wall_s,rtf\n",
                                 ".csv");
    t.push_back({"outputs", {"batch", "--merge", csv, "-o", csv}, "--output: cannot write",
                 "it is also the input --merge", {}, {csv}});
    // --resume of a CSV another batch wrote (another --seed): refused, the CSV as it was.
    const std::string other = (dir / "other-seed.csv").string();
    const std::string cmd = std::string("'") + RTAMP_BIN + "' batch 3-block --world symbolic --trials 2 --change " +
                            "none --algo astar --seed 7 -q -o '" + other + "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    t.push_back({"outputs",
                 {"batch", "3-block", "--world", "symbolic", "--trials", "2", "--change", "none", "--algo", "astar",
                  "--resume", "-o", other},
                 name_of(other) + ":2:", "(another --seed)", {}, {other}});
    t.push_back({"outputs", {"batch", "3-block", "--world", "symbolic", "--resume", "-o", other, "--change", "add"},
                 name_of(other) + ":2:", "is not a trial of this batch", {}, {other}});
  }
  // bt check: the schema to write is the file checked.
  {
    const std::string xml = file("<root BTCPP_format=\"4\">\n<BehaviorTree ID=\"T\"><Go/></BehaviorTree>\n"
                                 "<TreeNodesModel><Action ID=\"Go\"/></TreeNodesModel>\n</root>\n",
                                 ".xml");
    t.push_back({"outputs", {"bt", "check", xml, "--xsd", xml}, "--xsd: cannot write", "it is also the input FILE",
                 {}, {xml}});
  }
  // serve: the log to write is the log replayed.
  t.push_back({"outputs", {"serve", "3-block", "--replay", ep, "--log", link}, "--log: cannot write",
               "it is also the input --replay", {}, {ep}});

  // Logs `log to-mcap` refuses with the check of `serve --replay`; OUT neither created nor changed.
  const std::string existing = file("an existing OUT\n", ".mcap");
  auto refused = [&](const std::string& text, const std::string& where_in_log, const std::string& what) {
    const std::string p = file(text, ".jsonl");
    t.push_back({"to-mcap", {"log", "to-mcap", p, mcap_name}, name_of(p) + where_in_log, what, {mcap_name}, {p}});
    t.push_back({"to-mcap", {"log", "to-mcap", p, existing}, name_of(p) + where_in_log, what, {}, {p, existing}});
  };
  refused("", ":", "the log is empty");
  refused("\n  \n", ":", "the log is empty");
  auto edited = [&](std::size_t line, const std::string& from, const std::string& to) {
    std::vector<std::string> l = log;
    const std::size_t at = l[line].find(from);
    EXPECT_NE(at, std::string::npos) << l[line];
    l[line].replace(at, from.size(), to);
    return joined(l);
  };
  const std::size_t last = log.size() - 1;
  refused(edited(last, "\"t\":", "\"t\":1e300,\"x\":"), ":" + std::to_string(log.size()) + ":",
          "\"t\" must be a time in world seconds");
  refused(edited(1, "\"t\":0.0", "\"t\":-1"), ":2:", "\"t\" must be a time");
  refused(edited(0, "\"version\":1", "\"version\":2"), ":1:", "format version 2");
  refused(edited(0, "\"version\":1", "\"version\":\"1\""), ":1:", "\"version\" must be a version");
  {
    std::vector<std::string> l = log;  // out of order: a late record first
    l.insert(l.begin() + 1, "{\"ev\":\"replan\",\"why\":\"x\",\"t\":5000}");
    refused(joined(l), ":3:", "out of time order");
  }
  refused(joined(log) + joined(log), ":" + std::to_string(log.size() + 1) + ":", "after the `end` record");
  {
    std::vector<std::string> l = log;  // an `end` mid-log
    l.insert(l.begin() + 2, l[last]);
    l[2].replace(l[2].find("\"t\":"), 4, "\"t\":0,\"u\":");
    refused(joined(l), ":4:", "after the `end` record");
  }
  {
    std::vector<std::string> l = log;
    l.insert(l.begin() + 1, "{\"ev\":\"frame\",\"q\":[0,0,0,0,0],\"tool\":[0,0,0],\"things\":[],\"t\":0}");
    refused(joined(l), ":2:", "\"q\" must be 6 numbers");
  }
  {
    std::vector<std::string> l = log;
    l.pop_back();
    refused(joined(l), ":", "no `end` record");
  }
  refused(log[0] + "\n" + std::string((8u << 20) + 10, '0'), ":2:", "a line longer than 8 MiB");
  refused(std::string(9u << 20, '\0'), ":1:", "a line longer than 8 MiB");
  {
    const std::string d = (dir / "a_log_dir").string();
    fs::create_directories(d);
    t.push_back({"to-mcap", {"log", "to-mcap", d, mcap_name}, d + ": cannot read the episode log:",
                 "it is a directory", {mcap_name}});
  }
}

std::vector<Case> table() {
  std::vector<Case> t;
  output_cases(t);
  bt_cases(t);
  yaml_cases(t);
  colour_cases(t);
  task_cases(t);
  new_task_cases(t);
  change_cases(t);
  sim_cases(t);
  camera_cases(t);
  serve_cases(t);
  gen_cases(t);
  ltl_cases(t);
  option_cases(t);
  return t;
}

std::string shown(const std::vector<std::string>& args) {
  std::string s = "rtamp";
  for (const std::string& a : args) s += " '" + (a.size() > 80 ? a.substr(0, 80) + "...'" : a + "'");
  return s;
}

TEST(CliBadInput, EveryBadInputIsRefusedWithItsLocationBeforeAnythingRuns) {
  const std::vector<Case> cases = table();
  EXPECT_GE(cases.size(), 150u);
  std::printf("%zu bad inputs\n", cases.size());
  for (const Case& c : cases) {
    SCOPED_TRACE(c.group + ": " + shown(c.args));
    for (const std::string& f : c.not_created) fs::remove_all(scratch() / f);
    std::vector<std::string> before;
    for (const std::string& f : c.unchanged) before.push_back(fingerprint(f));
    const Outcome r = run_argv(c.args);
    for (std::size_t i = 0; i < c.unchanged.size(); ++i)
      EXPECT_EQ(fingerprint(c.unchanged[i]), before[i]) << c.unchanged[i] << " was changed";
    EXPECT_EQ(r.signal, 0) << "killed by signal " << r.signal;
    EXPECT_TRUE(r.exited);
    EXPECT_EQ(r.code, 2) << r.err;
    const std::string first = r.err.substr(0, r.err.find('\n'));
    EXPECT_EQ(first.rfind("rtamp: error: ", 0), 0u) << r.err;
    EXPECT_NE(first.find(c.where), std::string::npos) << "expected '" << c.where << "' in: " << first;
    if (!c.what.empty()) {
      EXPECT_NE(first.find(c.what), std::string::npos) << "expected '" << c.what << "' in: " << first;
    }
    // Further lines only show the input with a caret (indented).
    std::size_t from = r.err.find('\n');
    while (from != std::string::npos && from + 1 < r.err.size()) {
      EXPECT_EQ(r.err.compare(from + 1, 2, "  "), 0) << r.err;
      from = r.err.find('\n', from + 1);
    }
    EXPECT_EQ(r.out, "") << "something ran";
    for (const std::string& f : c.not_created) EXPECT_FALSE(fs::exists(scratch() / f)) << f << " was created";
  }
}

}  // namespace
}  // namespace rtamp::cli::testing
