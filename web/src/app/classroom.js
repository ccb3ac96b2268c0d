// Classroom mode: a guided walk through the method (Skouras et al. 2014) on one ready design, one step
// per screen, for a class of designers and students. Every step shows the app's real computation in its
// panes (the target, its seams and segments, the flattened panels, their inflated shape and its distance
// to the target, the optimized panels, the wrinkles, the cut outlines), with a title and a few plain
// sentences beside them. Started by the Classroom button or a #classroom (?classroom) link; keys: Right,
// PageDown, Space next; Left, PageUp back; Home, End; Escape leaves.
//
// The walk loads its example into the app like the gallery does, so the designer's own design is put
// aside first: the autosave is paused for the walk (the autosaved design stays as it was), and leaving
// puts the designer's target, design and undo history back.
import { Sphere, Vector3 } from 'three';
import { visibleBox } from '../views/pane3d.js';
import { parseDesign } from './design.js';
import { upFrameSize, upOf } from './up-axis.js';
import { patternForDisplay } from './pattern-session.js';
import { formatPercent, worseDistance } from './units.js';
import { formatPressure } from './materials.js';
import { Op } from '../worker/protocol.js';
import './classroom.css';

// The walk's example (web/public/gallery): three meridian seams cut a ball into three gores, so every
// step has something plain to see: 3 seams, 3 segments, 3 panels, a first try that misses, a round result.
export const CLASSROOM_DESIGN = 'sphere3.billow.json';

// layout: the panes the step shows (classroom.css), in the order they are laid out.
// needs: 'pattern' when the step needs the panels made (waits for them, with progress).
export const STEPS = [
  {
    id: 'target', title: 'The target shape', layout: 'target',
    text: [
      'This is the shape we want to build: a ball. An inflatable is made of flat sheets, sewn together and filled with air.',
      'Our job is to find the flat pieces that, once sewn and inflated, take this shape.',
    ],
  },
  {
    id: 'seams', title: 'Seams', layout: 'target',
    text: [
      'The designer draws seams on the shape: here three lines from top to bottom, like the seams of a beach ball.',
      'The sheets will be sewn together along these lines.',
    ],
  },
  {
    id: 'segments', title: 'Segments', layout: 'target',
    text: [
      'The seams cut the surface into pieces, one color each.',
      'Every piece must be a simple patch, without holes or handles, so that it can be cut from one flat sheet.',
    ],
  },
  {
    id: 'flattened', title: 'Flattened panels', layout: 'target pattern', needs: 'pattern',
    text: [
      'Each curved piece is pressed flat into a panel (right), as a map flattens the globe.',
      'A curved surface cannot lie flat without stretching a little, so these panels are a first guess.',
    ],
  },
  {
    id: 'naive', title: 'The first try misses', layout: 'target inflated', needs: 'pattern',
    text: [
      'The computer sews these panels together and inflates them (right).',
      'Pressure pushes outward everywhere: it rounds every flat area and pulls on the stretched parts, so the inflated shape is not the target.',
    ],
  },
  {
    id: 'optimized', title: 'Optimized panels', layout: 'target inflated pattern', needs: 'pattern',
    text: [
      'Billow now changes the outlines of the panels, inflates them again and again, and keeps every change that brings the inflated shape closer to the target.',
      'The panels look almost the same: small changes at their edges make the difference.',
    ],
  },
  {
    id: 'wrinkles', title: 'Wrinkles', layout: 'inflated', needs: 'pattern',
    text: [
      'The colors show where the sheet is squeezed and will wrinkle: blue is taut, orange wrinkles.',
      'Wrinkles gather along the seams and at the poles, where the pieces meet; more seams spread them out.',
    ],
  },
  {
    id: 'cut', title: 'The cut file', layout: 'pattern', needs: 'pattern',
    text: [
      'These are the pieces to cut, at true scale, each with a seam allowance around it and the seams to sew in matching colors.',
      'Export them as a cut file for a plotter, a laser cutter or a printer; then cut, sew and inflate.',
    ],
  },
];

const NEXT_KEYS = ['ArrowRight', 'PageDown', ' '];
const BACK_KEYS = ['ArrowLeft', 'PageUp'];
// The 3D panes look from above the front: the three gores of the example meet at the top pole there.
const VIEW = new Vector3(0.45, 0.85, 1).normalize();

// True when the page's address asks for the walk: #classroom or ?classroom.
export function classroomRequested(loc = location) {
  return loc.hash === '#classroom' || new URLSearchParams(loc.search).has('classroom');
}

function button(text, title, onClick, className = '') {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = text;
  b.title = title;
  if (className) b.className = className;
  b.addEventListener('click', onClick);
  return b;
}

// Frames object in a 3D pane seen from `direction`, whole in both directions: the walk's panes are often
// tall and narrow, where fitting the vertical field of view alone (Pane3D.frame) cuts the sides off.
function frameView(pane, object, direction = VIEW) {
  const sphere = visibleBox(object).getBoundingSphere(new Sphere());
  const r = pane.element.getBoundingClientRect();
  if (!(sphere.radius > 0) || !Number.isFinite(sphere.radius) || r.width <= 0 || r.height <= 0) return;
  const half = (pane.camera.fov * Math.PI) / 360;
  const halfWidth = Math.atan(Math.tan(half) * (r.width / r.height));
  const distance = (sphere.radius / Math.sin(Math.min(half, halfWidth))) * 1.02;
  pane.camera.position.copy(sphere.center).addScaledVector(direction, distance);
  pane.camera.near = distance / 100;
  pane.camera.far = distance * 100;
  pane.camera.updateProjectionMatrix();
  pane.controls.target.copy(sphere.center);
  pane.controls.update();
  pane.viewport.requestRender(pane);
}

// A shape's distance to the target, both ways (units.formatDistance), the worse one as the lead figure.
function distanceFigures(d) {
  const value = (f) => (d ? formatPercent(f(d)) : '…');
  return [
    ['Distance to target', value(worseDistance), 'Average distance between the inflated shape and the target, the worse of the two ways, in % of its size'],
    ['Inflated → target', value((x) => x.rms), 'How far the inflated shape lies from the target, on average'],
    ['Target → inflated', value((x) => x.targetRms ?? x.rms), 'How far the target lies from the inflated shape, on average: high where the shape leaves a part out'],
    ['Largest distance', value((x) => Math.max(x.max, x.targetMax ?? 0))],
  ];
}

export class Classroom {
  // seamTool: its mode is set to View for the walk and given back; exporter: the Export actions of step 8.
  constructor({ app, viewport, theme, exporter, seamTool }) {
    this.app = app;
    this.viewport = viewport;
    this.theme = theme;
    this.exporter = exporter;
    this.seamTool = seamTool;
    this.active = false;
    this.index = 0;
    this.ticket = 0; // a newer step (or leaving) supersedes the step being shown
    this.saved = null;
    this.naive = null; // { optimized, distance }: the first try's distance, for the panels it was measured on
    this.enteredFullscreen = false;
    this.waiting = new Set(); // the checks of until() still waiting
    this.build();
    // The walk follows the app's store: waits look again at every change (edits, panels started, made,
    // inflated, seams cut); the seam editor redraws seams and segments as its work arrives, which the early
    // steps hide again; the status line is the walk's progress line.
    app.store.subscribe((what) => {
      this.wake();
      if (what === 'seams' && this.active) this.hideTargetLayers();
      if (what === 'status') this.showProgress();
    });
    window.addEventListener('keydown', (e) => this.onKey(e), true);
    // Space activates a focused button on key up: in the walk, Space only means Next.
    window.addEventListener('keyup', (e) => this.active && e.key === ' ' && e.preventDefault(), true);
    document.addEventListener('fullscreenchange', () => this.renderFullscreen());
    // Full screen or a new window size changes the panes: the shapes are framed to them again.
    window.addEventListener('resize', () => this.active && this.reframe());
  }

  build() {
    const aside = (this.element = document.createElement('aside'));
    aside.className = 'classroom';
    aside.hidden = true;
    aside.setAttribute('aria-label', 'Classroom walk through the method');
    const top = document.createElement('div');
    top.className = 'classroom-top';
    this.counter = document.createElement('span');
    this.counter.className = 'classroom-counter';
    const name = document.createElement('span');
    name.className = 'classroom-name';
    name.textContent = 'How an inflatable is designed';
    top.append(this.counter, name);
    this.dots = document.createElement('nav');
    this.dots.className = 'classroom-dots';
    this.dots.setAttribute('aria-label', 'Steps');
    STEPS.forEach((step, i) => {
      const dot = button(String(i + 1), `Step ${i + 1}: ${step.title}`, () => this.go(i), 'classroom-dot');
      this.dots.append(dot);
    });
    this.title = document.createElement('h2');
    this.title.className = 'classroom-title';
    this.title.id = 'classroom-title';
    aside.setAttribute('aria-labelledby', 'classroom-title');
    this.text = document.createElement('div');
    this.text.className = 'classroom-text';
    this.figure = document.createElement('div');
    this.figure.className = 'classroom-figure';
    this.figure.setAttribute('aria-live', 'polite');
    this.actions = document.createElement('div');
    this.actions.className = 'classroom-actions';
    this.progress = document.createElement('div');
    this.progress.className = 'classroom-progress';
    this.progress.setAttribute('role', 'status');
    this.note = document.createElement('p');
    this.note.className = 'classroom-note';
    this.note.hidden = true;
    const nav = document.createElement('div');
    nav.className = 'classroom-nav';
    this.backButton = button('← Back', 'The previous step (Left arrow or Page Up)', () => this.go(this.index - 1), 'classroom-back');
    this.nextButton = button('Next →', 'The next step (Right arrow, Page Down or Space)', () => this.go(this.index + 1), 'classroom-next');
    nav.append(this.backButton, this.nextButton);
    const tools = document.createElement('div');
    tools.className = 'classroom-tools';
    this.fullscreenButton = button('Full screen', 'Fill the screen with the walk (for a projector)', () => this.toggleFullscreen(), 'classroom-fullscreen');
    this.largeButton = button('Larger text', 'Larger text for the back of the room (the Large type setting)', () => {
      this.theme.setLargeType(!this.theme.largeType);
      this.renderLargeType();
    }, 'classroom-large');
    this.leaveButton = button('Leave', 'Leave the walk and go back to your own design (Escape)', () => this.leave(), 'classroom-leave');
    tools.append(this.fullscreenButton, this.largeButton, this.leaveButton);
    aside.append(top, this.dots, this.title, this.text, this.figure, this.actions, this.progress, nav, tools, this.note);
    document.body.append(aside);
  }

  get step() {
    return STEPS[this.index];
  }

  // Starts the walk at its first step: the designer's work is put aside, the example loaded.
  async start() {
    if (this.active || !this.app.target) return;
    const { app } = this;
    this.active = true;
    this.index = 0;
    this.naive = null;
    this.failed = null;
    this.saved = {
      design: app.setAside(), // the walk's own history: loading its example resets it, not the designer's
      toolMode: this.seamTool.mode,
      messages: new Set(app.messages.container.children),
      hash: location.hash,
      colors: document.getElementById('color-select')?.value,
    };
    this.setColors('wrinkles'); // step 7 explains the wrinkle colors
    this.seamTool.setMode('orbit');
    app.seams.selection = null;
    document.body.dataset.classroom = 'true';
    if (!classroomRequested()) history.replaceState(null, '', `${location.pathname}${location.search}#classroom`); // a link to share
    this.element.hidden = false;
    this.renderLargeType();
    this.renderFullscreen();
    this.loading = this.loadExample();
    this.show();
    this.nextButton.focus();
    await this.loading;
  }

  async loadExample() {
    const { app } = this;
    let design;
    try {
      const response = await fetch(new URL(`gallery/${CLASSROOM_DESIGN}`, app.baseUrl));
      if (!response.ok) throw new Error(`HTTP ${response.status}`);
      design = parseDesign(await response.json()).design;
    } catch {
      this.failed = 'The example could not be loaded: check the connection and try again.';
      this.wake();
      this.show();
      return;
    }
    if (!this.active) return;
    this.example = design;
    await app.loadExample(design.target.example, design);
    if (!this.isExampleShown()) this.failed = 'The example could not be loaded: check the connection and try again.';
    this.wake();
    this.show();
  }

  isExampleShown() {
    return this.app.design.target.example === this.example?.target.example && this.app.design.seams.length === this.example.seams.length;
  }

  // Resolves true once ready() is, false when the step was superseded or the example failed. Looks again
  // when the app or the walk changes (wake), never on a timer.
  until(ready, ticket) {
    return new Promise((resolve) => {
      const check = () => {
        const superseded = ticket !== this.ticket || !this.active || Boolean(this.failed);
        if (!superseded && !ready()) return;
        this.waiting.delete(check);
        resolve(!superseded);
      };
      this.waiting.add(check);
      check();
    });
  }

  wake() {
    for (const check of [...this.waiting]) check();
  }

  // The example's panels: made, optimized and inflated by the app (it does this by itself once the seams
  // cut the target into pieces). Resolves true when they are there, false when the step was superseded.
  async panelsReady(ticket) {
    await this.loading;
    const { app } = this;
    const { store } = app;
    return this.until(() => {
      const made = store.result('optimized');
      const working = store.isWorking('panels') || store.isWorking('inflation');
      if (made && !working) return true;
      if (this.isExampleShown() && app.seams.segmentation && !made && !store.isWorking()) {
        this.failed = 'The panels of the example could not be made (see the message).';
        this.show();
      }
      return false;
    }, ticket);
  }

  go(index) {
    if (!this.active) return;
    const next = Math.max(0, Math.min(STEPS.length - 1, index));
    if (next === this.index) return;
    this.index = next;
    this.show();
  }

  // Shows the current step: its text at once, its panes as their content is there.
  async show() {
    const ticket = ++this.ticket;
    this.wake(); // the previous step's waits end
    const step = this.step;
    const n = this.index + 1;
    document.body.dataset.classroomStep = step.id;
    document.body.dataset.classroomLayout = step.layout;
    this.element.dataset.step = step.id;
    this.counter.textContent = `${n} / ${STEPS.length}`;
    this.title.textContent = step.title;
    this.text.replaceChildren(...step.text.map((line) => Object.assign(document.createElement('p'), { textContent: line })));
    [...this.dots.children].forEach((dot, i) => dot.setAttribute('aria-current', i === this.index ? 'step' : 'false'));
    this.backButton.disabled = this.index === 0;
    this.nextButton.disabled = this.index === STEPS.length - 1;
    this.figure.replaceChildren();
    this.actions.replaceChildren();
    this.showProgress();
    if (this.failed) return this.setFigure([['', this.failed]]);
    this.hideTargetLayers();
    if (step.id !== 'target') this.app.seams.draw();
    if (!['target', 'seams'].includes(step.id) && this.app.seams.segmentation) this.app.panes.target.setSegments(this.app.seams.segmentation);
    this.reframe();
    await this.loading;
    if (ticket !== this.ticket) return;
    if (!step.needs) {
      if (step.id === 'segments' && !(await this.until(() => this.app.seams.segmentation, ticket))) return;
      this.setFigure(this.targetFigures(step.id));
      return;
    }
    this.setFigure([['', 'Making the panels…']]);
    if (!(await this.panelsReady(ticket))) return;
    await this.showPanels(step, ticket);
  }

  async showPanels(step, ticket) {
    const { app } = this;
    const { shown } = app.store;
    const optimized = app.store.result('optimized');
    if (step.id === 'flattened') {
      app.panes.pattern.setPattern(patternForDisplay(optimized.flattenedText, 'the flattened panels'));
      this.patternPaneOverridden = true;
      this.setFigure([['Panels', String(app.panes.pattern.pattern.panels.length)]]);
      this.reframe();
      return;
    }
    const version = step.id === 'naive' ? 'flattened' : 'optimized';
    const texts = { optimized: optimized.patternText, flattened: optimized.flattenedText };
    if (this.patternPaneOverridden || !shown.inflated || shown.patternText !== texts[version]) {
      this.setFigure([['', version === 'flattened' ? 'Inflating the flattened panels…' : 'Inflating the optimized panels…']]);
      const result = await app.panels.showVersion(version);
      if (ticket !== this.ticket) return;
      if (!result) return this.setFigure([['', 'The panels could not be inflated (see the message).']]);
      this.patternPaneOverridden = false;
    }
    this.reframe();
    const naive = this.naiveDistance(version, optimized);
    if (step.id === 'optimized' && !this.naive) await this.measureNaive(ticket, optimized);
    if (ticket !== this.ticket) return;
    const figures = {
      naive: () => [['Pressure', formatPressure(app.design.pressure)], ...distanceFigures(naive)],
      optimized: () => [
        ...distanceFigures(this.optimizedDistance()),
        ['First try', this.naive ? formatPercent(worseDistance(this.naive.distance)) : '—'],
        ['Optimizer steps', String(optimized.status?.iteration ?? '—')],
      ],
      wrinkles: () => [['Most wrinkled', formatPercent(shown.inflated?.maxCompression ?? 0), 'The largest share of the sheet taken up by wrinkles']],
      cut: () => [['Panels', String(shown.pattern?.panels.length ?? 0)], [app.design.fabrication.joining === 'sealed' ? 'Seal band' : 'Seam allowance', `${app.design.fabrication.allowance} mm`]],
    };
    this.setFigure(figures[step.id]());
    if (step.id === 'cut') this.exportActions();
  }

  // The distance of the first try (panels as flattened), measured once per set of panels: the inflated
  // pane's (Panels.showVersion measures what it shows, in the worker, on the target's own projector).
  naiveDistance(version, optimized) {
    if (this.naive?.optimized === optimized) return this.naive.distance;
    const shown = this.app.panes.inflated.fields?.distance;
    if (version !== 'flattened' || !shown) return null;
    this.naive = { optimized, distance: shown };
    return shown;
  }

  // The first try's distance when its step was skipped: the flattened panels inflated in the worker,
  // without showing them.
  async measureNaive(ticket, optimized) {
    const { app } = this;
    this.setFigure([['', 'Measuring the first try…']]);
    try {
      const shape = await app.client.request(Op.inflatePattern, { patternText: optimized.flattenedText });
      const distance = await app.panels.distanceOf(shape);
      if (ticket !== this.ticket) return;
      this.naive = { optimized, distance };
    } catch {
      // no first-try figure then; the step still shows its own
    }
  }

  // The optimized panels' distance, measured like the first try's.
  optimizedDistance() {
    return this.app.panes.inflated.fields?.distance ?? null;
  }

  targetFigures(id) {
    const { app } = this;
    if (id === 'target') {
      const st = app.target?.report.stats;
      if (!st) return [];
      const scale = app.scaleFor(app.design);
      return [['Height', `${Math.round(100 * scale * upFrameSize(st, upOf(app.design))[1])} cm`]]; // as it stands
    }
    if (id === 'seams') return [['Seams', String(app.design.seams.length)]];
    const segments = app.seams.segmentation?.segments.length;
    return [['Segments', segments === undefined ? '…' : String(segments)]];
  }

  // rows: [label, value, title?]; a row without a label is a sentence.
  setFigure(rows) {
    this.figure.replaceChildren(
      ...rows.map(([label, value, title]) => {
        const row = document.createElement('div');
        row.className = label ? 'classroom-figure-row' : 'classroom-figure-line';
        if (title) row.title = title;
        if (label) {
          const l = document.createElement('span');
          l.className = 'label';
          l.textContent = label;
          const v = document.createElement('span');
          v.className = 'value';
          v.textContent = value;
          row.dataset.figure = label.toLowerCase().replace(/\s+/g, '-');
          row.append(l, v);
        } else row.textContent = value;
        return row;
      }),
    );
  }

  exportActions() {
    const kinds = [
      ['svg', 'Cut file (SVG)', 'The pieces nested on the sheet, true scale in mm (for plotters and laser cutters)'],
      ['dxf', 'Cut file (DXF)', 'The same as a DXF file with cut, sew, notch and label layers'],
      ['pdf-a4', 'Printable tiles (PDF)', 'An overview page, then true-scale A4 tiles to print and tape together'],
    ];
    this.actions.replaceChildren(
      ...kinds.map(([kind, text, title]) => {
        const b = button(text, title, () => this.exporter.run(kind), 'classroom-export');
        b.dataset.export = kind;
        return b;
      }),
    );
  }

  // The inflated pane's colors, through its select (where the page has one) so both stay in step.
  setColors(mode) {
    const select = document.getElementById('color-select');
    if (!select || select.value === mode || ![...select.options].some((o) => o.value === mode)) return;
    select.value = mode;
    select.dispatchEvent(new Event('change'));
  }

  // Step 1 shows the bare target, step 2 its seams without the segments' colors.
  hideTargetLayers() {
    const pane = this.app.panes.target;
    const id = this.step.id;
    if (id === 'target') {
      pane.seams?.update([], null);
      pane.setConnections([]);
    }
    if (id === 'target' || id === 'seams') pane.setSegments({ segments: [] });
  }

  // The panes change size from step to step: each is framed anew once the layout has taken effect.
  reframe() {
    requestAnimationFrame(() => {
      const { panes } = this.app;
      if (panes.target.mesh) frameView(panes.target, panes.target.group);
      if (panes.inflated.shape) frameView(panes.inflated, panes.inflated.group);
      if (panes.pattern.pattern) panes.pattern.frame(panes.pattern.content);
    });
  }

  // The app's status line, while something is being computed (its texts end with "…").
  showProgress() {
    if (!this.active) return;
    const text = this.app.store.status;
    this.progress.textContent = /…$/.test(text) ? text : '';
  }

  onKey(e) {
    if (!this.active) return;
    if (document.querySelector('dialog[open]')) return; // the help dialog takes its own keys
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    const plain = !e.ctrlKey && !e.metaKey && !e.altKey;
    if (plain && NEXT_KEYS.includes(e.key)) this.go(this.index + 1);
    else if (plain && BACK_KEYS.includes(e.key)) this.go(this.index - 1);
    else if (plain && e.key === 'Home') this.go(0);
    else if (plain && e.key === 'End') this.go(STEPS.length - 1);
    else if (e.key === 'Escape') this.leave();
    else if (e.key === '?' || e.key === 'Tab' || e.key === 'Enter' || /^F\d+$/.test(e.key)) return; // help, focus, browser keys
    else {
      // The app's editing shortcuts would change the example: none in the walk.
      e.stopImmediatePropagation();
      return;
    }
    e.preventDefault();
    e.stopImmediatePropagation();
  }

  async toggleFullscreen() {
    this.note.hidden = true;
    try {
      if (document.fullscreenElement) {
        await document.exitFullscreen();
        return;
      }
      if (!document.documentElement.requestFullscreen || document.fullscreenEnabled === false) throw new Error('unavailable');
      await document.documentElement.requestFullscreen();
      this.enteredFullscreen = true;
    } catch {
      this.note.textContent = 'This browser did not allow full screen here: use its own full-screen key (often F11) instead.';
      this.note.hidden = false;
    }
    this.renderFullscreen();
  }

  renderFullscreen() {
    const on = Boolean(document.fullscreenElement);
    this.fullscreenButton.textContent = on ? 'Exit full screen' : 'Full screen';
    this.fullscreenButton.setAttribute('aria-pressed', String(on));
    if (!on) this.enteredFullscreen = false;
  }

  renderLargeType() {
    this.largeButton.setAttribute('aria-pressed', String(this.theme.largeType));
  }

  // Leaves the walk: the designer's target, design, undo history and view come back; their autosave was
  // never touched. Resolves once their design is back.
  async leave() {
    if (!this.active) return;
    this.active = false;
    this.ticket += 1;
    this.wake();
    this.element.hidden = true;
    delete document.body.dataset.classroom;
    delete document.body.dataset.classroomStep;
    delete document.body.dataset.classroomLayout;
    if (this.enteredFullscreen && document.fullscreenElement) document.exitFullscreen().catch(() => {});
    if (location.hash === '#classroom') history.replaceState(null, '', `${location.pathname}${location.search}`);
    this.restoring = this.restore();
    await this.restoring;
  }

  async restore() {
    const { app } = this;
    const saved = this.saved;
    await this.loading?.catch(() => {});
    this.patternPaneOverridden = false;
    // Messages about the walk's example go with it.
    for (const box of [...app.messages.container.children]) if (!saved.messages.has(box)) box.remove();
    this.seamTool.setMode(saved.toolMode);
    if (saved.colors) this.setColors(saved.colors);
    // The walk's results leave the panes; the designer's own are made again from their seams.
    if (!(await app.takeBack(saved.design))) {
      // The autosave still holds the designer's design (it was paused): keep it so until the page reloads.
      app.messages.show('error', 'Your design could not be put back after the classroom walk. It is safe in the autosave: reload the page to get it back.');
    }
  }
}
