// Makes the design benchmark's seam layouts (bench/designs, see bench/README.md "Pattern optimization"):
// designs in the spirit of the paper's Table 1 on meshes from ../shared/meshes, with seams along plane
// sections of the target (scripts/plane-sections.mjs: a middle seam, rings around limbs, bands across the
// body); and front/back designs as foil balloons are made (issue 24): the seam the app's Outline tool lays
// around the shape seen from one side (two panels), or with a band width its gusset band (three panels),
// laid by the app's own seam tool and editor over the worker's handlers (so they need build/wasm).
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

// Front/back class (issue 24, "flat-cut" in the manifest): the seam a designer gets by turning the view to
// `towards` (the direction from the target to the viewer, in its own coordinates; these meshes stand Y up,
// so the view and the target's coordinates agree) and clicking Outline, with `bandMm` > 0 its gusset band
// that many mm wide on the cut pattern. The app's own SeamTool.layOutline lays it through the app's
// SeamEditor (commitLoops, then refresh: the band's seam across has its ends moved onto the traced sides), with
// the worker's handlers run here as the tests run them.
const FLAT_CUT = [
  // name, mesh, towards, band width in mm (0: one seam, two panels)
  ['bunny-front-back', 'bunny.obj', [0, 0, 1], 0], // from its side: head, both ears, back and feet
  ['spot-front-back', 'spot.obj', [1, 0, 0], 0], // the cow from its side: head, horns, four legs
  ['penguin-front-back', 'penguin.obj', [0, 0, 1], 0], // from the front: flippers and feet
  ['blub-front-back', 'blub.obj', [1, 0, 0], 0], // the fish from its side: fins and tail, a fish foil balloon
  ['spot-gusset', 'spot.obj', [1, 0, 0], 36], // the cow from its side with a band 36 mm wide (4 % of its 0.92 m diagonal)
];

async function flatCut() {
  const { HeadlessApp, handlers } = await import('../tests/node/worker-handlers.mjs');
  const { SeamEditor } = await import('../web/src/app/seam-editor.js');
  const { SeamTool } = await import('../web/src/tools/seam-tool.js');
  const { heightScale } = await import('../web/src/app/up-axis.js');
  const { Object3D, Vector3 } = await import('three');
  const { Pane3D } = await import('../web/src/views/pane3d.js');
  const out = [];
  for (const [name, file, towards, bandMm] of FLAT_CUT) {
    const obj = readObj(join(MESHES, file));
    const target = { positions: Float64Array.from(obj.v.flat()), indices: Int32Array.from(obj.t.flat()) };
    for (const _ of handlers.setTarget(target)); // eslint-disable-line no-unused-vars
    const b = bbox(obj);
    const stats = { bbox_min: b.lo, bbox_max: b.hi };
    const app = new HeadlessApp(target, design(`../../../shared/meshes/${file}`, 0.6, []), (d) => heightScale(d, stats));
    const editor = new SeamEditor(app);
    const pane = {
      element: { addEventListener() {}, dataset: {} },
      mesh: new Object3D(), // the target pane's: Y up, so no turn
      group: new Object3D(),
      viewDirection: () => new Vector3(...towards),
      // The Outline's note names a straighter view (SeamTool.straighterViewClause) as the target pane would.
      namedView: Pane3D.prototype.namedView,
      defaultView: Pane3D.prototype.defaultView,
      seams: { showCursor() {} },
      requestRender() {},
    };
    const tool = new SeamTool(pane, editor);
    tool.setBandWidth(bandMm);
    tool.layOutline();
    await editor.refresh();
    const segments = editor.segmentation?.segments ?? [];
    const problems = (editor.segmentation?.problems ?? []).map((p) => `${p.severity}: ${p.message}`);
    console.log(`${name}: ${app.design.seams.length} seams, ${segments.length} segments${app.notes.map((n) => `; ${n.severity}: ${n.text}`).join('')}${problems.length ? `; ${problems.join('; ')}` : ''}`);
    out.push([name, app.design]);
  }
  return out;
}

mkdirSync(OUT, { recursive: true });
const only = process.argv.slice(2);
const made = [['teddy', teddy()], ['elephant', elephant()], ...(await flatCut())];
for (const [name, d] of made) {
  if (only.length && !only.includes(name)) continue;
  writeFileSync(join(OUT, `${name}.billow.json`), `${JSON.stringify(d, null, 1)}\n`);
  console.log(`bench/designs/${name}.billow.json`);
}
