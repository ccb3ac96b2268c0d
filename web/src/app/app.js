// The design document's controller: every edit, with its checks, goes through here into the store (store.js:
// undo history, revision); it opens targets, design files and links, shares and autosaves. The panels made from
// the design are Panels' (panels.js), the seams the SeamEditor's (seam-editor.js), the fields on the page
// DesignFields' (views/design-fields.js).
import { Op, ErrorCode } from '../worker/protocol.js';
import { findExample } from './examples.js';
import { newDesign, parseDesign, clampHeight, designForFile } from './design.js';
import { autosave, tabRecordKey } from './autosave.js';
import { Store } from './store.js';
import { encodeDesign, decodeDesign, linkNotice } from './share.js';
import { awaitTarget } from './shared-link.js';
import { PatternSession } from './pattern-session.js';
import { Panels } from './panels.js';
import { resultKey, hashBytes } from './stored-result.js';
import { SeamEditor } from './seam-editor.js';
import { setHeight, setUp, setMaterial, setPressure, setFabrication, setSeamAllowance, addValve, setValveWidth, removeValve } from './commands.js';
import { upOf, heightScale, withGuessedUp } from './up-axis.js';
import { standUp } from '../views/up-frame.js';
import { DesignFields } from '../views/design-fields.js';
import { MAX_ALLOWANCE, MIN_SHEET, MAX_SHEET, MAX_VALVE_WIDTH, DEFAULT_VALVE_WIDTH, fabricationWithJoining, GRAIN_FIELDS, seamLabel } from './fabrication.js';
import { download } from './download.js';
import { MIN_PRESSURE, MAX_PRESSURE, presetMaterial, isPresetMaterial, formatPressure } from './materials.js';

// What a typed value must be, by the field's message cause, and what the designer is told otherwise (the
// ranges are the design reader's: design.js, fabrication.js, materials.js).
const TYPED_RULES = {
  height: { above: 0, message: () => 'The height must be a positive number of meters.' },
  pressure: { min: MIN_PRESSURE, max: MAX_PRESSURE, message: () => `The pressure must be between ${formatPressure(MIN_PRESSURE)} and ${formatPressure(MAX_PRESSURE)}.` },
  'fabrication.allowance': { min: 0, max: MAX_ALLOWANCE, message: () => `The seam allowance must be between 0 and ${MAX_ALLOWANCE} mm.` },
  'fabrication.sheet_width': { min: MIN_SHEET, max: MAX_SHEET, message: () => `The sheet width must be between ${MIN_SHEET} and ${MAX_SHEET} mm.` },
  'fabrication.free_edge_allowance': { min: 0, max: MAX_ALLOWANCE, message: () => `The allowance of free edges must be between 0 and ${MAX_ALLOWANCE} mm.` },
  'fabrication.valve': { above: 0, max: MAX_VALVE_WIDTH, message: () => `A fill valve's gap must be wider than 0 and at most ${MAX_VALVE_WIDTH} mm.` },
  'seam-allowance': { min: 0, max: MAX_ALLOWANCE, message: (id) => `The allowance of seam ${seamLabel(id)} must be between 0 and ${MAX_ALLOWANCE} mm.` },
};

const AUTOSAVE_KEY = 'current';
const TAB_RECORD_DAYS = 30; // per-tab records older than this are deleted

export class App {
  // elements: the page's status line, figures and version buttons; fields: the design's fields (DesignFields).
  constructor({ client, panes, messages, elements, fields, baseUrl }) {
    this.client = client;
    this.panes = panes;
    this.messages = messages;
    this.el = elements;
    this.fields = new DesignFields(fields);
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
    this.panels = new Panels(this, this.patterns);
    this.patterns.onPatternShown = (display, text) => this.panels.refreshCutLines(display, text);
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
    this.fields.example = id;
    let bytes;
    try {
      const response = await fetch(new URL(`examples/${example.file}`, this.baseUrl));
      if (!response.ok) throw new Error(`HTTP ${response.status}`);
      bytes = await response.arrayBuffer();
    } catch {
      // Offline before the examples were cached, or the site is missing the file.
      this.fields.example = this.design.target.example ?? '';
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
    this.fields.example = '';
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
      const inlineName = `${file.name.replace(/(\.billow)?\.json$/i, '')}.obj`;
      const { design, warnings, targetKnown, targetObj } = parseDesign(JSON.parse(text), { inlineName });
      if (!targetKnown)
        return this.messages.show('error', `"${file.name}" names no target Billow can open (an example, or a mesh file by its name), so its seams have nothing to lie on. Your current design is unchanged.`);
      for (const w of warnings) this.messages.show('warning', w);
      if (design.target.example) return this.loadExample(design.target.example, design);
      if (targetObj) {
        // The mesh comes with the design (the command line's inline target): it is opened as the designer's own file.
        this.fields.example = '';
        return this.loadTargetBytes(design.target.file, new TextEncoder().encode(targetObj).buffer, design, { quiet: true });
      }
      if (this.target && design.target.file === this.target.fileName) {
        this.commitDesign(design, { reset: true });
        if (this.thinHandlesLeft(design)) return this.cutThinHandles(); // the design's seams lie on the cut target
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
    const interrupted = this.panels.stop();
    // A copy stays here: an open mesh refused can be opened again with its holes closed (the bytes go to the worker).
    const kept = bytes.slice(0);
    try {
      const { cutThinHandles, closeHoles } = design?.target ?? {};
      const result = await this.track(`Opening ${fileName}…`, () =>
        this.client.latest('target', Op.loadTarget, { fileName, bytes, cutThinHandles, closeHoles }, {
          transfer: [bytes],
          onProgress: (p) => this.setStatus(`Opening ${fileName}: ${p.stage}…`),
        }).promise,
      );
      this.client.remember(Op.setTarget, { positions: result.positions, indices: result.indices });
      const opened = design;
      if (this.awaited) design = this.awaited.attach(fileName, result, design); // the linked design, if this file is its mesh
      // A designer's own file may be Z up (CAD, 3D printing): the guess goes into its new design (up-axis.js).
      const guess = !quiet && design === opened ? withGuessedUp(design, result.report, fileName) : { design, notice: null };
      design = guess.design;
      this.installTarget(fileName, result, design, stored);
      if (!stored) this.setStatus('Ready');
      // What the mesh report says belongs to this target: it goes with it (and the genus warning once seams cut
      // the handles open: SeamEditor.segment).
      this.messages.resolve('target.', { prefix: true });
      if (guess.notice) this.messages.show('notice', guess.notice, [], { cause: 'target.up' });
      this.showTargetIssues(result.report, { quiet });
      const closed = result.report.holesClosed ?? 0;
      if (closed)
        this.messages.show('notice', `Closed ${closed === 1 ? 'its hole' : `its ${closed} holes`} with ${closed === 1 ? 'a cap' : 'caps'} drawn across ${closed === 1 ? 'the rim' : 'their rims'}, as a base panel closes a statue; the design keeps ${closed === 1 ? 'it' : 'them'} closed.`, [], { cause: 'target.holes-closed' });
      if (this.thinHandlesLeft(design)) await this.cutThinHandles(); // a linked design whose mesh came as this file
    } catch (error) {
      if (error.code === ErrorCode.cancelled) return; // a newer load won
      const report = error.details?.report;
      const items = report ? report.issues.filter((i) => i.severity === 'error').map((i) => i.message) : [];
      // The reader's messages say what is wrong and where (a line, a byte); the file they mean is named here, once.
      const named = error.message.includes(`"${fileName}"`) || error.message.includes(`'${fileName}'`);
      const text = report
        ? `"${fileName}" cannot be used as a target. Your current design is unchanged.`
        : `${named ? '' : `"${fileName}" cannot be opened. `}${error.message}${this.target ? ' Your current design is unchanged.' : ''}`;
      // An open mesh whose holes are all it lacks: offered closed, as a new design that keeps them closed.
      const holes = report?.stats.holes ?? 0;
      const action = error.details?.closable && design
        ? { label: holes === 1 ? 'Close the hole' : `Close the ${holes} holes`, run: () => this.reopenClosed(fileName, kept, design, quiet) }
        : null;
      this.messages.show('error', text, items, { action });
      // The design on screen stays, and so do its example's name and the status (no "Opening…" left behind).
      this.fields.example = this.design.target.example ?? '';
      this.setStatus(this.target ? 'Ready' : '');
      if (interrupted) this.panels.remake(); // the design stays: so do its panels
    }
  }

  // The refused file opened again with its holes closed, as the designer's own file (no example chosen).
  reopenClosed(fileName, bytes, design, quiet) {
    if (!design.target.example) this.fields.example = '';
    return this.loadTargetBytes(fileName, bytes, { ...design, target: { ...design.target, closeHoles: true } }, { quiet });
  }

  // What the mesh report says of the target (its notices unless quiet). A shape with thin handles is offered to have
  // them cut through (the genus warning's action): each would need a seam around a tube no panel can follow.
  showTargetIssues(report, { quiet = false } = {}) {
    for (const issue of report.issues.filter((i) => i.severity !== 'error')) {
      if (quiet && issue.severity === 'notice') continue;
      const thin = issue.code === 'mesh.genus' ? report.thinHandles ?? [] : [];
      if (!thin.length) {
        this.messages.show(issue.severity, issue.message, [], { cause: `target.${issue.code}` });
        continue;
      }
      const scale = this.scaleFor(this.design);
      const [lo, hi] = [report.stats.bbox_min, report.stats.bbox_max];
      const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
      const cm = (units) => {
        const value = units * scale * 100;
        return `${value < 10 ? Math.max(0.1, Math.round(value * 10) / 10) : Math.round(value)} cm`;
      };
      const share = (units) => `${Math.max(1, Math.round((100 * units) / diagonal))} %`;
      const around = thin.length > 1 ? `${cm(thin[0])} to ${cm(thin.at(-1))} around, ${share(thin[0])} to ${share(thin.at(-1))}` : `${cm(thin[0])} around, ${share(thin[0])}`;
      const which = thin.length === report.stats.genus ? (thin.length > 1 ? `All ${thin.length} are` : 'It is') : `${thin.length} of them ${thin.length > 1 ? 'are' : 'is'}`;
      const them = thin.length > 1 ? 'them' : 'it';
      const text = `${issue.message} ${which} thin (${around} of the shape's size, as a boot's lace loops or a chain's links): a seam around ${thin.length > 1 ? 'each' : 'it'} would make a sleeve only a few of the panels' edges around. Cutting through ${them} closes the ends and leaves the rest of the shape as it is.`;
      this.messages.show(issue.severity, text, [], {
        cause: `target.${issue.code}`,
        action: { label: thin.length > 1 ? `Cut the ${thin.length} thin handles` : 'Cut the thin handle', run: () => this.cutThinHandles() },
      });
    }
  }

  // Whether the design has its thin handles cut while the target on screen still has them.
  thinHandlesLeft(design) {
    return Boolean(design.target.cutThinHandles && this.target?.report.thinHandles?.length);
  }

  // The target's thin handles cut through (suggest/thin_handles.hpp) and the design marked so, in one undo step, its
  // seams kept: every face of the target keeps its index. Its panels are made again.
  async cutThinHandles() {
    if (!this.target || this.design.target.example || this.target.uncut) return;
    const interrupted = this.panels.stop();
    try {
      const result = await this.setTargetCut(true);
      if (!this.design.target.cutThinHandles) this.commitDesign({ ...this.design, target: { ...this.design.target, cutThinHandles: true } });
      this.seams.refresh();
      const n = result.report.thinHandlesCut ?? 0;
      this.messages.show('notice', `Cut through ${n} thin handle${n === 1 ? '' : 's'} and closed ${n === 1 ? 'its' : 'their'} ends; the design keeps ${n === 1 ? 'it' : 'them'} cut (undo, or open the mesh file again, to have ${n === 1 ? 'it' : 'them'} back).`, [], { cause: 'target.thin-handles' });
    } catch (error) {
      if (error.code === ErrorCode.cancelled) return;
      this.messages.show('error', `The thin handles could not be cut: ${error.message} Your design is unchanged.`);
      this.setStatus('Ready');
      if (interrupted) this.panels.remake();
    }
  }

  // Undo or redo crossed the cut of the thin handles: the target follows the design (the seams of either lie on both,
  // every face keeping its index), then the seams are traced on it again.
  async followThinHandleCut() {
    const cut = Boolean(this.design.target.cutThinHandles);
    try {
      await this.setTargetCut(cut);
      this.save(); // the autosave's mesh is the target on screen
    } catch (error) {
      if (error.code === ErrorCode.cancelled) return;
      this.messages.show('error', `The thin handles could not be ${cut ? 'cut' : 'put back'}: ${error.message}`);
      this.setStatus('Ready');
    }
    this.seams.refresh();
    this.panels.refreshCutLines();
  }

  // Whether the target on screen is cut other than the design says: only across the cut's undo step, since a target
  // opened with the design's flag is cut as it opens (and its history starts there).
  thinHandleCutToFollow() {
    if (!this.target || this.design.target.example) return false;
    return this.design.target.cutThinHandles ? !this.target.uncut && this.thinHandlesLeft(this.design) : Boolean(this.target.uncut);
  }

  // The target with its thin handles cut, or as it was opened (kept on the cut one as `uncut`), in the worker and on
  // screen; the design is left to the caller. Returns the worker's result.
  async setTargetCut(cut) {
    const uncut = this.target.uncut ?? this.target;
    const stage = cut ? 'Cutting through the thin handles' : 'Putting the thin handles back';
    const result = await this.track(`${stage}…`, () =>
      this.client.latest('target', Op.setTarget, { positions: uncut.positions, indices: uncut.indices, cutThinHandles: cut }, {
        onProgress: (p) => this.setStatus(`${stage}: ${p.stage}…`),
      }).promise,
    );
    this.client.remember(Op.setTarget, { positions: result.positions, indices: result.indices });
    this.placeTarget(uncut.fileName, result, this.design);
    if (cut) this.target.uncut = uncut;
    this.showDesign(); // the target's figures
    this.setStatus('Ready');
    this.messages.resolve('target.', { prefix: true });
    this.showTargetIssues(result.report, { quiet: true });
    return result;
  }

  async installSavedMesh(design, mesh) {
    this.fields.example = '';
    const result = await this.client.request(Op.setTarget, { ...mesh, cutThinHandles: design.target.cutThinHandles });
    this.client.remember(Op.setTarget, { positions: result.positions, indices: result.indices });
    this.installTarget(design.target.file, result, design);
    this.setStatus('Ready');
  }

  installTarget(fileName, result, design, stored = null) {
    this.placeTarget(fileName, result, design);
    this.commitDesign(design, { reset: true });
    // The seams (and so the live optimization) after the stored result: its inflation and cut lines are then
    // queued in the worker first, not held back until the optimization is done.
    if (stored) this.panels.showStored(stored).finally(() => this.seams.refresh());
    else this.seams.refresh();
  }

  // The worker's target (result: { positions, indices, report }) on screen, its seams and panels to be made again.
  placeTarget(fileName, result, design) {
    this.target = { fileName, positions: result.positions, indices: result.indices, report: result.report };
    this.store.targetKey = `${hashBytes(result.positions)}${hashBytes(result.indices)}`;
    this.panes.target.setTarget(this.target, this.scaleFor(design), findExample(design.target.example)?.front);
    this.seams.reset();
    this.panels.markOutdated(false);
  }

  // Mesh files carry no units: the design's height (m) along the target's up axis fixes the scale of its units.
  scaleFor(design) {
    return heightScale(design, this.target?.report.stats);
  }

  // Every change of the design goes through here: history, views, autosave.
  commitDesign(design, { reset = false, mergeKey = null, gesture = false } = {}) {
    // Panels being made for the previous design are stale now, unless the edit left all they are made from
    // as it was (the mirror plane): those panels and any stored result still belong to the design.
    if (this.store.commit(design, { reset, mergeKey, gesture })) this.panels.designChanged();
    this.showDesign();
    this.save();
  }

  // The designer's design set aside while another is shown (the classroom walk's example): its undo history,
  // target and opened pattern; their autosave is left as it is until takeBack.
  setAside() {
    this.autosavePaused = true;
    const history = this.store.swapHistory();
    const optimized = this.store.result('optimized');
    const own = optimized && [optimized.patternText, optimized.flattenedText].includes(this.store.shown.patternText);
    return { history, target: this.target, exampleValue: this.fields.example, openedPattern: own ? null : this.store.shown.patternText };
  }

  // The design set aside comes back with its undo steps; its panels are made again from its seams, a pattern
  // the designer had opened is opened again. False when its target could not be installed again.
  async takeBack(aside) {
    this.panels.stop();
    this.panels.clear();
    const design = aside.history.present;
    if (design.target.example) await this.loadExample(design.target.example, design);
    else await this.installSavedMesh(design, { positions: aside.target.positions, indices: aside.target.indices }).catch(() => {});
    if (this.design !== design) return false;
    this.store.swapHistory(aside.history);
    this.fields.example = aside.exampleValue;
    this.showDesign();
    this.autosavePaused = false;
    if (aside.openedPattern) await this.patterns.open('the pattern', aside.openedPattern);
    return true;
  }

  // Turns the target and inflated panes towards a place on the target (its own units) and marks it there.
  showPlace(position, { radius = 0, colors = null } = {}) {
    this.panes.target.showPlace(position, radius);
    if (colors) this.setColorMode?.(colors);
    if (colors === 'distance') this.panes.inflated.frameWithUncovered();
  }

  setResolution(triangles) {
    this.store.setResolution(triangles);
    this.panels.designChanged();
    this.panels.remake();
  }

  // Sewn or heat sealed ('sewn' | 'sealed'): an allowance left at its joining's default follows.
  setJoining(joining) {
    this.applyFabrication({ ...this.design, fabrication: fabricationWithJoining(this.design.fabrication, joining) }, 'fabrication-joining');
  }

  // A fill valve on seam `seam` (exporter id) centred at share `at` of its length.
  addValve(seam, at) {
    this.applyFabrication(addValve(this.design, { seam, at: Math.min(1, Math.max(0, at)), width: DEFAULT_VALVE_WIDTH }), null);
  }

  // A typed value against its rule (TYPED_RULES): outside it the designer is told why and the fields show the
  // design's values again (false); within it an earlier warning about the field goes (true).
  accepts(field, value, subject) {
    const rule = TYPED_RULES[field];
    const ok = Number.isFinite(value) && !(value <= rule.above) && !(value < rule.min) && !(value > rule.max);
    if (ok) {
      this.messages.resolve(field);
      return true;
    }
    this.messages.show('warning', rule.message(subject), [], { cause: field });
    this.showDesign();
    return false;
  }

  setValveWidth(index, mm) {
    if (!this.accepts('fabrication.valve', mm)) return;
    this.applyFabrication(setValveWidth(this.design, index, mm), `valve-width-${index}`);
  }

  removeValves(indices) {
    let next = this.design;
    for (const index of [...indices].sort((a, b) => b - a)) next = removeValve(next, index);
    this.applyFabrication(next, null);
  }

  // Fabrication settings change the cut files only, never the panels: no new optimization.
  setFabrication(changes) {
    for (const key of ['allowance', 'sheet_width', 'free_edge_allowance'])
      if (changes[key] !== undefined && !this.accepts(`fabrication.${key}`, changes[key])) return;
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
    this.panels.refreshCutLines();
  }

  // One seam's own allowance [mm] (id as in the exporter's statistics; labelled S<id + 1>), or null for the
  // seam allowance; 0 for a heat-sealed seam.
  setSeamAllowance(id, mm) {
    if (mm !== null && !this.accepts('seam-allowance', mm, id)) return;
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

  setMaterialPreset(name) {
    if (name === 'custom' || (isPresetMaterial(this.design.material) && this.design.material.name === name)) return;
    this.commitDesign(setMaterial(this.design, presetMaterial(name)));
    this.panels.remake();
  }

  setPressure(pascals) {
    if (!this.accepts('pressure', pascals)) return;
    if (pascals === this.design.pressure) return;
    this.commitDesign(setPressure(this.design, pascals), { mergeKey: 'pressure' });
    this.panels.remake();
  }

  // A fix-up that belongs to the edit just made: no new undo step.
  amendDesign(design) {
    if (this.store.amend(design)) this.panels.designChanged();
    this.save();
  }

  // The design on the page: its fields, the target pane's scale, both 3D panes standing on its up axis.
  showDesign() {
    const design = this.design;
    const scale = this.scaleFor(design);
    this.fields.render({ design, target: this.target, scale, history: this.store.history });
    this.allowancePanel?.render(design.fabrication);
    this.panes.target.setScale(scale);
    standUp(this.panes, upOf(design)); // the target and its inflated shape stand on the design's up axis
    if (this.panes.inflated.targetScale !== scale || this.panes.inflated.targetOf !== this.target) this.panes.inflated.setTarget(this.target, scale);
  }


  setHeight(meters) {
    if (!this.accepts('height', meters)) return;
    const height = clampHeight(meters);
    if (height === this.design.size.height) return;
    this.commitDesign(setHeight(this.design, height), { mergeKey: 'height' });
    this.panels.remake(); // the panels' size changed: the edit cancelled the running optimization (commitDesign)
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
    if (newRevision) this.panels.designChanged();
    this.seams.selection = null;
    this.showDesign();
    this.save();
    if (this.thinHandleCutToFollow()) return this.followThinHandleCut();
    this.seams.refresh();
    this.panels.refreshCutLines();
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

  // Downloads the design document as a .json file (its seams' points on faces Billow added as 3D points).
  saveDesignFile() {
    download(JSON.stringify(designForFile(this.design, this.target), null, 2), `${this.fileBaseName()}.billow.json`, 'application/json');
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
