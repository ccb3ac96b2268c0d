// The worker protocol end to end in Node: the real SolverClient, and the worker's Runner and handlers (serve.js)
// over the wasm module, with an in-process stand-in for the Web Worker (same message passing, asynchronous).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { loadApi } from './load-module.mjs';
import { SolverClient } from '../../web/src/worker/client.js';
import { serveSolver } from '../../web/src/worker/serve.js';
import { Op, ErrorCode } from '../../web/src/worker/protocol.js';

const MESHES = fileURLToPath(new URL('../../../shared/meshes', import.meta.url));
const bytesOf = (name) => {
  const b = readFileSync(`${MESHES}/${name}`);
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength);
};

// A Worker look-alike: structured-clone messages both ways, a fresh wasm module per instance.
class InProcessWorker {
  static started = 0;
  constructor() {
    InProcessWorker.started += 1;
    this.terminated = false;
    this.early = [];
    loadApi().then((api) => {
      ({ receive: this.receive, runner: this.runner } = serveSolver(api, (message) => {
        const copy = structuredClone(message);
        queueMicrotask(() => !this.terminated && this.onmessage?.({ data: copy }));
      }));
      for (const m of this.early.splice(0)) this.receive(m);
    });
  }
  postMessage(message) {
    const copy = structuredClone(message);
    queueMicrotask(() => (this.receive ? this.receive(copy) : this.early.push(copy)));
  }
  terminate() {
    this.terminated = true;
  }
}

function newClient(hooks = {}) {
  return new SolverClient(() => new InProcessWorker(), hooks);
}

test('loadTarget replies to its request id with the welded, validated mesh and reports progress', async () => {
  const client = newClient();
  const stages = [];
  const { promise, id } = client.call(Op.loadTarget, { fileName: 'spot.obj', bytes: bytesOf('spot.obj') }, {
    onProgress: (p) => {
      assert.equal(p.id, id);
      stages.push(p.stage);
    },
  });
  const result = await promise;
  assert.equal(result.report.ok, true);
  assert.equal(result.report.stats.triangles, 5856);
  assert.equal(result.indices.length, 5856 * 3);
  assert.equal(result.positions.length, 2930 * 3);
  assert.deepEqual(stages, ['reading the file', 'checking the mesh']);
});

test('a broken file is rejected with a designer-facing message and its report', async () => {
  const client = newClient();
  const text = readFileSync(`${MESHES}/sphere.obj`, 'utf8').split('\n');
  const firstFace = text.findIndex((l) => l.startsWith('f '));
  text.splice(firstFace, 1); // one triangle fewer: a hole
  const bytes = new TextEncoder().encode(text.join('\n')).buffer;
  await assert.rejects(client.request(Op.loadTarget, { fileName: 'holey.obj', bytes }), (error) => {
    assert.equal(error.code, 'target.invalid');
    assert.match(error.message, /must be closed/);
    assert.ok(error.details.report.issues.some((i) => i.code === 'mesh.open'));
    return true;
  });
  await assert.rejects(
    client.request(Op.loadTarget, { fileName: 'notes.txt', bytes: new TextEncoder().encode('hello').buffer }),
    /OBJ, STL, PLY or OFF/,
  );
  await assert.rejects(
    client.request(Op.loadTarget, { fileName: 'empty.obj', bytes: new ArrayBuffer(0) }),
    (e) => e.code === 'mesh.empty-file' && e.message === '"empty.obj" is empty: the file holds no mesh.',
  );
  await assert.rejects(
    client.request(Op.loadTarget, { fileName: 'garbage.obj', bytes: new Uint8Array([0, 1, 2, 255]).buffer }),
    (e) => e.code === 'obj.no-faces' && /no faces/.test(e.message),
  );
  // The command line's reader names where a file is damaged.
  const damaged = readFileSync(`${MESHES}/sphere.obj`, 'utf8').replace(/\nf (\d+) /, '\nf $1x ');
  await assert.rejects(
    client.request(Op.loadTarget, { fileName: 'damaged.obj', bytes: new TextEncoder().encode(damaged).buffer }),
    (e) => e.code === 'obj.syntax' && /line \d+: '\d+x' is not a vertex index/.test(e.message),
  );
  // A coordinate that is not a number reaches validation as it is, which names it.
  const nan = readFileSync(`${MESHES}/sphere.obj`, 'utf8').replace(/\nv (\S+) /, '\nv nan ');
  await assert.rejects(client.request(Op.loadTarget, { fileName: 'nan.obj', bytes: new TextEncoder().encode(nan).buffer }), (e) => {
    assert.equal(e.code, 'target.invalid');
    assert.match(e.message, /1 vertex has invalid coordinates/);
    return true;
  });
});

// Some exporters write a vertex for each face corner; STL always does. Every format opens as the command line reads it:
// corners at one place welded, the faces in the file's order, so a design's seam points (face, bary) hold across them.
test('an OBJ written a vertex per corner and an STL of the same shape open as the same mesh as its indexed OBJ', async () => {
  const client = newClient();
  const indexed = await client.request(Op.loadTarget, { fileName: 'spot.obj', bytes: bytesOf('spot.obj') });
  const lines = readFileSync(`${MESHES}/spot.obj`, 'utf8').split('\n');
  const vertices = lines.filter((l) => l.startsWith('v ')).map((l) => l.trim().split(/\s+/).slice(1, 4));
  const faces = lines.filter((l) => l.startsWith('f ')).map((l) => l.trim().split(/\s+/).slice(1, 4).map((w) => Number(w.split('/')[0]) - 1));
  const perCorner = [...faces.flatMap((f) => f.map((i) => `v ${vertices[i].join(' ')}`)), ...faces.map((_, t) => `f ${3 * t + 1} ${3 * t + 2} ${3 * t + 3}`)].join('\n');
  const stl = new DataView(new ArrayBuffer(84 + 50 * faces.length));
  stl.setUint32(80, faces.length, true);
  faces.forEach((f, t) => f.forEach((i, c) => vertices[i].forEach((x, k) => stl.setFloat32(84 + 50 * t + 12 + 12 * c + 4 * k, Number(x), true))));
  for (const [fileName, bytes] of [['per-corner.obj', new TextEncoder().encode(perCorner).buffer], ['spot.stl', stl.buffer]]) {
    const read = await client.request(Op.loadTarget, { fileName, bytes });
    assert.equal(read.report.ok, true, fileName);
    assert.deepEqual(read.report.stats, indexed.report.stats, fileName);
    assert.deepEqual([...read.indices], [...indexed.indices], `${fileName}: the same triangles over the same vertices`);
    assert.ok(read.positions.every((x, k) => Math.abs(x - indexed.positions[k]) < 1e-6), `${fileName}: the same positions`);
  }
});

// spot.obj as a binary little-endian PLY: its vertices, and its triangles as faces, or as triangle strips of one
// triangle each (each ended by -1), or none at all (a point cloud).
function spotPly(triangles) {
  const lines = readFileSync(`${MESHES}/spot.obj`, 'utf8').split('\n');
  const vertices = lines.filter((l) => l.startsWith('v ')).map((l) => l.split(/\s+/).slice(1, 4).map(Number));
  const faces = lines.filter((l) => l.startsWith('f ')).map((l) => l.split(/\s+/).slice(1, 4).map((w) => Number(w.split('/')[0]) - 1));
  const element = { faces: `element face ${faces.length}\nproperty list uchar int vertex_indices\n`, strips: 'element tristrips 1\nproperty list int int vertex_indices\n', none: '' }[triangles];
  const header = `ply\nformat binary_little_endian 1.0\nelement vertex ${vertices.length}\nproperty float x\nproperty float y\nproperty float z\n${element}end_header\n`;
  const body = [];
  const view = (bytes, write) => {
    const b = new DataView(new ArrayBuffer(bytes));
    write(b);
    body.push(new Uint8Array(b.buffer));
  };
  for (const v of vertices) view(12, (b) => v.forEach((x, k) => b.setFloat32(4 * k, x, true)));
  if (triangles === 'faces') for (const f of faces) view(13, (b) => (b.setUint8(0, 3), f.forEach((i, k) => b.setInt32(1 + 4 * k, i, true))));
  if (triangles === 'strips') {
    const list = faces.flatMap((f) => [...f, -1]);
    view(4 * (list.length + 1), (b) => (b.setInt32(0, list.length, true), list.forEach((i, k) => b.setInt32(4 * (k + 1), i, true))));
  }
  return new Blob([header, ...body]).arrayBuffer();
}

test('a PLY file opens through the command line\'s reader: its faces, its triangle strips, and a point cloud says what it is', async () => {
  const client = newClient();
  const obj = await client.request(Op.loadTarget, { fileName: 'spot.obj', bytes: bytesOf('spot.obj') });
  for (const triangles of ['faces', 'strips']) {
    const ply = await client.request(Op.loadTarget, { fileName: `spot-${triangles}.PLY`, bytes: await spotPly(triangles) });
    assert.equal(ply.report.ok, true, triangles);
    assert.deepEqual(ply.report.stats, obj.report.stats, triangles);
    assert.deepEqual([...ply.indices], [...obj.indices], `${triangles}: the same triangles, facing the same way`);
  }
  await assert.rejects(client.request(Op.loadTarget, { fileName: 'scan.ply', bytes: await spotPly('none') }), (e) => {
    assert.equal(e.code, 'ply.no-faces');
    assert.match(e.message, /no faces \(it may be a point cloud\)/);
    return true;
  });
  // Cut off: early, the header's counts are more than the file holds; late, in its last face.
  const whole = await spotPly('faces');
  await assert.rejects(client.request(Op.loadTarget, { fileName: 'cut.ply', bytes: whole.slice(0, 5000) }), (e) => e.code === 'ply.bad-count' && /damaged or cut off/.test(e.message));
  await assert.rejects(client.request(Op.loadTarget, { fileName: 'cut.ply', bytes: whole.slice(0, whole.byteLength - 6) }), (e) => e.code === 'ply.truncated' && /face 5855/.test(e.message));
});

test('an OFF file opens through the command line\'s reader as its OBJ does, and a cut-off one says so', async () => {
  const client = newClient();
  const obj = await client.request(Op.loadTarget, { fileName: 'spot.obj', bytes: bytesOf('spot.obj') });
  const lines = readFileSync(`${MESHES}/spot.obj`, 'utf8').split('\n');
  const vertices = lines.filter((l) => l.startsWith('v ')).map((l) => l.split(/\s+/).slice(1, 4).join(' '));
  const faces = lines.filter((l) => l.startsWith('f ')).map((l) => `3 ${l.split(/\s+/).slice(1, 4).map((w) => Number(w.split('/')[0]) - 1).join(' ')}`);
  const text = `OFF\n${vertices.length} ${faces.length} 0\n${vertices.join('\n')}\n${faces.join('\n')}\n`;
  const off = await client.request(Op.loadTarget, { fileName: 'spot.off', bytes: new TextEncoder().encode(text).buffer });
  assert.equal(off.report.ok, true);
  assert.deepEqual(off.report.stats, obj.report.stats);
  assert.deepEqual([...off.indices], [...obj.indices], 'the same triangles, facing the same way');
  const cut = new TextEncoder().encode(text.slice(0, text.lastIndexOf('\n3 '))).buffer;
  await assert.rejects(client.request(Op.loadTarget, { fileName: 'cut.off', bytes: cut }), (e) => e.code === 'off.truncated' && /after 5,855 faces of the 5,856/.test(e.message));
});

test('cancel stops a request between steps', async () => {
  const client = newClient();
  await client.ready;
  const { promise, cancel } = client.call(Op.loadTarget, { fileName: 'spot.obj', bytes: bytesOf('spot.obj') }, {
    onProgress: () => cancel(),
  });
  await assert.rejects(promise, (e) => e.code === ErrorCode.cancelled);
  // The worker still answers afterwards.
  const ok = await client.request(Op.loadTarget, { fileName: 'sphere.obj', bytes: bytesOf('sphere.obj') });
  assert.equal(ok.report.ok, true);
});

test('latest: a newer call of the same kind cancels the older, which reports nothing more; only the newest answers', async () => {
  const client = newClient();
  await client.ready;
  const progress = { first: 0, second: 0 };
  const first = client.latest('target', Op.loadTarget, { fileName: 'spot.obj', bytes: bytesOf('spot.obj') }, {
    onProgress: () => (progress.first += 1),
  });
  assert.equal(client.running('target'), true);
  const second = client.latest('target', Op.loadTarget, { fileName: 'sphere.obj', bytes: bytesOf('sphere.obj') }, {
    onProgress: () => (progress.second += 1),
  });
  const seenByFirst = progress.first;
  await assert.rejects(first.promise, (e) => e.code === ErrorCode.cancelled);
  const result = await second.promise;
  assert.equal(result.report.ok, true);
  assert.equal(progress.first, seenByFirst, 'no progress of a superseded call');
  assert.ok(progress.second > 0);
  assert.equal(client.running('target'), false);
  // Another kind is left alone; a supersede with nothing running does nothing.
  client.supersede('segmentation');
  const other = client.latest('presets', Op.materialPresets, {});
  client.latest('target', Op.loadTarget, { fileName: 'sphere.obj', bytes: bytesOf('sphere.obj') }).promise.catch(() => {});
  assert.ok((await other.promise).length > 0);
  client.supersede('target');
  // The worker keeps no cancel of a request it has already answered.
  const done = client.call(Op.materialPresets, {});
  await done.promise;
  client.worker.postMessage({ kind: 'cancel', id: done.id });
  await client.request(Op.setTarget, { positions: result.positions, indices: result.indices }); // queued after the rest
  assert.equal(client.worker.runner.cancelled.size, 0);
  assert.equal(client.worker.runner.unfinished.size, 0);
});

test('the cut lines of a pattern are drawn while a long inflation runs, not after it', async () => {
  const client = newClient();
  await client.ready;
  const { patternText } = await client.request(Op.examplePattern, { name: 'sphere3', triangles: 3000 });
  const order = [];
  const inflation = client.request(Op.inflatePattern, { patternText }).then(() => order.push('inflated'));
  const cut = client.request(Op.exportPattern, { patternText, options: { sheet_width: 1000 } }).then((result) => {
    order.push('cut');
    return result;
  });
  assert.ok((await cut).statistics.totals.sheet_width_mm > 0);
  await inflation;
  assert.deepEqual(order, ['cut', 'inflated']);
});

test('a crashed worker is replaced, the target replayed, and the crash loop is bounded', async () => {
  const crashes = [];
  const client = newClient({ onCrash: (c) => crashes.push(c) });
  const loaded = await client.request(Op.loadTarget, { fileName: 'sphere.obj', bytes: bytesOf('sphere.obj') });
  client.remember(Op.setTarget, { positions: loaded.positions, indices: loaded.indices });
  const started = InProcessWorker.started;
  await assert.rejects(client.request(Op.crashForTesting), (e) => e.code === ErrorCode.crashed);
  assert.equal(crashes.length, 1);
  assert.equal(InProcessWorker.started, started + 1, 'a fresh worker was started');
  await crashes[0].replayed;
  // The new worker has the target again and serves requests.
  const again = await client.request(Op.setTarget, { positions: loaded.positions, indices: loaded.indices });
  assert.equal(again.report.stats.triangles, 1280);
  // Crash after crash with no success in between: the client gives up instead of looping.
  for (let i = 0; i < 4; i++) await client.request(Op.crashForTesting).catch(() => {});
  assert.equal(client.broken, true);
  await assert.rejects(client.request(Op.setTarget, {}), /Reload the page/);
});
