// Makes the gallery's files in web/public/gallery (see web/src/app/gallery.js):
//   node scripts/make-gallery.mjs data     the design files (sphere3, sphere-sliding, toy, koala, fish) and
//                                          star.pattern.json
//   node scripts/make-gallery.mjs thumbs   the thumbnails (<id>.png, 320x240): serves web/dist, opens every
//                                          item in headless Chromium (/usr/bin/chromium, as the e2e tests),
//                                          waits until its inflated result shows and screenshots that pane
//   node scripts/make-gallery.mjs thumbs ID...  only those items' thumbnails
//   node scripts/make-gallery.mjs results [ID...]  the stored results (<id>.result.json) of the design items,
//                                          computed as the app computes them: the wasm module in Node through
//                                          the worker's handlers (build/wasm, or BILLOW_WASM_DIR)
//   node scripts/make-gallery.mjs          data, results and thumbs
// To regenerate after changing an item: `node scripts/make-gallery.mjs data`, `node scripts/make-gallery.mjs
// results`, `bash scripts/build.sh web`, `node scripts/make-gallery.mjs thumbs`, `bash scripts/build.sh web`
// again (the thumbnails ship in web/dist). The node test tests/node/gallery-results.test.mjs fails when a
// design changed and its result was not made again.
// It prints how long each item takes to show its result. BILLOW_DIST=DIR serves another build of the site
// than web/dist (as the e2e tests do); the thumbnails are written to web/public/gallery all the same.
import { writeFileSync, mkdirSync, readFileSync, readdirSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { readObj } from './obj.mjs';
import { teddySeams } from './plane-sections.mjs';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const OUT = join(ROOT, 'web/public/gallery');
const round = (v) => Math.round(v * 1e5) / 1e5;
const design = (example, height, seams, extra = {}) => ({
  format: 'billow-design', version: 1, target: { example }, size: { height }, seams, connections: [],
  material: { name: 'foil', thickness: 2.5e-5, youngs_modulus: 3.0e9 }, pressure: 1000, ...extra,
});

// Distances along d at which the ray from o crosses the mesh's triangles (Moeller-Trumbore).
function rayHits({ v, t }, o, d) {
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const hits = [];
  for (const [i, j, k] of t) {
    const e1 = sub(v[j], v[i]), e2 = sub(v[k], v[i]);
    const p = cross(d, e2), det = dot(e1, p);
    if (Math.abs(det) < 1e-12) continue;
    const s = sub(o, v[i]), u = dot(s, p) / det;
    if (u < 0 || u > 1) continue;
    const q = cross(s, e1), w = dot(d, q) / det;
    if (w < 0 || u + w > 1) continue;
    hits.push(dot(e2, q) / det);
  }
  return hits;
}

const pointAlong = (o, d, dist) => o.map((c, a) => round(c + dist * d[a]));

// The farthest point where the ray from o along d leaves the mesh.
const farthestHit = (mesh, o, d) => pointAlong(o, d, Math.max(-1, ...rayHits(mesh, o, d)));

// The nearest point where the ray from o (inside the mesh) along d leaves it.
const nearestHit = (mesh, o, d) => pointAlong(o, d, Math.min(Infinity, ...rayHits(mesh, o, d).filter((h) => h > 0)));

// Surface points around the loop where the plane x = x0 cuts the mesh, seen from center c.
function sagittalLoop(mesh, c, count) {
  const points = [];
  for (let i = 0; i < count; i++) {
    const a = (2 * Math.PI * i) / count;
    points.push(farthestHit(mesh, c, [0, Math.cos(a), Math.sin(a)]));
  }
  return points;
}

// Blub the fish (mouth towards +z, symmetric in x, the mesh's own units): back and belly seams along the
// outline of the middle plane, from the mouth over the dorsal fin and around the forked tail to the tip of
// its upper lobe (the belly seam passes the notch between the lobes); on each side a seam along the flank at
// mid-height from the mouth to the notch, split just behind the head (z = 0.3) into a cheek seam and a flank
// seam. The internal connection joins the two flank seams (see makeData).
function fishSeams(mesh) {
  const x = (Math.min(...mesh.v.map((p) => p[0])) + Math.max(...mesh.v.map((p) => p[0]))) / 2;
  const top = (z) => farthestHit(mesh, [x, -3, z], [0, 1, 0]);
  const bottom = (z) => farthestHit(mesh, [x, 3, z], [0, -1, 0]);
  const side = (s, y, z) => nearestHit(mesh, [3 * s, y, z], [-s, 0, 0]);
  const mouth = farthestHit(mesh, [x, 0, 0], [0, 0, 1]);
  const tip = farthestHit(mesh, [x, 0.39, -1.5], [0, 0, -1]); // the upper tail lobe's tip
  const lowerTip = farthestHit(mesh, [x, -0.3, -1.4], [0, 0, -1]);
  const notch = nearestHit(mesh, [x, -0.08, -1], [0, 0, -1]); // from inside the tail stalk
  const back = [mouth, ...[0.8, 0.6, 0.3, 0.1, -0.1, -0.3, -0.5, -0.7, -0.8, -0.9, -1, -1.2, -1.4, -1.6, -1.8].map(top), tip];
  const belly = [mouth, ...[0.8, 0.6, 0.3, 0, -0.3, -0.6, -0.8, -1, -1.2, -1.4].map(bottom), lowerTip, notch,
    bottom(-1.7), bottom(-1.8), tip];
  // Mid-height of the flank [z, y]: the head, the body, the tail stalk and the tail.
  const cheek = [[0.8, 0], [0.6, 0.02]], split = [0.3, 0.04];
  const flank = [[0, 0.05], [-0.3, 0.05], [-0.6, 0.05], [-0.8, 0], [-1, -0.06], [-1.2, -0.055], [-1.4, -0.06]];
  const seam = (name, points) => ({ name, closed: false, weight: 1, points });
  const along = (s, zy) => zy.map(([z, y]) => side(s, y, z));
  const sides = [['left', 1], ['right', -1]].map(([name, s]) => {
    const at = side(s, split[1], split[0]);
    return { name, cheek: [mouth, ...along(s, cheek), at], flank: [at, ...along(s, flank), notch] };
  });
  return [seam('back', back), seam('belly', belly), ...sides.map((d) => seam(`${d.name} cheek`, d.cheek)),
    ...sides.map((d) => seam(`${d.name} flank`, d.flank))];
}

// A star of `tips` points, outer radius R, inner r: rings of the outline scaled towards the middle.
function starPanel(R, r, tips, perEdge, rings) {
  const outline = [];
  for (let c = 0; c < 2 * tips; c++) {
    const a0 = Math.PI / 2 + (Math.PI * c) / tips, a1 = Math.PI / 2 + (Math.PI * (c + 1)) / tips;
    const r0 = c % 2 ? r : R, r1 = c % 2 ? R : r;
    const p0 = [r0 * Math.cos(a0), r0 * Math.sin(a0)], p1 = [r1 * Math.cos(a1), r1 * Math.sin(a1)];
    for (let s = 0; s < perEdge; s++) outline.push([p0[0] + ((p1[0] - p0[0]) * s) / perEdge, p0[1] + ((p1[1] - p0[1]) * s) / perEdge]);
  }
  const m = outline.length;
  const vertices = [[0, 0]];
  for (let k = 1; k <= rings; k++) for (const [x, y] of outline) vertices.push([round((x * k) / rings), round((y * k) / rings)]);
  const at = (k, j) => 1 + (k - 1) * m + (j % m);
  const triangles = [];
  for (let j = 0; j < m; j++) triangles.push([0, at(1, j), at(1, j + 1)]);
  for (let k = 1; k < rings; k++)
    for (let j = 0; j < m; j++) {
      triangles.push([at(k, j), at(k + 1, j), at(k + 1, j + 1)]);
      triangles.push([at(k, j), at(k + 1, j + 1), at(k, j + 1)]);
    }
  const boundary = Array.from({ length: m }, (_, j) => at(rings, j));
  return { vertices, triangles, boundary };
}

function makeData() {
  mkdirSync(OUT, { recursive: true });
  const write = (name, value, indent = 1) => writeFileSync(join(OUT, name), `${JSON.stringify(value, null, indent)}\n`);

  // Sphere (unit sphere in its own coordinates): three meridians from pole to pole, 120 degrees apart.
  const meridian = (deg, name) => {
    const a = (deg * Math.PI) / 180;
    const at = (lat) => [round(Math.cos(lat) * Math.cos(a)), round(Math.sin(lat)), round(Math.cos(lat) * Math.sin(a))];
    return { name, closed: false, weight: 1, points: [[0, 1, 0], at(Math.PI / 4), at(0), at(-Math.PI / 4), [0, -1, 0]] };
  };
  write('sphere3.billow.json', design('sphere', 0.5, [meridian(0, 'meridian 1'), meridian(120, 'meridian 2'), meridian(240, 'meridian 3')]));
  // The same seams of weight 0, free to slide (paper Sec. 6: its sphere was designed so).
  const sliding = (seam) => ({ ...seam, weight: 0 });
  write('sphere-sliding.billow.json', design('sphere', 0.5, [meridian(0, 'meridian 1'), meridian(120, 'meridian 2'), meridian(240, 'meridian 3')].map(sliding)));

  // Penguin toy: one closed seam around the middle plane (x = center), left and right halves.
  const penguin = readObj(join(ROOT, 'web/public/examples/penguin.obj'));
  const lo = [0, 1, 2].map((a) => Math.min(...penguin.v.map((p) => p[a])));
  const hi = [0, 1, 2].map((a) => Math.max(...penguin.v.map((p) => p[a])));
  const center = lo.map((l, a) => (l + hi[a]) / 2);
  write('toy.billow.json', design('penguin', 0.9, [{ name: 'middle', closed: true, weight: 1, points: sagittalLoop(penguin, center, 16) }]));

  // Koala plush toy: the design benchmark's teddy cut (teddySeams, bench/designs/teddy.billow.json) on the
  // app's koala example, 18 panels: a middle seam, a seam down each side through the legs, bands across the
  // back and across the head, and a ring around each ear. (A plush-toy cut of four panels, halves along the
  // middle and a ring around the neck, inflated into a plump blob: the legs and ears rounded off.)
  write('koala.billow.json', design('koala', 0.4, teddySeams(readObj(join(ROOT, 'web/public/examples/koala.obj')))));

  // Fish: Blub in four panels, upper and lower halves on each side (fishSeams), and an internal panel
  // joining the left and right flank seams from behind the head to the tail. Behind the head the body, the
  // tail stalk and the tail fin are taller than wide; pressure pushes a balloon round, so it pushes the flank
  // seams apart and the panel between them is in tension there: it holds them in, and the rear of the fish
  // stays narrow. (An earlier fish had its internal panel in the middle plane, between back and belly seams:
  // the inflating sides pull those seams inward, so that panel hung slack and shaped nothing. Running the
  // panel forward to the mouth leaves its front third slack too: the head is round.)
  const blub = readObj(join(ROOT, 'web/public/examples/blub.obj'));
  write('fish.billow.json', design('blub', 0.5, fishSeams(blub), { connections: [{ seams: [4, 5] }] }));

  // Star foil balloon: two identical five-pointed stars (0.5 m tip to tip), the back one mirrored so both
  // are drawn as seen from outside, sealed at the rim vertex by vertex.
  const front = starPanel(0.25, 0.11, 5, 8, 10);
  const back = { vertices: front.vertices.map(([x, y]) => [round(-x), y]), triangles: front.triangles.map(([a, b, c]) => [a, c, b]) };
  write('star.pattern.json', {
    format: 'billow-pattern', version: 1, units: 'm', pressure: 1000,
    material: { name: 'foil', thickness: 2.5e-5, youngs_modulus: 3.0e9 },
    panels: [
      { name: 'front', internal: false, vertices: front.vertices, triangles: front.triangles },
      { name: 'back', internal: false, vertices: back.vertices, triangles: back.triangles },
    ],
    stitches: front.boundary.map((i) => [0, i, 1, i]),
  }, 0);
  console.log(`wrote the gallery's data files to ${OUT}`);
}

// Thumbnail views other than the pane's own framing: the direction to the camera and a zoom factor.
const THUMBNAIL_VIEWS = {
  koala: { direction: [1, 0.4, 0.9], zoom: 1.35 },
  fish: { direction: [1, 0.3, 0.25], zoom: 1.05 }, // from its left side: the flank seam along the middle
};

// Items whose lesson shows in another pane: the sliding sphere's target looks like sphere3's, its panels do not.
const THUMBNAIL_PANES = { 'sphere-sliding': 'pattern' };

async function makeThumbnails(only = []) {
  const { serve, launch, openFreshPage } = await import('../tests/e2e/harness.mjs');
  const server = await serve();
  const context = await launch();
  try {
    const page = await openFreshPage(context, server.url);
    const all = await page.evaluate(() => [...document.querySelectorAll('.gallery-card')].map((c) => c.dataset.item));
    const ids = only.length ? all.filter((id) => only.includes(id)) : all;
    for (const id of ids) {
      const started = Date.now();
      await page.evaluate(() => { document.querySelector('#status').textContent = ''; });
      await page.evaluate((i) => window.billow.test.openGalleryDesign(i), id);
      await page.waitForFunction(() => /^Inflated/.test(document.querySelector('#status').textContent)
        && !/^Inflated the flattened/.test(document.querySelector('#status').textContent), null, { timeout: 300000 });
      const seconds = ((Date.now() - started) / 1000).toFixed(1);
      await page.waitForTimeout(500);
      // Designs: the target with its seams; patterns: the inflated shape. Without the figures and legends.
      const pane = THUMBNAIL_PANES[id] ?? (/^Inflated the optimized panels/.test(await page.textContent('#status')) ? 'target' : 'inflated');
      // The docked boxes go altogether (display: none), so the view frames the whole pane again (free-area.js).
      const overlays = '.pane .dock, .pane .legend, .pane .hint, .pane .panel-label, .pane .segment-label';
      // A long target is seen from its side and closer than the pane frames it.
      if (pane === 'target' && THUMBNAIL_VIEWS[id]) {
        await page.evaluate(({ direction, zoom }) => {
          const { camera, controls, viewport } = window.billow.test.panes.target;
          const distance = camera.position.distanceTo(controls.target) / zoom;
          const n = Math.hypot(...direction);
          camera.position.set(...direction.map((d, k) => controls.target.getComponent(k) + (distance * d) / n));
          controls.update();
          viewport.render();
        }, THUMBNAIL_VIEWS[id]);
      }
      await page.evaluate((sel) => document.querySelectorAll(sel).forEach((el) => { el.style.display = 'none'; }), overlays);
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      await page.waitForTimeout(100);
      const box = await page.locator(`#pane-${pane} .pane-body`).boundingBox();
      const png = await page.screenshot({ clip: box });
      await page.evaluate((sel) => document.querySelectorAll(sel).forEach((el) => { el.style.display = ''; }), overlays);
      // Scaled to 320x240 in the page, cropped to cover.
      const dataUrl = await page.evaluate(async (b64) => {
        const img = new Image();
        img.src = `data:image/png;base64,${b64}`;
        await img.decode();
        const canvas = document.createElement('canvas');
        canvas.width = 320;
        canvas.height = 240;
        const s = Math.max(320 / img.width, 240 / img.height);
        const w = 320 / s, h = 240 / s;
        canvas.getContext('2d').drawImage(img, (img.width - w) / 2, (img.height - h) / 2, w, h, 0, 0, 320, 240);
        return canvas.toDataURL('image/png');
      }, png.toString('base64'));
      writeFileSync(join(OUT, `${id}.png`), Buffer.from(dataUrl.split(',')[1], 'base64'));
      console.log(`${id}: result shown after ${seconds} s (${await page.textContent('#status')})`);
    }
    if (page.errors.length) console.log('page errors:', page.errors);
  } finally {
    await context.close();
    await server.close();
  }
}

// Runs a worker handler (a generator of progress) to its end and returns its result.
function finish(steps) {
  let step = steps.next();
  while (!step.done) step = steps.next();
  return step.value;
}

// Coordinates to a micrometer: the panels' lengths then change by far less than the solver's tolerance.
const micro = (v) => Math.round(v * 1e6) / 1e6;

function roundPattern(pattern) {
  return {
    ...pattern,
    panels: pattern.panels.map((p) => ({ ...p, vertices: p.vertices.map((xy) => xy.map(micro)) })),
    inflated: pattern.inflated?.map((panel) => panel.map((xyz) => xyz.map(micro))),
  };
}

// The stored result of one gallery design: its panels optimized by the worker's own handlers (as
// Panels.make asks for them), rounded, and checked to inflate in balance as stored.
async function makeResult(api, file) {
  const { parseDesign } = await import('../web/src/app/design.js');
  const { findExample } = await import('../web/src/app/examples.js');
  const { createHandlers } = await import('../web/src/worker/handlers.js');
  const { optimizeArgs, resultKey, DEFAULT_RESOLUTION, RESULT_FORMAT, RESULT_VERSION } = await import('../web/src/app/stored-result.js');
  const { heightScale } = await import('../web/src/app/up-axis.js');
  const { design } = parseDesign(JSON.parse(readFileSync(join(OUT, file), 'utf8')));
  const example = findExample(design.target.example);
  const bytes = readFileSync(join(ROOT, 'web/public/examples', example.file));
  const handlers = createHandlers(api);
  const arrayBuffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const { report } = finish(handlers.loadTarget({ fileName: example.file, bytes: arrayBuffer }));
  const scale = heightScale(design, report.stats); // App.scaleFor: the height along the target's up axis
  const optimized = finish(handlers.optimizeDesign({ ...optimizeArgs(design, DEFAULT_RESOLUTION), scale }));
  const pattern = roundPattern(JSON.parse(optimized.patternText));
  const inflated = finish(handlers.inflatePattern({ patternText: JSON.stringify(pattern) }));
  const { state, iteration, distanceRms, distanceMax, seamMismatch } = optimized.status;
  return {
    format: RESULT_FORMAT, version: RESULT_VERSION, design: file, key: resultKey(design, DEFAULT_RESOLUTION, bytes),
    triangles: DEFAULT_RESOLUTION, solver: api.version(),
    optimizer: { state, iteration, distanceRms, distanceMax, seamMismatch },
    inflatedSteps: inflated.iterations, pattern,
  };
}

async function makeResults(only = []) {
  const { loadApi } = await import('../tests/node/load-module.mjs');
  const api = await loadApi();
  const files = readdirSync(OUT).filter((f) => f.endsWith('.billow.json')).sort();
  for (const file of files) {
    const id = file.replace(/\.billow\.json$/, '');
    if (only.length && !only.includes(id)) continue;
    const started = performance.now();
    const result = await makeResult(api, file);
    const text = `${JSON.stringify(result)}\n`;
    writeFileSync(join(OUT, `${id}.result.json`), text);
    const kb = (n) => `${(n / 1024).toFixed(0)} KB`;
    const { state, iteration, distanceRms } = result.optimizer;
    console.log(`${id}: ${((performance.now() - started) / 1000).toFixed(1)} s, ${iteration} steps (${state}), distance ${(100 * distanceRms).toFixed(2)} %, `
      + `inflates in ${result.inflatedSteps} steps; ${kb(text.length)}, ${kb(gzipSync(text).length)} gzipped`);
  }
}

const what = process.argv[2] ?? 'all';
if (what === 'data' || what === 'all') makeData();
if (what === 'results' || what === 'all') await makeResults(process.argv.slice(3));
if (what === 'thumbs' || what === 'all') await makeThumbnails(process.argv.slice(3));
