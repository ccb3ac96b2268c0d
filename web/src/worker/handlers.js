// The worker's operations (see protocol.js). Each is a generator: it yields progress between steps.
import { Op, SolverError } from './protocol.js';
import { parseMesh } from '../io/mesh-loaders.js';

export function createHandlers(api) {
  const state = { target: null };

  function* installTarget(positions, indices) {
    yield { stage: 'checking the mesh', done: 2, total: 3 };
    const { report, indices: fixed } = api.validateTarget(positions, indices);
    if (!report.ok) {
      const errors = report.issues.filter((i) => i.severity === 'error');
      throw new SolverError('target.invalid', errors.map((i) => i.message).join('\n'), { report });
    }
    state.target = { positions, indices: fixed };
    return { report, positions: positions.slice(), indices: fixed.slice() };
  }

  return {
    *[Op.loadTarget]({ fileName, bytes }) {
      yield { stage: 'reading the file', done: 0, total: 3 };
      const mesh = parseMesh(fileName, bytes);
      yield { stage: 'welding vertices', done: 1, total: 3 };
      return yield* installTarget(mesh.positions, mesh.indices);
    },
    *[Op.setTarget]({ positions, indices }) {
      return yield* installTarget(positions, indices);
    },
    *[Op.crashForTesting]() {
      api.crashForTesting();
    },
  };
}
