// Makes the design benchmark's seam layouts (bench/designs, see bench/README.md "Pattern optimization"):
// designs in the spirit of the paper's Table 1 on meshes from ../shared/meshes, with seams along plane
// sections of the target (scripts/plane-sections.mjs: a middle seam, rings around limbs, bands across the
// body).
//   node scripts/make-bench-designs.mjs            writes bench/designs/*.billow.json
//   node scripts/make-bench-designs.mjs --sections MESH AXIS VALUE   prints the section loops of a plane
import { writeFileSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { readObj } from './obj.mjs';
import { AXES, bbox, koalaSeams, length, sectionLoops, teddySeams } from './plane-sections.mjs';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const MESHES = join(ROOT, '../shared/meshes');
const OUT = join(ROOT, 'bench/designs');

const design = (obj, height, seams, extra = {}) => ({
  format: 'billow-design', version: 1, target: { obj }, size: { height }, seams, connections: [],
  material: { name: 'foil', thickness: 2.5e-5, youngs_modulus: 3.0e9 }, pressure: 1000, ...extra,
});

if (process.argv[2] === '--sections') {
  const [, , , file, axis, value] = process.argv;
  const mesh = readObj(join(MESHES, file));
  console.log(bbox(mesh));
  for (const loop of sectionLoops(mesh, AXES[axis], Number(value))) {
    const b = bbox({ v: loop });
    console.log(`loop: ${loop.length} points, length ${length(loop).toFixed(3)}, box ${b.lo.map((x) => x.toFixed(2))} .. ${b.hi.map((x) => x.toFixed(2))}`);
  }
  process.exit(0);
}

// Teddy class (paper Table 1 "Teddy": about 17 panels): the koala, cut like a plush toy: a middle seam and
// a seam down each side through the legs (four strips from nose to tail), bands across the back and across
// the head through the ears, and a ring around each ear (teddySeams; the gallery's koala is cut the same).
function teddy() {
  return design('../../../shared/meshes/koala.obj', 0.6, teddySeams(readObj(join(MESHES, 'koala.obj'))));
}

// Elephant class (paper Table 1 "Elephant": about 40 panels, 14k elements): the same koala in narrow
// strips, as a large float would be: the middle and side seams, five bands across the body and head, ear
// rings: 36 panels.
function elephant() {
  const bands = [-2.5, -1, 0.3, 2.2, 3.1].map((z) => [`band z ${z}`, z]);
  return design('../../../shared/meshes/koala.obj', 1.5, koalaSeams(readObj(join(MESHES, 'koala.obj')), { sidePoints: 120, bands }));
}

mkdirSync(OUT, { recursive: true });
for (const [name, make] of [['teddy', teddy], ['elephant', elephant]]) {
  writeFileSync(join(OUT, `${name}.billow.json`), `${JSON.stringify(make(), null, 1)}\n`);
  console.log(`bench/designs/${name}.billow.json`);
}
