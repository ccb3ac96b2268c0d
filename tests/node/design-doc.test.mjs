// The design document's pure modules: parse-with-defaults, undo/redo history, URL sharing (links with the
// designer's own mesh: share-link.test.mjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { newDesign, parseDesign } from '../../web/src/app/design.js';
import { History } from '../../web/src/app/history.js';
import { encodeDesign, decodeDesign, MAX_LINK_CHARS } from '../../web/src/app/share.js';

test('parseDesign keeps good fields and unknown ones, defaults bad ones with a warning', () => {
  const good = { ...newDesign('sphere'), size: { height: 0.8 }, extra: { keep: [1, 2] } };
  const { design, warnings } = parseDesign(good);
  assert.deepEqual(warnings, []);
  assert.equal(design.target.example, 'sphere');
  assert.equal(design.size.height, 0.8);
  assert.deepEqual(design.extra, { keep: [1, 2] });
  const bad = parseDesign({ format: 'billow-design', version: 1, target: { example: 'nope' }, size: { height: -3 }, seams: 'x' });
  assert.equal(bad.design.target.example, 'spot');
  assert.equal(bad.design.size.height, 0.6);
  assert.deepEqual(bad.design.seams, []);
  assert.equal(bad.warnings.length, 2);
  assert.equal(bad.targetKnown, false);
});

// The command line writes a mesh's path ({ obj }) or the mesh itself (docs/formats.md); the app must not put those
// seams on its default example, whose faces are another mesh's.
test('parseDesign reads the command line\'s targets as files, and drops seams that have no target to lie on', () => {
  const seams = [{ name: 'outline', closed: true, points: [{ face: 0, bary: [1, 0, 0] }] }];
  const byPath = parseDesign({ ...newDesign(), target: { obj: '../../meshes/octopus.obj', up: '+z' }, seams });
  assert.deepEqual(byPath.design.target, { file: 'octopus.obj', up: '+z' });
  assert.equal(byPath.targetKnown, true);
  assert.deepEqual(byPath.design.seams, seams);
  assert.equal(parseDesign({ ...newDesign(), target: { obj: 'C:\\shapes\\star.obj' } }).design.target.file, 'star.obj');

  const tetrahedron = { vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], triangles: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] };
  const inline = parseDesign({ ...newDesign(), target: tetrahedron, seams }, { inlineName: 'layout-1.obj' });
  assert.deepEqual(inline.design.target, { file: 'layout-1.obj' });
  assert.equal(inline.targetObj.split('\n').length, 8);
  assert.match(inline.targetObj, /^v 0 0 0\n/);
  assert.match(inline.targetObj, /\nf 2 3 4$/, 'faces 1-based, as OBJ numbers them');
  assert.deepEqual(inline.design.seams, seams);

  for (const target of [{ obj: 7 }, { vertices: [[0, 0, 0]], triangles: [[0, 0, 0]] }, { ...tetrahedron, triangles: [[0, 1, 9], ...tetrahedron.triangles.slice(1)] }, undefined]) {
    const { design, warnings, targetKnown } = parseDesign({ ...newDesign(), target, seams, connections: [[0, 0]] });
    assert.equal(targetKnown, false, JSON.stringify(target));
    assert.equal(design.target.example, 'spot');
    assert.deepEqual(design.seams, [], 'seams of a mesh that is not there are not put on the example');
    assert.deepEqual(design.connections, []);
    assert.match(warnings[0], /no target Billow knows/);
  }
});

// Internal connections in either form the design reader takes (docs/formats.md): the app keeps { seams: [i, j] }.
test('parseDesign takes internal connections as seam pairs in either form', () => {
  const { design, warnings } = parseDesign({ ...newDesign('sphere'), connections: [[0, 1], { seams: [1, 2] }] });
  assert.deepEqual(warnings, []);
  assert.deepEqual(design.connections, [{ seams: [0, 1] }, { seams: [1, 2] }]);
});

test('parseDesign refuses what is not a design, and newer versions, with a message', () => {
  assert.throws(() => parseDesign(null), /not a Billow design/);
  assert.throws(() => parseDesign({ format: 'billow-pattern', version: 1 }), /not a Billow design/);
  assert.throws(() => parseDesign({ format: 'billow-design', version: 99 }), /newer Billow/);
  assert.throws(() => parseDesign({ format: 'billow-design', version: 'one' }), /version/);
});

test('history: undo and redo step through snapshots; merged edits are one step', () => {
  const h = new History({ n: 0 });
  const add = (k) => (doc) => ({ n: doc.n + k });
  h.apply(add(1));
  h.apply(add(10), { mergeKey: 'slider', now: 1000 });
  h.apply(add(10), { mergeKey: 'slider', now: 1200 });
  h.apply(add(10), { mergeKey: 'slider', now: 1400 });
  assert.equal(h.present.n, 31);
  assert.equal(h.undo().n, 1, 'the three slider moves undo as one');
  assert.equal(h.undo().n, 0);
  assert.equal(h.canUndo, false);
  assert.equal(h.redo().n, 1);
  assert.equal(h.redo().n, 31);
  assert.equal(h.canRedo, false);
  h.undo();
  h.apply(add(5));
  assert.equal(h.canRedo, false, 'a new edit drops the redo branch');
  assert.equal(h.present.n, 6);
  const same = h.present;
  assert.equal(h.apply((d) => d), same, 'a no-op command adds no step');
  assert.equal(h.past.length, 2);
});

test('history: a gesture is one step however slowly it goes, and ends with endStep', () => {
  const h = new History({ n: 0 });
  const add = (k) => (doc) => ({ n: doc.n + k });
  h.apply(add(1), { mergeKey: 'move:0:1', gesture: true, now: 1000 });
  h.apply(add(1), { mergeKey: 'move:0:1', gesture: true, now: 5000 }); // a pause mid-drag
  h.apply(add(1), { mergeKey: 'move:0:1', gesture: true, now: 9000 });
  h.endStep();
  h.apply(add(10), { mergeKey: 'move:0:1', gesture: true, now: 9100 }); // the same point dragged again
  assert.equal(h.present.n, 13);
  assert.equal(h.undo().n, 3, 'the second drag undoes alone');
  assert.equal(h.undo().n, 0, 'the slow first drag undoes as one');
  h.apply(add(1), { mergeKey: 'slider', now: 1000 });
  h.apply(add(1), { mergeKey: 'slider', now: 5000 });
  assert.equal(h.undo().n, 1, 'without gesture, edits far apart are steps of their own');
});

test('a design survives the URL hash round trip', async () => {
  const design = {
    ...newDesign('blub'),
    seams: [{ name: 'belly <img src=x onerror=alert(1)>', closed: true, weight: 2, points: [{ face: 12, bary: [0.2, 0.3, 0.5] }] }],
  };
  const fragment = await encodeDesign(design);
  assert.match(fragment, /^design=[A-Za-z0-9_-]+$/);
  const back = await decodeDesign(`#${fragment}`);
  assert.deepEqual(back.design, parseDesign(design).design);
  assert.equal(back.design.seams[0].name, design.seams[0].name, 'markup stays plain text data');
});

test('damaged, foreign and oversized links get a message, and no hash means no design', async () => {
  assert.equal(await decodeDesign(''), null);
  assert.equal(await decodeDesign('#view=3'), null);
  await assert.rejects(decodeDesign('#design=%%%'), /readable Billow design/);
  await assert.rejects(decodeDesign('#design=AAAAAAAA'), /readable Billow design/);
  const fragment = await encodeDesign(newDesign());
  await assert.rejects(decodeDesign(`#${fragment.slice(0, fragment.length - 6)}`), /readable|cut short/);
  const notDesign = await encodeDesign({ format: 'something-else' }).catch(() => null);
  await assert.rejects(decodeDesign(`#${notDesign}`), /not a Billow design/);
  const huge = { ...newDesign(), seams: Array.from({ length: 4000 }, (_, i) => ({ points: [{ face: i, bary: [Math.random(), Math.random(), Math.random()] }] })) };
  await assert.rejects(encodeDesign(huge), new RegExp(`too large for a link`));
  assert.ok(MAX_LINK_CHARS > 1000);
});
