// The pattern pane: flat panels seen from above with pan and zoom (no rotation), in one of two views:
// 'panels' (side by side, each as drawn) or 'sheet' (as nested on the sheet for cutting, turned as the cut
// files have them, with the sheet's outline).
import {
  OrthographicCamera, Scene, GridHelper, Box3, Vector3, Group, BufferGeometry, Float32BufferAttribute, Mesh,
  MeshBasicMaterial, LineSegments, LineBasicMaterial, DoubleSide, Color, Shape, ShapeGeometry,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { segmentDistance } from '../app/geometry.js';
import { layoutPattern } from './pattern-layout.js';
import { panelTint, seamColor } from './palette.js';
import { unclutterLabels } from './label-rule.js';
import { freeArea, watchOverlays } from './free-area.js';

// The seal band's tint and the valve marks' colours, as the cut files (wasm/src/export/drawing.cpp).
const SEAL_TINT = 0xf6e7bd;
const VALVE_FILL = 0xffffff;
const VALVE_EDGE = 0x1a9850;

export class PatternPane {
  constructor(element, viewport) {
    this.element = element;
    this.viewport = viewport;
    this.scene = new Scene();
    this.halfHeight = 0.5; // meters visible above the center
    this.camera = new OrthographicCamera(-1, 1, 1, -1, -10, 10);
    this.camera.position.set(0, 0, 5);
    this.setGridColors(0xb8c0cc, 0xd8dde5);
    this.controls = new OrbitControls(this.camera, element);
    this.controls.enableRotate = false;
    this.controls.screenSpacePanning = true;
    this.controls.zoomToCursor = true; // a piece's corner under the cursor stays there as it grows
    this.controls.mouseButtons = { LEFT: 2, MIDDLE: 1, RIGHT: 2 }; // PAN, DOLLY, PAN
    this.controls.touches = { ONE: 1, TWO: 2 }; // PAN, DOLLY_PAN
    this.controls.addEventListener('change', () => viewport.requestRender(this));
    this.content = new Group();
    this.scene.add(this.content);
    this.labels = document.createElement('div');
    this.labels.className = 'pane-labels';
    element.parentElement.append(this.labels);
    this.labelAnchors = [];
    this.panelLabels = []; // the panel labels among them, largest panel first
    this.seamLabelAnchors = [];
    this.seams = null; // the exporter's seams of the shown pattern (setSeams)
    this.view = 'panels'; // or 'sheet'
    this.cut = null; // the exporter's figures of the shown pattern: { cutLines, notches, sheet, captions }
    this.sheet = null; // the last nesting: { width, length, placements } [m] (kept for streamed iterates)
    this.selectedSeam = null; // seam id, -1 for the free edges, or null
    this.onSeamPick = null; // (id | null) => void: a click on a seam (-1: a free edge) or beside every seam
    this.pickSeams(element);
    // The pieces stay framed in the free part of the pane when it changes (the window resized, the seam
    // allowances opened beside them) until the designer pans or zooms.
    this.framed = false;
    this.controls.addEventListener('start', () => {
      this.framed = false;
    });
    viewport.add(this);
    watchOverlays(element.parentElement, () => this.resize());
  }

  // The grid's colors (the axes, the 10 cm lines), from the theme.
  setGridColors(axes, lines) {
    this.gridColors = [axes, lines];
    this.placeGrid(this.gridBox ?? new Box3(new Vector3(-2, -2, 0), new Vector3(2, 2, 0)));
  }

  // A grid of 10 cm squares (1 m beyond 40 m) under everything shown, lines on round figures.
  placeGrid(box) {
    if (this.grid) {
      this.scene.remove(this.grid);
      this.grid.geometry.dispose();
      this.grid.material.dispose();
    }
    this.gridBox = box;
    const size = box.getSize(new Vector3());
    const span = Math.max(4, Math.ceil(1.4 * Math.max(size.x, size.y) + 1));
    const step = span > 40 ? 1 : 0.1;
    const center = box.getCenter(new Vector3());
    const round = (v) => Math.round(v / step) * step;
    const extent = 2 * Math.ceil(span / 2); // even: lines stay on multiples of the step around a rounded center
    const [, lines] = this.gridColors; // its middle is no particular place: no darker center lines
    this.grid = new GridHelper(extent, Math.round(extent / step), lines, lines);
    this.grid.rotation.x = Math.PI / 2;
    this.grid.position.set(round(center.x), round(center.y), -0.001);
    this.scene.add(this.grid);
    this.viewport.requestRender(this);
  }

  // pattern: panels in meters (see docs/formats.md); each seam has one color on both panels it joins;
  // labels name the panels. frame: fit the view to the panels (not for a streamed iterate: the designer's
  // pan and zoom stay). The exporter's figures (setCutResult) of the previous pattern are dropped; for a
  // streamed iterate (not framed) with as many panels, its sheet placements go on being used.
  setPattern(pattern, { frame = true } = {}) {
    this.pattern = pattern;
    this.layout = layoutPattern(pattern);
    this.cut = null;
    this.seamData = null;
    if (frame || this.sheet?.placements.length !== pattern.panels.length) this.sheet = null;
    this.redraw({ frame });
  }

  // 'panels' or 'sheet'; the view is framed again, since the panels move.
  setView(view) {
    if (view !== 'panels' && view !== 'sheet') return;
    this.view = view;
    if (this.pattern) this.redraw({ frame: true });
  }

  // Where panel i's point (x, y) [m] is drawn in the current view.
  placement(i) {
    const at = this.view === 'sheet' ? this.sheet?.placements[i] : null;
    if (!at) {
      const [dx, dy] = this.layout[i].offset;
      return (x, y) => [x + dx, y + dy];
    }
    const c = Math.cos(at.angle), s = Math.sin(at.angle);
    return (x, y) => [c * x - s * y + at.x, s * x + c * y + at.y];
  }

  // Everything shown, drawn again from what the pane holds (after a new pattern, figures or view).
  redraw({ frame = false } = {}) {
    this.clear();
    const pattern = this.pattern;
    if (!pattern) return;
    const seamIds = new Map();
    const seamIndex = (a, b) => {
      const k = a < b ? `${a}-${b}` : `${b}-${a}`;
      if (!seamIds.has(k)) seamIds.set(k, seamIds.size);
      return seamIds.get(k);
    };
    this.pairColor = (a, b) => seamColor(seamIndex(a, b));
    pattern.panels.forEach((panel, i) => {
      const { boundary } = this.layout[i];
      const place = this.placement(i);
      const xy = (v) => [...place(panel.vertices[v][0], panel.vertices[v][1]), 0];
      const fill = new BufferGeometry();
      fill.setAttribute('position', new Float32BufferAttribute(panel.triangles.flat().flatMap(xy), 3));
      const material = new MeshBasicMaterial({ color: panelTint(i), side: DoubleSide, transparent: panel.internal, opacity: 0.6 });
      this.content.add(new Mesh(fill, material));
      const points = [];
      const colors = [];
      for (const [a, b, partner] of boundary) {
        const color = partner < 0 ? seamColor(7) : seamColor(seamIndex(i, partner));
        points.push(...xy(a), ...xy(b));
        colors.push(color.r, color.g, color.b, color.r, color.g, color.b);
      }
      const outline = new BufferGeometry();
      outline.setAttribute('position', new Float32BufferAttribute(points, 3));
      outline.setAttribute('color', new Float32BufferAttribute(colors, 3));
      const line = new LineSegments(outline, new LineBasicMaterial({ vertexColors: true }));
      line.position.z = 0.002; // over the cut line: a seam cut on its sewing line (0 allowance) keeps its color
      this.content.add(line);
      const label = document.createElement('div');
      label.className = 'panel-label';
      // "Panel 3" carries its segment's number (the target pane shows it on the model); other names get their place.
      // An internal panel's name says which seams it joins: that is its tooltip, the label says "inside".
      const number = /^Panel (\d+)$/.exec(panel.name ?? '')?.[1];
      label.textContent = number ? panel.name : panel.internal ? `${i + 1} inside` : `${i + 1} ${panel.name ?? ''}`.trim();
      if (panel.internal) label.title = panel.name;
      const size = this.pieceSize(i);
      if (size) {
        const line = document.createElement('span');
        line.className = 'panel-size';
        line.textContent = size;
        label.append(line);
      }
      this.labels.append(label);
      label.dataset.full = label.firstChild.textContent;
      label.dataset.short = number ?? String(i + 1);
      // The piece's width as drawn [m]: a name wider than the piece on screen gives way to its number.
      const xs = panel.vertices.map(([x, y]) => place(x, y)[0]);
      const span = Math.max(...xs) - Math.min(...xs);
      this.labelAnchors.push({ label, at: new Vector3(...place(...this.layout[i].center), 0), area: panelArea(panel), span });
    });
    // Larger panels keep their full labels first (labelOrder).
    this.panelLabels = this.labelAnchors.filter((a) => a.area !== undefined).sort((a, b) => b.area - a.area);
    if (this.cut) {
      if (this.cut.sealed) this.drawSealBands(this.cut.cutLines);
      this.drawValves(this.cut.valves);
      this.drawCutLines(this.cut.cutLines);
      this.drawNotches(this.cut.notches);
    }
    if (this.view === 'sheet' && this.sheet) this.drawSheet();
    if (this.seamData) this.buildSeams();
    this.element.parentElement.querySelector('.hint')?.setAttribute('hidden', '');
    const box = new Box3().setFromObject(this.content);
    if (!box.isEmpty()) this.placeGrid(box);
    if (frame || this.outgrewFrame(box)) this.frame(this.content);
    else this.viewport.requestRender(this);
  }

  // The exporter's figures of `pattern` (ignored when another pattern is shown by now; web/src/worker/
  // protocol.js exportPattern): cutLines (sewing line plus seam allowance) and notches (tick segments) per
  // panel, flat [x0, y0, x1, ...] in its frame [m]; sheet: the nesting { width, length [m], placements };
  // outlines, seams and widths as for buildSeams; captions, as the designer reads them: { width, length } of
  // the sheet, and size(widthMm, heightMm) a piece's size.
  // sealed: the allowance is a seal band, drawn tinted; valves: per panel its fill valves' gap marks, each a
  // closed [x0, y0, ...] in its frame [m]; seamSides: per seam { id, sides: [{ panel, edges, forward,
  // length }] } (where a click on a seam lies along it: seamShareAt).
  setCutResult(pattern, { cutLines, notches = [], sheet = null, outlines, seams, widths = {}, captions = {}, sealed = false, valves = [], seamSides = [] }) {
    if (pattern !== this.pattern || !this.layout) return false;
    this.cut = { cutLines, notches, captions, sealed, valves, seamSides };
    const before = this.sheet;
    if (sheet?.placements?.length === pattern.panels.length) this.sheet = sheet;
    this.seamData = outlines && seams ? { outlines, seams, widths } : null;
    // Panels that were side by side move onto the sheet, or the sheet changed size: frame it again.
    const moved = !before || Math.abs(before.width - this.sheet?.width) > 1e-9 || Math.abs(before.length - this.sheet?.length) > 0.05 * before.length;
    this.redraw({ frame: this.view === 'sheet' && Boolean(this.sheet) && moved });
    return true;
  }

  // Panel i's cut piece's width and height as drawn (turned as on the sheet in the sheet view), as the
  // designer reads them; null before the cut lines arrive.
  pieceSize(i) {
    const line = this.cut?.cutLines[i];
    const format = this.cut?.captions.size;
    if (!line || !format) return null;
    const place = this.placement(i);
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (let k = 0; k + 1 < line.length; k += 2) {
      const [x, y] = place(line[k], line[k + 1]);
      minX = Math.min(minX, x); maxX = Math.max(maxX, x);
      minY = Math.min(minY, y); maxY = Math.max(maxY, y);
    }
    return format(1000 * (maxX - minX), 1000 * (maxY - minY));
  }

  // Closed outlines, each a flat [x0, y0, x1, ...] in its panel's frame, as one set of line segments.
  loopSegments(lines) {
    const points = [];
    lines.forEach((line, i) => {
      const place = this.placement(i);
      const n = line.length / 2;
      for (let k = 0; k < n; k++) {
        const j = (k + 1) % n;
        points.push(...place(line[2 * k], line[2 * k + 1]), 0, ...place(line[2 * j], line[2 * j + 1]), 0);
      }
    });
    return points;
  }

  drawCutLines(cutLines) {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(this.loopSegments(cutLines), 3));
    this.cutLines = new LineSegments(geometry, new LineBasicMaterial({ color: 0x1d2330 }));
    this.cutLines.position.z = 0.001;
    this.cutLines.userData.lines = cutLines; // per panel [x0, y0, ...] in its frame [m] (for tests)
    this.content.add(this.cutLines);
  }

  // Heat sealed: the seal band of every piece, tinted between its cut line and its outline (as the cut files'
  // seal-band layer), under the outline's seam colours.
  drawSealBands(cutLines) {
    const shapes = [];
    cutLines.forEach((line, i) => {
      const place = this.placement(i);
      const panel = this.pattern.panels[i];
      const loop = this.seamData?.outlines[i]?.loop;
      if (!loop || line.length < 6) return;
      const outer = new Shape();
      for (let k = 0; k < line.length; k += 2) outer[k ? 'lineTo' : 'moveTo'](...place(line[k], line[k + 1]));
      const inner = new Shape();
      loop.forEach((v, k) => inner[k ? 'lineTo' : 'moveTo'](...place(...panel.vertices[v])));
      outer.holes.push(inner);
      shapes.push(outer);
    });
    if (!shapes.length) return;
    this.sealBands = new Mesh(new ShapeGeometry(shapes), new MeshBasicMaterial({ color: SEAL_TINT, side: DoubleSide }));
    this.sealBands.position.z = 0.0005;
    this.sealBands.userData.count = shapes.length;
    this.content.add(this.sealBands);
  }

  // Fill valves: each gap in its seam as the cut files mark it, filled over the band with a green edge.
  drawValves(valves) {
    const shapes = [];
    const edges = [];
    valves.forEach((marks, i) => {
      const place = this.placement(i);
      for (const mark of marks) {
        const shape = new Shape();
        const n = mark.length / 2;
        // Named beside the rim, since a gap of a few cm is a speck on a whole piece.
        const label = document.createElement('div');
        label.className = 'valve-label';
        label.textContent = 'valve';
        this.labels.append(label);
        const centre = [0, 0];
        for (let k = 0; k < n; k++) place(mark[2 * k], mark[2 * k + 1]).forEach((v, j) => (centre[j] += v / n));
        this.labelAnchors.push({ label, at: new Vector3(...centre, 0) });
        for (let k = 0; k < n; k++) {
          const p = place(mark[2 * k], mark[2 * k + 1]), q = place(mark[2 * ((k + 1) % n)], mark[2 * ((k + 1) % n) + 1]);
          shape[k ? 'lineTo' : 'moveTo'](...p);
          edges.push(...p, 0, ...q, 0);
        }
        shapes.push(shape);
      }
    });
    if (!shapes.length) return;
    const fill = new Mesh(new ShapeGeometry(shapes), new MeshBasicMaterial({ color: VALVE_FILL, side: DoubleSide }));
    fill.position.z = 0.0007;
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(edges, 3));
    const outline = new LineSegments(geometry, new LineBasicMaterial({ color: VALVE_EDGE }));
    outline.position.z = 0.0008;
    this.valveMarks = fill;
    fill.userData.count = shapes.length;
    this.content.add(fill, outline);
  }

  // Where a point of the pane (client pixels) lies along seam `id`: the share of the seam's length from its
  // start, measured on the side nearest the point (both sides run the same way: export/outline.hpp); null
  // without the exporter's seam sides.
  seamShareAt(id, clientX, clientY) {
    const seam = this.cut?.seamSides?.find((s) => s.id === id);
    const outlines = this.seamData?.outlines;
    if (!seam || !outlines) return null;
    const r = this.element.getBoundingClientRect();
    const p = new Vector3(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1, 0).unproject(this.camera);
    let best = null;
    for (const side of seam.sides) {
      const panel = this.pattern.panels[side.panel];
      const loop = outlines[side.panel].loop;
      const place = this.placement(side.panel);
      const at = (k) => place(...panel.vertices[loop[k % loop.length]]);
      let along = 0;
      for (const e of side.edges) {
        const [a, b] = side.forward ? [at(e), at(e + 1)] : [at(e + 1), at(e)];
        const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
        const t = len > 0 ? Math.min(1, Math.max(0, ((p.x - a[0]) * (b[0] - a[0]) + (p.y - a[1]) * (b[1] - a[1])) / (len * len))) : 0;
        const d = Math.hypot(a[0] + t * (b[0] - a[0]) - p.x, a[1] + t * (b[1] - a[1]) - p.y);
        if (!best || d < best.d) best = { d, share: side.length > 0 ? (along + t * len) / side.length : 0 };
        along += len;
      }
    }
    return best ? Math.min(1, Math.max(0, best.share)) : null;
  }

  // Registration notches: short ticks across the cut line, as the cut files have them.
  drawNotches(notches) {
    const points = [];
    notches.forEach((ticks, i) => {
      const place = this.placement(i);
      for (let k = 0; k + 1 < ticks.length; k += 2) points.push(...place(ticks[k], ticks[k + 1]), 0);
    });
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
    this.notches = new LineSegments(geometry, new LineBasicMaterial({ color: 0x1d2330 }));
    this.notches.position.z = 0.001;
    this.notches.userData.count = points.length / 6;
    this.content.add(this.notches);
  }

  // The sheet the panels are nested on: its outline from the roll's start to the length used, its width
  // and length written along its edges, and an arrow along the roll.
  drawSheet() {
    const { width: w, length: l } = this.sheet;
    const sheetGeometry = new BufferGeometry();
    sheetGeometry.setAttribute('position', new Float32BufferAttribute([0, 0, 0, w, 0, 0, w, l, 0, 0, 0, 0, w, l, 0, 0, l, 0], 3));
    const [axes] = this.gridColors;
    const sheet = new Mesh(sheetGeometry, new MeshBasicMaterial({ color: axes, transparent: true, opacity: 0.12, side: DoubleSide, depthWrite: false }));
    sheet.position.z = -0.0005;
    sheet.userData.sheet = { width: w, length: l };
    this.sheetMesh = sheet;
    const edge = new BufferGeometry();
    edge.setAttribute('position', new Float32BufferAttribute([0, 0, 0, w, 0, 0, w, 0, 0, w, l, 0, w, l, 0, 0, l, 0, 0, l, 0, 0, 0, 0], 3));
    const border = new LineSegments(edge, new LineBasicMaterial({ color: axes }));
    this.content.add(sheet, border);
    const captions = this.cut?.captions ?? {};
    const caption = (text, x, y, className) => {
      const label = document.createElement('div');
      label.className = `sheet-label ${className}`;
      label.textContent = text;
      this.labels.append(label);
      this.labelAnchors.push({ label, at: new Vector3(x, y, 0) });
    };
    caption(`← ${captions.width ?? `${Math.round(w * 1000)} mm`} →`, w / 2, 0, 'sheet-width');
    caption(`roll ↑ ${captions.length ?? `${Math.round(l * 1000)} mm`} used`, w, l / 2, 'sheet-length');
  }

  // The exporter's seams (cf. setCutResult): outlines per panel { loop: [vertex], seams: [seam id of edge
  // loop[i] -> loop[i+1], -1 free] }; seams: the statistics' seams ({ id, label, panels: [a, b] (from 1) });
  // widths: { [id]: allowance mm } ("-1": free edges), for picking. Seams can then be picked with a click,
  // shown with labels (S1, S2, ... as on the cut pieces) and one highlighted.
  buildSeams() {
    const { outlines, seams, widths } = this.seamData;
    const pattern = this.pattern;
    const runs = new Map(); // id -> [{ panel, segments: [[x0, y0, x1, y1]], length }]
    outlines.forEach(({ loop, seams: edgeSeams }, p) => {
      const panel = pattern.panels[p];
      const place = this.placement(p);
      const n = loop.length;
      // Start at an edge that begins a run, so that no run wraps around loop[0].
      const start = Math.max(0, edgeSeams.findIndex((id, e) => id !== edgeSeams[(e + n - 1) % n]));
      let run = null;
      for (let k = 0; k < n; k++) {
        const e = (start + k) % n;
        const id = edgeSeams[e];
        const [x0, y0] = place(...panel.vertices[loop[e]]), [x1, y1] = place(...panel.vertices[loop[(e + 1) % n]]);
        if (!run || run.id !== id) {
          run = { id, panel: p, segments: [], length: 0 };
          if (!runs.has(id)) runs.set(id, []);
          runs.get(id).push(run);
        }
        run.segments.push([x0, y0, x1, y1]);
        run.length += Math.hypot(x1 - x0, y1 - y0);
      }
    });
    const colors = new Map(seams.map((seam) => [seam.id, this.seamColorOfPanels(seam.panels[0] - 1, seam.panels[1] - 1)]));
    colors.set(-1, seamColor(7));
    this.seams = { outlines, runs, colors, widths, labels: new Map(seams.map((seam) => [seam.id, seam.label])) };
    this.seamLabels();
    this.highlightSeam();
  }

  // The color a seam between panels a and b (from 0) has in this pane (the same on both panels).
  seamColorOfPanels(a, b) {
    return a === b || !this.pairColor ? seamColor(7) : this.pairColor(a, b);
  }

  seamColorOf(id) {
    return this.seams?.colors.get(id) ?? seamColor(7);
  }

  // Which seam to highlight (its id, -1 for the free edges, null for none) and which have their own
  // allowance (own: a Set of ids; their labels are marked).
  setSeamMarks({ selected = this.selectedSeam, own = this.ownSeams ?? new Set() } = {}) {
    this.selectedSeam = selected;
    this.ownSeams = own;
    for (const { label, id } of this.seamLabelAnchors) {
      label.classList.toggle('selected', id === selected);
      label.classList.toggle('own', own.has(id));
    }
    this.highlightSeam();
  }

  // Seam labels (S1, S2, ... as on the cut pieces) at the middle of each seam on each of its panels.
  setSeamLabelsShown(shown) {
    this.seamLabelsShown = shown;
    this.labels.classList.toggle('with-seams', shown);
    this.viewport.requestRender(this);
  }

  seamLabels() {
    for (const { label } of this.seamLabelAnchors) label.remove();
    this.seamLabelAnchors = [];
    if (!this.seams) return;
    for (const [id, list] of this.seams.runs) {
      if (id < 0) continue;
      for (const run of list) {
        // The point halfway along the run.
        let rest = run.length / 2;
        let at = run.segments[0];
        let t = 0;
        for (const seg of run.segments) {
          const len = Math.hypot(seg[2] - seg[0], seg[3] - seg[1]);
          at = seg;
          if (rest <= len) {
            t = len > 0 ? rest / len : 0;
            break;
          }
          rest -= len;
          t = 1;
        }
        const label = document.createElement('div');
        label.className = 'seam-label';
        label.textContent = this.seams.labels.get(id) ?? `S${id + 1}`;
        label.dataset.seam = String(id);
        label.style.setProperty('--seam-color', `#${this.seamColorOf(id).getHexString()}`);
        label.classList.toggle('selected', id === this.selectedSeam);
        label.classList.toggle('own', Boolean(this.ownSeams?.has(id)));
        this.labels.append(label);
        this.seamLabelAnchors.push({ label, id, length: run.length, at: new Vector3(at[0] + t * (at[2] - at[0]), at[1] + t * (at[3] - at[1]), 0) });
      }
    }
    this.viewport.requestRender(this);
  }

  // World meters per screen pixel.
  metersPerPixel() {
    const r = this.element.getBoundingClientRect();
    return (2 * this.halfHeight) / this.camera.zoom / Math.max(1, r.height);
  }

  // The selected seam as a band a few pixels wide along its sewing line on every panel it joins (rebuilt
  // when the zoom changes, so it keeps its width on screen).
  highlightSeam() {
    if (this.highlight) {
      this.content.remove(this.highlight);
      this.highlight.geometry.dispose();
      this.highlight.material.dispose();
      this.highlight = null;
    }
    const runs = this.seams?.runs.get(this.selectedSeam);
    if (!runs) return this.viewport.requestRender(this);
    const half = 3 * this.metersPerPixel();
    this.highlightScale = half;
    const points = [];
    for (const run of runs)
      for (const [x0, y0, x1, y1] of run.segments) {
        const len = Math.hypot(x1 - x0, y1 - y0) || 1;
        const nx = (-(y1 - y0) / len) * half, ny = ((x1 - x0) / len) * half;
        const ex = ((x1 - x0) / len) * half, ey = ((y1 - y0) / len) * half; // a little past each end: no gaps at corners
        const a = [x0 - ex + nx, y0 - ey + ny], b = [x0 - ex - nx, y0 - ey - ny];
        const c = [x1 + ex - nx, y1 + ey - ny], d = [x1 + ex + nx, y1 + ey + ny];
        points.push(...a, 0, ...b, 0, ...c, 0, ...a, 0, ...c, 0, ...d, 0);
      }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
    const color = this.selectedSeam < 0 ? new Color('#7a8494') : new Color(this.seamColorOf(this.selectedSeam)); // free edges: gray, not black
    this.highlight = new Mesh(geometry, new MeshBasicMaterial({ color, side: DoubleSide, transparent: true, opacity: 0.55, depthTest: false }));
    this.highlight.position.z = 0.003;
    this.highlight.renderOrder = 2;
    this.content.add(this.highlight);
    this.viewport.requestRender(this);
  }

  // The seam (id, -1 for a free edge) nearest a point of the pane (client pixels), within a few pixels of
  // its sewing line or inside its allowance; null when there is none.
  seamAt(clientX, clientY) {
    if (!this.seams) return null;
    const r = this.element.getBoundingClientRect();
    const p = new Vector3(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1, 0).unproject(this.camera);
    const pixel = this.metersPerPixel();
    const at = [p.x, p.y]; // once, not per segment: this runs on every pointer move
    let best = null;
    let bestScore = Infinity;
    for (const [id, list] of this.seams.runs) {
      const reach = Math.max(8 * pixel, Math.min((this.seams.widths[id] ?? 0) / 1000 + 3 * pixel, 40 * pixel));
      for (const run of list)
        for (const [x0, y0, x1, y1] of run.segments) {
          const d = segmentDistance(at, [x0, y0], [x1, y1]);
          if (d <= reach && d / reach < bestScore) {
            bestScore = d / reach;
            best = id;
          }
        }
    }
    return best;
  }

  // A click (a press and release without a drag) on a seam picks it; the cursor shows where one can.
  pickSeams(element) {
    let down = null;
    element.addEventListener('pointerdown', (e) => {
      down = e.button === 0 ? { x: e.clientX, y: e.clientY } : null;
    });
    element.addEventListener('pointerup', (e) => {
      if (!down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4 || !this.seams) return;
      down = null;
      this.onSeamPick?.(this.seamAt(e.clientX, e.clientY), e);
    });
    element.addEventListener('pointermove', (e) => {
      if (e.buttons) return;
      const id = this.seamAt(e.clientX, e.clientY);
      element.style.cursor = id === null ? '' : 'pointer';
      element.title = id === null ? '' : this.seamTitle?.(id) ?? '';
    });
  }

  clear() {
    this.cutLines = null;
    this.sealBands = null;
    this.valveMarks = null;
    this.notches = null;
    this.sheetMesh = null;
    this.seams = null;
    this.highlight = null;
    this.seamLabelAnchors = [];
    for (const child of [...this.content.children]) {
      this.content.remove(child);
      child.geometry.dispose();
      child.material.dispose();
    }
    this.labels.replaceChildren();
    this.labelAnchors = [];
    this.panelLabels = [];
    this.viewport.requestRender(this);
  }

  // Fits the object in the free part of the pane (free-area.js: beside the figures, the messages and the seam
  // allowances), with a margin: the view's centre moves so that the object's centre is the free part's.
  frame(object) {
    const box = new Box3().setFromObject(object);
    if (box.isEmpty()) return;
    const center = box.getCenter(new Vector3());
    const size = box.getSize(new Vector3());
    const body = this.element.getBoundingClientRect();
    if (!(body.width > 0 && body.height > 0)) return;
    const free = freeArea(this.element, size.y > 0 ? size.x / size.y : 1);
    const pixels = 1.2 * Math.max(size.y / (free.bottom - free.top), size.x / (free.right - free.left)); // meters per pixel
    this.halfHeight = (pixels * body.height) / 2;
    const dx = ((free.left + free.right) / 2 - (body.left + body.right) / 2) * pixels;
    const dy = ((free.top + free.bottom) / 2 - (body.top + body.bottom) / 2) * pixels;
    this.framedBox = box;
    this.camera.zoom = 1;
    this.controls.target.set(center.x - dx, center.y + dy, 0);
    this.camera.position.set(center.x - dx, center.y + dy, 5);
    this.controls.update();
    this.framed = true;
    this.viewport.requestRender(this);
  }

  // Whether what is shown now (box) reaches past the margin the last frame() left around the pieces, while the view
  // still follows them: the optimizer's panels grow as they are streamed, and the cut lines, drawn after the
  // pieces, stand out by the seam allowance (10 mm around a 66 mm piece is more than its margin).
  outgrewFrame(box) {
    if (!this.framed || !this.framedBox) return false;
    const room = this.framedBox.clone().expandByVector(this.framedBox.getSize(new Vector3()).multiplyScalar(0.09));
    return !box.isEmpty() && !room.containsBox(box);
  }

  // The pane or its free part changed size (Viewport, watchOverlays).
  resize() {
    if (this.framed && this.pattern) this.frame(this.content);
  }

  render(renderer, aspect) {
    const h = this.halfHeight;
    if (this.camera.top !== h || this.camera.right !== h * aspect) {
      Object.assign(this.camera, { left: -h * aspect, right: h * aspect, top: h, bottom: -h });
      this.camera.updateProjectionMatrix();
    }
    if (this.highlight && Math.abs(3 * this.metersPerPixel() / this.highlightScale - 1) > 0.05) this.highlightSeam();
    renderer.render(this.scene, this.camera);
    this.placeLabels();
  }

  placeLabels() {
    const r = this.element.getBoundingClientRect();
    const top = this.element.offsetTop;
    const p = new Vector3();
    for (const { label, at } of [...this.labelAnchors, ...(this.seamLabelsShown ? this.seamLabelAnchors : [])]) {
      p.copy(at).project(this.camera);
      label.style.left = `${((p.x + 1) / 2) * r.width}px`;
      label.style.top = `${top + ((1 - p.y) / 2) * r.height}px`;
    }
    unclutterLabels(this.labelOrder());
  }

  // The order in which labels keep their places (label-rule.js): the sheet's size, the selected seam, the
  // panels (larger first: their names and sizes are read most), then the other seams (longer first).
  labelOrder() {
    const seams = this.seamLabelsShown ? this.seamLabelAnchors : [];
    const selected = (s) => s.id === this.selectedSeam;
    return [
      ...this.labelAnchors.filter((a) => a.area === undefined).map(({ label }) => ({ label, always: true })),
      ...seams.filter(selected).map(({ label }) => ({ label, always: true })),
      ...this.panelLabels.map(({ label, span }) => ({ label, room: span / this.metersPerPixel() })),
      ...seams.filter((s) => !selected(s)).sort((a, b) => b.length - a.length),
    ];
  }
}

// A panel's area [m^2] (its triangles').
function panelArea(panel) {
  let area = 0;
  for (const [a, b, c] of panel.triangles) {
    const [ax, ay] = panel.vertices[a], [bx, by] = panel.vertices[b], [cx, cy] = panel.vertices[c];
    area += Math.abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2;
  }
  return area;
}
