// The worker's operations (see protocol.js). Each is a generator: it yields progress between steps.
import { Op, SolverError } from './protocol.js';
import { parseMesh } from '../io/mesh-loaders.js';

const STEP_ITERATIONS = 1000; // a step ends on time, not on count
export const STEP_MILLIS = 30; // short steps keep cancel responsive
const PANELS_EVERY_MS = 500; // how often an optimization streams its panels (their JSON costs a little)
const PREVIEW_MILLIS = 120; // how often the inflating shape is streamed to the page

// A distanceToTarget's figures without its per-vertex arrays (both ways: see SolverApi.distanceToTarget).
function distanceSummary({ rms, max, diagonal, targetRms, targetMax, uncovered, uncoveredDistance }) {
  return { rms, max, diagonal, targetRms, targetMax, uncovered, uncoveredDistance };
}

export function createHandlers(api) {
  const state = { target: null };

  // cutThinHandles: the design has its thin handles cut through (suggest/thin_handles.hpp). On a shape with handles
  // the report also tells its thin ones (report.thinHandles: their loops' lengths, in the mesh's units), or how many
  // were cut (report.thinHandlesCut).
  // closeHoles: the design has an open mesh's holes capped (mesh/close_holes.hpp; report.holesClosed says how many).
  // An open mesh refused otherwise says whether that would make it usable (the error's details.closable).
  function* installTarget(positions, indices, { cutThinHandles = false, closeHoles = false } = {}) {
    yield { stage: 'checking the mesh', done: 2, total: 3 };
    let report, fixed;
    ({ report, positions, indices: fixed } = api.validateTarget(positions, indices));
    const onlyHoles = (r) => r.issues.every((i) => i.severity !== 'error' || i.code === 'mesh.open');
    let holesClosed = 0;
    const facesRead = fixed.length / 3; // the file's own faces: closing and cutting append theirs after them
    if (!report.ok && closeHoles && onlyHoles(report)) {
      yield { stage: 'closing its holes', done: 2, total: 3 };
      const capped = api.closeHoles(positions, fixed);
      positions = Float32Array.from(capped.positions);
      holesClosed = capped.closed;
      ({ report, positions, indices: fixed } = api.validateTarget(positions, capped.indices));
    }
    if (!report.ok) {
      const errors = report.issues.filter((i) => i.severity === 'error');
      throw new SolverError('target.invalid', errors.map((i) => i.message).join('\n'), { report, closable: !closeHoles && onlyHoles(report) });
    }
    if (holesClosed) report.holesClosed = holesClosed;
    let thin = [];
    if (report.stats.genus > 0) {
      yield { stage: cutThinHandles ? 'cutting through its thin handles' : 'measuring its handles', done: 2, total: 3 };
      const found = api.thinHandles(positions, fixed, cutThinHandles);
      if (cutThinHandles && found.handles.length) {
        positions = Float32Array.from(found.positions);
        ({ report, positions, indices: fixed } = api.validateTarget(positions, found.indices));
        report.thinHandlesCut = found.handles.length;
      } else if (!cutThinHandles) thin = found.handles;
    }
    report.thinHandles = thin;
    if (fixed.length / 3 > facesRead) report.facesRead = facesRead;
    state.target = { positions, indices: fixed };
    state.suggestion = null; // the session forgets it with its target
    state.session ??= api.targetSession();
    state.session.setTarget(positions, fixed);
    return { report, positions: positions.slice(), indices: fixed.slice() };
  }

  // The suggestion these seams and options make, started unless it is the one this worker started last on its target.
  function startSuggestion(kept, options) {
    const key = JSON.stringify([kept, options]);
    if (state.suggestion?.key !== key) state.suggestion = { key, ...requireSession().suggestStart(kept, options) };
    return state.suggestion;
  }

  function requireSession() {
    if (!state.session || !state.target) throw new SolverError('seams.no-target', 'Load a target before drawing seams.');
    return state.session;
  }

  // The outer triangles (#S*3 vertex indices) of a sewn mesh: the distance figures are taken over them
  // (internal panels lie inside by design), as the optimizer and `billow design` measure them.
  function outerSurface(triangles, outer) {
    const surface = [];
    if (triangles && outer)
      for (let f = 0; f < outer.length; f++) if (outer[f]) surface.push(triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]);
    return surface;
  }

  return {
    *[Op.loadTarget]({ fileName, bytes, cutThinHandles, closeHoles }) {
      yield { stage: 'reading the file', done: 0, total: 3 };
      const mesh = parseMesh(fileName, bytes, (...file) => api.readMeshFile(...file));
      return yield* installTarget(mesh.positions, mesh.indices, { cutThinHandles, closeHoles });
    },
    *[Op.setTarget]({ positions, indices, cutThinHandles, closeHoles }) {
      return yield* installTarget(positions, indices, { cutThinHandles, closeHoles });
    },
    // { patternText, options } -> snapshot (see Inflation.snapshot). Streams the shape while it inflates.
    *[Op.inflatePattern]({ patternText, options = {} }) {
      const inflation = api.inflation();
      try {
        // load() also roughs out the shape of a large pattern by inflating a coarser version of it first.
        yield { stage: 'reading the pattern and roughing out its shape' };
        const info = inflation.load(patternText, options);
        yield { stage: 'inflating', iteration: 0, warnings: info.warnings, ...inflation.mesh(), positions: inflation.positions() };
        let lastPreview = performance.now();
        for (;;) {
          const status = inflation.step(STEP_ITERATIONS, STEP_MILLIS);
          if (status.state === 'failed') throw new SolverError('inflate.failed', status.message);
          if (status.state === 'converged') break;
          const progress = { stage: 'inflating', iteration: status.iteration, residual: status.residual };
          if (performance.now() - lastPreview > PREVIEW_MILLIS) {
            lastPreview = performance.now();
            progress.positions = new Float32Array(inflation.positions());
          }
          yield progress;
        }
        return { ...inflation.snapshot(), warnings: info.warnings };
      } finally {
        inflation.delete();
      }
    },
    // { points, closed } -> the seam's curve on the target (see TargetSession.traceSeam).
    *[Op.traceSeam](seam) {
      return requireSession().traceSeam(seam);
    },
    // { seams, up } -> the segmentation (see TargetSession.segment).
    *[Op.segment]({ seams, up }) {
      yield { stage: 'cutting the target along the seams' };
      return requireSession().segment(seams, { up });
    },
    // { seams, up } -> the segmentation's summary: what a seam being drawn would make.
    *[Op.checkSeams]({ seams, up }) {
      return requireSession().checkSeams(seams, { up });
    },
    // { seams, connections, fixed, scale, triangles, up } -> the seams with those that make every part a panel.
    *[Op.openIntoPanels]({ seams, ...options }) {
      yield { stage: 'adding the seams that make every part a panel' };
      return requireSession().openIntoPanels(seams, options);
    },
    // { seams, scale, triangles, pressure, material } -> { ok, patternText, figures, problems }
    *[Op.buildPattern]({ seams, triangles = 3000, ...physics }) {
      yield { stage: 'flattening the segments into panels' };
      const { pattern, ...rest } = requireSession().buildPattern(seams, { triangles, ...physics });
      return { ...rest, patternText: JSON.stringify(pattern) };
    },
    // { seams, scale, triangles, pressure, material } -> { flattenedText, patternText (optimized), history }.
    // Streams { stage, iteration, distanceRms, positions } as the optimizer improves the panels (Sec. 5).
    *[Op.optimizeDesign]({ seams, triangles = 1000, maxIterations = 400, gusseted = false, ...physics }) {
      const scale = physics.scale;
      yield { stage: 'flattening the segments into panels' };
      const session = requireSession();
      const start = session.startOptimization(seams, { triangles, ...physics });
      if (!start.ok) {
        const errors = start.problems.filter((p) => p.severity === 'error');
        throw new SolverError('pattern.not-built', errors.map((p) => p.message).join('\n') || 'These seams do not give panels yet.', { problems: errors });
      }
      const flattenedText = JSON.stringify(start.pattern);
      // What the panels were made despite (a segment that folds when laid flat, a seam with no panel across it):
      // the designer hears of it with the first look and with the result.
      const warnings = start.problems.filter((p) => p.severity === 'warning');
      // Every iterate streams: its inflated shape with its distance to the target, and every half second
      // the panels themselves (paper Sec. 5: the designer watches the optimization).
      let mesh = session.optimizedMesh();
      const iterate = () => {
        const positions = session.optimizedPositions();
        const d = scale > 0 ? session.optimizedDistance(scale, physics.up, gusseted) : null;
        return { positions: new Float32Array(positions), distances: d?.distances, uncoveredTriangles: d?.uncoveredTriangles, distance: d && distanceSummary(d) };
      };
      // Copies: typed arrays in a message are transferred away, and the mesh is needed for every iterate.
      const meshOf = () => ({ triangles: mesh.triangles.slice(), outer: mesh.outer.slice() });
      yield { stage: 'optimizing', iteration: 0, flattenedText, warnings, ...meshOf(), ...iterate() };
      // The flattened panels inflated (the first equilibrium, iteration 0 again): the first look at the balloon,
      // one solve after the panels instead of one optimizer iteration later.
      // Panels meshed anew (the coarse first phase's end, sliding seams) make a new sewn mesh: its triangles go
      // with the iterate.
      let remeshings = 0;
      const remeshed = () => {
        if (status.remeshings === remeshings) return false;
        remeshings = status.remeshings;
        mesh = session.optimizedMesh();
        return true;
      };
      let status = session.optimizeStep(0, STEP_MILLIS);
      if (status.state === 'failed') throw new SolverError('optimize.failed', status.message);
      const startMesh = remeshed() ? meshOf() : {}; // the design's mesh when its coarse one did not settle
      yield { stage: 'optimizing', ...status, ...iterate(), ...startMesh };
      let lastPanels = performance.now();
      for (;;) {
        status = session.optimizeStep(1, STEP_MILLIS);
        if (status.state === 'failed') throw new SolverError('optimize.failed', status.message);
        const newMesh = remeshed() ? meshOf() : {};
        const panels = performance.now() - lastPanels > PANELS_EVERY_MS ? { patternText: JSON.stringify(session.optimizedPattern()) } : {};
        if (panels.patternText) lastPanels = performance.now();
        yield { stage: 'optimizing', ...status, ...iterate(), ...newMesh, ...panels };
        if (status.state !== 'running' || status.iteration >= maxIterations) break;
      }
      return { flattenedText, patternText: JSON.stringify(session.optimizedPattern()), status, warnings };
    },
    *[Op.mirrorSymmetry]() {
      return requireSession().mirrorSymmetry();
    },
    // Seam layouts for the target (suggest/seam_layouts.hpp) and the first look at those of `indices` (all of them
    // where not given): several workers share one suggestion, each handed the next layout as it comes free
    // (web/src/app/suggest-run.js). One layout a step, so progress shows and a cancel stops between layouts.
    *[Op.suggestLook]({ kept = [], indices, ...options }) {
      const session = requireSession();
      const { proposals, optimize, ofOneFamily } = startSuggestion(kept, options);
      const mine = indices ?? [...proposals.keys()];
      const notUsed = [];
      for (const [k, index] of mine.entries()) {
        yield { stage: 'a first look at each layout', done: k, total: mine.length, detail: proposals[index] };
        const r = session.suggestLook(index);
        // Usable at once: its flattened panels' figures until it is optimized.
        if (r.ok) yield { stage: 'a first look at each layout', done: k + 1, total: mine.length, look: { index, ...r } };
        else notUsed.push({ index, name: proposals[index], why: r.problem });
      }
      return { tried: proposals.length, notUsed, optimize, ofOneFamily };
    },
    *[Op.suggestPrepare](options) {
      state.suggestion = null; // the session's suggestion is this preparation now
      return requireSession().suggestPrepare(options);
    },
    // A layout of the suggestion, optimized at its coarse resolution from the seams and internal connections its look
    // (on this worker or another) ended with; the suggestion is started here too where this worker has not (restarted
    // after a crash).
    *[Op.suggestOptimize]({ index, seams, connections = [], kept = [], ...options }) {
      startSuggestion(kept, options);
      yield { stage: 'optimizing the layout' };
      return { index, ...requireSession().suggestOptimize(index, seams, connections) };
    },
    *[Op.chooseLooks]({ looks, optimize, ofOneFamily }) {
      return api.chooseLooks(looks, optimize, ofOneFamily);
    },
    *[Op.exportPattern]({ patternText, options }) {
      yield { stage: 'laying out the panels' };
      return api.exportPattern(patternText, options);
    },
    *[Op.distanceToTarget]({ positions, scale, triangles = null, outer = null, up, gusseted = false }) {
      return requireSession().distanceToTarget(positions, scale, outerSurface(triangles, outer), up, gusseted);
    },
    *[Op.memoryStats]() {
      return api.memoryStats();
    },
    *[Op.materialPresets]() {
      return api.materialPresets();
    },
    *[Op.examplePattern]({ name, triangles }) {
      return { patternText: JSON.stringify(api.examplePattern(name, triangles)) };
    },
    *[Op.crashForTesting]() {
      api.crashForTesting();
    },
  };
}
