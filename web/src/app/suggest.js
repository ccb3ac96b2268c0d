// Suggested seam layouts (wasm/src/suggest/seam_layouts.hpp): the designer says how many panels they will cut at
// most, whether the layout keeps the target's mirror symmetry (offered where the target has one) and whether their own
// seams stay; the worker lays plane sections through and across the target's axes, opens what they leave unflattenable
// (a tube around a limb), looks at each layout, optimizes the most promising few at a coarse resolution and brings them
// best first. "Use" makes a layout's seams the design's, an ordinary edit (Undo returns). An edit to the seams while
// it runs stops it: its layouts were made for the seams there were. Not modal: the target stays in view beside it.
import './suggest.css';
import { ErrorCode, Op } from '../worker/protocol.js';
import { formatDistance, formatLength, formatPercent, worseDistance } from './units.js';
import { optimizeArgs } from './stored-result.js';
import { exportOptions, formatMillimeters } from './fabrication.js';
import { upOf } from './up-axis.js';
import { linkMirrorTwins, symmetryPlane } from './symmetry.js';
import { showOverInflatedPane, sidePanel } from '../views/dialog-header.js';
import { SolverClient } from '../worker/client.js';
import { better, suggestLayouts } from './suggest-run.js';
import { drawBalloon, viewOf } from '../views/balloon-thumbnail.js';

const PANELS = { min: 2, max: 40, start: 6 };
// What a suggestion is made at: coarse, so a dozen layouts are tried in seconds (the bench's comparison of layouts
// holds at this resolution: bench/README.md "Suggested seam layouts").
const TRIANGLES = 1000;
const MAX_ITERATIONS = 40;
// Workers of its own, one per core up to this many: the layouts are tried side by side, and the design's own worker
// stays free for the designer's edits meanwhile.
const MOST_HELPERS = 4;
const SHOW_EVERY = 250; // ms

// Optimized layouts first, those that fit the sheet and then the closest first; then the ones only looked at, closest
// first.
const byQuality = (a, b) => Boolean(a.firstLook) - Boolean(b.firstLook) || better(a, b);

// The share of the sheet its pieces cover, nested as the cut file nests them; where its widest piece is wider than the
// design's sheet, on the sheet it needs, said plainly.
function sheetFigure({ sheetUse, sheetNeeded }, { sheet_width: width, units }) {
  const share = `${Math.round(100 * sheetUse)} %`;
  const sheet = formatMillimeters(width, units);
  if (sheetNeeded > 0) {
    const needed = formatMillimeters(sheetNeeded, units);
    return [share, 'sheet-use', ` of a ${needed} sheet: a piece is wider than yours`, `Its widest piece does not fit your ${sheet} sheet: cut it on a roll ${needed} wide, or choose a layout with more panels`];
  }
  return [share, 'sheet-use', ' of the sheet used', `How much of your ${sheet} sheet its cut pieces cover, nested as the cut file nests them: the rest is waste`];
}

export class SeamSuggestions {
  // createWorker: () => Worker, as the app's own (main.js).
  constructor({ app, button, createWorker }) {
    this.app = app;
    this.createWorker = createWorker;
    this.helpers = null; // { target, clients }: workers with the target set, while the panel is open
    this.call = null;
    this.layouts = [];
    this.symmetryOf = new Map(); // target key -> the axis the worker found, or null
    this.pictures = new WeakMap(); // a layout's balloon -> its drawn canvas and the view it was drawn from
    this.cardsOf = new WeakMap(); // a layout -> its card, how to number it, and what it shows (render)
    this.pictureOf = new WeakMap(); // a canvas -> its picture
    this.build();
    // Within a panel's height of the cards in view, a picture is drawn.
    this.nearView = new IntersectionObserver(
      (entries) => {
        for (const entry of entries) {
          const picture = this.pictureOf.get(entry.target);
          if (!picture) continue;
          picture.seen = entry.isIntersecting;
          if (picture.seen) this.draw(picture);
        }
      },
      { root: this.cards.parentElement, rootMargin: '100% 0px' },
    );
    button?.addEventListener('click', () => (this.dialog.open ? this.close() : this.open()));
  }

  build() {
    const { dialog, body } = sidePanel('suggest', { title: 'Suggest seams', closeTitle: 'Close (a suggestion under way stops)', onClose: () => this.close() });
    this.dialog = dialog;
    const intro = document.createElement('p');
    intro.className = 'suggest-intro';
    intro.textContent = 'Billow tries seam layouts on this shape, makes and inflates the panels of each, and shows the closest to the target first. "Use" makes one your seams, to edit as your own (Undo returns).';
    const form = document.createElement('div');
    form.className = 'suggest-form';
    const panels = document.createElement('label');
    this.panels = Object.assign(document.createElement('input'), { type: 'number', min: PANELS.min, max: PANELS.max, step: 1, value: PANELS.start, className: 'suggest-panels' });
    this.panels.setAttribute('aria-label', 'Panels at most');
    panels.append('Panels, at most ', this.panels);
    const symmetry = document.createElement('label');
    symmetry.className = 'suggest-symmetry';
    this.symmetry = Object.assign(document.createElement('input'), { type: 'checkbox', checked: true });
    this.symmetryText = document.createElement('span');
    symmetry.append(this.symmetry, this.symmetryText);
    this.symmetryLabel = symmetry;
    const keep = document.createElement('label');
    keep.className = 'suggest-keep';
    this.keep = Object.assign(document.createElement('input'), { type: 'checkbox' });
    keep.append(this.keep, ' Keep my seams and add to them');
    this.keepLabel = keep;
    this.go = Object.assign(document.createElement('button'), { type: 'button', className: 'suggest-go', textContent: 'Suggest layouts' });
    this.go.addEventListener('click', () => (this.call ? this.stop() : this.start()));
    form.append(panels, symmetry, keep, this.go);
    this.progress = Object.assign(document.createElement('progress'), { className: 'suggest-progress', max: 1, value: 0, hidden: true });
    this.status = Object.assign(document.createElement('p'), { className: 'suggest-status' });
    this.status.setAttribute('role', 'status');
    this.cards = Object.assign(document.createElement('div'), { className: 'suggest-cards' });
    body.append(intro, form, this.progress, this.status, this.cards);
  }

  targetKey() {
    const { app } = this;
    return app.design.target.example ?? `${app.target?.fileName}:${app.target?.positions.length}`;
  }

  async open() {
    // Over the inflated pane, as the layout comparison: the target pane, where the seams are, stays in view.
    showOverInflatedPane(this.dialog, { down: true });
    delete this.dialog.dataset.symmetryKnown;
    this.watchView();
    this.keepLabel.hidden = !this.app.design.seams.length;
    this.keep.checked = false;
    this.render();
    this.prepare();
    // Offered where the target has a mirror plane: the one the design's seams are mirrored across, else the one the
    // worker finds.
    const key = this.targetKey();
    if (!this.app.design.symmetry && !this.symmetryOf.has(key)) {
      this.symmetryLabel.hidden = true;
      try {
        const { axis } = await this.app.client.call(Op.mirrorSymmetry, {}).promise;
        this.symmetryOf.set(key, axis);
      } catch {
        this.symmetryOf.set(key, null);
      }
    }
    this.showSymmetry();
    this.dialog.dataset.symmetryKnown = 'true'; // whether the target has a mirror plane (benches and tests wait for it)
  }

  // As the panel opens, the helpers start with the target and make the scene a suggestion at the design's size is laid
  // on (a fine target's simplified copy: a second or two), while the designer picks the panels. A request queues
  // behind it in each helper; at another size by then it is made again. Errors show when Suggest is clicked.
  prepare() {
    if (!this.app.target) return;
    const { scene } = this.settingsOf(this.app.design);
    this.helperClients()
      .then((clients) => Promise.all(clients.map((client) => client.request(Op.suggestPrepare, scene))))
      .catch(() => {});
  }

  // What a suggestion's scene is made with, as the design has it (its sheet, pressure and resolution, at its size:
  // one rule for the preparation and the suggestion, whose scene serves again only at the same size), and its seams.
  settingsOf(design) {
    const { seams, connections, ...physics } = optimizeArgs(design, TRIANGLES);
    return { seams, scene: { ...physics, scale: this.app.scaleFor(design), up: upOf(design) } };
  }

  // The mirror plane a layout may keep, or null.
  symmetryAxis() {
    return this.app.design.symmetry?.axis ?? this.symmetryOf.get(this.targetKey()) ?? null;
  }

  showSymmetry() {
    const axis = this.symmetryAxis();
    this.symmetryLabel.hidden = !axis;
    if (axis) this.symmetryText.textContent = ` Keep the mirror symmetry across ${axis.toUpperCase()}`;
  }

  close() {
    this.stop();
    this.hide();
    this.releaseHelpers();
    this.unwatchView?.();
    this.unwatchView = null;
    if (this.dialog.open) this.dialog.close();
  }

  // Shows a layout on the target: its segments in their colours, its seams dashed over the design's, until it is
  // shown again (a toggle), another is, the dialog closes or the design changes.
  async show(layout) {
    const { app } = this;
    if (this.shownName === layout.name) return this.hide();
    this.shownName = layout.name;
    this.render();
    this.unwatchShown ??= app.store.subscribe((what) => what === 'design' && this.hide());
    const seams = layout.seams.map(({ points, closed, weight, smooth }) => ({ points, closed, weight, smooth: Boolean(smooth) }));
    try {
      const [traces, segmentation] = await Promise.all([
        Promise.all(seams.map((s) => app.client.request(Op.traceSeam, s))),
        app.client.call(Op.segment, { seams, up: upOf(app.design) }).promise,
      ]);
      if (this.shownName !== layout.name) return;
      app.seams.overlay = traces.map((t) => t.curve);
      app.seams.draw();
      app.panes.target.setSegments(segmentation);
    } catch (error) {
      if (this.shownName === layout.name) this.hide();
      if (error.code !== ErrorCode.cancelled && error.code !== ErrorCode.crashed) this.status.textContent = `That layout could not be shown: ${error.message}`;
    }
  }

  // The design's own seams and segments on the target again.
  hide() {
    this.unwatchShown?.();
    this.unwatchShown = null;
    if (this.shownName === null || this.shownName === undefined) return;
    this.shownName = null;
    const { app } = this;
    app.seams.overlay = null;
    app.seams.draw();
    app.panes.target.setSegments(app.seams.segmentation ?? { segments: [] });
    this.render();
  }

  // The helper workers, started with the target on first use and kept while the panel is open.
  async helperClients() {
    const { target } = this.app;
    if (this.helpers?.target === target) return this.helpers.clients;
    this.releaseHelpers();
    const count = Math.max(1, Math.min(MOST_HELPERS, globalThis.navigator?.hardwareConcurrency || 1));
    const clients = Array.from({ length: count }, () => new SolverClient(this.createWorker));
    this.helpers = { target, clients };
    // setTarget is replayed into a helper that crashed and was restarted.
    await Promise.all(clients.map((client) => client.request(Op.setTarget, { positions: target.positions, indices: target.indices })));
    return clients;
  }

  releaseHelpers() {
    for (const client of this.helpers?.clients ?? []) client.terminate();
    this.helpers = null;
  }

  stop(note = 'Stopped.') {
    if (!this.call) return;
    this.call.cancel();
    this.finish(note);
  }

  // The progress and the cards as they stand, at most every SHOW_EVERY ms: each frame of the page costs the workers'
  // cores about 10 ms (its layout, paint and commit), and a suggestion's looks come 5-10 a second.
  showProgress(p, arrived) {
    this.pending = { p, arrived: arrived || Boolean(this.pending?.arrived) };
    this.showTimer ||= setTimeout(() => {
      const { p, arrived } = this.pending;
      this.showTimer = 0;
      this.pending = null;
      if (p.total) {
        this.progress.max = p.total;
        this.progress.value = p.done;
      }
      this.status.textContent = p.layout || p.look ? `${p.stage}: ${p.done} of ${p.total}…` : `${p.stage}: ${p.done + 1} of ${p.total}${p.detail ? `, ${p.detail}` : ''}…`;
      if (arrived) this.render();
    }, SHOW_EVERY);
  }

  finish(note) {
    // Layouts that came since the cards were last shown stay, stopped or not.
    const unshown = this.pending?.arrived;
    clearTimeout(this.showTimer);
    this.showTimer = 0;
    this.pending = null;
    if (unshown) this.render();
    this.call = null;
    this.unsubscribe?.();
    this.unsubscribe = null;
    this.progress.hidden = true;
    this.go.textContent = 'Suggest layouts';
    if (note !== null) this.status.textContent = note;
  }

  async start() {
    const { app } = this;
    const panels = Math.round(Number(this.panels.value));
    if (!(panels >= PANELS.min && panels <= PANELS.max)) {
      this.status.textContent = `Ask for ${PANELS.min} to ${PANELS.max} panels.`;
      return;
    }
    const design = app.design;
    const keep = this.keep.checked && !this.keepLabel.hidden;
    const axis = this.symmetry.checked ? this.symmetryAxis() : null;
    // The sheet, pressure and resolution as the panels are made; the design's seams only when kept; its fabrication
    // settings (the roll's width, the seam allowance) as its pieces are nested.
    const { seams, scene } = this.settingsOf(design);
    const args = {
      ...scene,
      fabrication: exportOptions(design.fabrication),
      kept: keep ? seams : [],
      panels,
      symmetry: axis,
      maxIterations: MAX_ITERATIONS,
    };
    this.layouts = [];
    this.nearView.disconnect(); // the last request's cards go
    this.request = { revision: app.revision, kept: keep ? design.seams.length : 0, axis, panels };
    this.render();
    this.progress.hidden = false;
    this.progress.removeAttribute('value'); // indeterminate until the first count
    this.go.textContent = 'Stop';
    this.status.textContent = 'Laying out seams…';
    // An edit to the design (its seams, its size, its sheet) makes the layouts under way stale.
    this.unsubscribe = app.store.subscribe((what) => {
      if (what === 'design' && this.call && app.revision !== this.request.revision) this.stop('Stopped: the design changed while the layouts were tried.');
    });
    // Stop works while the helpers start, before there is a call to cancel.
    const starting = (this.call = { cancel: () => {} });
    let clients;
    try {
      clients = await this.helperClients();
    } catch (error) {
      if (this.call === starting) this.finish(`The layouts could not be tried: ${error.message}`);
      return;
    }
    if (this.call !== starting) return; // stopped meanwhile
    const call = (this.call = suggestLayouts(clients, args, {
      onProgress: (p) => {
        if (call !== this.call) return;
        // A layout looked at shows with its flattened panels' figures; optimized, it takes its own.
        const arrived = p.layout ?? (p.look && { ...p.look, firstLook: true });
        if (arrived) this.layouts = [...this.layouts.filter((l) => l.name !== arrived.name), arrived].sort(byQuality);
        this.showProgress(p, Boolean(arrived));
      },
    }));
    try {
      const result = await call.promise;
      if (call !== this.call) return;
      this.layouts = result.layouts; // the optimized ones: the others were farther at first look
      this.finish(
        result.layouts.length
          ? `${result.tried} layouts tried; the ${result.layouts.length === 1 ? 'closest' : `${result.layouts.length} closest`} below, best first.`
          : this.noLayout(result.tried, panels),
      );
      this.render();
    } catch (error) {
      if (call !== this.call) return;
      if (error.code === ErrorCode.cancelled) return this.finish(null);
      this.finish(`The layouts could not be tried: ${error.message}`);
    }
  }

  // Why no layout came: too few panels, or thin handles that each need a seam around them (a sleeve no panel can
  // follow), which more panels would not cure.
  noLayout(tried, panels) {
    const thin = this.app.target?.report.thinHandles?.length ?? 0;
    const none = `None of the ${tried} layouts tried cuts this shape into at most ${panels} panels`;
    if (!thin) return `${none}: ask for more panels.`;
    this.app.showTargetIssues(this.app.target.report, { quiet: true }); // the handles' warning, with its button, again
    return `${none}: its ${thin === 1 ? 'thin handle needs' : `${thin} thin handles need`} a seam around ${thin === 1 ? 'it' : 'each'}. Cut through ${thin === 1 ? 'it' : 'them'} first: the message about its handles has the button.`;
  }

  // Makes a layout's seams the design's: one step of the history. Kept seams stay as they are (with their mirror
  // twins and bands); the layout's own follow them, mirror images linked as twins where the symmetry was kept.
  use(layout) {
    const { app } = this;
    // The panels of the layout chosen are made at once, not after the layouts still to try.
    this.stop('You chose a layout: the ones tried so far stay here to compare.');
    this.hide();
    const kept = this.request?.kept ?? 0;
    const design = app.design;
    const seams = [...design.seams.slice(0, kept), ...layout.seams.slice(kept)];
    const { symmetry, ...rest } = design;
    const axis = this.request?.axis;
    // The layout's internal connections ([a, b] pairs, as the design document writes them) after the kept ones; both
    // name seams by their index in `seams`.
    const connections = [...(kept ? design.connections : []), ...(layout.connections ?? []).map((pair) => ({ seams: pair }))];
    let next = { ...rest, seams, connections, ...(axis ? { symmetry: { axis } } : symmetry ? { symmetry } : {}) };
    // The layout's mirror images become twins, so that editing one side edits the other.
    if (axis) next = linkMirrorTwins(next, app.target, symmetryPlane(next, app.target), kept);
    app.seams.selection = null;
    app.commitDesign(next);
    app.seams.refresh();
    this.usedName = layout.name;
    this.render();
  }

  // Each layout keeps its card while it shows the same, renumbered as others arrive, and only a card that is new or
  // moved enters the list: made anew at each of a suggestion's 100-odd looks, every card was restyled, laid out and
  // painted again (a third of a core on two, beside the workers).
  render() {
    const { sheet_width: width, units } = this.app.design.fabrication;
    const cards = this.layouts.map((layout, k) => {
      const state = `${layout.name === this.usedName} ${layout.name === this.shownName} ${width} ${units}`;
      let kept = this.cardsOf.get(layout);
      if (kept?.state !== state) this.cardsOf.set(layout, (kept = { ...this.card(layout), state }));
      kept.number(k);
      return kept.card;
    });
    const children = this.cards.children;
    cards.forEach((card, i) => children[i] !== card && this.cards.insertBefore(card, children[i] ?? null));
    while (children.length > cards.length) children[children.length - 1].remove();
  }

  // The pictures are seen as the target is: turning it turns them (once a frame at most).
  watchView() {
    const controls = this.app.panes?.target?.controls;
    if (this.unwatchView || !controls) return;
    let frame = 0;
    const turned = () => {
      frame ||= requestAnimationFrame(() => {
        frame = 0;
        for (const layout of this.layouts) {
          const picture = layout.balloon && this.pictures.get(layout.balloon);
          if (picture?.seen) this.draw(picture);
        }
      });
    };
    controls.addEventListener('change', turned);
    this.unwatchView = () => {
      controls.removeEventListener('change', turned);
      cancelAnimationFrame(frame);
    };
  }

  // The canvas of the layout's balloon, drawn once it comes near the panel's view (a suggestion's hundred-odd first
  // looks arrive as cards, of which the designer sees a few before the optimized ones replace them).
  picture(layout) {
    let picture = this.pictures.get(layout.balloon);
    if (!picture) {
      const canvas = Object.assign(document.createElement('canvas'), { className: 'suggest-picture' });
      canvas.setAttribute('role', 'img');
      const label = `Its panels inflated${layout.firstLook ? ' as first flattened (not optimized yet)' : ''}, colored by distance from the target: blue inside it, orange outside, the seams dark lines`;
      canvas.setAttribute('aria-label', label);
      canvas.title = label;
      picture = { canvas, balloon: layout.balloon, key: null, seen: false };
      this.pictures.set(layout.balloon, picture);
      this.pictureOf.set(canvas, picture);
      this.nearView.observe(canvas);
    }
    return picture.canvas;
  }

  // A picture drawn from the target pane's view (once per view).
  draw(picture) {
    const view = viewOf(this.app.panes?.target);
    const key = view.elements.map((x) => x.toFixed(4)).join(' ');
    if (picture.key === key) return;
    drawBalloon(picture.canvas, picture.balloon, view);
    picture.key = key;
  }

  // A layout's card, and how to number it (its rank among the layouts shown).
  card(layout) {
    const card = document.createElement('article');
    card.className = 'suggest-card';
    if (layout.name === this.usedName) card.classList.add('current');
    if (layout.name === this.shownName) card.classList.add('shown');
    if (layout.firstLook) card.classList.add('first-look');
    // Its name's first clause as the card's title ("3 bands across the vertical axis"), the rest of it below ("each in
    // two pieces along the outline seen from the front"): the whole name in bold ran to five lines.
    const [title, ...rest] = layout.name.split(', ');
    const h = document.createElement('h3');
    h.title = layout.name;
    const number = (k) => {
      card.dataset.rank = String(k + 1);
      h.textContent = `${k + 1}. ${title[0].toUpperCase()}${title.slice(1)}`;
    };
    const kind = rest.length ? Object.assign(document.createElement('p'), { className: 'suggest-kind', textContent: rest.join(', ') }) : null;
    const shown = layout.name === this.shownName;
    const show = Object.assign(document.createElement('button'), { type: 'button', className: 'suggest-show', textContent: shown ? 'Hide' : 'Show' });
    show.setAttribute('aria-pressed', String(shown));
    show.title = shown ? 'Show the design\'s own seams on the target again' : 'Show this layout\'s seams and panels on the target, without changing the design';
    show.addEventListener('click', () => this.show(layout));
    const use = Object.assign(document.createElement('button'), { type: 'button', className: 'suggest-use', textContent: 'Use' });
    use.title = 'Make these seams the design\'s, to edit as your own (Ctrl+Z undoes it)';
    use.addEventListener('click', () => this.use(layout));
    // One line of figures: the panels, the distance (the worse way; both in its tooltip), the seams to sew.
    const figures = document.createElement('p');
    figures.className = 'suggest-figures';
    const distance = { rms: layout.inflatedToTarget, targetRms: layout.targetToInflated };
    const parts = [
      [String(layout.panels), 'panels', layout.panels === 1 ? ' panel' : ' panels', ''],
      [
        formatPercent(worseDistance(distance)),
        'distance',
        layout.firstLook ? ' from the target, before optimizing' : ' from the target',
        `Distance between its inflated panels (${layout.firstLook ? 'as flattened, not optimized yet' : 'optimized at a coarse resolution'}) and the target: ${formatDistance(distance)}`,
      ],
      [formatLength(layout.seamLength), 'seam-length', ' of seams', 'The length of all its seams on the balloon'],
      ...(layout.firstLook ? [] : [sheetFigure(layout, this.app.design.fabrication)]),
    ];
    parts.forEach(([value, name, after, title], i) => {
      if (i) figures.append(' · ');
      const b = Object.assign(document.createElement('b'), { textContent: value });
      b.dataset.figure = name;
      const span = document.createElement('span');
      span.append(b, after);
      if (title) span.title = title;
      figures.append(span);
    });
    const buttons = Object.assign(document.createElement('span'), { className: 'suggest-buttons' });
    buttons.append(show, use);
    if (layout.balloon) card.append(this.picture(layout));
    card.append(h);
    if (kind) card.append(kind);
    // What was added to its sections, or left out, so that every part is a panel.
    if (layout.description) card.append(Object.assign(document.createElement('p'), { className: 'suggest-description', textContent: `With ${layout.description}.` }));
    card.append(figures, buttons);
    return { card, number };
  }
}
