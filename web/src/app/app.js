// The application controller: owns the design document (through its undo history), talks to the
// worker, updates the panes, autosaves, and shares designs by link or file.
import { Op, ErrorCode } from '../worker/protocol.js';
import { EXAMPLES, findExample } from './examples.js';
import { newDesign, parseDesign, clampHeight } from './design.js';
import { autosave, tabRecordKey } from './autosave.js';
import { Store } from './store.js';
import { encodeDesign, decodeDesign, linkNotice } from './share.js';
import { awaitTarget } from './shared-link.js';
import { PatternSession, patternForDisplay } from './pattern-session.js';
import { optimizeArgs, resultKey } from './stored-result.js';
import { renderTargetStats } from './target-stats.js';
import { SeamEditor } from './seam-editor.js';
import { setHeight, setUp, setMaterial, setPressure, setFabrication, setSeamAllowance, addValve, setValveWidth, removeValve } from './commands.js';
import { upOf, heightScale, withGuessedUp } from './up-axis.js';
import { standUp } from '../views/up-frame.js';
import { MAX_ALLOWANCE, MIN_SHEET, MAX_SHEET, MM_PER_INCH, MAX_VALVE_WIDTH, DEFAULT_VALVE_WIDTH, fabricationWithJoining, patternStatRows, exportOptions, grainMode, GRAIN_FIELDS, seamLabel, formatMillimeters, formatSize, joiningOf } from './fabrication.js';
import { download } from './download.js';
import { renderStats } from '../views/stats-list.js';
import { MATERIAL_PRESETS, MIN_PRESSURE, MAX_PRESSURE, presetMaterial, isPresetMaterial, describeMaterial, formatPressure } from './materials.js';
import { formatDistance } from './units.js';

// Example patterns computed by the solver (wasm/src/simulate/example_patterns.cpp).
export const PATTERN_EXAMPLES = [
  { id: 'mylar', name: 'Mylar balloon (two discs)' },
  { id: 'pillow', name: 'Pillow (two squares)' },
  { id: 'sphere3', name: 'Sphere (three gores)' },
];

const AUTOSAVE_KEY = 'current';
const STORED_STATUS = 'Showing the stored result while it is refined live';
const TAB_RECORD_DAYS = 30; // per-tab records older than this are deleted

// How the optimizer ended (its state, OptimizeState in pattern_optimizer.hpp), in a designer's words: a run
// that reached its limit is not one that settled.
export function optimizerEnd({ state, iteration }) {
  const steps = `${iteration} step${iteration === 1 ? '' : 's'}`;
  if (state === 'converged') return `settled after ${steps}`;
  return `stopped at the optimizer's limit (${steps}) before settling; the panels may fit a little better than shown`;
}

export class App {
  constructor({ client, panes, messages, elements, baseUrl }) {
    this.client = client;
    this.panes = panes;
    this.messages = messages;
    this.el = elements;
    this.baseUrl = baseUrl;
    this.store = new Store(newDesign());
    this.store.subscribe((what) => what === 'status' && (this.el.status.textContent = this.store.status));
    this.target = null; // { positions, indices, report, fileName }
    this.patterns = new PatternSession({
      client,
      store: this.store,
      panes,
      messages,
      status: (text) => this.setStatus(text),
      stats: elements.inflatedStats,
    });
    this.patterns.onPatternShown = (display, text) => this.refreshCutLines(display, text);
    this.seams = new SeamEditor(this);
  }

  get design() {
    return this.store.design;
  }

  get revision() {
    return this.store.revision;
  }

  get resolution() {
    return this.store.resolution;
  }

  async start() {
    this.populateExamples();
    this.populateMaterials();
    this.tabKey = tabRecordKey();
    autosave.pruneTabs(this.tabKey, TAB_RECORD_DAYS * 86400e3).catch(() => {});
    if (await this.openFromLink(location.hash)) return;
    // A reloaded tab reopens its own design; a new tab the one the autosaving tab saved.
    const own = this.tabKey ? await autosave.load(this.tabKey).catch(() => null) : null;
    const saved = own ?? (await autosave.load(AUTOSAVE_KEY).catch(() => null));
    if (saved?.design) {
      try {
        const { design, warnings } = parseDesign(saved.design);
        for (const w of warnings) this.messages.show('warning', w);
        if (design.target.example) return await this.loadExample(design.target.example, design);
        if (saved.mesh) return await this.installSavedMesh(design, saved.mesh);
      } catch (error) {
        this.messages.show('warning', `The autosaved design could not be restored: ${error.message}`);
      }
    }
    await this.loadExample(this.design.target.example);
  }

  // A shared link (#design=...): true when it held a design that was opened.
  async openFromLink(hash) {
    let decoded;
    try {
      decoded = await decodeDesign(hash);
    } catch (error) {
      this.messages.show('error', `${error.message} Billow opened your last design instead.`);
      history.replaceState(null, '', location.pathname + location.search);
      return false;
    }
    if (!decoded) return false;
    this.awaited = awaitTarget(decoded, this.messages); // a design whose mesh stayed out of the link waits for that file (shared-link.js)
    for (const w of decoded.warnings) this.messages.show('warning', w);
    history.replaceState(null, '', location.pathname + location.search); // the design is autosaved from now on
    if (decoded.design.target.example) {
      await this.loadExample(decoded.design.target.example, decoded.design);
      return true;
    }
    if (!decoded.mesh) {
      await this.loadExample(newDesign().target.example);
      return true;
    }
    try {
      await this.installSavedMesh(decoded.design, decoded.mesh);
    } catch (error) {
      this.messages.show('error', `The target shape in this link cannot be used: ${error.message} Billow opened an example instead.`);
      await this.loadExample(newDesign().target.example);
    }
    return true;
  }

  populateExamples() {
    const select = this.el.exampleSelect;
    select.replaceChildren();
    select.append(new Option('Choose…', ''));
    const targets = document.createElement('optgroup');
    targets.label = 'Targets';
    for (const e of EXAMPLES) targets.append(new Option(e.name, e.id));
    const patterns = document.createElement('optgroup');
    patterns.label = 'Patterns to inflate';
    for (const e of PATTERN_EXAMPLES) patterns.append(new Option(e.name, `pattern:${e.id}`));
    select.append(targets, patterns);
  }

  setStatus(text) {
    this.store.setStatus(text);
  }

  async track(label, fn) {
    this.store.working('opening', +1);
    this.setStatus(label);
    try {
      return await fn();
    } finally {
      this.store.working('opening', -1);
    }
  }

  // An example from the menu: a target ("spot") or a pattern ("pattern:mylar").
  async openExample(value) {
    if (value.startsWith('pattern:')) return this.patterns.openExample(value.slice('pattern:'.length));
    return this.loadExample(value);
  }

  // design: the design to open on the example (else a new one); stored: a stored result of that design
  // (stored-result.js), shown at once when its key is the design's, as made from this very mesh file.
  async loadExample(id, design = null, { stored = null } = {}) {
    const example = findExample(id);
    if (!example) return this.messages.show('error', `There is no example called "${id}".`);
    this.el.exampleSelect.value = id;
    let bytes;
    try {
      const response = await fetch(new URL(`examples/${example.file}`, this.baseUrl));
      if (!response.ok) throw new Error(`HTTP ${response.status}`);
      bytes = await response.arrayBuffer();
    } catch {
      // Offline before the examples were cached, or the site is missing the file.
      this.el.exampleSelect.value = this.design.target.example ?? '';
      return this.messages.show(
        'error',
        `The example "${example.name}" could not be loaded: check the connection and try again.${this.target ? ' Your current design is unchanged.' : ''}`,
      );
    }
    const matching = design && stored?.key === resultKey(design, this.resolution, bytes) ? stored : null;
    return this.loadTargetBytes(example.file, bytes, design ?? newDesign(id), { quiet: true, stored: matching });
  }

  // A file the designer picked or dropped: a mesh becomes the target; a .json is a design or a pattern.
  async openFile(file) {
    if (/\.json$/i.test(file.name)) return this.openJsonFile(file);
    const bytes = await file.arrayBuffer();
    const design = { ...newDesign(), target: { file: file.name }, size: { height: this.design.size.height } };
    this.el.exampleSelect.value = '';
    return this.loadTargetBytes(file.name, bytes, design, { quiet: false });
  }

  async openJsonFile(file) {
    const text = await file.text();
    let format = null;
    try {
      format = JSON.parse(text)?.format;
    } catch {
      return this.messages.show('error', `"${file.name}" is not a valid JSON file.`);
    }
    if (format === 'billow-pattern') return this.patterns.open(file.name, text);
    if (format !== 'billow-design')
      return this.messages.show('error', `"${file.name}" is neither a Billow design nor a Billow pattern.`);
    try {
      const { design, warnings } = parseDesign(JSON.parse(text));
      for (const w of warnings) this.messages.show('warning', w);
      if (design.target.example) return this.loadExample(design.target.example, design);
      if (this.target && design.target.file === this.target.fileName) {
        this.commitDesign(design, { reset: true });
        return this.seams.refresh();
      }
      return this.messages.show('warning', `This design uses the target file "${design.target.file}": open that mesh first, then the design.`);
    } catch (error) {
      return this.messages.show('error', `"${file.name}" cannot be opened: ${error.message}`);
    }
  }

  async loadTargetBytes(fileName, bytes, design, { quiet, stored = null }) {
    // The worker takes one long operation at a time: panels still being made for the design on screen would
    // hold the new target back until they are done.
    const interrupted = this.stopWork();
    try {
      const result = await this.track(`Opening ${fileName}…`, () =>
        this.client.latest('target', Op.loadTarget, { fileName, bytes }, {
          transfer: [bytes],
          onProgress: (p) => this.setStatus(`Opening ${fileName}: ${p.stage}…`),
        }).promise,
      );
      this.client.remember(Op.setTarget, { positions: result.positions, indices: result.indices });
      const opened = design;
      if (this.awaited) design = this.awaited.attach(fileName, result, design); // the linked design, if this file is its mesh
      // A designer's own file may be Z up (CAD, 3D printing): the guess goes into its new design (up-axis.js).
      const guess = !quiet && design === opened ? withGuessedUp(design, result, fileName) : { design, notice: null };
      design = guess.design;
      this.installTarget(fileName, result, design, stored);
      if (!stored) this.setStatus('Ready');
      // What the mesh report says belongs to this target: it goes with it (and the genus warning once seams cut
      // the handles open: SeamEditor.segment).
      this.messages.resolve('target.', { prefix: true });
      if (guess.notice) this.messages.show('notice', guess.notice, [], { cause: 'target.up' });
      const shown = result.report.issues.filter((i) => i.severity !== 'error');
      for (const issue of shown)
        if (!quiet || issue.severity !== 'notice') this.messages.show(issue.severity, issue.message, [], { cause: `target.${issue.code}` });
    } catch (error) {
      if (error.code === ErrorCode.cancelled) return; // a newer load won
      const report = error.details?.report;
      const items = report ? report.issues.filter((i) => i.severity === 'error').map((i) => i.message) : [];
      const text = report
        ? `"${fileName}" cannot be used as a target. Your current design is unchanged.`
        : `${error.message}${this.target ? ' Your current design is unchanged.' : ''}`;
      this.messages.show('error', text, items);
      if (!this.target) this.setStatus('');
      if (interrupted) this.remakePattern(); // the design stays: so do its panels
    }
  }

  async installSavedMesh(design, mesh) {
    this.el.exampleSelect.value = '';
    const result = await this.client.request(Op.setTarget, mesh);
    this.client.remember(Op.setTarget, mesh);
    this.installTarget(design.target.file, result, design);
    this.setStatus('Ready');
  }

  installTarget(fileName, result, design, stored = null) {
    this.target = { fileName, positions: result.positions, indices: result.indices, report: result.report };
    this.panes.target.setTarget(this.target, this.scaleFor(design));
    this.seams.reset();
    this.setPanelsOutdated(false);
    this.commitDesign(design, { reset: true });
    // The seams (and so the live optimization) after the stored result: its inflation and cut lines are then
    // queued in the worker first, not held back until the optimization is done.
    if (stored) this.showStoredResult(stored).finally(() => this.seams.refresh());
    else this.seams.refresh();
  }

  // A stored result of the design just opened (a gallery design's, made at build time by this pipeline):
  // its optimized panels and their inflated shape, shown at once. The live optimization then runs as usual
  // but shows none of its iterates, worse than the stored result until the last; its result replaces it.
  async showStoredResult(stored) {
    this.store.setResult('stored', true);
    const status = () => this.storedShown() && this.setStatus(`${STORED_STATUS}…`);
    const result = await this.patterns.open('the stored optimized panels', stored.patternText, { status });
    if (result) await this.measureDistance(result);
  }

  // True while the stored result belongs to the current design and resolution: no edit since it was shown.
  storedShown() {
    return Boolean(this.store.result('stored'));
  }

  // Mesh files carry no units: the design's height (m) along the target's up axis fixes the scale of its units.
  scaleFor(design) {
    return heightScale(design, this.target?.report.stats);
  }

  // Every change of the design goes through here: history, views, autosave.
  commitDesign(design, { reset = false, mergeKey = null } = {}) {
    // Panels being made for the previous design are stale now, unless the edit left all they are made from
    // as it was (the mirror plane): those panels and any stored result still belong to the design.
    if (this.store.commit(design, { reset, mergeKey })) this.panelsOutdated();
    this.showDesign();
    this.save();
  }

  // What the panels are made from changed (a new revision): the panels and inflation under way are for the
  // design before, and "before optimization" waits for this design's own panels.
  panelsOutdated() {
    this.stopWork();
    this.el.compareGroup.hidden = true;
  }

  // Stops making and inflating panels; true when something was under way.
  stopWork() {
    const running = this.client.running('panels') || this.client.running('inflation');
    this.client.supersede('panels');
    this.client.supersede('inflation');
    return running;
  }

  // The results on screen leave: the panes, their figures, the optimized panels (the classroom walk, done).
  clearResults() {
    this.store.clearResults();
    this.store.show({ patternText: null, pattern: null, inflated: null, cut: null });
    this.panes.inflated.clear();
    this.panes.inflated.legend.hidden = true;
    this.panes.pattern.clear();
    this.panes.pattern.pattern = null;
    for (const id of ['pane-inflated', 'pane-pattern']) document.querySelector(`#${id} .hint`)?.removeAttribute('hidden');
    this.el.inflatedStats.replaceChildren();
    this.el.patternStats.replaceChildren();
    this.el.compareGroup.hidden = true;
  }

  // The designer's design set aside while another is shown (the classroom walk's example): its undo history,
  // target and opened pattern; their autosave is left as it is until takeBack.
  setAside() {
    this.autosavePaused = true;
    const history = this.store.swapHistory();
    const optimized = this.store.result('optimized');
    const own = optimized && [optimized.patternText, optimized.flattenedText].includes(this.store.shown.patternText);
    return { history, target: this.target, exampleValue: this.el.exampleSelect.value, openedPattern: own ? null : this.store.shown.patternText };
  }

  // The design set aside comes back with its undo steps; its panels are made again from its seams, a pattern
  // the designer had opened is opened again. False when its target could not be installed again.
  async takeBack(aside) {
    this.stopWork();
    this.clearResults();
    const design = aside.history.present;
    if (design.target.example) await this.loadExample(design.target.example, design);
    else await this.installSavedMesh(design, { positions: aside.target.positions, indices: aside.target.indices }).catch(() => {});
    if (this.design !== design) return false;
    this.store.swapHistory(aside.history);
    this.el.exampleSelect.value = aside.exampleValue;
    this.showDesign();
    this.autosavePaused = false;
    if (aside.openedPattern) await this.patterns.open('the pattern', aside.openedPattern);
    return true;
  }

  // The panels of the current seams: flattened (shown at once in the pattern pane), then optimized in the
  // worker so their inflated shape matches the target (paper Sec. 5), then inflated for the panes. A newer
  // edit supersedes this one (commitDesign cancels it).
  async makePattern() {
    this.setPanelsOutdated(false);
    const revision = this.revision;
    this.client.supersede('inflation');
    const call = this.client.latest(
      'panels',
      Op.optimizeDesign,
      { ...optimizeArgs(this.design, this.resolution), scale: this.scaleFor(this.design), up: upOf(this.design) },
      {
        onProgress: (p) => {
          if (p.flattenedText) this.flattenedText = p.flattenedText;
          const step = p.iteration !== undefined && p.stage === 'optimizing'
            ? `step ${p.iteration}${p.distanceRms !== undefined ? `, distance ${formatDistance({ rms: p.distanceRms, targetRms: p.targetDistanceRms })}` : ''}${p.slidingSeams ? ', light seams sliding' : ''}`
            : null;
          if (this.storedShown()) return this.setStatus(`${STORED_STATUS}: ${step ?? p.stage}…`);
          if (p.flattenedText) this.panes.pattern.setPattern(patternForDisplay(p.flattenedText, 'the panels'));
          this.showIterate(p);
          this.setStatus(step ? `Optimizing the panels: ${step}…` : `Making the panels: ${p.stage}…`);
        },
      },
    );
    this.store.working('panels', +1);
    try {
      const result = await call.promise;
      this.store.setResult('optimized', result, revision);
      this.store.setResult('stored', false, revision); // replaced by the live result
      this.messages.resolve('pattern', { prefix: true });
      const shown = await this.showVersion('optimized');
      if (shown && revision === this.revision) this.setStatus(`Inflated the optimized panels: ${optimizerEnd(result.status)}`);
    } catch (error) {
      if (error.code === ErrorCode.cancelled || error.code === ErrorCode.crashed || revision !== this.revision) return;
      this.patternFailed(error);
      this.setStatus('');
    } finally {
      this.store.working('panels', -1);
    }
  }

  // The panels shown were made from seams that have changed and now make none (SeamEditor.segment): they stay in
  // view, dimmed and marked, the status says so, and what was said about their shape goes, until new panels.
  setPanelsOutdated(outdated) {
    const shown = Boolean(this.panes.inflated.shape || this.panes.pattern.pattern);
    for (const pane of [this.panes.inflated, this.panes.pattern]) pane.element.closest('.pane')?.toggleAttribute('data-stale', outdated && shown);
    if (!outdated || !shown) return;
    this.messages.resolve('distance.uncovered', { prefix: true });
    this.setStatus('These seams make no panels yet (see the seam panel): the panels shown are from the seams before');
  }

  // Panels that could not be made: each problem the builder placed is its own message, with "Show where"; memory
  // messages say what to do on their own; others are about the seams.
  patternFailed(error) {
    this.messages.resolve('pattern', { prefix: true });
    const placed = (error.details?.problems ?? []).filter((p) => p.location);
    if (error.code === 'pattern.not-built' && placed.length) {
      placed.slice(0, 3).reverse().forEach((p, i) => { // the first problem in last, to lead the stack
        this.messages.show('error', `The panels could not be made from these seams: ${p.message}`, [], { cause: `pattern.${i}`, locate: () => this.showPlace(p.location) });
      });
      return;
    }
    const text = error.code?.startsWith('memory') ? error.message : `The panels could not be made from these seams: ${error.message}`;
    this.messages.show('error', text, [], { cause: 'pattern' });
  }

  // An optimization iterate: its inflated shape (colored by its distance to the target when that is the
  // chosen view) and, now and then, its panels. The final result replaces both.
  showIterate(p) {
    const pane = this.panes.inflated;
    if (p.triangles) {
      pane.setResult({ positions: p.positions, triangles: p.triangles, outer: p.outer }, { frame: !pane.shape });
      this.patterns.markStatsStale();
    }
    else if (p.positions && pane.shape && pane.position?.count * 3 === p.positions.length) pane.updatePositions(p.positions);
    if (p.distances && pane.shape) pane.setDistances(p.distances, p.distance, p.uncoveredTriangles);
    if (p.patternText) this.panes.pattern.setPattern(patternForDisplay(p.patternText, 'the panels being optimized'), { frame: false });
  }

  // The inflated pane shows the optimized panels or, for comparison (paper Fig. 8), the panels as first
  // flattened: pressure rounds them, which is why they miss the target.
  async showVersion(which) {
    const optimized = this.store.result('optimized');
    if (!optimized) return null;
    this.el.compareGroup.hidden = false;
    this.el.showOptimized.setAttribute('aria-pressed', String(which === 'optimized'));
    this.el.showFlattened.setAttribute('aria-pressed', String(which !== 'optimized'));
    const result =
      which === 'optimized'
        ? await this.patterns.open('the optimized panels', optimized.patternText)
        : await this.patterns.open('the flattened panels', optimized.flattenedText);
    if (result) await this.measureDistance(result);
    return result;
  }

  // The signed distance of an inflated shape ({ positions, triangles, outer }) to the target, from the worker:
  // { distances (per vertex, m), rms, max (outer surface, over the target's diagonal), diagonal }.
  distanceOf(shape) {
    const { positions, triangles, outer } = shape;
    return this.client.call(Op.distanceToTarget, { positions, triangles, outer, scale: this.scaleFor(this.design), up: upOf(this.design) }).promise;
  }

  // The signed distance of the shown inflated shape to the target, for the "distance to target" colors, and the
  // other way: the parts of the target it leaves out, each a warning that shows where.
  async measureDistance(result) {
    const pane = this.panes.inflated;
    const serial = pane.serial;
    try {
      const d = await this.distanceOf(result);
      if (pane.serial !== serial) return;
      pane.setDistances(d.distances, d, d.uncoveredTriangles);
      this.warnUncovered(d.uncovered ?? []);
    } catch (error) {
      // Without distances the pane keeps its other colors; a crashed worker says so elsewhere.
      if (error.code !== 'cancelled' && error.code !== 'worker.crashed') console.warn('distance to target:', error.message);
    }
  }

  // The parts of the target the shown inflated shape leaves out (UncoveredRegion in surface_distance.hpp): where,
  // how much, and what helps.
  warnUncovered(regions) {
    this.messages.resolve('distance.uncovered', { prefix: true });
    // The newest message is on top of the stack (messages.js): the largest part goes in last, to lead.
    const shown = regions.slice(0, 3);
    for (let i = shown.length - 1; i >= 0; i--) {
      const r = shown[i];
      this.messages.show('warning', r.message, [], { cause: `distance.uncovered.${i}`, locate: () => this.showPlace(r.position, { radius: r.radius, colors: 'distance' }) });
    }
  }

  // Turns the target and inflated panes towards a place on the target (its own units) and marks it there.
  showPlace(position, { radius = 0, colors = null } = {}) {
    this.panes.target.showPlace(position, radius);
    if (colors) this.setColorMode?.(colors);
    if (colors === 'distance') this.panes.inflated.frameWithUncovered();
  }

  setResolution(triangles) {
    this.store.setResolution(triangles);
    this.panelsOutdated();
    this.remakePattern();
  }

  // After a change of the physics (resolution, material, pressure): new panels when the seams give some.
  remakePattern() {
    if (this.seams.segmentation?.segments?.every((s) => s.isDisk) && this.design.seams.length) this.makePattern();
  }

  // The cut lines (with the seam allowance) and the pattern's figures, from the solver's exporter.
  async refreshCutLines(display = this.store.shown.pattern, text = this.store.shown.patternText) {
    if (!text) return;
    const f = this.design.fabrication;
    try {
      const result = await this.client.latest('cut-lines', Op.exportPattern, {
        patternText: text,
        options: exportOptions(f),
      }).promise;
      const widths = Object.fromEntries(result.statistics.seams.map((seam) => [seam.id, seam.allowance_mm]));
      widths[-1] = result.statistics.free_edge_allowance_mm;
      const totals = result.statistics.totals;
      this.panes.pattern.setCutResult(display, {
        ...result,
        seams: result.statistics.seams,
        sealed: result.statistics.joining === 'sealed',
        widths,
        captions: {
          width: formatMillimeters(totals.sheet_width_mm, f.units),
          length: formatMillimeters(totals.sheet_length_mm, f.units),
          size: (widthMm, heightMm) => formatSize(widthMm, heightMm, f.units),
        },
      });
      this.store.show({ cut: result.statistics });
      this.messages.resolve('cut-lines');
      this.noteUnplacedValves(result.statistics.valves);
      this.allowancePanel?.setSeams(result.statistics);
      renderStats(this.el.patternStats, patternStatRows(result.statistics, f.units));
    } catch (error) {
      if (error.code === ErrorCode.cancelled || error.code === ErrorCode.crashed) return;
      this.store.show({ cut: null });
      renderStats(this.el.patternStats, []);
      // A piece wider than the sheet: the width that fits every piece, in one click.
      const fits = error.code === 'export.sheet-too-narrow' && error.details?.sheet_width <= MAX_SHEET && error.details.sheet_width;
      const action = fits ? { label: `Use a ${formatMillimeters(fits, f.units)} sheet`, run: () => this.setFabrication({ sheet_width: fits }) } : null;
      this.messages.show('warning', `The cut outline could not be drawn: ${error.message}`, [], { cause: 'cut-lines', action });
    }
  }

  // Valves on seams this pattern does not have (the seams were redrawn): said once, with a way to drop them.
  noteUnplacedValves(valves = []) {
    const lost = valves.map((v, index) => ({ ...v, index })).filter((v) => !v.placed);
    if (!lost.length) return this.messages.resolve('valves');
    const names = lost.map((v) => v.label).join(', ');
    const text = `${lost.length === 1 ? 'A fill valve is' : `${lost.length} fill valves are`} on ${names}, which this pattern does not have (the seams were redrawn), so ${lost.length === 1 ? 'it is' : 'they are'} not in the cut files. Open Seams to place ${lost.length === 1 ? 'it' : 'them'} again.`;
    const action = { label: lost.length === 1 ? 'Remove it' : 'Remove them', run: () => this.removeValves(lost.map((v) => v.index)) };
    this.messages.show('warning', text, [], { cause: 'valves', action });
  }

  // Sewn or heat sealed ('sewn' | 'sealed'): an allowance left at its joining's default follows.
  setJoining(joining) {
    this.applyFabrication({ ...this.design, fabrication: fabricationWithJoining(this.design.fabrication, joining) }, 'fabrication-joining');
  }

  // A fill valve on seam `seam` (exporter id) centred at share `at` of its length.
  addValve(seam, at) {
    this.applyFabrication(addValve(this.design, { seam, at: Math.min(1, Math.max(0, at)), width: DEFAULT_VALVE_WIDTH }), null);
  }

  setValveWidth(index, mm) {
    if (!(Number.isFinite(mm) && mm > 0 && mm <= MAX_VALVE_WIDTH)) {
      this.messages.show('warning', `A fill valve's gap must be wider than 0 and at most ${MAX_VALVE_WIDTH} mm.`, [], { cause: 'fabrication.valve' });
      this.showDesign();
      return;
    }
    this.messages.resolve('fabrication.valve');
    this.applyFabrication(setValveWidth(this.design, index, mm), `valve-width-${index}`);
  }

  removeValves(indices) {
    let next = this.design;
    for (const index of [...indices].sort((a, b) => b - a)) next = removeValve(next, index);
    this.applyFabrication(next, null);
  }

  // Fabrication settings change the cut files only, never the panels: no new optimization.
  setFabrication(changes) {
    const checks = {
      allowance: [0, MAX_ALLOWANCE, `The seam allowance must be between 0 and ${MAX_ALLOWANCE} mm.`],
      sheet_width: [MIN_SHEET, MAX_SHEET, `The sheet width must be between ${MIN_SHEET} and ${MAX_SHEET} mm.`],
      free_edge_allowance: [0, MAX_ALLOWANCE, `The allowance of free edges must be between 0 and ${MAX_ALLOWANCE} mm.`],
    };
    for (const [key, [lo, hi, message]] of Object.entries(checks)) {
      const v = changes[key];
      if (v !== undefined && !(Number.isFinite(v) && v >= lo && v <= hi)) {
        this.messages.show('warning', message, [], { cause: `fabrication.${key}` });
        this.showDesign();
        return;
      }
      if (v !== undefined) this.messages.resolve(`fabrication.${key}`);
    }
    this.applyFabrication(setFabrication(this.design, changes), `fabrication-${Object.keys(changes).join()}`);
  }

  applyFabrication(next, mergeKey) {
    if (JSON.stringify(next.fabrication) === JSON.stringify(this.design.fabrication)) {
      this.showDesign(); // a field typed back to what it was shows the stored value again
      return;
    }
    this.store.commit(next, { mergeKey });
    this.showDesign();
    this.save();
    this.refreshCutLines();
  }

  // One seam's own allowance [mm] (id as in the exporter's statistics; labelled S<id + 1>), or null for the
  // seam allowance; 0 for a heat-sealed seam.
  setSeamAllowance(id, mm) {
    if (mm !== null && !(Number.isFinite(mm) && mm >= 0 && mm <= MAX_ALLOWANCE)) {
      this.messages.show('warning', `The allowance of seam ${seamLabel(id)} must be between 0 and ${MAX_ALLOWANCE} mm.`);
      this.showDesign();
      return;
    }
    this.applyFabrication(setSeamAllowance(this.design, id, mm), `seam-allowance-${id}`);
  }

  // The allowance of free edges [mm], or null: as the seams.
  setFreeEdgeAllowance(mm) {
    this.setFabrication({ free_edge_allowance: mm ?? undefined });
  }

  // How panels may turn when nested: 'free', 'grain' (kept along the roll) or 'fixed' (as drawn).
  setGrain(mode) {
    if (GRAIN_FIELDS[mode]) this.applyFabrication(setFabrication(this.design, GRAIN_FIELDS[mode]), 'fabrication-grain');
  }

  populateMaterials() {
    const select = this.el.materialSelect;
    select.replaceChildren(
      ...MATERIAL_PRESETS.map((m) => {
        const option = new Option(m.label, m.name);
        option.title = describeMaterial(m);
        return option;
      }),
      Object.assign(new Option('Custom (from the design file)', 'custom'), { disabled: true }),
    );
  }

  setMaterialPreset(name) {
    if (name === 'custom' || (isPresetMaterial(this.design.material) && this.design.material.name === name)) return;
    this.commitDesign(setMaterial(this.design, presetMaterial(name)));
    this.remakePattern();
  }

  setPressure(pascals) {
    if (!Number.isFinite(pascals) || pascals < MIN_PRESSURE || pascals > MAX_PRESSURE) {
      this.messages.show('warning', `The pressure must be between ${formatPressure(MIN_PRESSURE)} and ${formatPressure(MAX_PRESSURE)}.`, [], { cause: 'pressure' });
      this.showDesign();
      return;
    }
    this.messages.resolve('pressure');
    if (pascals === this.design.pressure) return;
    this.commitDesign(setPressure(this.design, pascals), { mergeKey: 'pressure' });
    this.remakePattern();
  }

  // A fix-up that belongs to the edit just made: no new undo step.
  amendDesign(design) {
    if (this.store.amend(design)) this.panelsOutdated();
    this.save();
  }

  showDesign() {
    const design = this.design;
    this.el.heightInput.value = String(design.size.height);
    const material = design.material;
    this.el.materialSelect.value = isPresetMaterial(material) ? material.name : 'custom';
    this.el.materialSelect.title = `The sheet the panels are cut from: ${describeMaterial(material)}`;
    const f = design.fabrication;
    const inches = f.units === 'in';
    this.el.unitsSelect.value = f.units;
    this.el.allowanceInput.value = String(+(inches ? f.allowance / MM_PER_INCH : f.allowance).toFixed(inches ? 3 : 1));
    const sealed = joiningOf(f) === 'sealed';
    this.el.allowanceLabel.firstChild.textContent = sealed ? 'Seal band ' : 'Allowance ';
    this.el.allowanceLabel.title = sealed
      ? 'Heat sealed: the band along the outline where the two pieces are sealed; the cut line runs at its outer edge'
      : 'Extra material outside the sewing line, on every seam without its own allowance; 0 for heat sealing';
    this.el.sheetInput.value = String(+(inches ? f.sheet_width / MM_PER_INCH : f.sheet_width).toFixed(inches ? 2 : 0));
    if (this.el.grainSelect) this.el.grainSelect.value = grainMode(f);
    this.allowancePanel?.render(f);
    const unit = Number(this.el.pressureUnit.value) || 1000;
    this.el.pressureInput.value = String(+(design.pressure / unit).toPrecision(6));
    this.panes.target.setScale(this.scaleFor(design));
    this.el.upSelect.value = upOf(design);
    standUp(this.panes, upOf(design)); // the target and its inflated shape stand on the design's up axis
    if (this.panes.inflated.targetScale !== this.scaleFor(design) || this.panes.inflated.targetOf !== this.target)
      this.panes.inflated.setTarget(this.target, this.scaleFor(design));
    renderTargetStats(this.el.stats, this.target, this.scaleFor(design), upOf(design));
    this.el.undoButton.disabled = !this.store.history.canUndo;
    this.el.redoButton.disabled = !this.store.history.canRedo;
  }

  setHeight(meters) {
    if (!Number.isFinite(meters) || meters <= 0) {
      this.messages.show('warning', 'The height must be a positive number of meters.', [], { cause: 'height' });
      this.el.heightInput.value = String(this.design.size.height);
      return;
    }
    this.messages.resolve('height');
    const height = clampHeight(meters);
    if (height === this.design.size.height) return;
    this.commitDesign(setHeight(this.design, height), { mergeKey: 'height' });
    this.remakePattern(); // the panels' size changed: the edit cancelled the running optimization (commitDesign)
  }
  // Which of the target's own axes points up (up-axis.js): it stands on it and Height is measured along it, so
  // like the height it changes the panels' size; the problems' places ("near the top") are read in it too, so
  // the target is segmented again, which makes the panels anew.
  setUp(up) {
    this.messages.resolve('target.up');
    if (up === upOf(this.design)) return;
    this.commitDesign(setUp(this.design, up));
    this.seams.segment();
  }


  undo() {
    this.afterHistoryMove(this.store.undo());
  }

  redo() {
    this.afterHistoryMove(this.store.redo());
  }

  afterHistoryMove(newRevision) {
    if (newRevision) this.panelsOutdated();
    this.seams.selection = null;
    this.showDesign();
    this.save();
    this.seams.refresh();
    this.refreshCutLines();
  }

  // Puts the design into the page's link and copies it; a target from the designer's own file travels in
  // the link too (quantized and compressed), unless it makes the link too long.
  async shareLink() {
    try {
      const fragment = await encodeDesign(this.design, this.ownMesh());
      const url = `${location.origin}${location.pathname}${location.search}#${fragment}`;
      await navigator.clipboard?.writeText(url).catch(() => {});
      this.messages.show('notice', linkNotice(fragment, this.design));
      return url;
    } catch (error) {
      this.messages.show('warning', error.message);
      return null;
    }
  }

  // Downloads the design document as a .json file.
  saveDesignFile() {
    download(JSON.stringify(this.design, null, 2), `${this.fileBaseName()}.billow.json`, 'application/json');
  }

  // The name files of this design are called by: its example or mesh file, without extension.
  fileBaseName() {
    return (this.design.target.example ?? this.target?.fileName ?? 'design').replace(/\.[^.]+$/, '');
  }

  // The target mesh when it is the designer's own file (links and the autosave carry it), else null.
  ownMesh() {
    return this.design.target.example ? null : { positions: this.target.positions, indices: this.target.indices };
  }

  // This tab now autosaves (the tab that did was closed): the design is saved at once, not only after the
  // next edit.
  becamePrimary() {
    this.save();
  }

  // Every tab saves its own record; the tab that autosaves (tab-guard.js) also the shared one.
  // autosavePaused: while the classroom walk shows its example, the designer's autosaved design stays.
  save() {
    if (!this.target || this.autosavePaused) return;
    const record = { design: this.design, mesh: this.ownMesh() };
    const keys = [this.tabKey, this.tabGuard && !this.tabGuard.isPrimary ? null : AUTOSAVE_KEY].filter(Boolean);
    Promise.all(keys.map((key) => autosave.save(key, record))).catch((error) =>
      this.messages.show('warning', `Autosave failed (${error?.message || error}); save your design to a file.`),
    );
  }
}
