// The run controls: pause / resume, one step, the speed (live and replay), and the clock;
// every change goes to the server as a `control` request and the buttons follow the
// server's `state` messages (never the page's own guess).

export class ControlsPanel {
  constructor(root, send) {
    this.root = root;
    this.send = send;
    this.pause = root.querySelector('#pause');
    this.step = root.querySelector('#step');
    this.speed = root.querySelector('#speed');
    this.clock = root.querySelector('#clock');
    this.pause.addEventListener('click', () => this.send(this.paused ? 'resume' : 'pause'));
    this.step.addEventListener('click', () => this.send('step'));
    this.speed.addEventListener('change', () => this.send('speed', Number(this.speed.value)));
    this.paused = false;
  }

  setState(s) {
    if (s.paused != null) {
      this.paused = s.paused;
      this.pause.textContent = s.paused ? '▶ resume' : '❚❚ pause';
      this.step.disabled = !s.paused;
    }
    if (s.speed != null && document.activeElement !== this.speed) this.speed.value = String(s.speed);
    if (s.t != null) this.setTime(s.t);
    if (s.ended) this.clock.classList.add('ended');
  }

  setTime(t) {
    this.clock.textContent = `t = ${t.toFixed(2)} s`;
  }
}
