// The current-plan panel: the latest plan's moves in order with each move's motion cost
// (plan record `costs`), the lasso's cycle marked, finished moves struck through and
// the running one highlighted; the header gives the total cost and the planning time.
import { fmt } from '../episode.js';

export class PlanPanel {
  constructor(el) {
    this.el = el;
  }

  update(plan) {
    this.el.replaceChildren();
    if (!plan) {
      this.el.textContent = 'no plan yet';
      return;
    }
    const head = document.createElement('div');
    head.className = 'plan-head';
    head.textContent = `cost ${fmt(plan.cost)} · found in ${Math.round(plan.seconds * 1e6)} µs`;
    this.el.appendChild(head);
    const ol = document.createElement('ol');
    plan.actions.forEach((a, i) => {
      const li = document.createElement('li');
      li.className = 'plan-step';
      if (plan.done.has(i)) li.classList.add('done');
      if (plan.running === i) li.classList.add('running');
      if (plan.in_cycle[i]) li.classList.add('cycle');
      li.textContent = a + (plan.costs[i] != null ? `  (${fmt(plan.costs[i])})` : '');
      ol.appendChild(li);
    });
    this.el.appendChild(ol);
  }
}
