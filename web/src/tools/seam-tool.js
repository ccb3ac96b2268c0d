// The seam tool in the target pane. Draw: click control points on the surface (a click is a press
// without a drag, so dragging still orbits); the curve follows the cursor as a dashed preview; Enter or
// a double-click finishes, clicking the first point closes a loop, Backspace removes the last point,
// Esc cancels. Near an existing seam or control point the cursor snaps (shown in orange before the click).
// Edit: drag a control point (the seam follows live), double-click a seam to insert a point, Delete
// removes the selected point. Section: a click lays a seam all around the target where a plane through the
// clicked point cuts it (across the model's x, y or z as shown, or the view), previewed under the pointer.
// Touch and pen input: a fingertip covers more pixels than a mouse pointer, so taps may wander more and
// reach farther to snap or grab; the seam panel shows Finish / Close / Cancel buttons while drawing, since
// there is no Enter key or reliable double-tap.
import { Matrix4, Vector3 } from 'three';
import { outlineLoop, sectionThrough, acrossHandles, straighterView } from '../app/section.js';
import { bandNames, lowestPoint, outlineBandLoops } from '../app/band.js';
import { UP_FRAMES, upOf } from '../app/up-axis.js';

const CLICK_SLOP_PX = { mouse: 4, pen: 6, touch: 12 };
const SNAP_PX = { mouse: 12, pen: 16, touch: 28 }; // to control points and the start of the loop being drawn
const CURVE_SNAP_PX = { mouse: 6, pen: 9, touch: 18 }; // to a seam's curve between its points
const PICK_PX = { mouse: 10, pen: 14, touch: 26 }; // mouse: SeamEditor's default
const reach = (table, event) => table[event.pointerType] ?? table.mouse;
// The parts of the surface that go with the other side's panel when the outline is laid: under SMALL_PART of the
// surface each, folds and creases; from LARGE_PART on, the note looks for a straight view that turns less away.
const SMALL_PART = 0.01;
const LARGE_PART = 0.02;
const percent = (share) => (share < 0.01 ? 'under 1 %' : `${Math.round(100 * share)} %`);
// The straight views the Outline note may point to, with their keys.
const STRAIGHT_VIEWS = [['front', '1'], ['right', '3'], ['top', '7']];
export const SECTION_AXES = ['x', 'y', 'z', 'view'];

export class SeamTool {
  // pane: TargetPane; app: the SeamEditor (seam commands and traces)
  constructor(pane, app) {
    this.pane = pane;
    this.app = app;
    this.mode = 'orbit'; // 'orbit' | 'draw' | 'edit' | 'section'
    this.sectionAxis = 'y'; // across which the section tool's plane lies: SECTION_AXES
    this.bandWidth = 0; // mm on the cut pattern: a click lays a gusset band of two sections this far apart; 0: one
    this.section = null; // the section loops under the pointer (section.js planeSection), for the click
    this.drawing = null; // { points: [surface point], positions: [[x,y,z]] }
    this.drag = null; // { seam, index }
    this.down = null;
    const el = pane.element;
    el.addEventListener('pointerdown', (e) => this.onDown(e));
    el.addEventListener('pointermove', (e) => this.onMove(e));
    el.addEventListener('pointerup', (e) => this.onUp(e));
    el.addEventListener('dblclick', (e) => this.onDoubleClick(e));
    el.addEventListener('pointerleave', () => {
      pane.seams.showCursor(null);
      this.clearSection(); // no section previewed where the pointer is not
      pane.requestRender();
    });
  }

  setMode(mode) {
    if (this.drawing) this.cancel();
    this.clearSection();
    this.mode = mode;
    this.pane.element.dataset.tool = mode;
    this.pane.seams.showCursor(null);
    this.pane.requestRender();
  }

  // The surface point under the pointer, snapped to seams/control points when close on screen.
  pick(event) {
    const hit = this.pane.pick(event);
    if (!hit) return null;
    return this.snap(event) ?? { ...hit, snapped: false };
  }

  // Only points the designer sees can be snapped to: a seam or a start point behind the model is not where
  // they aimed, however close on screen. A seam's curve snaps within a few pixels (a click beside a seam is a
  // point beside it, not a tiny segment against it); its control points and the loop's start a little farther.
  snap(event) {
    const candidates = [];
    // The first point of the seam being drawn closes it.
    if (this.drawing?.points.length >= 2) {
      const d = this.pane.screenDistance(event, this.drawing.positions[0]);
      if (d < reach(SNAP_PX, event)) candidates.push({ d: d - 3, hit: { point: this.drawing.points[0], position: this.drawing.positions[0], snapped: true, closes: true } });
    }
    // A snapped point remembers its host seam ("on"), so it follows when that seam is edited.
    const consider = (point, position, seam, within, bias = 0) => {
      const d = this.pane.screenDistance(event, position);
      if (d < within) candidates.push({ d: d - bias, hit: { point: { face: point.face, bary: point.bary, on: seam }, position, snapped: true } });
    };
    this.app.seamTraces().forEach((trace, seam) => {
      if (!trace) return;
      const controls = this.app.design.seams[seam].points;
      // trace.controls is flat (x, y, z per control point); control points win close calls.
      controls.forEach((point, k) => consider(point, Array.from(trace.controls.slice(3 * k, 3 * k + 3)), seam, reach(SNAP_PX, event), 3));
      for (let i = 0; i < trace.faces.length; i++) {
        const position = [trace.curve[3 * i], trace.curve[3 * i + 1], trace.curve[3 * i + 2]];
        const point = { face: trace.faces[i], bary: [trace.barys[3 * i], trace.barys[3 * i + 1], trace.barys[3 * i + 2]] };
        consider(point, position, seam, reach(CURVE_SNAP_PX, event));
      }
    });
    candidates.sort((a, b) => a.d - b.d);
    return candidates.find((c) => this.pane.isVisible(c.hit.position))?.hit ?? null;
  }

  onDown(event) {
    if (event.button !== 0 || this.mode === 'orbit') return;
    this.down = { x: event.clientX, y: event.clientY };
    if (this.mode === 'edit') {
      const grabbed = this.app.controlPointAt(event, reach(PICK_PX, event));
      if (grabbed) {
        this.drag = grabbed;
        this.pane.controls.enabled = false;
        this.pane.element.setPointerCapture?.(event.pointerId);
        this.app.selectControlPoint(grabbed.seam, grabbed.index);
      }
    }
  }

  onMove(event) {
    if (this.mode === 'orbit') return;
    if (this.mode === 'section') return this.previewSection(event);
    if (this.drag) {
      const hit = this.pane.pick(event);
      if (hit) this.app.moveControlPoint(this.drag.seam, this.drag.index, hit.point);
      return;
    }
    const hit = this.pick(event);
    this.pane.seams.showCursor(hit ? { x: hit.position[0], y: hit.position[1], z: hit.position[2] } : null, hit?.snapped);
    if (this.drawing && hit) {
      if (hit.closes) this.app.previewSeam(this.drawing.points, { closed: true });
      else this.app.previewSeam([...this.drawing.points, hit.point]);
    }
    this.pane.requestRender();
  }

  onUp(event) {
    if (this.drag) {
      this.pane.controls.enabled = true;
      this.pane.element.releasePointerCapture?.(event.pointerId);
      this.drag = null;
      this.app.endDrag();
      return;
    }
    if (!this.down || (this.mode !== 'draw' && this.mode !== 'section')) return;
    const moved = Math.hypot(event.clientX - this.down.x, event.clientY - this.down.y);
    this.down = null;
    if (moved > reach(CLICK_SLOP_PX, event)) return; // that was an orbit drag
    if (this.mode === 'section') return this.laySection(event);
    const hit = this.pick(event);
    if (!hit) return;
    if (hit.closes) {
      this.finish(true);
      return;
    }
    if (!this.drawing) this.drawing = { points: [], positions: [] };
    this.drawing.points.push(hit.point);
    this.drawing.positions.push(hit.position);
    this.app.previewSeam(this.drawing.points);
  }

  onDoubleClick(event) {
    if (this.mode === 'draw' && this.drawing) {
      // The double-click's second click added a point at the same place: drop it, then finish.
      if (this.drawing.points.length > 2) {
        this.drawing.points.pop();
        this.drawing.positions.pop();
      }
      this.finish(false);
    } else if (this.mode === 'edit') {
      this.app.insertControlPointAt(event);
    }
  }

  finish(closed) {
    const drawing = this.drawing;
    this.drawing = null;
    this.app.previewSeam(null);
    if (drawing && drawing.points.length >= 2) this.app.commitSeam(drawing.points, closed && drawing.points.length >= 3);
  }

  cancel() {
    this.drawing = null;
    this.app.previewSeam(null);
  }

  setSectionAxis(axis) {
    if (!SECTION_AXES.includes(axis)) return;
    this.sectionAxis = axis;
    this.clearSection();
  }

  // The plane's normal in the target's own coordinates: the axis as the target is shown (standing on its up
  // axis), or the view direction.
  sectionNormal() {
    return this.toTarget(this.sectionAxis === 'view' ? this.pane.viewDirection() : new Vector3(...[0, 1, 2].map((k) => (SECTION_AXES[k] === this.sectionAxis ? 1 : 0))));
  }

  setBandWidth(millimetres) {
    this.bandWidth = Number.isFinite(millimetres) && millimetres > 0 ? millimetres : 0;
    this.clearSection();
  }

  // The section through the point under the pointer, or the band's two: planes half the band's width to each
  // side, each loop the one nearest the point.
  previewSection(event) {
    const hit = this.pane.pick(event);
    this.section = null;
    this.lastHit = hit?.position ?? null;
    if (hit) {
      const normal = this.sectionNormal();
      const half = (this.bandWidth / 2) * this.app.unitsPerMillimetre;
      const offsets = half > 0 ? [-half, half] : [0];
      const loops = offsets.map((o) => sectionThrough(this.app.target, { position: hit.position.map((x, k) => x + o * normal[k]), face: o ? -1 : hit.point.face }, normal));
      if (loops.every(Boolean)) this.section = loops;
    }
    this.pane.seams.showCursor(hit ? { x: hit.position[0], y: hit.position[1], z: hit.position[2] } : null, false);
    this.app.previewLoops(this.section?.map((loop) => loop.map((p) => p.position)) ?? null);
  }

  laySection(event) {
    this.previewSection(event);
    const loops = this.section;
    if (!loops) return;
    this.clearSection();
    if (loops.length === 1) return this.app.commitLoops(loops);
    // The strip between the two is opened by a seam across it, where the designer clicked.
    const band = { kind: 'section', width_mm: this.bandWidth, normal: this.sectionNormal(), origin: this.lastHit };
    this.app.commitLoops(loops, { names: bandNames('section', this.bandWidth), across: this.lastHit, band });
  }

  // The outline as seen from here, in one action: the seam that splits the shape into a front and a back panel,
  // or with a band width, a gusset band around the shape between them.
  layOutline() {
    if (!this.pane.mesh) return;
    const towards = this.toTarget(this.pane.viewDirection());
    if (this.bandWidth > 0) return this.layOutlineBand(towards);
    const outline = outlineLoop(this.app.target, towards);
    if (!outline) return this.app.noteLaid('The shape shows no outline from here: turn the view and try again.', 'warning');
    const notes = [];
    // Parts of SMALL_PART or more are named with the largest's share; on a detailed mesh (a boot's laces and tread)
    // a hundred small folds come with them, which the note only mentions.
    const large = outline.movedParts.filter((share) => share >= SMALL_PART).length;
    const small = outline.movedParts.length - large;
    const parts = large || small;
    const one = parts === 1;
    if (parts) {
      const what = large ? `${large} ${one ? 'part' : 'parts'}` : `${small} small ${one ? 'part' : 'parts'}`;
      const share = large ? `, ${one ? '' : 'the largest '}${percent(outline.largestMoved)} of the surface${small ? `, and ${small} small ${small === 1 ? 'fold' : 'folds'} with ${one ? 'it' : 'them'}` : ''}` : '';
      const straighter = outline.largestMoved >= LARGE_PART ? this.straighterViewClause(outline.largestMoved) : '';
      notes.push(`${what} turned away from the rest of ${one ? 'its' : 'their'} side (a fold, a limb in front of the body, an ear seen at an angle) went with the panel around ${one ? 'it' : 'them'}${share}; a section seam around a limb gives it panels of its own${straighter}`);
    }
    // Seen through a handle (a ring, a letter O), the front and back are rings: each hole's rim is laid too,
    // and two sections across each ring, where they run around it, cut them into halves.
    const holes = outline.holes.length;
    const across = holes ? acrossHandles(this.app.target, outline.loop, outline.holes, towards) : [];
    const halved = across.length / 2;
    if (holes) {
      const cuts = halved === holes ? '' : halved ? ` around ${halved} of the holes` : null;
      const halves = cuts === null ? '' : `, and two seams across the ring${cuts} (where it is narrowest and opposite) to cut the front and back into halves (drag their points to move them)`;
      notes.push(`the shape has ${holes === 1 ? 'a handle' : `${holes} handles`}, so the outline makes ${holes + 1} loops: the rim of each hole was laid too${halves}`);
    }
    const loops = [outline.loop, ...outline.holes, ...across];
    const names = ['Outline', ...outline.holes.map((_, k) => `Outline, hole ${k + 1}`), ...across.map((_, k) => `Across the ring ${k + 1}`)];
    const note = notes.length ? `Outline seam laid as seen from here: ${notes.join('; ')}.` : null;
    // On a shape with handles the front or the back may still be a ring, or hold a handle this view does not look
    // through (a statue's arm joined to its body): the seams that open them come with the outline.
    if (this.app.target.report?.stats.genus > 0) return this.app.commitLoopsOpened(loops, { names, note, keep: 1 + holes, asSeen: true });
    this.app.commitLoops(loops, { names, note, asSeen: true });
  }

  // The note's clause naming a straight view (front, side, top) that leaves less than half the largest part `largest`
  // out of its outline (section.js straighterView), else ''.
  straighterViewClause(largest) {
    const views = STRAIGHT_VIEWS.map(([name, key]) => ({ name, key, towards: this.toTarget(this.pane.namedView(name, this.pane.group)) }));
    const best = straighterView(this.app.target, views, largest);
    if (!best) return '';
    const moved = best.share > 0 ? `the largest part turned away is ${percent(best.share)} of it` : 'no part turns away';
    return `; seen straight from the ${best.name} (View menu, or key ${best.key}) ${moved}`;
  }

  // Two seams half the band's width to each side of the outline, measured on the surface, and the seam across
  // the strip at the outline's lowest point, where it is least seen.
  layOutlineBand(towards) {
    const band = { kind: 'outline', width_mm: this.bandWidth, towards };
    const laid = outlineBandLoops(this.app.target, band, this.bandWidth * this.app.unitsPerMillimetre);
    if (laid.problem) return this.app.noteLaid(laid.problem, 'warning');
    band.origin = lowestPoint(laid.outline.loop, UP_FRAMES[upOf(this.app.design)][1]);
    const notes = [];
    if (laid.absorbed)
      notes.push(`${laid.absorbed} narrow ${laid.absorbed === 1 ? 'part' : 'parts'} of the front or back (thinner than the band: a tail, an ear) went into the band`);
    // Seen through a handle (a letter O, a number 8) the band follows the outline's outer loop, and each hole's rim is
    // laid too, so the front and the back meet there; the cuts that open a ring come with them.
    const holes = laid.outline.holes;
    if (holes.length)
      notes.push(`the shape has ${holes.length === 1 ? 'a handle' : `${holes.length} handles`}: the band follows the outline's outer loop, and the rim of each hole was laid too`);
    const note = notes.length ? `Band laid around the outline as seen from here: ${notes.join('; ')}.` : null;
    const names = [...bandNames('outline', this.bandWidth), ...holes.map((_, k) => `Outline, hole ${k + 1}`)];
    const laying = { names, across: band.origin, band, note, asSeen: true };
    // On a shape with handles the front or the back may be a ring, or hold a handle: the seams that open them
    // come with the band, as with the outline alone; the band's own seams stay whole.
    if (this.app.target.report?.stats.genus > 0) return this.app.commitLoopsOpened([...laid.loops, ...holes], { ...laying, keep: Infinity });
    this.app.commitLoops([...laid.loops, ...holes], laying);
  }

  // A direction in the view (world) as one in the target's own coordinates.
  toTarget(direction) {
    const mesh = this.pane.mesh;
    mesh.updateMatrixWorld(true);
    return direction.clone().transformDirection(new Matrix4().copy(mesh.matrixWorld).invert()).toArray();
  }

  clearSection() {
    if (!this.section && this.mode !== 'section') return;
    this.section = null;
    this.app.previewLoops(null);
  }

  // For the Finish / Close loop buttons: what the seam being drawn allows.
  get canFinish() {
    return (this.drawing?.points.length ?? 0) >= 2;
  }

  get canClose() {
    return (this.drawing?.points.length ?? 0) >= 3;
  }

  // Keys for the tool. Returns true when handled.
  onKey(event) {
    if (this.mode === 'draw' && this.drawing) {
      if (event.key === 'Enter') return this.finish(false), true;
      if (event.key === 'Escape') return this.cancel(), true;
      if (event.key === 'Backspace') {
        this.drawing.points.pop();
        this.drawing.positions.pop();
        if (!this.drawing.points.length) this.cancel();
        else this.app.previewSeam(this.drawing.points);
        return true;
      }
    }
    if (this.mode === 'edit' && (event.key === 'Delete' || event.key === 'Backspace')) return this.app.deleteSelection(), true;
    if (event.key === 'Escape' && this.mode !== 'orbit') return this.setMode('orbit'), true;
    return false;
  }
}
