// The episode as the page knows it, rebuilt from the JSON Lines log records
// (docs/exec.md "The episode log"; record names from src/rtamp/exec/episode_log.cpp):
// the current plan (`plan`: actions, costs, in_cycle; `action` finished/started marks
// progress), the tracked Büchi states (`run`/`plan` automaton_states), the timeline
// (`intervention`, `replan`, `plan` with its µs, `tree`, `handled_by_tree`, `things`,
// `end`), and the end record. Invariant: feeding the same records in order gives the
// same state (the page rebuilds it from hello.history after every hello).

export class Episode {
  constructor() {
    this.reset();
  }

  reset() {
    this.records = [];
    this.plan = null; // {actions, costs, in_cycle, cost, seconds, done:Set<index>, running}
    this.tracked = [];
    this.timeline = [];
    this.end = null;
    this.placement = null;
    this.info = null;
    this.task = null; // the task in force after a change: {task, automaton, version}
  }

  add(r) {
    this.records.push(r);
    const t = r.t ?? 0;
    switch (r.ev) {
      case 'episode':
        this.info = r;
        break;
      case 'plan':
        this.plan = {
          actions: r.actions || [],
          costs: r.costs || [],
          in_cycle: r.in_cycle || [],
          cost: r.cost,
          seconds: r.seconds,
          first: r.first,
          done: new Set(),
          running: -1,
        };
        if (r.automaton_states) this.tracked = r.automaton_states;
        this.timeline.push({ t, kind: r.first ? 'plan' : 'replanned', text: `${r.first ? 'first plan' : 'new plan'}: ${r.actions.length} moves, cost ${fmt(r.cost)}, ${Math.round(r.seconds * 1e6)} µs` });
        break;
      case 'action': {
        if (!this.plan) break;
        const i = this.plan.actions.findIndex((a, k) => a === r.action && !this.plan.done.has(k));
        if (r.what === 'start') this.plan.running = i;
        if (r.what === 'finished' && i >= 0) {
          this.plan.done.add(i);
          this.plan.running = -1;
        }
        if (r.what === 'failed' || r.what === 'halted') this.plan.running = -1;
        break;
      }
      case 'run':
        this.tracked = r.automaton_states || this.tracked;
        this.placement = r.state;
        break;
      case 'intervention':
        this.timeline.push({
          t,
          kind: r.applied ? 'intervention' : 'refused',
          text: `${r.kind} ${r.subject || ''}${r.location ? ' → ' + r.location : ''}${r.applied ? '' : ' (refused)'}${r.detail ? ': ' + r.detail : ''}`,
        });
        break;
      case 'task':
        if (r.applied) {
          this.task = { task: r.task, automaton: r.automaton, version: (this.task?.version ?? 0) + 1 };
          this.tracked = [];
        }
        this.timeline.push({
          t,
          kind: r.applied ? 'task' : 'refused',
          text: r.applied ? `new task from ${r.by}: ${r.task} (${r.automaton_states} automaton states)` : `new task from ${r.by} refused: ${r.refused}`,
        });
        break;
      case 'redirect':
        this.timeline.push({ t, kind: 'replan', text: `redirected ${r.action}: ${r.rule}` });
        break;
      case 'replan':
        this.timeline.push({ t, kind: 'replan', text: `replan: ${r.why}` });
        break;
      case 'handled_by_tree':
        this.timeline.push({ t, kind: 'handled', text: `handled by the tree: ${r.by}` });
        break;
      case 'tree':
        this.timeline.push({ t, kind: 'tree', text: `tree change #${r.changes}: +${r.inserted} −${r.removed} ~${r.updated}${r.applied ? '' : ' (deferred)'}` });
        break;
      case 'things':
        this.timeline.push({ t, kind: 'things', text: `things ${r.added?.length ? '+' + r.added.join(', ') : ''} ${r.removed?.length ? '−' + r.removed.join(', ') : ''}` });
        break;
      case 'end':
        this.end = r;
        this.placement = r.placement;
        this.timeline.push({ t, kind: 'end', text: `end: ${r.end}${r.reason ? ' (' + r.reason + ')' : ''}` });
        break;
      default:
        break;
    }
  }

  // The moves of the current plan still to do, in order.
  remaining() {
    if (!this.plan) return [];
    return this.plan.actions.filter((_, i) => !this.plan.done.has(i));
  }
}

export function fmt(x) {
  if (x == null || Number.isNaN(x)) return '–';
  return Number(x).toFixed(Math.abs(x) < 10 ? 3 : 1).replace(/\.?0+$/, '');
}
