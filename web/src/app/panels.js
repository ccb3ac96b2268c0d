// The design's panels: made from the seams' segments, optimized in the worker so their inflated shape matches
// the target (paper Sec. 5), inflated and shown in the inflated and pattern panes with their distance to the
// target and their cut lines. Results go into the store keyed by the design revision they were made for; a
// newer edit supersedes the work under way (the worker client's latest).
import { Op, ErrorCode } from '../worker/protocol.js';
import { patternForDisplay } from './pattern-session.js';
import { optimizeArgs } from './stored-result.js';
import { upOf } from './up-axis.js';
import { hasGusset } from './band.js';
import { MAX_SHEET, patternStatRows, exportOptions, formatMillimeters, formatSize } from './fabrication.js';
import { renderStats } from '../views/stats-list.js';
import { narrowOutlineShare } from '../views/pattern-layout.js';
import { formatDistance, worseDistance } from './units.js';

const STORED_STATUS = 'Showing the stored result while it is refined live';

// How the optimizer ended (its state, OptimizeState in pattern_optimizer.hpp), in a designer's words: a run
// that reached its limit is not one that settled.
export function optimizerEnd({ state, iteration }) {
  const steps = `${iteration} step${iteration === 1 ? '' : 's'}`;
  if (state === 'converged') return `settled after ${steps}`;
  return `stopped at the optimizer's limit (${steps}) before settling; the panels may fit a little better than shown`;
}

// A share of the outlines this narrow (narrowOutlineShare) makes the cut panels' own meshing a likely cause of their
// other shape (bench/README.md "Flat-cut designs").
const NARROW_OUTLINES = 0.1;
// The cut panels count as clearly farther at 1.2 x the own mesh's distance and at least this much more (of the size):
// a ring balloon whose own mesh read 0.11 % and whose cut panels read 0.26 % was told part of it takes another shape,
// where the two differ by a millimetre a metre.
const CLEARLY_FARTHER = 0.0025;

// When the optimized outlines, cut and inflated, settle clearly farther (CLEARLY_FARTHER) from the target than the
// optimizer's own mesh had (status.ownMesh, OptimizeRemeshing::cutPanels): part of the balloon takes another shape once cut, and
// the panes show it as cut; where much of the outlines runs along parts only a triangle or so across (narrowShare)
// and the Panels menu has a finer setting (finer, its name), that it follows them better. Null otherwise.
export function cutPanelsNote({ ownMesh, distanceRms, targetDistanceRms }, { narrowShare = 0, finer = null } = {}) {
  if (!ownMesh) return null;
  const own = worseDistance({ rms: ownMesh.distanceRms, targetRms: ownMesh.targetDistanceRms });
  const cut = worseDistance({ rms: distanceRms, targetRms: targetDistanceRms });
  if (!(cut > 1.2 * own && cut - own > CLEARLY_FARTHER)) return null;
  const percent = (f) => `${(100 * f).toFixed(2)} %`;
  const finerHelps = finer && narrowShare >= NARROW_OUTLINES
    ? ` A ${Math.round(100 * narrowShare)} % share of the outlines borders parts only a triangle or so across ` +
      `at this resolution (a leg, a tail, a strip): the "${finer}" Panels setting follows them better.`
    : '';
  return `Cut from these outlines, the panels inflate farther from the target than the optimizer's own mesh showed ` +
    `(${percent(own)} → ${percent(cut)}): part of the balloon takes another shape once cut. ` +
    `The panes show it as cut.${finerHelps}`;
}

export class Panels {
  // app: the App (the design, its target's scale, the status line, "Show where"); patterns: the PatternSession
  // that inflates and shows a pattern.
  constructor(app, patterns) {
    this.app = app;
    this.client = app.client;
    this.store = app.store;
    this.panes = app.panes;
    this.messages = app.messages;
    this.el = app.el;
    this.patterns = patterns;
  }

  // A stored result of the design just opened (a gallery design's, made at build time by this pipeline):
  // its optimized panels and their inflated shape, shown at once. The live optimization then runs as usual
  // but shows none of its iterates, worse than the stored result until the last; its result replaces it.
  async showStored(stored) {
    this.store.setResult('stored', true);
    const status = () => this.storedShown() && this.app.setStatus(`${STORED_STATUS}…`);
    const result = await this.patterns.open('the stored optimized panels', stored.patternText, { status });
    if (result) await this.measureDistance(result);
  }

  // True while the stored result belongs to the current design and resolution: no edit since it was shown.
  storedShown() {
    return Boolean(this.store.result('stored'));
  }

  // What the panels are made from changed (a new revision): the panels and inflation under way are for the
  // design before, and "before optimization" waits for this design's own panels.
  designChanged() {
    this.stop();
    this.el.compareGroup.hidden = true;
  }

  // Stops making and inflating panels; true when something was under way.
  stop() {
    const running = this.client.running('panels') || this.client.running('inflation');
    this.client.supersede('panels');
    this.client.supersede('inflation');
    return running;
  }

  // The results on screen leave: the panes, their figures, the optimized panels (the classroom walk, done).
  clear() {
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

  // The panels of the current seams: flattened (shown at once in the pattern pane), then optimized in the
  // worker so their inflated shape matches the target (paper Sec. 5), then inflated for the panes. A newer
  // edit supersedes this one (commitDesign cancels it). Panels made before for the same seams and physics (undo,
  // redo, a compared layout put back) are the store's kept result, shown without optimizing again.
  async make() {
    this.markOutdated(false);
    this.messages.resolve('distance.cut-panels');
    this.messages.resolve('panels.made-despite', { prefix: true });
    const revision = this.app.revision;
    const key = this.store.madeKey();
    this.client.supersede('inflation');
    const kept = this.store.keptResult(key);
    if (kept) {
      this.client.supersede('panels');
      this.store.working('panels', +1); // until shown with its distance, as a result just made
      try {
        return await this.showMade(kept, revision);
      } finally {
        this.store.working('panels', -1);
      }
    }
    const call = this.client.latest(
      'panels',
      Op.optimizeDesign,
      { ...optimizeArgs(this.app.design, this.app.resolution), scale: this.app.scaleFor(this.app.design), up: upOf(this.app.design), gusseted: hasGusset(this.app.design) },
      {
        onProgress: (p) => {
          // The target's side from the stream, measured whole (on a fine target, which the record samples during a
          // run, at most a second before: TargetSession::optimizedDistance).
          const step = p.iteration !== undefined && p.stage === 'optimizing'
            ? `step ${p.iteration}${p.distanceRms !== undefined ? `, distance ${formatDistance({ rms: p.distanceRms, targetRms: p.distance?.targetRms ?? p.targetDistanceRms })}` : ''}${p.slidingSeams ? ', light seams sliding' : ''}`
            : null;
          if (this.storedShown()) return this.app.setStatus(`${STORED_STATUS}: ${step ?? p.stage}…`);
          if (p.flattenedText) this.panes.pattern.setPattern(patternForDisplay(p.flattenedText, 'the panels'));
          if (p.warnings) this.showMadeDespite(p.warnings);
          this.showIterate(p);
          this.app.setStatus(step ? `Optimizing the panels: ${step}…` : `Making the panels: ${p.stage}…`);
        },
      },
    );
    this.store.working('panels', +1);
    try {
      const result = await call.promise;
      if (revision === this.app.revision) this.store.keepResult(key, result);
      await this.showMade(result, revision);
    } catch (error) {
      if (error.code === ErrorCode.cancelled || error.code === ErrorCode.crashed || revision !== this.app.revision) return;
      this.showFailure(error);
      this.app.setStatus('');
    } finally {
      this.store.working('panels', -1);
    }
  }

  // The optimized panels of the design at `revision`: the store's result, inflated and shown, with how the
  // optimizer ended.
  async showMade(result, revision) {
    this.store.setResult('optimized', result, revision);
    this.store.dropResult('stored'); // replaced by the live result
    this.messages.resolve('pattern', { prefix: true });
    this.showMadeDespite(result.warnings ?? []);
    const shown = await this.showVersion('optimized');
    if (shown && revision === this.app.revision) {
      this.app.setStatus(`Inflated the optimized panels: ${optimizerEnd(result.status)}`);
      // The outlines' narrow share is measured only where there is a note to add it to.
      const shape = this.panes.pattern.pattern;
      const note = cutPanelsNote(result.status) && cutPanelsNote(result.status, {
        narrowShare: shape ? narrowOutlineShare(shape) : 0,
        finer: this.finerResolution(),
      });
      if (note) this.messages.show('notice', note, [], { cause: 'distance.cut-panels' });
    }
  }

  // The Panels menu's next setting finer than the current resolution, by its name; null at the finest.
  finerResolution() {
    const option = [...(this.el.resolutionSelect?.options ?? [])].find((o) => Number(o.value) > this.app.resolution);
    return option ? option.textContent.trim() : null;
  }

  // The panels shown were made from seams that have changed and now make none (SeamEditor.segment): they stay in
  // view, dimmed and marked, the status says so, and what was said about their shape goes, until new panels.
  markOutdated(outdated) {
    const shown = Boolean(this.panes.inflated.shape || this.panes.pattern.pattern);
    for (const pane of [this.panes.inflated, this.panes.pattern]) pane.element.closest('.pane')?.toggleAttribute('data-stale', outdated && shown);
    if (!outdated || !shown) return;
    this.messages.resolve('distance.uncovered', { prefix: true });
    this.messages.resolve('panels.made-despite', { prefix: true });
    this.messages.resolve('distance.cut-panels');
    this.app.setStatus('These seams make no panels yet (see the seam panel): the panels shown are from the seams before');
  }

  // What the panels were made despite (the builder's warnings: a segment that folds when laid flat, a seam with no
  // panel across it), each its own message with "Show where", the first leading the stack as showFailure's do.
  showMadeDespite(warnings) {
    this.messages.resolve('panels.made-despite', { prefix: true });
    warnings.slice(0, 3).reverse().forEach((w, i) => {
      const locate = w.location ? () => this.app.showPlace(w.location) : null;
      this.messages.show('warning', w.message, [], { cause: `panels.made-despite.${i}`, locate });
    });
  }

  // Panels that could not be made: each problem the builder placed is its own message, with "Show where"; memory
  // messages say what to do on their own; others are about the seams.
  showFailure(error) {
    this.messages.resolve('pattern', { prefix: true });
    const placed = (error.details?.problems ?? []).filter((p) => p.location);
    if (error.code === 'pattern.not-built' && placed.length) {
      placed.slice(0, 3).reverse().forEach((p, i) => { // the first problem in last, to lead the stack
        this.messages.show('error', `The panels could not be made from these seams: ${p.message}`, [], { cause: `pattern.${i}`, locate: () => this.app.showPlace(p.location) });
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
    return this.client.call(Op.distanceToTarget, { positions, triangles, outer, scale: this.app.scaleFor(this.app.design), up: upOf(this.app.design), gusseted: hasGusset(this.app.design) }).promise;
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
      this.messages.show('warning', r.message, [], { cause: `distance.uncovered.${i}`, locate: () => this.app.showPlace(r.position, { radius: r.radius, colors: 'distance' }) });
    }
  }

  // After a change of the physics (resolution, material, pressure): new panels when the seams give some.
  remake() {
    if (this.app.seams.segmentation?.segments?.every((s) => s.isDisk) && this.app.design.seams.length) this.make();
  }

  // The cut lines (with the seam allowance) and the pattern's figures, from the solver's exporter.
  async refreshCutLines(display = this.store.shown.pattern, text = this.store.shown.patternText) {
    if (!text) return;
    const f = this.app.design.fabrication;
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
      this.app.allowancePanel?.setSeams(result.statistics);
      renderStats(this.el.patternStats, patternStatRows(result.statistics, f.units));
    } catch (error) {
      if (error.code === ErrorCode.cancelled || error.code === ErrorCode.crashed) return;
      this.store.show({ cut: null });
      renderStats(this.el.patternStats, []);
      // A piece wider than the sheet: the width that fits every piece, in one click.
      const fits = error.code === 'export.sheet-too-narrow' && error.details?.sheet_width <= MAX_SHEET && error.details.sheet_width;
      const action = fits ? { label: `Use a ${formatMillimeters(fits, f.units)} sheet`, run: () => this.app.setFabrication({ sheet_width: fits }) } : null;
      this.messages.show('warning', `The cut outline could not be drawn: ${error.message}`, [], { cause: 'cut-lines', action });
      if (fits) await this.figuresOnSheet(text, fits);
    }
  }

  // The pattern's figures where its pieces do not fit the designer's sheet: laid out on the width that fits them, the
  // sheet's row saying what it needs (its panels, material and seams do not depend on the sheet).
  async figuresOnSheet(text, width) {
    const f = this.app.design.fabrication;
    try {
      const result = await this.client.latest('cut-lines', Op.exportPattern, {
        patternText: text,
        options: exportOptions(f, { sheet_width: width }),
      }).promise;
      const rows = patternStatRows(result.statistics, f.units).map(([name, value]) =>
        name === 'Sheet' ? [name, `needs ${formatMillimeters(width, f.units)}; this one is ${formatMillimeters(f.sheet_width, f.units)}`] : [name, value]);
      renderStats(this.el.patternStats, rows);
    } catch {
      // cancelled by a newer request, or the worker restarted: the figures stay empty until the next result
    }
  }

  // Valves on seams this pattern does not have (the seams were redrawn): said once, with a way to drop them.
  noteUnplacedValves(valves = []) {
    const lost = valves.map((v, index) => ({ ...v, index })).filter((v) => !v.placed);
    if (!lost.length) return this.messages.resolve('valves');
    const names = lost.map((v) => v.label).join(', ');
    const text = `${lost.length === 1 ? 'A fill valve is' : `${lost.length} fill valves are`} on ${names}, which this pattern does not have (the seams were redrawn), so ${lost.length === 1 ? 'it is' : 'they are'} not in the cut files. Open Seams to place ${lost.length === 1 ? 'it' : 'them'} again.`;
    const action = { label: lost.length === 1 ? 'Remove it' : 'Remove them', run: () => this.app.removeValves(lost.map((v) => v.index)) };
    this.messages.show('warning', text, [], { cause: 'valves', action });
  }
}
