#!/usr/bin/python3
"""The command examples of README.md and docs/*.md, run against the built rtamp.

An example is a fenced block whose info string is `console`:

    ```console
    $ rtamp ltl2ba 'F G p'
    HOA: v1
    ...
    ```

Every line starting with `$ ` is a command (run by /bin/sh in a scratch
directory, `rtamp` meaning the binary under test); the lines up to the next
command are its recorded output: standard output, followed by standard error
when the command fails (exit code not 0), as a terminal shows an error.
A recorded line whose text starts with `...` (after blanks) stands for any
number of lines; inside a line, `...` stands for any text (figures that follow
search internals, details a later change may add). Before comparing, both sides are normalised: timings
(a number followed by us, µs, ms, or "s wall"), real-time factors ("20.6x")
small decimals of seconds (0.000088) and memory figures become
placeholders, and trailing blanks are dropped. `console mujoco` blocks run the MuJoCo simulation: they
are skipped unless --mujoco is given (ctest runs them as a test labelled
slow); every decimal in them is normalised too (world times, costs),
since planning on a worker thread charges its wall time to the simulated
clock, and so are runs of blanks (table columns follow their figures' widths).

Exit 0 when every example matches, 1 otherwise (with a diff per mismatch).
"""
import argparse
import difflib
import glob
import os
import re
import subprocess
import sys
import tempfile

TIMING = [
    (re.compile(r"\d+(\.\d+)?(e[-+]?\d+)?\s?(us|µs|ms)\b"), "<T>"),
    (re.compile(r"\d+(\.\d+)?\s?s wall"), "<T> wall"),
    (re.compile(r"\d+(\.\d+)?x\b"), "<X>"),
    (re.compile(r"\b0\.0\d{3,}\b"), "<T>"),
    # memory figures follow the allocator's reservations, not the plan
    (re.compile(r"memory \d+ B \(\d+(\.\d+)? B/node\)"), "memory <M>"),
]
# ltl2ba --format stats: the time_us column.
STATS = re.compile(r"^(\d+\t\d+\t\d+\t)\d+(\t)")
# MuJoCo runs: every decimal (world times, costs, table cells) and the stamp's padding.
WORLD_TIME = [
    (re.compile(r"\d+\.\d+"), "<N>"),
    (re.compile(r"\[\s+<N> s\]"), "[<N> s]"),
]


def normalise(line, mujoco):
    line = line.rstrip()
    line = STATS.sub(r"\1<T>\2", line)
    for pattern, repl in TIMING:
        line = pattern.sub(repl, line)
    if mujoco:
        for pattern, repl in WORLD_TIME:
            line = pattern.sub(repl, line)
        line = re.sub(r"\s+", " ", line)  # table columns are as wide as their figures
    return line


def trimmed(cmd):
    """Blank lines that separate one command's output from the next are not output."""
    while cmd["expected"] and not cmd["expected"][-1].strip():
        cmd["expected"].pop()
    return cmd


def examples(root):
    files = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    for path in files:
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        i = 0
        while i < len(lines):
            m = re.match(r"^```console(\s+mujoco)?\s*$", lines[i])
            if not m:
                i += 1
                continue
            start = i + 1
            j = start
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            block = lines[start:j]
            cmd = None
            for k, text in enumerate(block):
                if text.startswith("$ "):
                    if cmd:
                        yield trimmed(cmd)
                    cmd = {"file": os.path.relpath(path, root), "line": start + k + 1, "command": text[2:],
                           "expected": [], "mujoco": bool(m.group(1))}
                elif cmd is not None:
                    cmd["expected"].append(text)
            if cmd:
                yield trimmed(cmd)
            i = j + 1


def same_line(expected, actual):
    """Equal, or, if the recorded line holds `...`, equal with each `...` standing for any text."""
    if "..." not in expected:
        return expected == actual
    parts = expected.split("...")
    if not actual.startswith(parts[0]) or not actual.endswith(parts[-1]):
        return False
    at = len(parts[0])
    for part in parts[1:-1]:
        k = actual.find(part, at)
        if k < 0:
            return False
        at = k + len(part)
    return at <= len(actual) - len(parts[-1])


def matches(expected, actual):
    """Expected lines (with `...` lines as wildcards) against actual lines."""
    memo = {}

    def go(e, a):
        key = (e, a)
        if key in memo:
            return memo[key]
        if e == len(expected):
            r = a == len(actual)
        elif expected[e].lstrip().startswith("..."):
            r = any(go(e + 1, k) for k in range(a, len(actual) + 1))
        else:
            r = a < len(actual) and same_line(expected[e], actual[a]) and go(e + 1, a + 1)
        memo[key] = r
        return r

    sys.setrecursionlimit(100000)
    return go(0, 0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True, help="the rtamp binary")
    ap.add_argument("--root", required=True, help="the source tree (README.md, docs/)")
    ap.add_argument("--mujoco", action="store_true", help="run only the `console mujoco` examples")
    args = ap.parse_args()
    binary = os.path.abspath(args.bin)
    failures = 0
    ran = 0
    with tempfile.TemporaryDirectory(prefix="rtamp_docs_") as scratch:
        shim = os.path.join(scratch, "bin")
        os.mkdir(shim)
        os.symlink(binary, os.path.join(shim, "rtamp"))
        env = dict(os.environ, PATH=shim + os.pathsep + os.environ.get("PATH", ""))
        work = os.path.join(scratch, "work")
        os.mkdir(work)
        for ex in examples(args.root):
            if ex["mujoco"] != args.mujoco:
                continue
            ran += 1
            p = subprocess.run(["/bin/sh", "-c", ex["command"]], cwd=work, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=300)
            text = p.stdout.decode("utf-8", "replace")
            if p.returncode != 0:
                text += p.stderr.decode("utf-8", "replace")
            actual = text.split("\n")
            while actual and not actual[-1].strip():
                actual.pop()
            want = [normalise(x, ex["mujoco"]) for x in ex["expected"]]
            got = [normalise(x, ex["mujoco"]) for x in actual]
            if not matches(want, got):
                failures += 1
                print(f"{ex['file']}:{ex['line']}: $ {ex['command']}: output differs from the recorded one")
                for d in difflib.unified_diff(want, got, "recorded", "actual", lineterm=""):
                    print("    " + d)
    print(f"{ran} example(s), {failures} mismatch(es)")
    return 1 if failures or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
