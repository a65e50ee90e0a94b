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
"""

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


def run(scenario, *, algorithms=("astar-exp", "astar", "dijkstra"), changes=("relocate", "remove", "add"),
        bts=("online-action",), trials=30, seed=1, world="symbolic", max_time=900.0, cost="euclid",
        randomize_initial=True, scripted_operator=False, client=None, chunk=1, output=None):
    """Runs the grid and returns the CSV text (written to `output` too, if given).

    scenario: a Scenario, or a built-in name / YAML path. client: a dask.distributed.Client
    (None: run here, one episode at a time). chunk: trials per Dask task.
    """
    if isinstance(scenario, str):
        scenario = rtamp.load_scenario(scenario)
    if chunk < 1:
        raise rtamp.Error("chunk must be at least 1")
    grid = globals()["trials"](algorithms=algorithms, changes=changes, bts=bts, trials=trials, seed=seed)
    options = dict(world=world, jobs=1, max_time=max_time, cost=cost, randomize_initial=randomize_initial,
                   scripted_operator=scripted_operator)
    if client is None:
        slices = [rtamp.run_trials(scenario, grid, **options)]
    else:
        yaml = scenario.to_yaml()
        futures = client.map(_run_chunk, [yaml] * len(_chunks(grid, chunk)),
                             [scenario.source or scenario.name] * len(_chunks(grid, chunk)),
                             _chunks(grid, chunk), [options] * len(_chunks(grid, chunk)), pure=False)
        slices = client.gather(futures)
    csv = rtamp.merge_csv(slices)
    if output:
        with open(output, "w", encoding="utf-8", newline="") as f:
            f.write(csv)
    return csv
