// The worker protocol, in one place. Every request carries an id; every reply and progress event echoes it.
//
//   main -> worker   { kind: 'request', id, op, args }      start an operation (ops below)
//                    { kind: 'cancel', id }                 cooperative cancel: checked between steps
//   worker -> main   { kind: 'ready', version }             the wasm module is loaded
//                    { kind: 'progress', id, stage, done, total, detail }
//                    { kind: 'reply', id, ok: true, result } | { kind: 'reply', id, ok: false, error: { code, message } }
//                    { kind: 'crashed', message }           the module trapped; the client replaces the worker
//
// The worker's state is a pure function of the replayable requests it received (the target, later the
// design), so a crashed worker is replaced and those requests are sent again.

export const Op = Object.freeze({
  // { fileName, bytes: ArrayBuffer } -> { report, positions: Float32Array, indices: Uint32Array }
  // Reads OBJ/STL/PLY with the command line's reader (welded), validates (orientation fixed in place) and makes this mesh the target.
  loadTarget: 'loadTarget',
  // Re-installs a target that was already loaded: { positions, indices } -> same as loadTarget.
  setTarget: 'setTarget',
  // { points: [{ face, bary }], closed } -> { curve, faces, barys, controls, controlSamples, length }
  traceSeam: 'traceSeam',
  // { seams: [{ points, closed, weight }], up } -> { segments, problems, junctions, positions, indices, faceSegment }
  // (up: the target's up axis, '+y' when absent; problems say where as the target stands)
  segment: 'segment',
  // { seams, up } -> { segments, problems, junctions }: what these seams would make, for a seam being drawn.
  checkSeams: 'checkSeams',
  // { seams, scale, triangles, pressure, material, up } -> { ok, patternText, figures, problems }: flattened
  // panels of the segments, sewn, with the target shape as the simulation's start. scale: meters per target
  // unit; pressure [Pa]; material { name (preset), thickness [m], youngs_modulus [Pa] }.
  buildPattern: 'buildPattern',
  // { seams, scale, triangles, pressure, material, maxIterations } -> { flattenedText, patternText, status, warnings }:
  // the panels optimized so their inflated shape matches the target; progress streams each iterate's shape, the
  // first with the warnings the panels were made despite ({ code, message, segment, location } in target units).
  optimizeDesign: 'optimizeDesign',
  // {} -> { axis: 'x' | 'y' | 'z' | null }: the target's mirror symmetry plane, where it has one.
  mirrorSymmetry: 'mirrorSymmetry',
  // { scale, triangles, pressure, material, up } -> { onCopy }: the scene a suggestion at that scale is laid on, made
  // ahead while the designer picks the panels (a fine target's simplified copy takes a second or two); suggestLook
  // takes it on.
  suggestPrepare: 'suggestPrepare',
  // { kept (seams), panels, symmetry, scale, triangles, pressure, material, up, maxIterations, indices } ->
  // { tried, notUsed: [{ index, name, why }] }: the seam layouts for the target, of which this worker looks at those
  // of `indices` (all where not given; none: the layouts made ready and counted); progress carries each as it is looked
  // at ({ look: { index, name, panels, seamLength, distance, inflatedToTarget, targetToInflated, rank, lookRank, family,
  // seams, connections, balloon } }, its flattened panels' figures); cancellable. Several workers share one
  // suggestion (web/src/app/suggest-run.js).
  suggestLook: 'suggestLook',
  // { index, seams, connections, ...suggestLook's args } -> layout `index` of that suggestion, optimized at a coarse
  // resolution from the seams and internal connections its look ended with, on any worker (the suggestion started
  // there if it was not: a worker restarted after a crash) -> the look's fields, and sheetUse.
  suggestOptimize: 'suggestOptimize',
  // { looks: [{ lookRank, family }], optimize, ofOneFamily } -> [index into looks]: which of the looks (all workers')
  // to optimize, the best ranked first, at most ofOneFamily of one family, `optimize` in all.
  chooseLooks: 'chooseLooks',
  // { seams, connections, fixed, scale, triangles, up } -> { ok, problem, description, seams }: the seams with those
  // that make every part a panel where they leave one that is not (cuts that open a tube, seams around a handle: the
  // suggested layouts' rule), the first `fixed` (all where not given) as they were, the others as mended (a loop
  // that only grazes the shape left out); ok when every part is then a panel.
  openIntoPanels: 'openIntoPanels',
  // Traps the wasm module on purpose (tests of crash recovery).
  crashForTesting: 'crashForTesting',
  // { patternText, options } -> inflated result (Inflation.snapshot in solver-api.js); stepped, with
  // progress events that carry the sewn mesh first and then streamed positions; cancellable.
  inflatePattern: 'inflatePattern',
  // { name, triangles } -> { patternText }: a built-in example pattern (mylar, pillow, sphere3).
  examplePattern: 'examplePattern',
  // { patternText, options } -> { svg, dxf, pdf: Uint8Array, statistics, cutLines, outlines, notches, sheet }: the cut files and
  // printable tiles of a pattern (see SolverApi.exportPattern for the options).
  exportPattern: 'exportPattern',
  // { positions (#V*3, meters), scale, triangles?, outer?, up? } -> { distances: Float32Array #V, rms, max, diagonal }:
  // signed distance of each point to the target (positive outside), for the inflated pane's "distance to
  // target" colors; rms and max over the diagonal, of the outer surface's vertices when triangles/outer are given.
  distanceToTarget: 'distanceToTarget',
  // {} -> [{ name, label, thickness, youngs_modulus, density, strength }]: the material presets.
  materialPresets: 'materialPresets',
  // {} -> { heapBytes, probe }: the wasm memory's size and where a fresh 1 MB block lands (the top of the
  // allocator's used memory: it rises when anything leaks). For soak tests and the curious.
  memoryStats: 'memoryStats',
});

// Quick operations that only read the worker's state: they run at once, even between the steps of a
// long operation, so drawing stays responsive while the panels inflate, and a new sheet width or allowance
// is drawn while the live optimization runs (the cut lines of a pattern take tens of milliseconds).
export const IMMEDIATE_OPS = new Set([Op.traceSeam, Op.segment, Op.checkSeams, Op.openIntoPanels, Op.distanceToTarget, Op.exportPattern, Op.materialPresets, Op.memoryStats, Op.mirrorSymmetry, Op.chooseLooks]);

// Requests whose effect is part of the worker's state and must be replayed into a fresh worker.
export const REPLAYED_OPS = new Set([Op.setTarget]);

export const ErrorCode = Object.freeze({
  cancelled: 'cancelled',
  crashed: 'worker.crashed',
  unknownOp: 'worker.unknown-op',
  internal: 'internal',
});

export class SolverError extends Error {
  constructor(code, message, details = undefined) {
    super(message);
    this.name = 'SolverError';
    this.code = code;
    this.details = details; // e.g. { report } for a target that failed validation
  }
}

// Typed arrays inside a result, to transfer instead of copy.
export function transferables(value, out = []) {
  if (ArrayBuffer.isView(value)) out.push(value.buffer);
  else if (value instanceof ArrayBuffer) out.push(value);
  else if (value && typeof value === 'object') for (const v of Object.values(value)) transferables(v, out);
  return out;
}
