// One seam suggestion shared by several workers (issue 27): the layouts are independent, so each is looked at
// (suggestLook) and the most promising looks are optimized (suggestOptimize, from the seams each look ended with), each
// by whichever worker is free. No DOM: the app runs it over its helper workers (suggest.js), the tests and the bench
// over workers in Node.
import { ErrorCode, Op } from '../worker/protocol.js';

// The same seams, their names aside: two proposals can end alike once the loops that only grazed the shape are gone
// (as lookAtLayout's `looked` tells them apart for the command line; here across all the workers' looks).
const seamsKey = (seams) => JSON.stringify(seams.map(({ closed, points }) => [closed, points]));

// Lower first, entry by entry, then in the order they were proposed: how the worker ranks them (`rank` for layouts,
// best first: layoutRank in suggest/seam_layouts.hpp, the one rule the command line ranks by too).
export const better = (a, b) => {
  for (let i = 0; i < a.rank.length; i++) if (a.rank[i] !== b.rank[i]) return a.rank[i] - b.rank[i];
  return a.index - b.index;
};

// clients: [{ call(op, args, { onProgress }) -> { promise, cancel } }] (SolverClient's), each with the target set.
// args: suggestLook's (kept, panels, symmetry, scale, triangles, pressure, material, up, maxIterations) and
// `optimize`, how many of the most promising to optimize (by default the solver's kOptimizedLayouts). onProgress gets
// { stage, done, total, detail } as the work goes, with { look } when a layout has been looked at and { layout } when
// one has been optimized.
// Returns { promise -> { layouts (optimized, best first), notUsed: [{ name, why }], tried }, cancel }.
export function suggestLayouts(clients, { optimize, ...args }, { onProgress = () => {} } = {}) {
  const running = new Set();
  const call = (client, op, callArgs, options) => {
    const c = client.call(op, callArgs, options);
    running.add(c);
    const forget = () => running.delete(c);
    c.promise.then(forget, forget);
    return c.promise;
  };
  const cancel = () => {
    for (const c of [...running]) c.cancel();
  };
  const work = async () => {
    const looked = [];
    const notUsed = [];
    const seen = new Set();
    // Every worker makes the layouts ready (the same on each), then takes the next one to look at as it comes free:
    // looks differ by several times, and a fixed share each left one worker idle for a fifth of the looks (the cat
    // at 12 panels, every other layout each: 12.9 s against 18.6 s).
    const ready = await Promise.all(clients.map((client) => call(client, Op.suggestLook, { ...args, indices: [] })));
    const { tried, optimize: optimizeByDefault, ofOneFamily } = ready[0];
    let next = 0;
    let finished = 0;
    await Promise.all(
      clients.map(async (client) => {
        for (let index = next++; index < tried; index = next++) {
          const reply = await call(client, Op.suggestLook, { ...args, indices: [index] }, {
            onProgress: ({ stage, detail, look }) => {
              const progress = { stage, done: finished, total: tried, detail };
              if (!look) return onProgress(progress);
              const key = seamsKey(look.seams);
              if (seen.has(key)) return notUsed.push({ name: look.name, why: 'it ends with the same seams as a layout before it' });
              seen.add(key);
              looked.push(look);
              onProgress({ ...progress, done: finished + 1, detail: undefined, look });
            },
          });
          finished++;
          notUsed.push(...reply.notUsed.map(({ name, why }) => ({ name, why })));
        }
      }),
    );
    // Which to optimize, as the command line chooses (chooseLooks): asked of one worker, all of them having looked.
    const picks = await call(clients[0], Op.chooseLooks, {
      looks: looked.map(({ lookRank, family }) => ({ lookRank, family })),
      optimize: optimize ?? optimizeByDefault,
      ofOneFamily,
    });
    const chosen = picks.map((i) => looked[i]);
    const queue = [...chosen];
    const layouts = [];
    let optimized = 0;
    onProgress({ stage: 'optimizing the most promising layouts', done: 0, total: chosen.length });
    // Each worker takes the most promising layout left when it is free: their times differ by several times.
    await Promise.all(
      clients.map(async (client) => {
        for (let next = queue.shift(); next; next = queue.shift()) {
          // A fine target's layouts are laid on a simplified copy of it: optimized from their seams there.
          const { index, seams, copySeams, connections } = next;
          let layout;
          try {
            layout = await call(client, Op.suggestOptimize, { ...args, index, seams: copySeams ?? seams, connections });
          } catch (error) {
            // A crash or a cancel stops the suggestion; an error of this layout's own (seams the solver would not
            // read, a pattern it refused) leaves this layout out, and the others are still shown.
            if (error.code === ErrorCode.cancelled || error.code === ErrorCode.crashed) throw error;
            layout = { ok: false, problem: `it could not be optimized: ${error.message}` };
          }
          optimized++;
          if (!layout.ok) notUsed.push({ name: next.name, why: layout.problem });
          else layouts.push({ ...layout, description: next.description }); // what its look did to its sections
          onProgress({ stage: 'optimizing the most promising layouts', done: optimized, total: chosen.length, ...(layout.ok ? { layout } : {}) });
        }
      }),
    );
    return { layouts: layouts.sort(better), notUsed, tried };
  };
  const promise = work();
  // One worker's failure (a crash, a cancel) stops the others.
  promise.catch(cancel);
  return { promise, cancel };
}
