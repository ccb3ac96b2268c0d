// Comparing seam layouts on one target: the designer keeps the current seams as Layout A (or B), changes
// them, and sees the kept layouts beside the current one: the number of panels, the distance of the
// inflated optimized panels to the target (the optimizer's own figure), the largest
// distance and the worst wrinkling, with a thumbnail of the inflated shape. "Use" puts a kept layout's
// seams back as an ordinary edit, so Undo returns to the seams it replaced. Kept layouts live in this
// page only (they are views of the design, not part of it). While open, the panel follows the app through
// the app's store (edits, undo, panels started, made and inflated); it does nothing while the app is idle.
import './compare.css';
import { formatDistance, formatPercent } from './units.js';
import { showOverInflatedPane, sidePanel } from '../views/dialog-header.js';

const LETTERS = ['A', 'B'];
// The store's changes the cards follow (Store.subscribe).
const RENDERED_ON = new Set(['design', 'results', 'work', 'shown']);
const THUMB_SIZE = 150;

// What makes a layout: the seams and internal connections (and the mirror plane they were drawn with).
function layoutOf(design) {
  return { seams: design.seams, connections: design.connections, symmetry: design.symmetry ?? null };
}

const layoutKey = (layout) => JSON.stringify([layout.seams, layout.connections]);

export class LayoutCompare {
  constructor({ app, viewport, button }) {
    this.app = app;
    this.viewport = viewport;
    this.layouts = { A: null, B: null };
    this.unsubscribe = null;
    this.shownKey = null;
    this.build();
    button?.addEventListener('click', () => (this.dialog.open ? this.close() : this.open()));
  }

  build() {
    const { dialog, body } = sidePanel('compare', {
      title: 'Compare seam layouts',
      closeTitle: 'Close the comparison (kept layouts stay until the page is closed)',
      onClose: () => this.close(),
    });
    this.dialog = dialog;
    this.intro = document.createElement('p');
    this.intro.className = 'compare-intro';
    this.cards = document.createElement('div');
    this.cards.className = 'compare-cards';
    const foot = document.createElement('div');
    foot.className = 'compare-foot';
    this.keepButtons = LETTERS.map((letter) => {
      const b = document.createElement('button');
      b.type = 'button';
      b.dataset.keep = letter;
      b.textContent = `Keep current as Layout ${letter}`;
      b.addEventListener('click', () => this.keep(letter));
      foot.append(b);
      return b;
    });
    body.append(this.intro, this.cards, foot);
    dialog.addEventListener('close', () => this.stopWatching());
  }

  open() {
    // Over the inflated pane, whose shape the current layout's card shows anyway.
    showOverInflatedPane(this.dialog);
    this.shownKey = null;
    this.render();
    // What the cards show: the design, its results, the work under way and the panes' result; not the seams'
    // redraws (every pointer move while drawing) nor the status line.
    this.unsubscribe ??= this.app.store.subscribe((what) => RENDERED_ON.has(what) && this.render());
  }

  close() {
    if (this.dialog.open) this.dialog.close();
    this.stopWatching();
  }

  stopWatching() {
    this.unsubscribe?.();
    this.unsubscribe = null;
  }

  // The target the layouts are drawn on: kept layouts only apply to the same one.
  targetKey() {
    const { app } = this;
    return app.design.target.example ?? `${app.target?.fileName}:${app.target?.positions.length}`;
  }

  // The settings the figures depend on besides the seams.
  settingsKey() {
    const { app } = this;
    return JSON.stringify([app.design.pressure, app.design.material, app.design.size.height, app.resolution]);
  }

  // The current layout's figures once its optimized panels are made and inflated, else null.
  currentFigures() {
    const shown = this.app.store.optimizedShown();
    if (!shown) return null;
    const { optimized: o, inflated, pattern } = shown;
    return {
      panels: pattern?.panels.length ?? 0,
      distance: o.status?.distanceRms ?? null,
      distanceMax: o.status?.distanceMax ?? null,
      targetDistance: o.status?.targetDistanceRms ?? null,
      targetDistanceMax: o.status?.targetDistanceMax ?? null,
      wrinkling: inflated.maxCompression ?? null,
    };
  }

  // The square of the inflated pane where the shape is framed, as a small PNG (the renderer keeps
  // its drawing buffer), or null.
  thumbnail() {
    const pane = document.querySelector('#pane-inflated .pane-body');
    const canvas = this.viewport.canvas;
    if (!pane || !canvas) return null;
    this.viewport.render();
    const box = canvas.getBoundingClientRect();
    const square = this.app.panes.inflated.square; // where the shape is framed, beside the figures (Pane3D.fitView)
    if (!(square?.side > 0)) return null;
    const scale = canvas.width / box.width;
    const { side } = square;
    const left = square.left - box.left;
    const top = square.top - box.top;
    const out = document.createElement('canvas');
    out.width = out.height = THUMB_SIZE;
    out.getContext('2d').drawImage(canvas, left * scale, top * scale, side * scale, side * scale, 0, 0, THUMB_SIZE, THUMB_SIZE);
    return out.toDataURL('image/png');
  }

  keep(letter) {
    const figures = this.currentFigures();
    if (!figures) return;
    this.layouts[letter] = {
      letter,
      layout: layoutOf(this.app.design),
      figures,
      thumbnail: this.thumbnail(),
      target: this.targetKey(),
      settings: this.settingsKey(),
    };
    this.shownKey = null;
    this.render();
  }

  // The letter of the kept layout the design has now, or null.
  currentLetter() {
    const key = layoutKey(layoutOf(this.app.design));
    return LETTERS.find((l) => this.layouts[l] && this.layouts[l].target === this.targetKey() && layoutKey(this.layouts[l].layout) === key) ?? null;
  }

  // Puts a kept layout's seams into the design: one undo step. Seams not kept yet go into the free slot
  // first, so both layouts stay one click away.
  use(letter) {
    const kept = this.layouts[letter];
    if (!kept || kept.target !== this.targetKey() || this.currentLetter() === letter) return;
    const free = LETTERS.find((l) => !this.layouts[l]);
    if (!this.currentLetter() && free && this.currentFigures() && this.app.design.seams.length) this.keep(free);
    const { symmetry, ...rest } = this.app.design;
    const { seams, connections, symmetry: keptSymmetry } = kept.layout;
    const next = { ...rest, seams, connections, ...(keptSymmetry ? { symmetry: keptSymmetry } : {}) };
    this.app.seams.selection = null;
    this.app.commitDesign(next);
    this.app.seams.refresh();
    this.shownKey = null;
    this.render();
  }

  render() {
    if (!this.dialog.open) return;
    const figures = this.currentFigures();
    const current = this.currentLetter();
    const key = JSON.stringify([figures, current, this.app.revision, this.targetKey(), this.settingsKey(), LETTERS.map((l) => this.layouts[l]?.thumbnail?.length ?? 0)]);
    if (key === this.shownKey) return; // nothing changed: the buttons keep their focus
    this.shownKey = key;
    const anyKept = LETTERS.some((l) => this.layouts[l]);
    this.intro.textContent = anyKept
      ? 'Change the seams and compare them with the kept layouts. "Use" puts a kept layout back (Undo returns).'
      : 'Keep the current seams as Layout A, then change the seams: both layouts are compared here.';
    const cards = LETTERS.filter((l) => this.layouts[l]).map((l) => this.keptCard(this.layouts[l], l === current));
    if (!current) cards.push(this.currentCard(figures));
    this.cards.replaceChildren(...cards);
    for (const b of this.keepButtons) {
      b.disabled = !figures;
      b.title = figures
        ? `Keep the current seams and their figures as Layout ${b.dataset.keep}${this.layouts[b.dataset.keep] ? ' (replaces it)' : ''}`
        : 'Wait until the current seams have their optimized panels';
    }
  }

  keptCard(kept, isCurrent) {
    const card = this.card(`Layout ${kept.letter}`, kept.figures, kept.thumbnail);
    card.dataset.layout = kept.letter;
    if (isCurrent) card.classList.add('current');
    const notes = [];
    if (isCurrent) notes.push('These are the current seams.');
    const sameTarget = kept.target === this.targetKey();
    if (!sameTarget) notes.push('Made on another target.');
    else if (kept.settings !== this.settingsKey()) notes.push('Made with other material, pressure, size or resolution.');
    for (const text of notes) card.append(Object.assign(document.createElement('p'), { className: 'compare-note', textContent: text }));
    const use = document.createElement('button');
    use.type = 'button';
    use.className = 'compare-use';
    use.textContent = `Use Layout ${kept.letter}`;
    use.disabled = isCurrent || !sameTarget;
    use.title = isCurrent ? 'These seams are the current ones' : sameTarget ? `Put Layout ${kept.letter}'s seams back (Ctrl+Z undoes it)` : 'This layout was drawn on another target';
    use.addEventListener('click', () => this.use(kept.letter));
    card.append(use);
    return card;
  }

  currentCard(figures) {
    const card = this.card('Current seams', figures, figures ? this.thumbnail() : null);
    card.dataset.layout = 'current';
    card.classList.add('current');
    if (!figures) {
      const busy = this.app.store.isWorking('panels') || this.app.store.isWorking('inflation');
      card.append(Object.assign(document.createElement('p'), {
        className: 'compare-note',
        textContent: busy ? 'Making the panels…' : 'No panels yet: draw seams that cut the target into pieces.',
      }));
    }
    return card;
  }

  card(title, figures, thumbnail) {
    const card = document.createElement('article');
    card.className = 'compare-card';
    const h = document.createElement('h3');
    h.textContent = title;
    card.append(h);
    if (thumbnail) {
      const img = document.createElement('img');
      img.src = thumbnail;
      img.alt = `${title}, inflated`;
      img.width = img.height = THUMB_SIZE;
      card.append(img);
    }
    const rows = figures
      ? [
          ['Panels', String(figures.panels), 'panels'],
          ['Distance to target', figures.distance === null ? '—' : formatDistance({ rms: figures.distance, targetRms: figures.targetDistance }, 1), 'distance', 'Average distance between the inflated optimized panels and the target, both ways (target → inflated is high where the shape leaves a part out), in % of its size'],
          ['Largest distance', figures.distanceMax === null ? '—' : formatPercent(Math.max(figures.distanceMax, figures.targetDistanceMax ?? 0)), 'distance-max'],
          ['Most wrinkled', figures.wrinkling === null ? '—' : formatPercent(figures.wrinkling), 'wrinkling', 'The largest share of the sheet taken up by wrinkles'],
        ]
      : [];
    if (rows.length) {
      const dl = document.createElement('dl');
      for (const [label, value, name, title] of rows) {
        const dt = document.createElement('dt');
        dt.textContent = label;
        const dd = document.createElement('dd');
        dd.textContent = value;
        dd.dataset.figure = name;
        if (title) dt.title = dd.title = title;
        dl.append(dt, dd);
      }
      card.append(dl);
    }
    return card;
  }
}
