// A seam being drawn is checked before it is committed (SeamEditor.checkDraft): the worker segments the
// target with it (Op.checkSeams) and draftProblem picks what it would make wrong: its own crossing, or a tiny
// or thin segment the committed seams do not make. Problems are placed as the target stands (its up axis).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { readObjText } from './obj.mjs';
import { handlers, run } from './worker-handlers.mjs';
import { draftProblem } from '../../web/src/app/seam-editor.js';

const sphere = readObjText(readFileSync(new URL('../../web/public/examples/sphere.obj', import.meta.url), 'utf8'));
for (const _ of handlers.setTarget({ positions: sphere.positions, indices: sphere.indices }));

const check = (seams, up) => run(handlers.checkSeams({ seams, up }));
// A loop around the unit sphere at height y, as 3D control points (projected onto the target).
const ring = (y, n = 8) => ({
  closed: true,
  smooth: true,
  points: Array.from({ length: n }, (_, k) => [Math.cos((2 * Math.PI * k) / n), y, Math.sin((2 * Math.PI * k) / n)]),
});

test('a loop drawn beside a committed one is a strip too thin to sew; one drawn apart is not', () => {
  const equator = ring(0);
  const committed = check([equator]).problems;
  assert.deepEqual(committed.map((p) => p.code), [], 'the equator alone makes two good halves');
  const beside = check([equator, ring(0.012)]);
  assert.equal(beside.segments.length, 3);
  const problem = draftProblem(beside.problems, 1, committed);
  assert.equal(problem?.code, 'segment.thin', JSON.stringify(beside.problems));
  assert.equal(problem.text, 'Leaves a strip too thin to sew');
  assert.ok(Math.abs(problem.location[1]) < 0.05, `placed on the strip: ${problem.location}`);
  assert.equal(draftProblem(beside.problems, 1, committed, true).text, 'Closing here: leaves a strip too thin to sew');
  const apart = check([equator, ring(0.5)]);
  assert.equal(apart.segments.length, 3);
  assert.equal(draftProblem(apart.problems, 1, committed), null, JSON.stringify(apart.problems));
  // A thin strip the committed seams already make is not the new seam's doing.
  assert.equal(draftProblem(beside.problems, 2, beside.problems), null);
});

test('a seam that crosses itself is the drawn seam\'s problem, wherever the others are', () => {
  const bowTie = { closed: false, smooth: true, points: [[0.5, 0.9, 1], [-0.5, 0.2, 1], [0.5, 0.2, 1], [-0.5, 0.9, 1]] };
  const result = check([ring(0), bowTie]);
  const problem = draftProblem(result.problems, 1, []);
  assert.equal(problem?.code, 'seam.self-crossing', JSON.stringify(result.problems));
  assert.equal(problem.text, 'Crosses itself here');
  assert.ok(problem.location[2] > 0.5, `at the crossing, on the front: ${problem.location}`);
  // Another seam's crossing is not this one's (and what the layout made before is not new).
  assert.equal(draftProblem(result.problems, 0, result.problems), null);
});

test('a tiny loop cuts off a tiny piece', () => {
  const tiny = { closed: true, smooth: true, points: [[0.02, 0, 1], [-0.02, 0, 1], [0, 0.03, 1]] };
  const result = check([tiny]);
  assert.equal(draftProblem(result.problems, 0, [], true)?.text, 'Closing here: cuts off a tiny piece', JSON.stringify(result.problems));
});

test('problems say where as the target stands on its up axis', () => {
  // A slit from the top of the sphere (+y): "near the top" standing Y up, not when it stands Z up.
  const slit = { closed: false, points: [[0, 1, 0], [0.7, 0.7, 0], [1, 0, 0]] };
  const words = (up) => check([ring(0), slit], up).problems.filter((p) => p.code === 'seam.dangling').map((p) => p.message);
  const yUp = words('+y');
  assert.ok(yUp.some((m) => / near the top /.test(m)), yUp.join(' | '));
  assert.deepEqual(words(undefined), yUp, 'no axis given is Y up');
  const zUp = words('+z');
  assert.ok(zUp.length > 0 && zUp.every((m) => !/ near the top /.test(m)), zUp.join(' | '));
  assert.throws(() => check([ring(0)], 'sideways'), /up axis \(target\.up\) must be one of/);
});
