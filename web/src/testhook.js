// The page's read-only test hook, window.rtamp: what the scene shows (things with their
// class, kind, position, location), where a world point or a thing is on the screen
// (page pixels, for real mouse drags), the messages and replies seen, the draw counter,
// scale and costs (as the drawing worker reports them), where the scene is drawn, and the
// drop → intervention latencies. Nothing here changes the page.

import { linkFrames, origin } from './kinematics.js';

export function installTestHook(app) {
  const { scene } = app;
  window.rtamp = {
    // The page has shown its latest hello: panels filled, the scene built and drawn once.
    get ready() {
      return app.ready && scene.drawnSeq === scene.seq;
    },
    get hello() {
      return app.hello;
    },
    get t() {
      return app.t;
    },
    get state() {
      return app.state;
    },
    get held() {
      return app.held;
    },
    get records() {
      return app.episode.records;
    },
    get tracked() {
      return app.episode.tracked;
    },
    // Scene draws (on demand: not every animation frame draws).
    get frames() {
      return scene.drawn;
    },
    // The canvas's drawing-buffer scale of the last draw (1 when still; lower while moving
    // if frames are too slow to draw at full resolution).
    get drawScale() {
      return scene.drawScale;
    },
    // What each drawn frame cost (ms, from the animation frame that drew to the next one,
    // in the thread that draws), oldest first.
    get drawCosts() {
      return scene.costs;
    },
    // When each draw was made (epoch ms, in the thread that draws), oldest first.
    get drawTimes() {
      return scene.drawTimes;
    },
    // The drawing-buffer scale of each of those draws (1: full resolution).
    get drawScales() {
      return scene.drawScales;
    },
    // Where the scene is drawn: 'worker' (OffscreenCanvas), 'main' (the fallback, with
    // `renderWhy` saying why) or 'starting'.
    get renderer() {
      return scene.link.mode;
    },
    get renderWhy() {
      return scene.link.why;
    },
    get framesReceived() {
      return app.framesReceived;
    },
    get notices() {
      return app.notice.history.map((n) => ({ text: n.text, kind: n.kind }));
    },
    // The tool point of the arm as drawn (forward kinematics of the angles shown).
    get tool() {
      return app.arm?.toolPoint ?? null;
    },
    get streamedTool() {
      return app.tool;
    },
    // The origins of the arm's link frames as drawn (base, shoulder, elbow, wrists, flange, tool).
    get armPoints() {
      return app.arm ? linkFrames(app.arm.robot, app.arm.q).map(origin) : null;
    },
    // The Camera panel: camera messages received and drawn, and the last one drawn.
    get camera() {
      const c = app.camera;
      return { received: c.received, drawn: c.drawn, last: c.last };
    },
    // The behavior-tree panel as drawn: node count, the statuses shown (one letter a
    // node, read from the boxes), the running node kept in view, the view (pan, zoom), and
    // what the last tree's layout and drawing and the last status change cost (ms).
    get tree() {
      const t = app.tree;
      const letters = { idle: 'I', running: 'R', success: 'S', failure: 'F' };
      return {
        nodes: t.boxes.length,
        statuses: t.boxes.map((b) => letters[b.getAttribute('data-status')] ?? '?').join(''),
        running: t.runningLeaf(),
        followed: t.followed,
        view: { ...t.view },
        size: t.layout ? { width: t.layout.width, height: t.layout.height } : null,
        buildMs: t.buildMs,
        statusMs: t.statusMs,
      };
    },
    get latencies() {
      return app.latencies;
    },
    things() {
      return [...scene.things.entries()]
        .filter(([, e]) => e.mesh.visible)
        .map(([name, e]) => ({ name, class: e.info.class, kind: e.info.kind, pos: e.pos, at: e.at }));
    },
    regions() {
      return scene.regions.map((r) => ({ name: r.name, center: r.center, size: r.size }));
    },
    projectPoint(p) {
      return scene.project(p);
    },
    project(name) {
      const e = scene.things.get(name);
      if (!e) {
        const r = scene.regions.find((x) => x.name === name);
        return r ? scene.project([r.center[0], r.center[1], scene.tableTop]) : null;
      }
      return scene.project(e.mesh.position.toArray());
    },
  };
}
