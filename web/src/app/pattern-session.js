// Importing a sewn pattern (billow-pattern JSON): the worker inflates it while the inflated pane shows
// each streamed iterate and the pattern pane shows the panels. A new pattern cancels the running one. What is
// shown goes into the store (store.shown: the pattern, its inflated shape).
import { Op, ErrorCode } from '../worker/protocol.js';
import { formatVolume } from './units.js';
import { renderStats } from '../views/stats-list.js';
import { balloonFigures, balloonRows, peakStress } from './fabrication.js';
import { findMaterialPreset } from './materials.js';

// Example patterns computed by the solver (wasm/src/simulate/example_patterns.cpp).
export const PATTERN_EXAMPLES = [
  { id: 'mylar', name: 'Mylar balloon (two discs)' },
  { id: 'pillow', name: 'Pillow (two squares)' },
  { id: 'sphere3', name: 'Sphere (three gores)' },
];

const UNIT_SCALE = { m: 1, cm: 0.01, mm: 0.001 };

// The panels in meters, for display. Throws Error with a designer-facing message for a non-pattern.
export function patternForDisplay(text, fileName) {
  let value;
  try {
    value = JSON.parse(text);
  } catch {
    throw new Error(`"${fileName}" is not a valid JSON file.`);
  }
  if (value?.format !== 'billow-pattern') throw new Error(`"${fileName}" is not a Billow pattern (its "format" is not "billow-pattern").`);
  const scale = UNIT_SCALE[value.units ?? 'm'];
  if (!scale) throw new Error(`"${fileName}" uses the unknown unit "${value.units}"; use m, cm or mm.`);
  if (!Array.isArray(value.panels)) throw new Error(`"${fileName}" has no panels.`);
  return {
    ...value,
    panels: value.panels.map((p) => ({ ...p, vertices: p.vertices.map(([x, y]) => [x * scale, y * scale]) })),
  };
}

// Many warnings of one kind become one line: unequal sewn edges are reported by count and the largest.
export function summarizeWarnings(warnings) {
  const seams = warnings.filter((w) => w.code === 'pattern.seam-length');
  const others = warnings.filter((w) => w.code !== 'pattern.seam-length').map((w) => w.message);
  if (seams.length === 1) others.unshift(seams[0].message);
  else if (seams.length > 1) {
    const worst = Math.max(...seams.map((w) => w.mismatch ?? 0));
    others.unshift(
      `${seams.length}${seams.length >= 100 ? ' or more' : ''} sewn edges join boundaries of different lengths (up to ${(100 * worst).toFixed(1)} %): those seams would pucker when sewn.`,
    );
  }
  return others;
}

// The internal panels' share of triangles in tension (taut or wrinkled) at equilibrium, in panel order:
// [{ name, tense }]. A panel that hangs slack carries nothing: pressure does not pull on it, so it does not
// shape the balloon (an internal panel works when it joins seams that pressure pushes apart). The
// simulation's triangles are the panels' triangles in panel order.
export function internalPanelTension(pattern, result) {
  const panels = pattern?.panels ?? [];
  const regime = result?.regime;
  const total = panels.reduce((n, p) => n + (p.triangles?.length ?? 0), 0);
  if (!regime || regime.length !== total) return [];
  const out = [];
  let t = 0;
  for (const p of panels) {
    const n = p.triangles.length;
    if (p.internal && n > 0) {
      let tense = 0;
      for (let k = t; k < t + n; ++k) tense += regime[k] !== 0;
      out.push({ name: p.name, tense: tense / n });
    }
    t += n;
  }
  return out;
}

// The figures row for them: "in tension" or "mostly slack: not shaping" (the least tense panel).
export function internalPanelRow(pattern, result) {
  const panels = internalPanelTension(pattern, result);
  if (!panels.length) return null;
  const least = Math.min(...panels.map((p) => p.tense));
  const label = panels.length === 1 ? 'Internal panel' : 'Internal panels';
  if (least < 0.5) return [label, `mostly slack (${Math.round(100 * (1 - least))} %): not shaping`];
  return [label, `in tension (${Math.round(100 * least)} %)`];
}

export class PatternSession {
  constructor({ client, store, panes, messages, status, stats }) {
    this.client = client;
    this.store = store;
    this.panes = panes;
    this.messages = messages;
    this.status = status; // (text) => void
    this.stats = stats; // element for the inflated shape's figures
    this.onPatternShown = null; // (display, text) => void
  }

  async openExample(name, triangles = 3000) {
    const { patternText } = await this.client.request(Op.examplePattern, { name, triangles });
    return this.open(`${name} pattern`, patternText);
  }

  // status: what reports the inflation's progress (a stored result's says so instead; see Panels.showStored).
  async open(fileName, text, { status = this.status } = {}) {
    let display;
    try {
      display = patternForDisplay(text, fileName);
    } catch (error) {
      this.messages.show('error', error.message);
      return null;
    }
    const started = performance.now();
    let shown = false;
    const call = this.client.latest('inflation', Op.inflatePattern, { patternText: text }, {
      onProgress: (p) => {
        if (p.triangles) {
          this.panes.pattern.setPattern(display);
          this.store.show({ patternText: text, pattern: display });
          this.onPatternShown?.(display, text);
          this.panes.inflated.setResult({ positions: p.positions, triangles: p.triangles, outer: p.outer });
          shown = true;
          for (const text of summarizeWarnings(p.warnings ?? [])) this.messages.show('warning', text);
        } else if (p.positions && shown) {
          this.panes.inflated.updatePositions(p.positions);
        }
        status(p.iteration !== undefined ? `Inflating ${fileName}: step ${p.iteration}…` : `Inflating ${fileName}: ${p.stage}…`);
      },
    });
    this.store.working('inflation', +1);
    try {
      const result = await call.promise;
      this.panes.inflated.setStrength(findMaterialPreset(display.material?.name)?.strength ?? null);
      this.panes.inflated.setResult(result, { frame: !shown });
      this.store.show({ inflated: result });
      const seconds = ((performance.now() - started) / 1000).toFixed(1);
      // Optimized panels arrive in balance already: no steps to report then.
      status(result.iterations ? `Inflated ${fileName} in ${seconds} s (${result.iterations} steps)` : `Inflated ${fileName}: in balance under pressure`);
      this.renderStats(result, display);
      return result;
    } catch (error) {
      if (error.code === ErrorCode.cancelled) return null;
      const last = this.store.shown.inflated; // the last good result
      this.messages.show('error', `The pattern "${fileName}" could not be inflated: ${error.message}`);
      status(last ? 'The last good result is shown.' : '');
      if (last) this.panes.inflated.setResult(last, { frame: false });
      return null;
    } finally {
      this.store.working('inflation', -1);
    }
  }

  // While new panels are optimized the inflated pane streams their iterates, and these figures are still the
  // last inflated result's: dimmed, and they say so, until the next result replaces them.
  markStatsStale() {
    if (!this.stats.firstChild) return;
    this.stats.classList.add('stale');
    this.stats.title = 'The figures of the last inflated result: the panels are being optimized';
  }

  renderStats(result, pattern) {
    this.stats.classList.remove('stale');
    this.stats.removeAttribute('title');
    const peak = peakStress(result);
    const rows = [
      ['Volume', formatVolume(result.volume)],
      ['Pressure', `${(result.pressure / 1000).toFixed(2)} kPa`],
      ['Max wrinkling', `${(100 * result.maxCompression).toFixed(1)} %`],
      // The stress the most stressed 1 % of the surface reaches; the single highest triangle beside it.
      ['Peak stress', `${(peak / 1e6).toFixed(1)} MPa${result.maxStress > 1.5 * peak ? ` (${(result.maxStress / 1e6).toFixed(0)} MPa at one spot)` : ''}`],
      // The steps of this inflation, not the optimizer's: optimized panels arrive in balance and take none.
      ['Inflation steps', result.iterations ? String(result.iterations) : 'none: the optimized shape is in balance'],
    ];
    const internal = internalPanelRow(pattern, result);
    if (internal) rows.push(internal);
    if (pattern?.material) rows.push(...balloonRows(balloonFigures(pattern, result.volume, peak)));
    renderStats(this.stats, rows);
  }
}
