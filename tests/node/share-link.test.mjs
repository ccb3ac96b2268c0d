// Share links with the designer's own mesh (web/src/app/share.js, mesh-link.js, shared-link.js): every
// mesh of ../shared/meshes travels in a link with a typical design, comes back with the same triangles and
// positions within the grid's half step, and the design's seam points land where they were; damaged mesh
// parts give the designer's message; a mesh too large for a link leaves a link that asks for its file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { encodeDesign, decodeDesign, linkNotice, MAX_LINK_CHARS } from '../../web/src/app/share.js';
import { packMesh, unpackMesh } from '../../web/src/app/mesh-link.js';
import { QUANT_BITS } from '../../web/src/app/mesh-grid.js';
import { deflate, toBase64Url } from '../../web/src/app/link-bytes.js';
import { awaitTarget } from '../../web/src/app/shared-link.js';
import { parseDesign } from '../../web/src/app/design.js';
import { readObjText } from './obj.mjs';

const MESHES = fileURLToPath(new URL('../../../shared/meshes', import.meta.url));
const LINKED_TRIANGLES = 20000; // every mesh up to this many triangles must travel in its link
const DAMAGED = /target shape in this link is damaged/;

// As the app holds a target: float32 positions (the worker's), integer indices.
function readMesh(name) {
  const { positions, indices } = readObjText(readFileSync(`${MESHES}/${name}`, 'utf8'));
  return { positions: Float32Array.from(positions), indices: Uint32Array.from(indices) };
}

// A deterministic stand-in for Math.random.
function random(seed) {
  let s = seed;
  return () => (s = (Math.imul(s, 1103515245) + 12345) >>> 0) / 2 ** 32;
}

// A design as the app draws it: seams of surface points with full-precision barycentrics, a point snapped
// onto another seam, a plain 3D point, and everything else a design has.
function typicalDesign(file, triangles, seed = 7) {
  const rand = random(seed);
  const point = () => {
    const a = rand();
    const b = rand() * (1 - a);
    return { face: Math.floor(rand() * triangles), bary: [a, b, 1 - a - b] };
  };
  const seams = Array.from({ length: 6 }, (_, i) => ({
    name: `seam ${i + 1}`, closed: i % 2 === 0, weight: i === 5 ? 0.05 : 1,
    points: Array.from({ length: 12 }, point),
  }));
  seams[1].points[0] = { ...point(), on: 0 };
  seams[3].points.push([0.01, 0.02, 0.03]);
  return {
    format: 'billow-design', version: 1, target: { file }, size: { height: 0.6 }, seams, connections: [{ seams: [1, 3] }],
    material: { name: 'foil', thickness: 2.5e-5, youngs_modulus: 3e9 }, pressure: 1000,
    fabrication: { allowance: 10, sheet_width: 1000, units: 'mm', seam_allowance: { 2: 0 } },
  };
}

// A surface point's place in space: its triangle's corners weighted by the barycentric coordinates.
function placeOf({ positions, indices }, { face, bary }) {
  return [0, 1, 2].map((a) => bary.reduce((sum, w, c) => sum + w * positions[3 * indices[3 * face + c] + a], 0));
}

function meanEdge({ positions, indices }) {
  let sum = 0;
  for (let h = 0; h < indices.length; h++) {
    const u = 3 * indices[h];
    const v = 3 * indices[h - (h % 3) + ((h + 1) % 3)];
    sum += Math.hypot(positions[u] - positions[v], positions[u + 1] - positions[v + 1], positions[u + 2] - positions[v + 2]);
  }
  return sum / indices.length;
}

// Closed, oriented, every directed edge once, no triangle without area: what the worker's validation needs.
function assertClosedSurface({ positions, indices }, name) {
  const edges = new Set();
  const nv = positions.length / 3;
  for (let h = 0; h < indices.length; h++) {
    const key = indices[h] * nv + indices[h - (h % 3) + ((h + 1) % 3)];
    assert.ok(!edges.has(key), `${name}: an edge is used twice the same way`);
    edges.add(key);
  }
  for (const key of edges) assert.ok(edges.has((key % nv) * nv + Math.floor(key / nv)), `${name}: an edge has one side`);
  for (let f = 0; f < indices.length / 3; f++) {
    const [a, b, c] = [0, 1, 2].map((k) => 3 * indices[3 * f + k]);
    const u = [0, 1, 2].map((i) => positions[b + i] - positions[a + i]);
    const v = [0, 1, 2].map((i) => positions[c + i] - positions[a + i]);
    assert.ok(Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) > 0, `${name}: triangle ${f} has no area`);
  }
}

// Each triangle split into four at its edges' midpoints.
function subdivide({ positions, indices }) {
  const out = Array.from(positions);
  const middle = new Map();
  const mid = (a, b) => {
    const key = Math.min(a, b) * 1e7 + Math.max(a, b);
    if (!middle.has(key)) {
      middle.set(key, out.length / 3);
      for (let i = 0; i < 3; i++) out.push((positions[3 * a + i] + positions[3 * b + i]) / 2);
    }
    return middle.get(key);
  };
  const faces = [];
  for (let f = 0; f < indices.length; f += 3) {
    const [a, b, c] = [indices[f], indices[f + 1], indices[f + 2]];
    const [ab, bc, ca] = [mid(a, b), mid(b, c), mid(c, a)];
    faces.push(a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca);
  }
  return { positions: Float32Array.from(out), indices: Uint32Array.from(faces) };
}

// A torus (genus 1: the traversal's loops merge once), shifted along x.
function torus(n, m, shift = 0) {
  const positions = [];
  const indices = [];
  for (let i = 0; i < n; i++)
    for (let j = 0; j < m; j++) {
      const u = (2 * Math.PI * i) / n;
      const v = (2 * Math.PI * j) / m;
      positions.push((1 + 0.4 * Math.cos(v)) * Math.cos(u) + shift, (1 + 0.4 * Math.cos(v)) * Math.sin(u), 0.4 * Math.sin(v));
    }
  const id = (i, j) => (i % n) * m + (j % m);
  for (let i = 0; i < n; i++)
    for (let j = 0; j < m; j++) indices.push(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1));
  return { positions: Float32Array.from(positions), indices: Uint32Array.from(indices) };
}

// The packed mesh comes back as the same surface: triangle face[t] of the result is triangle t turned by
// turn[t], on vertices order[] of the original, each within half a grid step per axis.
function assertSameSurface(mesh, packed, back, name) {
  const { renumbering: { face, turn }, order, step } = packed;
  assert.equal(back.indices.length, mesh.indices.length, `${name}: triangle count`);
  for (let t = 0; t < mesh.indices.length / 3; t++)
    for (let c = 0; c < 3; c++)
      assert.equal(order[back.indices[3 * face[t] + c]], mesh.indices[3 * t + ((c + turn[t]) % 3)], `${name}: triangle ${t} corner ${c}`);
  let worst = 0;
  for (let v = 0; v < order.length; v++)
    for (let a = 0; a < 3; a++) {
      const original = mesh.positions[3 * order[v] + a];
      const error = Math.abs(back.positions[3 * v + a] - original) - 1e-6 * Math.abs(original); // float32
      worst = Math.max(worst, error / step);
    }
  assert.ok(worst <= 0.5, `${name}: a position moved ${worst.toFixed(3)} grid steps (at most 0.5)`);
  return worst;
}

const names = readdirSync(MESHES).filter((n) => n.endsWith('.obj')).sort();

test('every mesh up to 20,000 triangles travels in its link with a typical design; seams land where they were', async () => {
  const rows = [];
  for (const name of names) {
    const mesh = readMesh(name);
    const triangles = mesh.indices.length / 3;
    const design = typicalDesign(name, triangles);
    const fragment = await encodeDesign(design, mesh);
    const designOnly = (await encodeDesign(design)).length;
    if (triangles > LINKED_TRIANGLES) {
      assert.match(fragment, /&(mesh|target)=/, `${name}: with its mesh, or asking for its file`);
      continue;
    }
    assert.match(fragment, /^design=[A-Za-z0-9_-]+&mesh=[A-Za-z0-9_-]+$/, `${name} travels with its mesh`);
    assert.ok(fragment.length < MAX_LINK_CHARS, `${name}: ${fragment.length} characters`);
    const back = await decodeDesign(`#${fragment}`);
    assert.equal(back.awaiting, null);
    assertClosedSurface(back.mesh, name);

    // The same triangles on a grid step of 1/64 of the mean edge (finer only where thin triangles need it).
    const packed = packMesh(mesh);
    assert.deepEqual(unpackMesh(packed.bytes), back.mesh, `${name}: the link's mesh is packMesh's`);
    assert.ok(packed.step <= meanEdge(mesh) / 2 ** QUANT_BITS * (1 + 1e-6), `${name}: grid step ${packed.step}`);
    const worst = assertSameSurface(mesh, packed, back.mesh, name);

    // The design comes back as it was, but for its seam points, now on the renumbered triangles.
    const sent = parseDesign(design).design;
    assert.deepEqual({ ...back.design, seams: null }, { ...sent, seams: null }, `${name}: the design's other fields`);
    let moved = 0;
    sent.seams.forEach((seam, s) => {
      const got = back.design.seams[s];
      assert.deepEqual({ ...got, points: null }, { ...seam, points: null });
      seam.points.forEach((p, k) => {
        const q = got.points[k];
        if (Array.isArray(p)) return assert.deepEqual(q, p, 'a 3D point stays as it is');
        assert.equal(q.on, p.on);
        assert.ok(Math.abs(q.bary[0] + q.bary[1] + q.bary[2] - 1) < 1e-12);
        const d = Math.hypot(...placeOf(back.mesh, q).map((x, a) => x - placeOf(mesh, p)[a]));
        moved = Math.max(moved, d / packed.step);
      });
    });
    // Each corner moves by at most half a step per axis: a point between them by at most sqrt(3)/2 step.
    assert.ok(moved <= Math.sqrt(3) / 2 + 1e-3, `${name}: a seam point moved ${moved.toFixed(3)} grid steps`);
    rows.push({ name, triangles, designOnly, link: fragment.length, perTriangle: (fragment.length - designOnly) / triangles, worst, moved });
  }
  console.log('mesh            triangles   link chars  (design alone)  mesh chars/triangle  worst axis error / step  worst seam point / step');
  for (const r of rows)
    console.log(`${r.name.padEnd(16)}${String(r.triangles).padStart(9)}${String(r.link).padStart(13)}${String(r.designOnly).padStart(16)}${r.perTriangle.toFixed(2).padStart(21)}${r.worst.toFixed(3).padStart(25)}${r.moved.toFixed(3).padStart(25)}`);
  assert.ok(rows.length > 0, 'the shared meshes were read');
});

test('closed surfaces of any genus and several pieces come back whole; an open one keeps its order (version 1)', () => {
  const ring = torus(40, 16);
  const other = torus(20, 10, 5);
  const pieces = {
    positions: Float32Array.from([...ring.positions, ...other.positions]),
    indices: Uint32Array.from([...ring.indices, ...Array.from(other.indices, (i) => i + ring.positions.length / 3)]),
  };
  for (const [name, mesh] of [['torus', ring], ['two tori', pieces]]) {
    const packed = packMesh(mesh);
    assert.equal(packed.bytes[2], 2, `${name}: version 2`);
    assertSameSurface(mesh, packed, unpackMesh(packed.bytes), name);
  }
  const open = { positions: ring.positions, indices: ring.indices.subarray(0, ring.indices.length - 3) };
  const packed = packMesh(open);
  assert.equal(packed.bytes[2], 1, 'an open mesh is sent in version 1');
  assert.equal(packed.renumbering, null);
  assert.deepEqual(Array.from(unpackMesh(packed.bytes).indices), Array.from(open.indices), 'version 1 keeps the order');
});

test('a version-1 link still opens: same triangles, positions within 1/65535 of the box', async () => {
  // Made by Billow before version 2: a tetrahedron with a seam point on its last triangle.
  const link = '#design=TYtBCoMwEEXv8tfToJVs5iriYqxjTImmJKHSincvUgvlw1v8x9swxjRLAaP3IcT1Mmj2bgHhqSn7uIBrQpHktIA3jD4oGEVLEhP7O3ZC9m893KTeTQVcGXu8KnMGtxsWmY9GB6cg3ELMOoBHCVkJ6xnVhEf0S_kmo9wU3BB6SS9wW5krVaahythup5-v_72lE7bbj30A&mesh=c_Jl5OBgQAEN9gjM8O8_OwPD3__syDQTEzMbMwMLIzMLEwA';
  const back = await decodeDesign(link);
  assert.deepEqual(Array.from(back.mesh.indices), [0, 1, 2, 0, 3, 1, 1, 3, 2, 0, 2, 3]);
  assert.deepEqual(Array.from(back.mesh.positions), [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]);
  assert.deepEqual(back.design.seams[0].points[0], { face: 3, bary: [0.2, 0.3, 0.5] }, 'faces as they were: version 1 kept the order');
  assert.equal(back.awaiting, null);
});

test('damaged, truncated and garbage mesh parts give the designer\'s message, never another error', async () => {
  const mesh = readMesh('sphere.obj');
  const design = typicalDesign('sphere.obj', 1280);
  const fragment = await encodeDesign(design, mesh);
  const [designPart, meshPart] = fragment.split('&');
  const bytes = packMesh(mesh).bytes;
  const rand = random(11);
  const tries = [];
  const packedMesh = meshPart.slice('mesh='.length);
  for (let cut = 0; cut < packedMesh.length; cut += 97) tries.push(`#${designPart}&mesh=${packedMesh.slice(0, cut)}`);
  for (let cut = 0; cut < bytes.length; cut += 37) tries.push(bytes.subarray(0, cut)); // deflated whole, cut inside
  for (let i = 0; i < 300; i++) {
    const damaged = bytes.slice();
    for (let k = 0; k < 1 + (i % 4); k++) damaged[Math.floor(rand() * damaged.length)] = Math.floor(rand() * 256);
    tries.push(damaged);
  }
  for (let i = 0; i < 50; i++) tries.push(Uint8Array.from({ length: 3 + i * 13 }, (_, k) => (k < 2 ? [0x42, 0x4d][k] : k === 2 ? 1 + (i % 2) : rand() * 256)));
  tries.push(Uint8Array.of(0x42, 0x4d, 2, 0xfe, 0xff, 0x7f, 0xfe, 0xff, 0x7f)); // a million vertices, nothing else
  tries.push(`#${designPart}&mesh=AAAA`, `#${designPart}&mesh=%%%`, `#${designPart}&mesh=`);
  let refused = 0;
  for (const t of tries) {
    const hash = typeof t === 'string' ? t : `#${designPart}&mesh=${toBase64Url(await deflate(t))}`;
    try {
      const back = await decodeDesign(hash);
      assert.ok(back.mesh.indices.every((i) => i < back.mesh.positions.length / 3), 'a mesh that reads has its vertices');
    } catch (error) {
      assert.match(error.message, DAMAGED);
      refused += 1;
    }
  }
  assert.ok(refused > tries.length / 2, `${refused} of ${tries.length} damaged parts refused`);
});

test('a mesh over 20,000 triangles still travels when its link fits (spot subdivided, 23,424)', async () => {
  const mesh = subdivide(readMesh('spot.obj'));
  const fragment = await encodeDesign(typicalDesign('fine spot.obj', mesh.indices.length / 3), mesh);
  console.log(`spot.obj subdivided: ${mesh.indices.length / 3} triangles, link with the mesh ${fragment.length} characters`);
  assert.match(fragment, /&mesh=/);
  assert.ok(fragment.length <= MAX_LINK_CHARS);
});

test('a mesh too large for a link leaves a link that asks for its file; that file, and only that one, takes the design', async () => {
  const mesh = subdivide(readMesh('hand.obj'));
  const triangles = mesh.indices.length / 3;
  assert.ok(triangles > LINKED_TRIANGLES);
  const design = typicalDesign('my hand.obj', triangles);
  const fragment = await encodeDesign(design, mesh);
  console.log(`hand.obj subdivided: ${triangles} triangles, link without the mesh ${fragment.length} characters`);
  assert.match(fragment, /^design=[A-Za-z0-9_-]+&target=63928\.\d+\.[0-9a-f]{8}$/);
  assert.match(linkNotice(fragment, design), /copied.*"my hand\.obj" \(63,928 triangles\) is too large.*send the file/);
  assert.equal(linkNotice('design=abc', design), 'A link to this design was copied to the clipboard.');

  const back = await decodeDesign(`#${fragment}`);
  assert.equal(back.mesh, null);
  assert.deepEqual(back.design, parseDesign(design).design, 'the design as drawn: its faces are the file\'s own');
  const shown = [];
  const messages = {
    show: (severity, text) => {
      const message = { severity, text, removed: false, remove: () => (message.removed = true) };
      shown.push(message);
      return message;
    },
  };
  const awaited = awaitTarget(back, messages);
  assert.match(shown[0].text, /drawn on your mesh "my hand\.obj" \(63,928 triangles\).*too large.*Open that file/);
  assert.equal(shown[0].severity, 'warning');

  const blank = { ...design, seams: [], target: { file: 'other.obj' } };
  const hand = readMesh('hand.obj');
  assert.equal(awaited.attach('hand.obj', hand, { ...blank, target: { file: 'hand.obj' } }).seams.length, 0, 'another mesh opens on its own');
  assert.match(shown.at(-1).text, /"hand\.obj" is not the mesh the shared design was drawn on \(this file has 15,982 triangles.*still waits: open "my hand\.obj"/);
  const moved = { positions: mesh.positions.map((x, i) => (i === 0 ? x + 0.01 : x)), indices: mesh.indices };
  assert.equal(awaited.attach('moved.obj', moved, { ...blank, target: { file: 'moved.obj' } }).seams.length, 0, 'a vertex moved');
  assert.match(shown.at(-1).text, /not where they were/);
  assert.equal(shown.filter((m) => !m.removed).length, 1, 'one message at a time about the waiting design');
  assert.equal(awaited.attach('spot.obj', mesh, { ...blank, target: { example: 'spot' } }).seams.length, 0, 'examples are not the file');

  const attached = awaited.attach('hand-fine.obj', mesh, { ...blank, target: { file: 'hand-fine.obj' } });
  assert.deepEqual(attached.seams, back.design.seams, 'the same mesh takes the design, seams on the same triangles');
  assert.deepEqual(attached.target, { file: 'hand-fine.obj' });
  assert.ok(shown.every((m) => m.removed), 'the waiting design\'s messages are gone once it is on its mesh');
  assert.equal(awaited.attach('hand-fine.obj', mesh, blank), blank, 'once only');

  const linked = await decodeDesign(`#${await encodeDesign(design, readMesh('sphere.obj'))}`);
  assert.equal(awaitTarget(linked, messages), null, 'a link with its mesh waits for nothing');
  const bare = await decodeDesign(`#${fragment.split('&')[0]}`);
  assert.equal(awaitTarget(bare, messages), null);
  assert.match(shown.at(-1).text, /refers to the file "my hand\.obj", which is not in the link/);
});

test('a design too large even without its mesh is refused with a message', async () => {
  const huge = typicalDesign('big.obj', 1000);
  huge.seams = Array.from({ length: 400 }, (_, i) => typicalDesign('x', 1000, i).seams[0]);
  await assert.rejects(encodeDesign(huge, readMesh('sphere.obj')), /too large for a link.*Save it to a file/);
});
