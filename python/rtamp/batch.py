"""rtamp.batch: the trial grid of `rtamp batch`, run on a Dask cluster.

    from dask.distributed import Client
    import rtamp.batch
    csv = rtamp.batch.run("3-block-tray", algorithms=["astar-exp", "dijkstra"],
                          changes=["relocate", "add"], trials=30, world="symbolic",
                          client=Client("tcp://scheduler:8786"), output="table1.csv")

The grid (algorithms x changes x BT variants x trials, each trial seeded by its
index exactly as `rtamp batch` seeds it) is cut into chunks; each chunk is one
Dask task that runs its episodes in C++ on the worker (rtamp.run_trials, the
same code `rtamp batch` runs) and returns CSV rows; the rows are merged into the
canonical CSV `rtamp batch --output` writes (same header, same row order).
Without a client the grid runs here, in one process. Deterministic columns
(trial, seed, success, ...) do not depend on where an episode ran; measured wall
times do.

With `output`, each chunk's rows are appended to it as the chunk finishes (so a
batch that is killed keeps what it did), and the file is replaced by the whole
canonical CSV at the end. `resume=True` goes on with an interrupted batch as
`rtamp batch --resume` does: the whole rows of `output` are kept (a torn last
line dropped), each must be a trial of this grid with the same seed (else
rtamp.Error naming the file and line, before anything runs or the file is
changed), and only the missing trials run.
"""

import csv as _csv
import io
import os

import rtamp

TRIAL_FIELDS = ("algorithm", "change", "bt", "trial", "seed")


def trials(*, algorithms=("astar-exp", "astar", "dijkstra"), changes=("relocate", "remove", "add"),
           bts=("online-action",), trials=30, seed=1, shard=""):
    """The trial list of `rtamp batch` (trial-major), as (algorithm, change, bt, trial, seed) tuples."""
    return rtamp.make_trials(algorithms=list(algorithms), changes=list(changes), bts=list(bts),
                             trials=trials, seed=seed, shard=shard)


def _run_chunk(scenario_yaml, source, chunk, options):
    """One Dask task: run a chunk of trials on this worker; returns its CSV rows (no header)."""
    import rtamp as r  # imported on the worker
    scenario = r.parse_scenario(scenario_yaml, source)
    return r.run_trials(scenario, chunk, **options)


def _chunks(items, size):
    return [items[i:i + size] for i in range(0, len(items), size)]


def _kept_rows(output, scenario, grid):
    """The whole rows (no header) of an interrupted batch's CSV, the trials they ran, their bytes with the header."""
    if not os.path.exists(output):
        return "", set(), 0
    with open(output, encoding="utf-8", newline="") as f:
        text = f.read()
    whole = text[:text.rfind("\n") + 1]  # a torn last line dropped
    if not whole.strip():
        return "", set(), 0
    header, _, body = whole.partition("\n")
    if header.rstrip("\r") != ",".join(rtamp.csv_columns()):
        raise rtamp.Error(f"{output}:1: resume: not the CSV of an rtamp batch (its header differs)")
    rtamp.merge_csv([body])  # whole rows of this version's CSV, no trial twice (rtamp.Error otherwise)
    seeds = {t[:4]: t[4] for t in grid}
    done = set()
    for line, row in enumerate(_csv.DictReader(io.StringIO(whole)), start=2):
        key = (row["algorithm"], row["change"], row["bt"], int(row["trial"]))
        where = f"{output}:{line}: resume: the row ({row['change']} {row['algorithm']} {row['bt']} trial {row['trial']})"
        if row["scenario"] != scenario.name:
            raise rtamp.Error(f"{where} is of scenario '{row['scenario']}', not '{scenario.name}'")
        if key not in seeds:
            raise rtamp.Error(f"{where} is not a trial of this batch")
        if int(row["seed"]) != seeds[key]:
            raise rtamp.Error(f"{where} has seed {row['seed']}, this batch's trial has seed {seeds[key]} (another seed)")
        done.add(key)
    return body, done, len(whole.encode())


def run(scenario, *, algorithms=("astar-exp", "astar", "dijkstra"), changes=("relocate", "remove", "add"),
        bts=("online-action",), trials=30, seed=1, world="symbolic", max_time=900.0, cost="euclid",
        randomize_initial=True, scripted_operator=False, client=None, chunk=1, output=None, resume=False):
    """Runs the grid and returns the CSV text (written to `output` too, if given).

    scenario: a Scenario, or a built-in name / YAML path. client: a dask.distributed.Client
    (None: run here, one chunk at a time). chunk: trials per Dask task (and per append to
    `output`). resume: keep the whole rows `output` holds and run only the missing trials.
    """
    if isinstance(scenario, str):
        scenario = rtamp.load_scenario(scenario)
    if chunk < 1:
        raise rtamp.Error("chunk must be at least 1")
    if resume and not output:
        raise rtamp.Error("resume: resumes the `output` CSV of an interrupted batch; give output")
    grid = globals()["trials"](algorithms=algorithms, changes=changes, bts=bts, trials=trials, seed=seed)
    options = dict(world=world, jobs=1, max_time=max_time, cost=cost, randomize_initial=randomize_initial,
                   scripted_operator=scripted_operator)
    kept, done, kept_bytes = _kept_rows(output, scenario, grid) if resume else ("", set(), 0)
    todo = [t for t in grid if t[:4] not in done]
    slices = [kept] if kept else []
    sink = None
    if output and kept:  # the kept rows stay where they are; a torn line after them goes
        sink = open(output, "r+", encoding="utf-8", newline="")
        sink.truncate(kept_bytes)
        sink.seek(0, io.SEEK_END)
    elif output:  # the header, then each chunk's rows as it finishes
        sink = open(output, "w", encoding="utf-8", newline="")
        sink.write(",".join(rtamp.csv_columns()) + "\n")
        sink.flush()

    def finished(rows):
        slices.append(rows)
        if sink:
            sink.write(rows)
            sink.flush()

    try:
        if client is None:
            for part in _chunks(todo, chunk):
                finished(rtamp.run_trials(scenario, part, **options))
        elif todo:
            from dask.distributed import as_completed
            yaml, parts = scenario.to_yaml(), _chunks(todo, chunk)
            futures = client.map(_run_chunk, [yaml] * len(parts), [scenario.source or scenario.name] * len(parts),
                                 parts, [options] * len(parts), pure=False)
            for future in as_completed(futures):
                finished(future.result())
    finally:
        if sink:
            sink.close()
    merged = rtamp.merge_csv(slices)
    if output:
        with open(output + ".tmp", "w", encoding="utf-8", newline="") as f:
            f.write(merged)
        os.replace(output + ".tmp", output)
    return merged
