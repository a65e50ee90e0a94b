// The Camera panel: the latest image of camera perception (`camera` messages, served at
// most 5 a second) with the detections' boxes drawn over it, each labelled with the
// believed thing it is taken for and that thing's belief state ("o1 visible") in the
// state's colour (the server's: sim/camera_overlay.hpp). Hidden until a camera message
// comes (episodes with truth perception send none). Images are decoded as they come;
// one decoded after a newer one is dropped.
export class CameraPanel {
  constructor(section, canvas, caption) {
    this.section = section;
    this.canvas = canvas;
    this.caption = caption;
    this.received = 0;
    this.drawn = 0;
    this.last = null; // the last message drawn
    this.seq = 0;
  }

  show(m) {
    this.received++;
    const seq = ++this.seq;
    const img = new Image();
    img.onload = () => {
      if (seq !== this.seq) return;
      this.draw(m, img);
    };
    img.src = `data:image/png;base64,${m.png}`;
  }

  draw(m, img) {
    this.section.hidden = false;
    const c = this.canvas;
    if (c.width !== m.width) c.width = m.width;
    if (c.height !== m.height) c.height = m.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    g.lineWidth = 2;
    const px = Math.max(12, Math.round(m.height / 28)); // the labels' size: ~17 px on a 480-row image
    g.font = `bold ${px}px sans-serif`;
    g.textBaseline = 'bottom';
    for (const b of m.boxes) {
      const colour = `rgb(${b.rgb.join(',')})`;
      g.strokeStyle = colour;
      // On whole pixels: the 2-px outline covers the pixels either side of each edge, crisp.
      const [x0, y0, x1, y1] = [b.x0, b.y0, b.x1, b.y1].map(Math.round);
      g.strokeRect(x0, y0, x1 - x0, y1 - y0);
      const w = g.measureText(b.label).width + 6;
      const y = y0 >= px + 5 ? y0 - 1 : y1 + px + 5; // above the box, or below it at the top edge
      g.fillStyle = colour;
      g.fillRect(x0 - 1, y - px - 4, w, px + 4);
      g.fillStyle = '#000';
      g.fillText(b.label, x0 + 2, y - 2);
    }
    this.caption.textContent = `${m.camera} · t = ${m.t.toFixed(2)} s · ${m.boxes.length} detection${m.boxes.length === 1 ? '' : 's'}`;
    this.last = m;
    this.drawn++;
  }
}
