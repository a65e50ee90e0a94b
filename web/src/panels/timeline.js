// The timeline panel: interventions (applied and refused), replans, new plans with their
// planning time in µs, tree changes, things appearing or vanishing, the end — newest at
// the bottom, each with its world time. In replay mode a slider over [0, duration]
// scrubs the episode (the caller sends `seek`); clicking an entry seeks to its time.
import { fmt } from '../episode.js';

export class TimelinePanel {
  constructor(list, scrub, onSeek) {
    this.list = list;
    this.scrub = scrub;
    this.onSeek = onSeek;
    this.shown = 0;
    this.scrub.addEventListener('change', () => this.onSeek(Number(this.scrub.value)));
  }

  setMode(mode, duration) {
    this.replay = mode === 'replay';
    this.scrub.hidden = !this.replay;
    if (this.replay) {
      this.scrub.max = String(duration ?? 0);
      this.scrub.step = 'any';
    }
  }

  reset() {
    this.list.replaceChildren();
    this.shown = 0;
  }

  update(timeline) {
    for (; this.shown < timeline.length; this.shown++) {
      const e = timeline[this.shown];
      const row = document.createElement('div');
      row.className = `tl-entry tl-${e.kind}`;
      row.dataset.t = e.t;
      const time = document.createElement('span');
      time.className = 'tl-time';
      time.textContent = fmt(e.t) + ' s';
      row.append(time, ' ', e.text);
      if (this.replay) row.addEventListener('click', () => this.onSeek(e.t));
      this.list.appendChild(row);
    }
    this.list.scrollTop = this.list.scrollHeight;
  }

  setTime(t) {
    if (this.replay && document.activeElement !== this.scrub) this.scrub.value = String(t);
  }
}
