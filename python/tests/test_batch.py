"""rtamp.batch on a real local Dask cluster: a scheduler and two worker processes (dask-scheduler /
dask-worker, loopback only). The merged CSV must equal a one-process run on its deterministic
columns (and `rtamp batch` itself, when the binary is at hand), with the same header and row order."""

import csv
import io
import os
import socket
import subprocess
import sys
import time

import pytest

import rtamp
import rtamp.batch

DETERMINISTIC = ["scenario", "algorithm", "bt", "change", "trial", "seed", "success", "interventions"]
GRID = dict(algorithms=["astar-exp", "dijkstra"], changes=["relocate", "add"], bts=["online-action"],
            trials=3, seed=7, world="symbolic", max_time=400)


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def columns(text, names):
    return [tuple(r[n] for n in names) for r in rows(text)]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_trial_grid_matches_rtamp_batch_seeding():
    t = rtamp.batch.trials(algorithms=["astar"], changes=["relocate"], trials=2, seed=1)
    assert [x[:4] for x in t] == [("astar", "relocate", "online-action", 1), ("astar", "relocate", "online-action", 2)]
    assert t[0][4] != t[1][4]
    half = rtamp.batch.trials(algorithms=["astar"], changes=["relocate"], trials=2, seed=1, shard="2/2")
    assert half == t[1:]
    assert rtamp.csv_columns()[:6] == ["scenario", "algorithm", "bt", "change", "trial", "seed"]
    with pytest.raises(rtamp.Error):
        rtamp.batch.trials(algorithms=["quick"])


def test_merge_refuses_duplicates():
    s = rtamp.load_scenario("3-block-tray")
    one = rtamp.run_trials(s, rtamp.batch.trials(algorithms=["astar"], changes=["none"], trials=1))
    with pytest.raises(rtamp.Error):
        rtamp.merge_csv([one, one])


@pytest.fixture
def dask_cluster(tmp_path):
    distributed = pytest.importorskip("distributed")
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ)
    procs = [subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                               "--port", str(port), "--no-dashboard", "--no-show"],
                              env=env, cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        for _ in range(2):
            procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address,
                                           "--nthreads", "1", "--nworkers", "1", "--host", "127.0.0.1",
                                           "--no-dashboard", "--local-directory", str(tmp_path)],
                                          env=env, cwd=tmp_path, stdout=subprocess.DEVNULL,
                                          stderr=subprocess.DEVNULL))
        client = distributed.Client(address, timeout=60)
        client.wait_for_workers(2, timeout=120)
        yield client
        client.close()
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()


def test_dask_batch_equals_one_process_run(dask_cluster, tmp_path):
    workers = dask_cluster.scheduler_info()["workers"]
    assert len(workers) == 2 and all(w.startswith("tcp://127.0.0.1:") for w in workers)
    out = tmp_path / "dask.csv"
    merged = rtamp.batch.run("3-block-tray", client=dask_cluster, chunk=2, output=str(out), **GRID)
    assert out.read_text() == merged
    local = rtamp.batch.run("3-block-tray", **GRID)
    assert merged.splitlines()[0] == local.splitlines()[0] == ",".join(rtamp.csv_columns())
    assert len(rows(merged)) == 2 * 2 * 3
    assert columns(merged, DETERMINISTIC) == columns(local, DETERMINISTIC)
    # every episode really ran on a worker process, not here
    ran_on = dask_cluster.run(lambda: os.getpid())
    assert len(set(ran_on.values())) == 2 and os.getpid() not in ran_on.values()

    binary = os.environ.get("RTAMP_BINARY")
    if binary and os.path.exists(binary):
        ref = tmp_path / "rtamp-batch.csv"
        cmd = [binary, "batch", "3-block-tray", "--world", "symbolic", "--trials", "3", "--seed", "7",
               "--max-time", "400", "--algo", "astar-exp", "--algo", "dijkstra", "--change", "relocate",
               "--change", "add", "--bt", "online-action", "--output", str(ref), "--quiet"]
        subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL, timeout=300)
        assert columns(ref.read_text(), DETERMINISTIC) == columns(merged, DETERMINISTIC)


def interrupted(path, whole, rows_kept):
    """The CSV a batch killed after `rows_kept` rows leaves: those rows and a torn line."""
    lines = whole.splitlines(keepends=True)
    path.write_text("".join(lines[:1 + rows_kept]) + lines[1 + rows_kept][:25], encoding="utf-8")
    return lines[1:1 + rows_kept]


def test_resume_keeps_whole_rows_and_runs_the_missing_trials(tmp_path):
    out = tmp_path / "r.csv"
    whole = rtamp.batch.run("3-block-tray", output=str(out), **GRID)
    assert out.read_text() == whole
    kept = interrupted(out, whole, 5)
    resumed = rtamp.batch.run("3-block-tray", output=str(out), resume=True, **GRID)
    assert out.read_text() == resumed
    assert columns(resumed, DETERMINISTIC) == columns(whole, DETERMINISTIC)
    assert set(kept) <= set(resumed.splitlines(keepends=True))  # kept as they were, wall times too
    # A CSV of another batch: refused at its line, the file as it was.
    before = out.read_bytes()
    with pytest.raises(rtamp.Error, match=r"r\.csv:2: resume: the row .* \(another seed\)"):
        rtamp.batch.run("3-block-tray", output=str(out), resume=True, **{**GRID, "seed": 8})
    with pytest.raises(rtamp.Error, match=r"r\.csv:\d+: resume: the row .* is not a trial of this batch"):
        rtamp.batch.run("3-block-tray", output=str(out), resume=True, **{**GRID, "changes": ["relocate"]})
    assert out.read_bytes() == before
    with pytest.raises(rtamp.Error, match="give output"):
        rtamp.batch.run("3-block-tray", resume=True, **GRID)


def test_dask_batch_resumes(dask_cluster, tmp_path):
    out = tmp_path / "d.csv"
    whole = rtamp.batch.run("3-block-tray", **GRID)
    interrupted(out, whole, 4)
    resumed = rtamp.batch.run("3-block-tray", client=dask_cluster, chunk=2, output=str(out), resume=True, **GRID)
    assert out.read_text() == resumed
    assert columns(resumed, DETERMINISTIC) == columns(whole, DETERMINISTIC)
