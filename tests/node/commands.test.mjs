// Design commands are pure and keep the document consistent.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { newDesign } from '../../web/src/app/design.js';
import * as cmd from '../../web/src/app/commands.js';

const p = (face) => ({ face, bary: [1 / 3, 1 / 3, 1 / 3] });

test('seam commands add, move, insert, delete and weigh without mutating their input', () => {
  const d0 = Object.freeze(newDesign('sphere'));
  const d1 = cmd.addSeam(d0, { points: [p(1), p(2), p(3)], closed: true });
  assert.equal(d0.seams.length, 0);
  assert.equal(d1.seams.length, 1);
  assert.equal(d1.seams[0].name, 'Seam 1');
  assert.equal(d1.seams[0].weight, 1);
  const d2 = cmd.moveControlPoint(d1, 0, 1, p(9));
  assert.equal(d2.seams[0].points[1].face, 9);
  assert.equal(d1.seams[0].points[1].face, 2);
  const d3 = cmd.insertControlPoint(d2, 0, 1, p(7));
  assert.deepEqual(d3.seams[0].points.map((q) => q.face), [1, 7, 9, 3]);
  const d4 = cmd.setSeamWeight(d3, 0, 4);
  assert.equal(d4.seams[0].weight, 4);
  assert.equal(cmd.setSeamWeight(d4, 0, -1), d4, 'a negative weight is refused');
  const d5 = cmd.deleteControlPoint(cmd.deleteControlPoint(d4, 0, 0), 0, 0);
  assert.deepEqual(d5.seams[0].points.map((q) => q.face), [9, 3]);
  assert.equal(d5.seams[0].closed, false, 'a loop needs three points');
  assert.equal(cmd.deleteControlPoint(d5, 0, 0).seams.length, 0, 'a seam needs two points');
});

test('deleting a seam drops the internal connections that use it and renumbers the rest', () => {
  let d = newDesign();
  for (let i = 0; i < 4; i++) d = cmd.addSeam(d, { points: [p(i), p(i + 10)], closed: false });
  d = { ...d, connections: [{ seams: [0, 1] }, { seams: [2, 3] }] };
  const after = cmd.deleteSeam(d, 1);
  assert.equal(after.seams.length, 3);
  assert.deepEqual(after.connections, [{ seams: [1, 2] }]);
  assert.equal(cmd.deleteSeam(d, 9), d);
});

test('internal connections join two different seams once, and can be deleted', () => {
  let d = newDesign();
  for (let i = 0; i < 3; i++) d = cmd.addSeam(d, { points: [p(i), p(i + 10)], closed: false });
  const c1 = cmd.addConnection(d, 0, 2);
  assert.deepEqual(c1.connections, [{ seams: [0, 2] }]);
  assert.equal(cmd.addConnection(c1, 2, 0), c1, 'no duplicate');
  assert.equal(cmd.addConnection(c1, 1, 1), c1, 'not to itself');
  assert.equal(cmd.addConnection(c1, 1, 7), c1, 'not to a missing seam');
  assert.deepEqual(cmd.deleteConnection(c1, 0).connections, []);
});
