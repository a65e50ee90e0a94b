#!/usr/bin/python3
"""Held-out scenarios with task changes (tests/data/new-task/*.yaml), run as a user runs them.

Each scenario was written from README.md and docs/ alone (docs/scenario.md
"Operator", docs/exec.md "A new task"): a scripted `new_task` (or two) at a
moment of the episode. Each is run with `rtamp run FILE --world symbolic`
over several seeds (the scenario's layout and shuffled ones, --random-initial),
or with --mujoco once in the MuJoCo world, and must end as the docs promise:

  - the end (`task-done`, `unsatisfiable` naming the change, `cycles` of the
    new task) and the exit code (0 when done, 1 otherwise);
  - `tasks` in the metrics: one per task in force, from the times given, every
    one but the last `superseded`, the last the episode's end; as many applied
    `task` records in the log, each with its automaton;
  - where things end up, checked here on the end record's placement;
  - what must hold on the run from the change on (a thing kept out of a
    region: every `run` state after the change);
  - a running move the new task allows is finished (no `redirect`), one it
    forbids is halted and logged (`redirect`); a task already satisfied ends
    the episode with no move started after it.

The same change given with `--new-task` instead of the script ends alike.
Exit 0 when every run ends as expected, 1 otherwise (a line per failure).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def blocks(p):
    return {k: v for k, v in p.items() if k.startswith('o')}


def all_in(p, where):
    return all(v == where for v in blocks(p).values())


def count_in(p, where):
    return sum(1 for v in blocks(p).values() if v == where)


# file -> what the docs promise. `changes`: the times of its new tasks; `redirect`
# False: the move running at the change is finished; `forbidden(action)`: a move the
# new task forbids, halted and redirected if it runs at the change (in the symbolic
# world one does: the scenario's time is chosen so); `always(state)`: holds on every
# step of the run from the change on; `final(placement)`: holds at the end.
EXPECT = {
    'reach-then-other-reach.yaml': dict(changes=[5], end='task-done', final=lambda p: all_in(p, 'r3'), redirect=False),
    'keep-o2-out.yaml': dict(changes=[2], end='task-done', redirect=False,
                             final=lambda p: p['o1'] == 'r2' and p['o3'] == 'r2' and p['o2'] != 'r2',
                             always=lambda s: s['o2'] != 'r2'),
    'carry-redirected.yaml': dict(changes=[3], end='task-done', forbidden=lambda a: a.endswith(', r2)'), final=lambda p: all_in(p, 'r3'),
                                  always=lambda s: count_in(s, 'r2') == 0),
    'already-satisfied.yaml': dict(changes=[3], end='task-done', final=lambda p: p['o3'] == 'r1', no_move_after=True),
    'unsatisfiable-change.yaml': dict(changes=[1], end='unsatisfiable', reason='new task given at t = 1 s'),
    'new-propositions.yaml': dict(changes=[4], end='task-done', final=lambda p: p['o3'] == 'r2' and count_in(p, 'r1') >= 2),
    'two-changes.yaml': dict(changes=[4, 12], end='task-done', final=lambda p: all_in(p, 'r1')),
    'patrol-later.yaml': dict(changes=[3], end='cycles', args=['--cycles', '2'], cycles=2,
                              visits={'o1': ['r3', 'r2']}),
    'tray-carry-all.yaml': dict(changes=[6], end='task-done', final=lambda p: all_in(p, 'r3') and p['r3'] == 'r2'),
    'tray-stays-home.yaml': dict(changes=[12], end='task-done', forbidden=lambda a: a.startswith('move(r3, '),
                                 final=lambda p: all_in(p, 'r2') and p['r3'] == 'r1', always=lambda s: s['r3'] == 'r1'),
}

# The same change from the command line: (file, its task at its time).
COMMAND_LINE = [('reach-then-other-reach.yaml', '5@F G all_in_r3')]


def run(binary, path, world, args, tmp, tag):
    log = os.path.join(tmp, tag + '.jsonl')
    cmd = [binary, 'run', path, '--world', world, '--quiet', '--json', '--log', log] + args
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    try:
        metrics = json.loads(r.stdout)
    except ValueError:
        return None, None, r, cmd
    with open(log) as f:
        records = [json.loads(line) for line in f if line.strip()]
    return metrics, records, r, cmd


def running_at(records, t):
    """The move running at world time t (started at or before it, not ended before it), or None."""
    running = None
    for x in records:
        if x['ev'] != 'action' or x['t'] > t:
            continue
        if x['what'] == 'start':
            running = x['action']
        elif x['t'] < t:
            running = None
    return running


def check(e, metrics, records, r, by, world):
    """The failures of one run (empty: it ended as the docs promise)."""
    bad = []
    if metrics is None:
        return ['no metrics on stdout (exit %d): %s' % (r.returncode, r.stderr.strip()[:300])]
    want_code = 0 if e['end'] in ('task-done', 'cycles') else 1
    if metrics['end'] != e['end']:
        bad.append('ended %s (%s), not %s' % (metrics['end'], metrics['reason'], e['end']))
    if r.returncode != want_code:
        bad.append('exit %d, not %d' % (r.returncode, want_code))
    if 'reason' in e and e['reason'] not in metrics['reason']:
        bad.append('reason %r does not name the change (%r)' % (metrics['reason'], e['reason']))
    tasks = metrics['tasks']
    # A task takes effect at the loop's first step at or after its time (MuJoCo's steps are 2 ms).
    times = [t['time'] for t in tasks]
    if len(times) != len(e['changes']) + 1 or any(not (w <= t < w + 0.1) for t, w in zip(times, [0] + e['changes'])):
        bad.append('tasks at %s, not %s' % ([t['time'] for t in tasks], [0] + e['changes']))
    elif [t['by'] for t in tasks[1:]] != [by] * len(e['changes']):
        bad.append('tasks given by %s, not %s' % ([t['by'] for t in tasks], by))
    if tasks and [t['outcome'] for t in tasks] != ['superseded'] * (len(tasks) - 1) + [metrics['end']]:
        bad.append('task outcomes %s' % [t['outcome'] for t in tasks])
    applied = [x for x in records if x['ev'] == 'task' and x['applied']]
    if len(applied) != len(e['changes']):
        bad.append('%d applied task records, not %d' % (len(applied), len(e['changes'])))
    for x in applied:
        if len(x['automaton']['states']) != x['automaton_states']:
            bad.append('task record at %s: automaton of %d states, size %d' % (x['t'], len(x['automaton']['states']), x['automaton_states']))
    end = records[-1]
    if end['ev'] != 'end':
        bad.append('the log does not end with its end record')
    if 'final' in e and not e['final'](end['placement']):
        bad.append('ends with %s' % end['placement'])
    change = e['changes'][-1]
    if 'always' in e:
        for x in records:
            if x['ev'] == 'run' and x['t'] >= e['changes'][0] and not e['always'](x['state']):
                bad.append('at %s the run is at %s, which the new task forbids' % (x['t'], x['state']))
                break
    redirects = [x for x in records if x['ev'] == 'redirect']
    if 'forbidden' in e:
        running = running_at(records, e['changes'][0])
        must = running is not None and e['forbidden'](running)
        if world == 'symbolic' and not must:
            bad.append('the scenario runs %s at its change, not a move the new task forbids' % running)
        if must and not any(x['action'] == running for x in redirects):
            bad.append('no redirect of %s: the forbidden move was finished' % running)
        if not must and redirects:
            bad.append('redirected %s, though %s ran at the change' % (redirects[0]['action'], running))
    if e.get('redirect') is False and redirects:
        bad.append('redirected %s, though the new task allows finishing it' % redirects[0]['action'])
    if e.get('no_move_after'):
        late = [x for x in records if x['ev'] == 'action' and x['what'] == 'start' and x['t'] > change]
        if late:
            bad.append('a move started after the satisfied task: %s at %s' % (late[0]['action'], late[0]['t']))
    if 'cycles' in e and tasks and tasks[-1]['cycles'] != e['cycles']:
        bad.append('%s cycles of the new task, not %d' % (tasks[-1]['cycles'], e['cycles']))
    for thing, places in e.get('visits', {}).items():
        seen = {x['state'][thing] for x in records if x['ev'] == 'run' and x['t'] >= change}
        if not set(places) <= seen:
            bad.append('%s visited %s after the change, not all of %s' % (thing, sorted(seen), places))
    return bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--bin', required=True)
    ap.add_argument('--data', required=True, help='the folder of the scenarios')
    ap.add_argument('--mujoco', action='store_true', help='one run each in the MuJoCo world')
    ap.add_argument('--seeds', type=int, default=4)
    a = ap.parse_args()
    files = sorted(f for f in os.listdir(a.data) if f.endswith('.yaml'))
    failures = []
    if sorted(EXPECT) != files:
        failures.append('the scenarios %s and the expectations %s differ' % (files, sorted(EXPECT)))
    world = 'mujoco' if a.mujoco else 'symbolic'
    variants = [[]] if a.mujoco else [[]] + [['--seed', str(s), '--random-initial'] for s in range(1, a.seeds + 1)]
    runs = 0
    with tempfile.TemporaryDirectory() as tmp:
        for f in files:
            e = EXPECT.get(f)
            if e is None:
                continue
            for k, v in enumerate(variants):
                args = e.get('args', []) + v
                metrics, records, r, cmd = run(a.bin, os.path.join(a.data, f), world, args, tmp, '%s-%d' % (f, k))
                runs += 1
                for b in check(e, metrics, records, r, 'script', world):
                    failures.append('%s: %s' % (' '.join(cmd[1:]), b))
        for f, change in COMMAND_LINE:
            e = EXPECT[f]
            args = e.get('args', []) + ['--no-operator', '--new-task', change]
            metrics, records, r, cmd = run(a.bin, os.path.join(a.data, f), world, args, tmp, 'cli-' + f)
            runs += 1
            for b in check(e, metrics, records, r, 'command line', world):
                failures.append('%s: %s' % (' '.join(cmd[1:]), b))
    for line in failures:
        print('FAIL ' + line)
    print('%d runs of %d scenarios in the %s world: %s' % (runs, len(files), world, 'all as documented' if not failures else '%d failures' % len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
