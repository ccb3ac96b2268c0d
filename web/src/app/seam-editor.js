// Seam editing: keeps the traced curves of the design's seams (derived from the document, cached by
// their control points), previews the seam being drawn, applies seam commands through the App's
// history, and asks the worker for the segmentation after each committed edit. Each redraw is a 'seams'
// change of the app's store.
import { Op, ErrorCode } from '../worker/protocol.js';
import * as cmd from './commands.js';
import { upOf } from './up-axis.js';
import { symmetryPlane, mirrorPoint, addMirroredTwin, needsNoTwin, isSelfSymmetric, positionOf } from './symmetry.js';
import { optimizeArgs } from './stored-result.js';
import { sectionSeamPoints } from './section.js';
import { BAND_PARTS, bandLoops, bandSeamPoints } from './band.js';

const keyOf = (seam) => JSON.stringify([seam.points, seam.closed, Boolean(seam.smooth)]);
const PICK_PX = 10;

export class SeamEditor {
  constructor(app) {
    this.app = app;
    this.cache = new Map(); // keyOf(seam) -> trace
    this.pending = new Map(); // keyOf(seam) -> promise
    this.preview = null; // Float32Array of the seam being drawn
    this.draftWarning = null; // { text, location } of what the seam being drawn would make wrong (checkDraft)
    this.draft = null; // the seam being drawn, as its preview was asked for: { points, closed }
    this.selection = null; // { seam, index | null }
    this.segmentation = null;
    this.overlay = null; // curves (Float32Array each) shown dashed over the seams: a suggested layout (suggest.js)
  }

  get design() {
    return this.app.design;
  }

  get pane() {
    return this.app.panes.target;
  }

  get target() {
    return this.app.target;
  }

  // fn() after every redraw of the seams and every new segmentation. Returns the function that unsubscribes.
  onChange(fn) {
    return this.app.store.subscribe((what) => what === 'seams' && fn());
  }

  changed() {
    this.app.store.changed('seams');
  }

  // The traces of the design's seams, aligned with design.seams (null while one is being traced).
  seamTraces() {
    return this.design.seams.map((s) => this.cache.get(keyOf(s)) ?? null);
  }

  async trace(points, closed, smooth) {
    return this.app.client.request(Op.traceSeam, { points, closed, smooth: Boolean(smooth) });
  }

  // Traces every seam that is not cached yet, then redraws and re-segments.
  async refresh({ segment = true } = {}, depth = 0) {
    const seams = this.design.seams;
    const jobs = seams.map((s) => {
      const key = keyOf(s);
      if (this.cache.has(key)) return null;
      if (!this.pending.has(key))
        this.pending.set(key, this.trace(s.points, s.closed, s.smooth).then(
          (t) => this.cache.set(key, t),
          (error) => this.traceFailed(s, error),
        ).finally(() => this.pending.delete(key)));
      return this.pending.get(key);
    });
    await Promise.all(jobs.filter(Boolean));
    this.trimCache();
    // Seam ends attached to a seam that moved follow it (part of the same undo step), then re-trace.
    const attached = cmd.reattachSeamEnds(this.design, this.seamTraces(), (p) => this.positionOf(p));
    if (attached !== this.design && depth < 4) {
      this.app.amendDesign(attached);
      return this.refresh({ segment }, depth + 1);
    }
    this.draw();
    if (segment) await this.segment();
  }

  // The 3D position (target units) of a surface point.
  positionOf(point) {
    return positionOf(this.app.target, point);
  }

  traceFailed(seam, error) {
    if (error.code === ErrorCode.cancelled || error.code === ErrorCode.crashed) return;
    this.app.messages.show('error', `${seam.name ?? 'A seam'} could not be traced on the surface: ${error.message}`);
  }

  trimCache() {
    const live = new Set(this.design.seams.map(keyOf));
    for (const key of this.cache.keys()) if (!live.has(key)) this.cache.delete(key);
  }

  draw() {
    if (!this.pane.seams) return;
    const traces = this.seamTraces();
    const seams = this.design.seams.map((s, i) => ({
      curve: traces[i]?.curve,
      controls: traces[i] ? chunks(traces[i].controls) : [],
      weight: s.weight,
      selected: this.selection?.seam === i,
      selectedPoint: this.selection?.seam === i ? this.selection.index : null,
    }));
    this.pane.seams.update(seams, [this.preview, ...(this.overlay ?? [])], Boolean(this.preview && this.draftWarning));
    this.pane.setDraftWarning(this.preview ? this.draftWarning : null);
    this.pane.setConnections(this.design.connections.map((c) => c.seams.map((k) => traces[k]?.curve ?? null)));
    this.pane.setSymmetryPlane(this.plane);
    this.pane.requestRender();
    this.changed();
  }

  // The dashed curve of the seam being drawn (latest request wins); null clears it. closed: the cursor is on
  // the loop's start, so the seam would close there.
  async previewSeam(points, { closed = false } = {}) {
    const draft = (this.draft = points?.length >= 2 ? { points, closed, smooth: true } : null); // as the new seam will be: smooth
    if (!draft) {
      this.app.client.supersede('seam-preview');
      this.preview = null;
      this.draftWarning = null;
      this.draw();
      return;
    }
    try {
      const t = await this.app.client.latest('seam-preview', Op.traceSeam, draft).promise;
      this.preview = t.curve;
      this.draw();
      this.checkDraft(draft);
    } catch {
      // a preview that fails (e.g. the cursor left the surface) is simply not shown
    }
  }

  // What the seam being drawn would make, before it is committed: a seam that crosses itself, a tiny piece or
  // a strip too thin to sew is shown as such (the preview in red, a note where it happens). One check at a
  // time: the cursor moves faster than the target is cut, so a check starts when the last one is back.
  async checkDraft(draft) {
    this.nextDraft = draft;
    if (this.checkingDraft) return;
    this.checkingDraft = true;
    try {
      while (this.nextDraft) {
        const next = this.nextDraft;
        this.nextDraft = null;
        const seams = [...requestSeams(this.design), next];
        let result = null;
        try {
          result = await this.app.client.request(Op.checkSeams, { seams, up: upOf(this.design) });
        } catch {
          // a check that fails says nothing about the seam: no warning
        }
        if (next !== this.draft) continue; // drawing moved on (or ended) meanwhile
        this.draftWarning = result && draftProblem(result.problems, seams.length - 1, this.segmentation?.problems ?? [], next.closed);
        this.draw();
      }
    } finally {
      this.checkingDraft = false;
    }
  }

  // The mirror plane while symmetry is on (null otherwise).
  get plane() {
    return symmetryPlane(this.design, this.app.target);
  }

  // The twin of seam i that edits of i carry over to, or null (no symmetry, no twin, or out of step).
  twinOf(design, i) {
    const twin = design.seams[i]?.mirror;
    if (twin === undefined || !this.plane) return null;
    return design.seams[twin]?.points.length === design.seams[i].points.length ? twin : null;
  }

  mirrored(design, point) {
    return mirrorPoint(design, this.app.target, this.plane, point);
  }

  // Loops laid in one action (the section tool): lists of positions [[x, y, z]] shown as the seams-to-be; null
  // or an empty list clears them.
  previewLoops(loops) {
    this.draft = null;
    this.app.client.supersede('seam-preview');
    this.preview = loops?.length ? loops.map((positions) => Float32Array.from([...positions, positions[0]].flat())) : null;
    this.draftWarning = null;
    this.draw();
  }

  // Loops laid in one action (section.js: a plane section, a gusset band's two, the outline), each a closed seam
  // of surface paths between its resampled points, in one step of the history; names: the seams' own, if any;
  // `note` says what was done to make them.
  // across: a point near which a seam runs across from the first loop to the second (a gusset band's strip is a
  // tube until a seam opens it), joined to both. band: the band's record without id and part (band.js), kept on
  // its seams so it can be laid again at another width. With the design's symmetry on, each loop gets its mirrored
  // twin (a section through one leg, one through the other), unless `asSeen`: the outline seen from one side is its
  // own front and back, and its mirror image, the outline seen from the other side, would lie over it along the body
  // and cut slivers off where they part (a cow's legs seen from its side).
  commitLoops(loops, { note = null, ...laying } = {}) {
    const next = this.withLoops(loops, laying);
    this.app.commitDesign(next);
    this.selection = { seam: next.seams.length - 1, index: null };
    this.refresh();
    this.noteLaid(note);
  }

  // commitLoops' design, not yet committed.
  withLoops(loops, { names = [], across = null, band = null, asSeen = false } = {}) {
    const target = this.app.target;
    let next = this.design;
    const id = band && cmd.nextBandId(next);
    const record = (part) => band && { ...band, id, part };
    const laid = [];
    // A band's two sides are the first two loops, its seam across comes after them, and any further loops (the holes'
    // rims of a band around an outline) after that.
    const banded = across && loops.length >= 2;
    const { sides, across: ends } = banded ? bandSeamPoints(target, loops.slice(0, 2), across, { width: this.stripWidth(band) }) : { sides: loops.map((loop) => sectionSeamPoints(target, loop, { corners: true })) };
    for (const [k, points] of sides.entries()) {
      next = cmd.addSeam(next, { points, closed: true, smooth: false, name: names[k], band: record(BAND_PARTS[k]) });
      laid.push(next.seams.length - 1);
    }
    if (ends) {
      next = cmd.addSeam(next, { points: ends.map((p, k) => ({ ...p, on: laid[k] })), closed: false, smooth: false, name: names[2], band: record('across') });
      laid.push(next.seams.length - 1);
    }
    for (const [k, loop] of (banded ? loops.slice(2) : []).entries()) {
      next = cmd.addSeam(next, { points: sectionSeamPoints(target, loop, { corners: true }), closed: true, smooth: false, name: names[3 + k] });
      laid.push(next.seams.length - 1);
    }
    if (this.plane && !asSeen) for (const index of laid) next = addMirroredTwin(next, target, this.plane, index);
    return next;
  }

  // Loops laid in one action on a shape with handles, where their parts may not all be panels (the Outline seen past
  // a handle its view does not look through leaves a front that is a ring or holds the handle): committed with the
  // seams that make every part a panel, in the same step of the history (the suggested layouts' rule,
  // Op.openIntoPanels), which the note names. The designer's seams and the first `keep` seams laid (the outline's rim
  // and its holes' rims, which part the front from the back; all of a gusset band's, relaid by their parts) stay as
  // they are; the other loops may be mended (a loop that only grazes the shape left out, one that crosses itself
  // undone), unless mirror twins link seams by their indices. Where even that makes no panels, the loops alone: the
  // parts' messages say what is left.
  async commitLoopsOpened(loops, { note = null, keep = 1, ...laying } = {}) {
    const before = this.design;
    let next = this.withLoops(loops, laying);
    const fixed = this.plane && !laying.asSeen ? next.seams.length : Math.min(next.seams.length, before.seams.length + keep);
    let opening = '';
    const status = this.app.store.status, adding = 'Adding the seams that make every part a panel…';
    this.app.setStatus(adding);
    try {
      const { seams, ...physics } = optimizeArgs(next, this.app.resolution);
      const opened = await this.app.client.request(Op.openIntoPanels, { seams, ...physics, fixed, scale: this.app.scaleFor(next), up: upOf(next) });
      if (opened.ok && opened.description) {
        const named = (seam) => ({ ...seam, name: seam.name ? seam.name[0].toUpperCase() + seam.name.slice(1) : undefined });
        next = { ...next, seams: [...next.seams.slice(0, fixed), ...opened.seams.slice(fixed).map(named)] };
        opening = opened.description;
      }
    } catch {
      // the loops alone: the segmentation says which parts are not panels yet
    } finally {
      if (this.app.store.status === adding) this.app.setStatus(status);
    }
    if (this.design !== before) return this.noteLaid('Nothing was laid: the design changed while the seams were made. Lay them again.', 'warning');
    this.app.commitDesign(next);
    this.selection = { seam: next.seams.length - 1, index: null };
    this.refresh();
    const also = opening && `to make every part a panel: ${opening}`;
    this.noteLaid(note && also ? note.replace(/\.$/, `; ${also}.`) : note ?? (also && `Seams laid ${also}.`));
  }

  // The gusset band seam i belongs to (band.js; its own record, or its mirror twin's), with both its sides still
  // in the design, or null.
  bandOf(i) {
    const seam = this.design.seams[i];
    const band = seam?.band ?? (seam?.mirror !== undefined ? this.design.seams[seam.mirror]?.band : undefined);
    if (!band) return null;
    const members = cmd.bandMembers(this.design, band.id);
    return members['side 1'] !== undefined && members['side 2'] !== undefined ? band : null;
  }

  // The band seam i belongs to, laid again at another width (mm on the cut pattern): both sides where the band
  // was laid from (the same plane's point, or the same view of the outline), the seam across between them, mirror
  // twins after them, in one step of the history. Points the designer had moved are replaced, and told so.
  setBandWidth(i, widthMm) {
    const band = this.bandOf(i);
    if (!band || !(widthMm > 0) || widthMm === band.width_mm) return;
    const target = this.app.target;
    const units = this.unitsPerMillimetre;
    const width = `${+widthMm.toFixed(1)} mm`;
    const laid = bandLoops(target, band, units, widthMm);
    if (laid.problem) return this.noteLaid(`The band was not laid again at ${width}: ${laid.problem}`, 'warning');
    const members = cmd.bandMembers(this.design, band.id);
    const { sides, across } = bandSeamPoints(target, laid.loops, band.origin, { width: this.stripWidth(band, widthMm) });
    const points = { 'side 1': sides[0], 'side 2': sides[1], across: across.map((p, k) => ({ ...p, on: members[BAND_PARTS[k]] })) };
    let next = cmd.relayBand(this.design, band.id, { width_mm: widthMm, points });
    for (const seam of Object.values(members)) {
      const twin = this.twinOf(this.design, seam);
      if (twin === null) continue;
      const mirrored = next.seams[seam].points.map((p) => this.mirrored(next, p));
      next = cmd.relaySeam(next, twin, { points: mirrored, name: cmd.bandSeamName(next.seams[twin].name, widthMm) });
    }
    const moved = this.movedBandSides(band, members);
    this.app.commitDesign(next);
    this.refresh();
    this.noteLaid(moved.length ? `The band was laid again at ${width}: the points you had moved on ${moved.join(' and ')} were replaced by the band's own (undo brings them back).` : null);
  }

  // Where an outline band's seam across may go: where its sides are about this far apart (target units), not
  // across a narrow part laid into the band (bandSeamPoints). A section band's goes where the designer clicked.
  stripWidth(band, widthMm = band?.width_mm) {
    return band?.kind === 'outline' ? widthMm * this.unitsPerMillimetre : null;
  }

  // The names of the band's sides whose points are no longer those the band lays at its width (dragged, added).
  movedBandSides(band, members) {
    const laid = bandLoops(this.app.target, band, this.unitsPerMillimetre);
    if (laid.problem) return [];
    const { sides } = bandSeamPoints(this.app.target, laid.loops, band.origin);
    const same = (a, b) => a.length === b.length && a.every((p, k) => p.face === b[k].face && p.bary.every((x, c) => Math.abs(x - b[k].bary[c]) < 1e-9));
    return ['side 1', 'side 2'].filter((part, k) => !same(this.design.seams[members[part]].points, sides[k])).map((part) => this.design.seams[members[part]].name ?? part);
  }

  // Target units per millimetre on the cut pattern, at the design's height.
  get unitsPerMillimetre() {
    return 1 / (1000 * this.app.scaleFor(this.design));
  }

  // What laying a seam in one action did, or why it laid none (severity 'warning'); the next one replaces it.
  noteLaid(text, severity = 'notice') {
    this.app.messages.resolve('seam.laid');
    if (text) this.app.messages.show(severity, text, [], { cause: 'seam.laid' });
  }

  commitSeam(points, closed) {
    let next = cmd.addSeam(this.design, { points, closed });
    const index = next.seams.length - 1;
    if (this.plane) next = addMirroredTwin(next, this.app.target, this.plane, index);
    this.app.commitDesign(next);
    this.selection = { seam: index, index: null };
    this.refresh();
  }

  // Whether seam i may get a mirrored twin: symmetry is on, it has none, and it is not mostly its own mirror image.
  canMirror(i) {
    const seam = this.design.seams[i];
    return Boolean(this.plane && seam && seam.mirror === undefined && !needsNoTwin(seam, this.app.target, this.plane));
  }

  // A mirrored copy of seam i across the symmetry plane (for seams drawn before symmetry was on).
  mirrorSeam(i) {
    const plane = this.plane;
    if (!plane) return;
    const next = addMirroredTwin(this.design, this.app.target, plane, i);
    if (next === this.design) {
      const seam = this.design.seams[i];
      const text =
        seam?.mirror !== undefined
          ? 'This seam already has a mirrored twin.'
          : isSelfSymmetric(seam, this.app.target, plane)
            ? 'This seam is its own mirror image: it needs no twin.'
            : 'Most of this seam runs along its own mirror image: a twin would lie over it and cut slivers off. Draw the part on one side as a seam of its own to mirror it.';
      this.app.messages.show('notice', text);
      return;
    }
    this.app.commitDesign(next);
    this.refresh();
  }

  setSymmetry(axis) {
    this.app.commitDesign(cmd.setSymmetry(this.design, axis));
    this.draw();
  }

  // The control point under the pointer: { seam, index } or null.
  controlPointAt(event, radius = PICK_PX) {
    let best = null;
    let bestDistance = radius;
    this.seamTraces().forEach((trace, seam) => {
      chunks(trace?.controls ?? []).forEach((c, index) => {
        const d = this.pane.screenDistance(event, c);
        if (d < bestDistance) {
          bestDistance = d;
          best = { seam, index };
        }
      });
    });
    return best;
  }

  selectControlPoint(seam, index) {
    this.selection = { seam, index };
    this.draw();
  }

  // A segmentation problem, shown: the view turned to its place, marked, and its seam selected.
  showProblem(problem) {
    if (problem.seam >= 0 && problem.seam < this.design.seams.length) this.selectSeam(problem.seam);
    if (problem.location) this.app.showPlace(problem.location);
  }

  selectSeam(seam) {
    this.selection = seam === null ? null : { seam, index: null };
    this.draw();
  }

  // Live drag: one undo step per drag (merged until endDrag, however slowly it goes), the curve re-traced as the point
  // moves.
  moveControlPoint(seam, index, point) {
    let next = cmd.moveControlPoint(this.design, seam, index, point);
    const twin = this.twinOf(next, seam);
    if (twin !== null) next = cmd.moveControlPoint(next, twin, index, this.mirrored(next, point));
    this.app.commitDesign(next, { mergeKey: `move:${seam}:${index}`, gesture: true });
    this.refresh({ segment: false });
  }

  endDrag() {
    this.app.store.endStep(); // the next drag is a new step
    // Segment only once the last position is traced and the seam ends attached to the moved seam have
    // followed it (a drag's last re-trace may still be under way when the button comes up).
    this.refresh();
  }

  // Double-click on a seam: a new control point there, between the control points around it.
  insertControlPointAt(event) {
    const hit = this.nearestSample(event);
    if (!hit) return;
    const { seam, sample, point } = hit;
    const controlSamples = this.seamTraces()[seam].controlSamples;
    let index = controlSamples.findIndex((s) => s > sample);
    if (index < 0) index = controlSamples.length; // after the last control point (closed loops)
    let next = cmd.insertControlPoint(this.design, seam, index, point);
    const twin = this.twinOf(this.design, seam);
    if (twin !== null) next = cmd.insertControlPoint(next, twin, index, this.mirrored(next, point));
    this.app.commitDesign(next);
    this.selection = { seam, index };
    this.refresh();
  }

  nearestSample(event) {
    let best = null;
    let bestDistance = PICK_PX;
    this.seamTraces().forEach((trace, seam) => {
      if (!trace) return;
      for (let i = 0; i < trace.faces.length; i++) {
        const d = this.pane.screenDistance(event, [trace.curve[3 * i], trace.curve[3 * i + 1], trace.curve[3 * i + 2]]);
        if (d < bestDistance) {
          bestDistance = d;
          best = { seam, sample: i, point: { face: trace.faces[i], bary: Array.from(trace.barys.subarray(3 * i, 3 * i + 3)) } };
        }
      }
    });
    return best;
  }

  deleteSelection() {
    if (!this.selection) return;
    const { seam, index } = this.selection;
    if (index === null) return this.deleteSeam(seam);
    const twin = this.twinOf(this.design, seam);
    let next = cmd.deleteControlPoint(this.design, seam, index);
    // A twin goes with its seam, or loses the same point (deleting a seam renumbers the ones after it).
    if (twin !== null) next = next.seams.length < this.design.seams.length ? cmd.deleteSeam(next, twin > seam ? twin - 1 : twin) : cmd.deleteControlPoint(next, twin, index);
    this.selection = null;
    this.app.commitDesign(next);
    this.refresh();
  }

  // With symmetry on, a seam and its twin go together (one undo step).
  deleteSeam(seam) {
    this.selection = null;
    const twin = this.twinOf(this.design, seam);
    const next = twin === null ? cmd.deleteSeam(this.design, seam) : cmd.deleteSeam(cmd.deleteSeam(this.design, Math.max(seam, twin)), Math.min(seam, twin));
    this.app.commitDesign(next);
    this.refresh();
  }

  // A seam setting applied to the seam and, with symmetry on, to its twin (one design, one undo step).
  withTwin(seam, set) {
    const next = set(this.design, seam);
    const twin = this.twinOf(next, seam);
    return twin === null ? next : set(next, twin);
  }

  setSmooth(seam, smooth) {
    this.app.commitDesign(this.withTwin(seam, (d, i) => cmd.setSeamSmooth(d, i, smooth)));
    this.refresh();
  }

  // Weights and internal connections leave the segments as they are but not the panels: the edit cancelled
  // the optimization running (commitDesign), and the panels are made again at once.
  setWeight(seam, weight) {
    this.app.commitDesign(this.withTwin(seam, (d, i) => cmd.setSeamWeight(d, i, weight)), { mergeKey: `weight:${seam}` });
    this.draw();
    this.app.panels.remake();
  }

  connect(a, b) {
    this.app.commitDesign(cmd.addConnection(this.design, a, b));
    this.draw();
    this.app.panels.remake();
  }

  deleteConnection(index) {
    this.app.commitDesign(cmd.deleteConnection(this.design, index));
    this.draw();
    this.app.panels.remake();
  }

  // The segmentation of the target by the current seams (latest request wins).
  async segment() {
    if (!this.design.seams.length) {
      // Nothing drawn yet is not a problem to report: the whole target is simply one piece.
      this.app.client.supersede('segmentation');
      this.segmentation = null;
      this.pane.setSegments({ segments: [] });
      this.changed();
      return;
    }
    const seams = requestSeams(this.design);
    try {
      const result = await this.app.client.latest('segmentation', Op.segment, { seams, up: upOf(this.design) }).promise;
      this.segmentation = result;
      this.pane.setSegments(result);
      const patternable = result.segments.length >= 2 && result.segments.every((s) => s.isDisk);
      this.app.messages.resolve('segment');
      // Seams that cut every handle open leave no handle to warn of.
      if (patternable) this.app.messages.resolve('target.mesh.genus');
      // The panels are under way before anyone hears of the new segments: a segmentation that makes panels is
      // never seen with none being made.
      if (patternable) this.app.panels.make();
      else this.app.panels.markOutdated(true);
      this.changed();
    } catch (error) {
      if (error.code === ErrorCode.cancelled || error.code === ErrorCode.crashed) return;
      this.app.messages.show('error', `The target could not be cut along the seams: ${error.message}`, [], { cause: 'segment' });
    }
  }

  // A new target or design: traces are recomputed from scratch.
  reset() {
    this.cache.clear();
    this.preview = null;
    this.draftWarning = null;
    this.selection = null;
    this.segmentation = null;
  }
}

// The design's seams as the worker's segmentation takes them.
const requestSeams = (design) => design.seams.map(({ points, closed, weight, smooth }) => ({ points, closed, weight, smooth: Boolean(smooth) }));

const DRAFT_WORDS = {
  'seam.self-crossing': 'Crosses itself here',
  'segment.sliver': 'Cuts off a tiny piece',
  'segment.thin': 'Leaves a strip too thin to sew',
};

// The problem a seam being drawn (index `draft`) would make, in a few words for the note beside it, or null:
// its own crossing, or a tiny or thin segment the committed seams do not make (`before`: their problems; a
// segment that stays as it was keeps its place, so it is found there).
export function draftProblem(problems, draft, before, closed = false) {
  const same = (p, q) => p.code === q.code && Math.hypot(...p.location.map((x, k) => x - q.location[k])) < 1e-9;
  const found = problems.find((p) => p.code === 'seam.self-crossing' && p.seam === draft)
    ?? problems.find((p) => (p.code === 'segment.sliver' || p.code === 'segment.thin') && !before.some((q) => same(p, q)));
  if (!found) return null;
  const words = DRAFT_WORDS[found.code];
  return { code: found.code, location: found.location, text: closed && found.code !== 'seam.self-crossing' ? `Closing here: ${words.toLowerCase()}` : words };
}

function chunks(flat) {
  const out = [];
  for (let i = 0; i + 2 < flat.length; i += 3) out.push([flat[i], flat[i + 1], flat[i + 2]]);
  return out;
}
