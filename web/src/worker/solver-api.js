// A small JS layer over the embind module with friendly names. Bulk data is copied into the wasm heap
// from typed arrays and copied out at once (heap views detach when memory grows). Used by the worker
// and, unchanged, by the Node tests.
import { SolverError } from './protocol.js';

const HEAP_BY_TYPE = new Map([
  [Uint8Array, 'HEAPU8'],
  [Float64Array, 'HEAPF64'],
  [Float32Array, 'HEAPF32'],
  [Int32Array, 'HEAP32'],
  [Uint32Array, 'HEAPU32'],
]);

export class SolverApi {
  constructor(module) {
    this.module = module;
  }

  version() {
    return this.module.version();
  }

  // Fabrication outputs of a billow-pattern (JSON text): { svg, dxf, pdf: Uint8Array, statistics, cutLines,
  // outlines, notches, sheet } (wasm/bindings/export_bindings.cpp). options (lengths in mm): { allowance, free_edge_allowance,
  // seam_allowance: { "<seam id>": mm }, sheet_width, notch_spacing, overlap, paper, units, grain_lock, rotate, title }
  exportPattern(patternText, options = {}) {
    const { pdfBase64, ...rest } = SolverApi.unwrap(this.module.exportPattern(patternText, JSON.stringify(options)));
    const binary = atob(pdfBase64);
    const pdf = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; i++) pdf[i] = binary.charCodeAt(i);
    return { ...rest, pdf };
  }

  // The wasm heap's size, where a fresh 1 MB block lands (it rises as the free blocks fragment or leak) and the
  // bytes in use (they rise only with what is held: a leak).
  memoryStats() {
    const probe = this.module._malloc(1 << 20);
    this.module._free(probe);
    return { heapBytes: this.module.HEAPU8.length, probe, inUse: this.module.bytesInUse() };
  }

  // [{ name, label, thickness, youngs_modulus, density, strength }] (wasm/src/simulate/materials.cpp)
  materialPresets() {
    return SolverApi.unwrap(this.module.materialPresets());
  }

  // The looks of a suggestion to optimize: indices into looks ([{ lookRank, family }], suggestLook's), as the command
  // line chooses (chooseLooks in suggest/seam_layouts.hpp).
  chooseLooks(looks, optimize, ofOneFamily) {
    return SolverApi.unwrap(this.module.chooseLooks(JSON.stringify({ looks, optimize, ofOneFamily })));
  }

  // Copies a typed array into a fresh heap allocation; returns the pointer (caller frees).
  toHeap(array) {
    const heap = HEAP_BY_TYPE.get(array.constructor);
    if (!heap) throw new TypeError(`unsupported array type ${array.constructor.name}`);
    const ptr = this.module._malloc(Math.max(array.byteLength, 8));
    if (!ptr) throw new SolverError('memory', 'Billow ran out of memory for this mesh.');
    this.module[heap].set(array, ptr / array.BYTES_PER_ELEMENT);
    return ptr;
  }

  // A copy of count elements of type Type at ptr.
  fromHeap(Type, ptr, count) {
    const heap = this.module[HEAP_BY_TYPE.get(Type)];
    return heap.slice(ptr / Type.BYTES_PER_ELEMENT, ptr / Type.BYTES_PER_ELEMENT + count);
  }

  // Runs fn with the arrays copied into the heap; frees them whatever happens.
  withHeap(arrays, fn) {
    const pointers = [];
    try {
      for (const a of arrays) pointers.push(this.toHeap(a));
      return fn(...pointers);
    } finally {
      for (const p of pointers) this.module._free(p);
    }
  }

  // Parses the {"status": ...} JSON that every binding returns; throws SolverError on "error".
  static unwrap(text) {
    const reply = JSON.parse(text);
    if (reply.status !== 'ok') throw new SolverError(reply.code || 'internal', reply.message || 'Unknown solver error', reply.details);
    return reply.result;
  }

  // A mesh's arrays as the bindings read them from the heap: positions as doubles, indices as int32.
  static meshArrays(positions, indices) {
    return [positions instanceof Float64Array ? positions : Float64Array.from(positions), indices instanceof Int32Array ? indices : Int32Array.from(indices)];
  }

  // positions: #V*3 numbers, indices: #F*3 integers. Returns { report, positions, indices } where indices is a new
  // Uint32Array with any repair applied (report.modified tells) and positions are the ones given, or where a point
  // the surface touched itself at got vertices of its own, a new Float32Array with them last.
  validateTarget(positions, indices) {
    const [pos, idx] = SolverApi.meshArrays(positions, indices);
    return this.withHeap([pos, idx], (pPos, pIdx) => {
      const { positions: split, ...report } = SolverApi.unwrap(this.module.validateTarget(pPos, pos.length / 3, pIdx, idx.length / 3));
      // Repaired in place: turned triangles, and fewer where a triangle's copy was left out (report.stats.triangles).
      const fixed = report.modified ? new Uint32Array(this.fromHeap(Int32Array, pIdx, 3 * report.stats.triangles).buffer) : null;
      return { report, positions: split ? Float32Array.from(split) : positions, indices: fixed ?? Uint32Array.from(idx) };
    });
  }

  // A checked target's thin handles (suggest/thin_handles.hpp): { handles: [loop length, ...] }, thinnest first, and
  // with cut the target cut through them as { positions: Float64Array, indices: Uint32Array } besides.
  thinHandles(positions, indices, cut = false) {
    const [pos, idx] = SolverApi.meshArrays(positions, indices);
    const reply = this.withHeap([pos, idx], (pPos, pIdx) =>
      SolverApi.unwrap(this.module.thinHandles(pPos, pos.length / 3, pIdx, idx.length / 3, cut)));
    if (!cut) return { handles: reply.handles };
    return { handles: reply.handles, positions: Float64Array.from(reply.positions), indices: Uint32Array.from(reply.indices) };
  }

  // An open target turned one way (validateTarget's indices) with its holes capped (mesh/close_holes.hpp):
  // { closed, positions: Float64Array, indices: Uint32Array }.
  closeHoles(positions, indices) {
    const [pos, idx] = SolverApi.meshArrays(positions, indices);
    const reply = this.withHeap([pos, idx], (pPos, pIdx) => SolverApi.unwrap(this.module.closeHoles(pPos, pos.length / 3, pIdx, idx.length / 3)));
    return { closed: reply.closed, positions: Float64Array.from(reply.positions), indices: Uint32Array.from(reply.indices) };
  }

  // A mesh file (bytes: an ArrayBuffer) read by the command line's reader for its extension, refused beyond maxTriangles:
  // { positions: Float64Array, indices: Uint32Array } as the file has them, or a SolverError with the reader's message.
  readMeshFile(fileName, bytes, maxTriangles) {
    const array = new Uint8Array(bytes);
    const reply = this.withHeap([array], (pBytes) => SolverApi.unwrap(this.module.readMeshFile(pBytes, array.length, fileName, maxTriangles)));
    return { positions: Float64Array.from(reply.positions), indices: Uint32Array.from(reply.indices) };
  }

  crashForTesting() {
    this.module.crashForTesting();
  }

  inflation() {
    return new Inflation(this);
  }

  targetSession() {
    return new TargetSession(this);
  }

  // A built-in example pattern (mylar, pillow, sphere3) as billow-pattern JSON text.
  examplePattern(name, triangles = 3000) {
    return SolverApi.unwrap(this.module.examplePattern(name, JSON.stringify({ triangles })));
  }
}

// A stepped inflation of a sewn pattern (wasm InflationSession). Call delete() when done.
export class Inflation {
  constructor(api) {
    this.api = api;
    this.session = new api.module.InflationSession();
  }

  // patternText: billow-pattern JSON text; options: { pressure, tolerance, maxIterations }.
  load(patternText, options = {}) {
    this.info = SolverApi.unwrap(this.session.load(patternText, JSON.stringify(options)));
    return this.info;
  }

  // Restarts from given simulation-vertex positions (#V*3).
  setStart(positions) {
    const p = Float64Array.from(positions);
    this.api.withHeap([p], (ptr) => SolverApi.unwrap(this.session.setStart(ptr, p.length / 3)));
  }

  // Runs Newton iterations for at most maxIterations or maxMillis: { state, iteration, residual, volume, ... }.
  step(maxIterations, maxMillis) {
    return SolverApi.unwrap(this.session.step(maxIterations, maxMillis));
  }

  // The sewn mesh's triangles (#F*3, outward) and outer flags (#F).
  mesh() {
    const s = this.session;
    const F = s.numTriangles();
    return {
      triangles: this.api.fromHeap(Int32Array, s.trianglesPtr(), F * 3),
      outer: this.api.fromHeap(Int32Array, s.outerPtr(), F),
    };
  }

  positions() {
    return this.api.fromHeap(Float64Array, this.session.positionsPtr(), this.session.numVertices() * 3);
  }

  // Everything the panes need, copied out of the heap at once.
  snapshot() {
    const s = this.session;
    const fields = SolverApi.unwrap(s.updateFields());
    const F = s.numTriangles();
    const panels = this.info.panels;
    return {
      ...SolverApi.unwrap(s.result()),
      ...fields,
      positions: this.positions(),
      triangles: this.api.fromHeap(Int32Array, s.trianglesPtr(), F * 3),
      outer: this.api.fromHeap(Int32Array, s.outerPtr(), F),
      compression: this.api.fromHeap(Float64Array, s.compressionPtr(), F * 4),
      stress: this.api.fromHeap(Float64Array, s.stressPtr(), F * 2),
      regime: this.api.fromHeap(Int32Array, s.regimePtr(), F),
      panelVertexStart: this.api.fromHeap(Int32Array, s.panelVertexStartPtr(), panels + 1),
      panelVertexMap: this.api.fromHeap(Int32Array, s.panelVertexMapPtr(), this.info.panelVertices),
    };
  }

  delete() {
    this.session.delete();
  }
}

// The target with its seams (wasm TargetSession): tracing seams and cutting the target into segments.
export class TargetSession {
  constructor(api) {
    this.api = api;
    this.session = new api.module.TargetSession();
  }

  setTarget(positions, indices) {
    const pos = Float64Array.from(positions);
    const idx = Int32Array.from(indices);
    this.api.withHeap([pos, idx], (p, i) => SolverApi.unwrap(this.session.setTarget(p, pos.length / 3, i, idx.length / 3)));
  }

  // seam: { points: [{ face, bary }], closed } -> { curve, faces, barys, controls, controlSamples, length }
  traceSeam(seam) {
    const r = SolverApi.unwrap(this.session.traceSeam(JSON.stringify(seam)));
    return {
      curve: Float32Array.from(r.positions),
      faces: Int32Array.from(r.faces),
      barys: Float64Array.from(r.barys), // full precision: a snapped point must lie exactly on the curve
      controls: Float32Array.from(r.controls),
      controlSamples: Int32Array.from(r.controlIndices),
      length: r.length,
    };
  }

  // seams: [{ points, closed, weight }]; options: { up } (the target's up axis: problems are placed as it
  // stands) -> summary (segments, problems, junctions) and the cut mesh.
  segment(seams, options = {}) {
    const summary = this.checkSeams(seams, options);
    const s = this.session;
    return {
      ...summary,
      positions: new Float32Array(this.api.fromHeap(Float64Array, s.cutPositionsPtr(), s.cutVertices() * 3)),
      indices: new Uint32Array(this.api.fromHeap(Int32Array, s.cutTrianglesPtr(), s.cutTriangles() * 3).buffer),
      faceSegment: this.api.fromHeap(Int32Array, s.faceSegmentPtr(), s.cutTriangles()),
    };
  }

  // The segmentation's summary alone (segments, problems, junctions): what seams being drawn would make.
  checkSeams(seams, options = {}) {
    return SolverApi.unwrap(this.session.segment(JSON.stringify(seams), JSON.stringify(options)));
  }

  // Starts optimizing the panels of these seams; returns the flattened pattern like buildPattern.
  // options: { scale (m per target unit), triangles, pressure [Pa], material { name, thickness, youngs_modulus } }
  startOptimization(seams, options) {
    return SolverApi.unwrap(this.session.startOptimization(JSON.stringify(seams), JSON.stringify(options)));
  }

  // { state: "running"|"converged"|"stopped"|"failed", iteration, distanceRms, distanceMax, seamMismatch, message }
  optimizeStep(maxIterations, maxMillis) {
    return SolverApi.unwrap(this.session.optimizeStep(maxIterations, maxMillis));
  }

  optimizedPositions() {
    return this.api.fromHeap(Float64Array, this.session.optimizedPositionsPtr(), this.session.optimizedVertices() * 3);
  }

  // The optimizer's sewn mesh: { triangles: Int32Array #F*3 (outward), outer: Int32Array #F (1: outer surface) }.
  optimizedMesh() {
    const s = this.session;
    const F = s.optimizedTriangles();
    return {
      triangles: this.api.fromHeap(Int32Array, s.optimizedTrianglesPtr(), F * 3),
      outer: this.api.fromHeap(Int32Array, s.optimizedOuterPtr(), F),
    };
  }

  // The current panels as a pattern object whose "inflated" is their inflated shape.
  optimizedPattern() {
    return SolverApi.unwrap(this.session.optimizedPattern());
  }

  // positions (#V*3, meters) -> { distances: Float32Array #V (signed, meters, positive outside the target),
  // rms, max (of |d| over the target box's diagonal, over the corners of `surface`, #S*3 vertex indices such
  // as the outer triangles; over all points when empty), diagonal [m] }; scale: meters per target unit. With a
  // surface also the other way, the target's to the shape: targetRms, targetMax, uncovered (the parts of the
  // target left out: [{ area, max, position, radius, where }], placed as the target stands on `up`) and
  // uncoveredTriangles (Uint32Array, 3 target vertex indices per triangle of those parts, to draw them).
  // gusseted: the design has a gusset band, so a part too flat asks for a wider one.
  distanceToTarget(positions, scale, surface = [], up = '+y', gusseted = false) {
    const pos = Float64Array.from(positions);
    const tris = Int32Array.from(surface);
    const n = pos.length / 3;
    const summary = this.api.withHeap([pos, tris], (p, t) => SolverApi.unwrap(this.session.distanceToTarget(p, n, scale, t, tris.length / 3, up, gusseted)));
    return this.distanceArrays(summary, n);
  }

  // distanceToTarget of the optimizer's current shape on its outer surface (the target's side as the
  // optimizer's last iterate measured it, not measured again).
  optimizedDistance(scale, up = '+y', gusseted = false) {
    const summary = SolverApi.unwrap(this.session.optimizedDistance(scale, up, gusseted));
    return this.distanceArrays(summary, this.session.optimizedVertices());
  }

  // A distance summary with the per-point distances and the uncovered triangles its call left on the heap.
  distanceArrays(summary, n) {
    const distances = new Float32Array(this.api.fromHeap(Float64Array, this.session.distancesPtr(), n));
    if (summary.targetRms === undefined) return { ...summary, distances };
    const uncoveredTriangles = new Uint32Array(this.api.fromHeap(Int32Array, this.session.uncoveredTrianglesPtr(), 3 * this.session.uncoveredTriangles()).buffer);
    return { ...summary, distances, uncoveredTriangles };
  }

  // The sewn pattern of the current seams: { ok, pattern (object), figures, problems }.
  buildPattern(seams, options) {
    return SolverApi.unwrap(this.session.buildPattern(JSON.stringify(seams), JSON.stringify(options)));
  }

  // { axis: 'x' | 'y' | 'z' | null }: the plane of the target's box across which it is its own mirror image.
  mirrorSymmetry() {
    return SolverApi.unwrap(this.session.mirrorSymmetry());
  }

  // The scene a suggestion at options' size is laid on (buildPattern's options), made ahead: suggestStart at that size
  // takes it on -> { onCopy }.
  suggestPrepare(options) {
    return SolverApi.unwrap(this.session.suggestPrepare(JSON.stringify(options)));
  }

  // Suggested seam layouts: kept (the designer's seams the layouts add to), options: buildPattern's and { panels,
  // symmetry ('x' | 'y' | 'z' | null), maxIterations } -> { proposals: [name] }; then suggestLook(i), a first look at
  // layout i, and suggestOptimize(i, seams, connections), it optimized from the seams and internal connections its look
  // ended with (a look of any worker's; its `copySeams` where it has them): { ok, problem, name, panels, seamLength,
  // sheetUse, distance, inflatedToTarget, targetToInflated, iterations, ms, seams, copySeams, connections, balloon },
  // copySeams the same seams on the simplified copy of a fine target the layouts are laid on (absent where they are
  // laid on the target itself: suggest/seam_layouts.hpp suggestionScene), balloon its inflated
  // outer surface for the card's picture: { positions #V*3 [m], triangles #F*3, distance #V (signed, over the
  // target's diagonal), panel #F } as plain arrays (typed ones would be transferred away with the progress message
  // that brings a layout before the reply brings it again).
  suggestStart(kept, options) {
    return SolverApi.unwrap(this.session.suggestStart(JSON.stringify(kept), JSON.stringify(options)));
  }

  suggestLook(index) {
    return SolverApi.unwrap(this.session.suggestLook(index));
  }

  suggestOptimize(index, seams, connections = []) {
    return SolverApi.unwrap(this.session.suggestOptimize(index, JSON.stringify(seams), JSON.stringify(connections)));
  }

  // The seams with those that make every part a panel (TargetSession.openIntoPanels); options as buildPattern's.
  openIntoPanels(seams, options) {
    return SolverApi.unwrap(this.session.openIntoPanels(JSON.stringify(seams), JSON.stringify(options)));
  }

  delete() {
    this.session.delete();
  }
}
