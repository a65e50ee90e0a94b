// The person in the loop, the parts that are not dragging: a palette of the scenario's
// classes to add a thing at a location, delete the selected thing, take the held thing
// out of the gripper (to a location, or away). Each becomes an `intervene` request; the
// server validates it like a scripted intervention and a refusal's reason is shown.

export class PersonPanel {
  constructor(root, actions) {
    this.root = root;
    this.actions = actions; // {add(cls, loc), remove(name), take(loc)}
    this.palette = root.querySelector('#palette');
    this.addAt = root.querySelector('#add-at');
    this.del = root.querySelector('#delete');
    this.selected = root.querySelector('#selected');
    this.take = root.querySelector('#take');
    this.takeTo = root.querySelector('#take-to');
    this.del.addEventListener('click', () => this.selection && this.actions.remove(this.selection));
    this.take.addEventListener('click', () => this.actions.take(this.takeTo.value || null));
    this.select(null);
    this.setHeld(null);
  }

  setScene(scene) {
    this.palette.replaceChildren();
    for (const c of scene.classes) {
      const b = document.createElement('button');
      b.className = 'class-button';
      b.dataset.class = c.name;
      b.style.setProperty('--swatch', c.color);
      b.textContent = `+ ${c.name}`;
      b.addEventListener('click', () => this.actions.add(c, this.addAt.value));
      this.palette.appendChild(b);
    }
    const locations = scene.regions.map((r) => r.name);
    for (const sel of [this.addAt, this.takeTo]) {
      const keep = sel === this.takeTo ? [['', 'away (remove it)']] : [];
      sel.replaceChildren(...[...keep, ...locations.map((l) => [l, l])].map(([v, t]) => new Option(t, v)));
    }
  }

  select(name) {
    this.selection = name;
    this.selected.textContent = name ? `selected: ${name}` : 'click a thing to select it';
    this.del.disabled = !name;
  }

  setHeld(held) {
    this.take.disabled = !held;
    this.take.textContent = held ? `take ${held} from the gripper` : 'gripper empty';
  }
}
