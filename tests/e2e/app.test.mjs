// The app in headless Chromium: loads, renders, opens files (picker and drop), reports bad meshes,
// resizes, autosaves, and survives a worker crash. Every page fails on any console error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { autosaveHolds, serve, launch, openFreshPage, screenshot, paintedFraction, MESHES, useBrowser } from './harness.mjs';

const env = useBrowser();

const stat = (page, name) => page.textContent(`#target-stats dd[data-stat="${name}"]`);

const fresh = () => openFreshPage(env.context, env.server.url);

function assertNoErrors(page) {
  assert.deepEqual(page.errors, [], 'no console errors');
}

test('the app opens on an example target, renders it and shows its statistics', async () => {
  const page = await fresh();
  for (const pane of ['target', 'inflated', 'pattern']) assert.ok(await page.isVisible(`#pane-${pane}`), pane);
  assert.equal(await stat(page, 'triangles'), '5,856');
  assert.equal(await stat(page, 'genus'), '0');
  assert.match(await stat(page, 'size'), /60\.0 cm/);
  await page.waitForTimeout(200);
  const painted = await paintedFraction(page, '#pane-target .pane-body');
  assert.ok(painted > 0.05, `the target is drawn (${(painted * 100).toFixed(1)} % of the pane)`);
  // The cow is seen from the front, its head (the horns, its highest point) nearer the viewer than its middle.
  const facing = await page.evaluate(() => {
    const pane = window.billow.test.panes.target;
    const positions = pane.mesh.geometry.attributes.position;
    const Vector3 = pane.camera.position.constructor;
    let top = new Vector3(0, -Infinity, 0);
    for (let i = 0; i < positions.count; i++) if (positions.getY(i) > top.y) top = new Vector3().fromBufferAttribute(positions, i);
    const center = pane.mesh.geometry.boundingBox.getCenter(new Vector3());
    pane.mesh.localToWorld(top), pane.mesh.localToWorld(center);
    return top.sub(center).normalize().dot(pane.viewDirection());
  });
  assert.ok(facing > 0.3, `the cow faces the viewer (${facing.toFixed(2)})`);
  await screenshot(page, 'app-start');
  // Headless Chromium renders on SwiftShader: no multisampling there (viewport.js).
  const gl = await page.evaluate(() => {
    const context = document.getElementById('viewport').getContext('webgl2');
    const info = context.getExtension('WEBGL_debug_renderer_info');
    return { renderer: context.getParameter(info.UNMASKED_RENDERER_WEBGL), antialias: context.getContextAttributes().antialias };
  });
  assert.match(gl.renderer, /SwiftShader/i);
  assert.equal(gl.antialias, false, 'no multisampling on a software rasterizer');
  assertNoErrors(page);
  await page.close();
});

test('a mesh with a hole, opened with the file picker, gets a clear message and changes nothing', async () => {
  const page = await fresh();
  const lines = readFileSync(`${MESHES}/sphere.obj`, 'utf8').split('\n');
  lines.splice(lines.findIndex((l) => l.startsWith('f ')), 1);
  await page.setInputFiles('#file-input', { name: 'holey.obj', mimeType: 'text/plain', buffer: Buffer.from(lines.join('\n')) });
  const message = page.locator('.message.error');
  await message.waitFor();
  const text = await message.textContent();
  assert.match(text, /holey\.obj" cannot be used/);
  assert.match(text, /must be closed/);
  assert.match(text, /largest hole is near/);
  assert.equal(await stat(page, 'triangles'), '5,856', 'the previous target stays');
  // So do the example's name in the menu and a status that is not left saying the file is being opened.
  assert.equal(await page.inputValue('#example-select'), 'spot');
  assert.doesNotMatch(await page.textContent('#status'), /Opening/);
  await screenshot(page, 'app-open-error');
  // Garbage with a mesh extension, and an unsupported extension.
  await page.setInputFiles('#file-input', { name: 'noise.stl', mimeType: 'model/stl', buffer: Buffer.from([1, 2, 3, 4, 5]) });
  await page.locator('.message.error >> nth=1').waitFor();
  // The command line's reader says what is wrong; the page names the file.
  assert.match(await page.locator('.message.error >> nth=1').textContent(), /"noise\.stl" cannot be opened\. The STL file is only 5 bytes/);
  await page.setInputFiles('#file-input', { name: 'photo.jpg', mimeType: 'image/jpeg', buffer: Buffer.from('xx') });
  await page.locator('.message.error >> nth=2').waitFor();
  assert.match(await page.locator('.message.error >> nth=2').textContent(), /OBJ, STL, PLY or OFF/);
  assertNoErrors(page);
  await page.close();
});

test('opening a file (OBJ, PLY, OFF) and dropping one (STL) each replace the target', async () => {
  const page = await fresh();
  await page.setInputFiles('#file-input', { name: 'blub.obj', mimeType: 'text/plain', buffer: readFileSync(`${MESHES}/blub.obj`) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="triangles"]')?.textContent === '1,886');
  assert.equal(await stat(page, 'file'), 'blub.obj');
  // Drop an STL made in the page from the sphere (binary STL, welded back into 642 vertices).
  const sphere = readFileSync(`${MESHES}/sphere.obj`, 'utf8');
  await page.evaluate((objText) => {
    const v = [];
    const f = [];
    for (const line of objText.split('\n')) {
      const p = line.trim().split(/\s+/);
      if (p[0] === 'v') v.push([+p[1], +p[2], +p[3]]);
      if (p[0] === 'f') f.push([+p[1] - 1, +p[2] - 1, +p[3] - 1]);
    }
    const buffer = new ArrayBuffer(84 + 50 * f.length);
    const view = new DataView(buffer);
    view.setUint32(80, f.length, true);
    f.forEach((tri, i) => tri.forEach((k, c) => v[k].forEach((x, d) => view.setFloat32(84 + 50 * i + 12 + 12 * c + 4 * d, x, true))));
    const data = new DataTransfer();
    data.items.add(new File([buffer], 'sphere.stl'));
    window.dispatchEvent(new DragEvent('dragenter', { dataTransfer: data }));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: data }));
  }, sphere);
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'sphere.stl');
  assert.equal(await stat(page, 'vertices'), '642');
  assert.equal(await stat(page, 'triangles'), '1,280');
  assert.ok(await page.isHidden('#drop-overlay'));
  // An ascii PLY whose surface is triangle strips (as scanned meshes came), each strip a triangle and a -1.
  const lines = sphere.split('\n').map((l) => l.trim().split(/\s+/));
  const vertices = lines.filter((p) => p[0] === 'v').map((p) => p.slice(1, 4).join(' '));
  const strips = lines.filter((p) => p[0] === 'f').flatMap((p) => [...p.slice(1, 4).map((k) => Number(k) - 1), -1]);
  const ply = `ply\nformat ascii 1.0\nelement vertex ${vertices.length}\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n${vertices.join('\n')}\n${strips.length} ${strips.join(' ')}\n`;
  await page.setInputFiles('#file-input', { name: 'scan.ply', mimeType: 'application/octet-stream', buffer: Buffer.from(ply) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'scan.ply');
  assert.equal(await stat(page, 'vertices'), '642');
  assert.equal(await stat(page, 'triangles'), '1,280');
  // An OFF file (libigl's and CGAL's meshes come so): its header, counts, a comment, 0-based faces.
  const faces = lines.filter((p) => p[0] === 'f').map((p) => `3 ${p.slice(1, 4).map((k) => Number(k) - 1).join(' ')}`);
  const off = `OFF\n# the sphere\n${vertices.length} ${faces.length} 0\n${vertices.join('\n')}\n${faces.join('\n')}\n`;
  await page.setInputFiles('#file-input', { name: 'sphere.off', mimeType: 'application/octet-stream', buffer: Buffer.from(off) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'sphere.off');
  assert.equal(await stat(page, 'vertices'), '642');
  assert.equal(await stat(page, 'triangles'), '1,280');
  assertNoErrors(page);
  await page.close();
});

// billow suggest and billow design write a mesh's path or the mesh itself (docs/formats.md); seams name that mesh's
// faces, so they must never land on whatever target is open.
test('a design from the command line opens on its own mesh; one with no target it can find changes nothing', async () => {
  const page = await fresh();
  const file = JSON.parse(readFileSync(new URL('../data/sphere-gores.billow.json', import.meta.url), 'utf8'));
  const open = (name, value) => page.setInputFiles('#file-input', { name, mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(value)) });
  const seamCount = () => page.evaluate(() => window.billow.test.design.seams.length);
  // By path: the designer is asked for that mesh, and the cow stays as it was.
  assert.match(file.target.obj, /\/sphere\.obj$/);
  await open('sphere-gores.billow.json', file);
  await page.locator('.message.warning', { hasText: '"sphere.obj": open that mesh first' }).waitFor();
  assert.equal(await stat(page, 'triangles'), '5,856');
  assert.equal(await seamCount(), 0);
  await page.setInputFiles('#file-input', { name: 'sphere.obj', mimeType: 'text/plain', buffer: readFileSync(`${MESHES}/sphere.obj`) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'sphere.obj');
  await open('sphere-gores.billow.json', file);
  await page.waitForFunction(() => window.billow.test.design.seams.length === 3);

  // The mesh inline: it opens with the design, named after the file.
  await page.selectOption('#example-select', 'spot');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'spot.obj');
  const lines = readFileSync(`${MESHES}/sphere.obj`, 'utf8').split('\n');
  const numbers = (prefix, shift) => lines.filter((l) => l.startsWith(prefix)).map((l) => l.trim().split(/\s+/).slice(1).map((x) => Number(x) - shift));
  await open('gores-inline.billow.json', { ...file, target: { vertices: numbers('v ', 0), triangles: numbers('f ', 1) } });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'gores-inline.obj');
  assert.equal(await stat(page, 'triangles'), '1,280');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 3);
  await page.locator('.segment-label >> nth=2').waitFor({ state: 'attached' });

  // A target that is none of these: refused, the design on screen unchanged.
  await open('lost.billow.json', { ...file, target: { obj: 7 } });
  const refused = await page.locator('.message.error', { hasText: 'lost.billow.json' }).textContent();
  assert.match(refused, /names no target Billow can open.*Your current design is unchanged/);
  assert.equal(await stat(page, 'file'), 'gores-inline.obj');
  assert.equal(await seamCount(), 3);
  assertNoErrors(page);
  await page.close();
});

test('examples menu, real size, and autosave across a reload', async () => {
  const page = await fresh();
  await page.selectOption('#example-select', 'sphere');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'sphere.obj');
  await page.fill('#height-input', '0.9');
  await page.press('#height-input', 'Enter');
  await page.waitForFunction(() => /90\.0 cm/.test(document.querySelector('#target-stats dd[data-stat="size"]')?.textContent));
  await autosaveHolds(page, (design) => design?.target?.example === 'sphere' && design.size?.height === 0.9);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await stat(page, 'triangles'), '1,280', 'the example came back');
  assert.match(await stat(page, 'size'), /90\.0 cm/, 'the height came back');
  assert.equal(await page.inputValue('#height-input'), '0.9');
  assertNoErrors(page);
  await page.close();
});

test('a file target is autosaved with its mesh and restored', async () => {
  const page = await fresh();
  await page.setInputFiles('#file-input', { name: 'blub.obj', mimeType: 'text/plain', buffer: readFileSync(`${MESHES}/blub.obj`) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'blub.obj');
  await autosaveHolds(page, (design) => design?.target?.file === 'blub.obj');
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await stat(page, 'file'), 'blub.obj');
  assert.equal(await stat(page, 'triangles'), '1,886');
  assertNoErrors(page);
  await page.close();
});

test('panes resize with the window and the pattern pane pans and zooms', async () => {
  const page = await fresh();
  const before = await page.locator('#pane-target').boundingBox();
  await page.setViewportSize({ width: 1000, height: 700 });
  await page.waitForTimeout(200);
  const afterBox = await page.locator('#pane-target').boundingBox();
  assert.ok(afterBox.width < before.width - 100, 'the target pane narrowed');
  assert.ok((await paintedFraction(page, '#pane-target .pane-body')) > 0.05, 'still drawn after resize');
  const pattern = page.locator('#pane-pattern .pane-body');
  const box = await pattern.boundingBox();
  const zoom0 = await page.evaluate(() => window.billow.test.panes.pattern.camera.zoom);
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, -400);
  await page.waitForTimeout(100);
  const zoom1 = await page.evaluate(() => window.billow.test.panes.pattern.camera.zoom);
  assert.ok(zoom1 > zoom0, `zoomed in (${zoom0} -> ${zoom1})`);
  const x0 = await page.evaluate(() => window.billow.test.panes.pattern.camera.position.x);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2, { steps: 5 });
  await page.mouse.up();
  const x1 = await page.evaluate(() => window.billow.test.panes.pattern.camera.position.x);
  assert.ok(x1 < x0, 'dragging right moves the view left');
  await screenshot(page, 'app-resized');
  assertNoErrors(page);
  await page.close();
});

test('the target and inflated panes turn together, each keeping its own zoom', async () => {
  const page = await fresh();
  const view = () => page.evaluate(() => {
    const at = (pane) => {
      const d = pane.camera.position.clone().sub(pane.controls.target);
      return { dir: d.clone().normalize().toArray(), distance: d.length() };
    };
    const { target, inflated } = window.billow.test.panes;
    return { target: at(target), inflated: at(inflated) };
  });
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const drag = async (selector, dx, dy) => {
    const box = await page.locator(selector).boundingBox();
    const x = box.x + box.width * 0.3, y = box.y + box.height * 0.6;
    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(x + dx, y + dy, { steps: 6 });
    await page.mouse.up();
  };
  const v0 = await view();
  assert.ok(dot(v0.target.dir, v0.inflated.dir) > 0.9999, 'both panes start from the same side');
  await drag('#pane-target .pane-body', 160, 30);
  const v1 = await view();
  assert.ok(dot(v1.target.dir, v0.target.dir) < 0.98, `the target turned (${dot(v1.target.dir, v0.target.dir)})`);
  assert.ok(dot(v1.target.dir, v1.inflated.dir) > 0.9999, 'the inflated pane turned with it');
  await drag('#pane-inflated .pane-body', -90, -40);
  const v2 = await view();
  assert.ok(dot(v2.inflated.dir, v1.inflated.dir) < 0.99, 'the inflated pane turned');
  assert.ok(dot(v2.target.dir, v2.inflated.dir) > 0.9999, 'the target pane turned with it');
  // Zooming one pane leaves the other's distance alone.
  const box = await page.locator('#pane-inflated .pane-body').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, -300);
  await page.waitForTimeout(100);
  const v3 = await view();
  assert.ok(v3.inflated.distance < 0.95 * v2.inflated.distance, 'the inflated pane zoomed in');
  assert.ok(Math.abs(v3.target.distance - v2.target.distance) < 1e-9 * v2.target.distance, 'the target kept its zoom');
  assert.ok(dot(v3.target.dir, v3.inflated.dir) > 0.9999);
  assertNoErrors(page);
  await page.close();
});

test('a crashed solver is replaced, the designer is told, and work goes on', async () => {
  const page = await fresh();
  const code = await page.evaluate(() => window.billow.test.request('crashForTesting').catch((e) => e.code));
  assert.equal(code, 'worker.crashed');
  await page.locator('.message.warning', { hasText: 'restarted' }).waitFor();
  await page.selectOption('#example-select', 'blub');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="triangles"]')?.textContent === '1,886');
  // The trap itself is logged by the dying worker; anything else is an error.
  assert.deepEqual(page.errors.filter((e) => !/Aborted|RuntimeError|unreachable/.test(e)), []);
  await page.close();
});

test('a mesh far beyond the interactive budget is refused quickly with a message', async () => {
  const page = await fresh();
  const triangles = 600000;
  const stl = Buffer.alloc(84 + 50 * triangles);
  stl.writeUInt32LE(triangles, 80);
  for (let i = 0; i < triangles; i++) {
    const o = 84 + 50 * i + 12;
    stl.writeFloatLE(i, o); stl.writeFloatLE(i + 1, o + 12); stl.writeFloatLE(1, o + 16); stl.writeFloatLE(i, o + 24); stl.writeFloatLE(2, o + 28);
  }
  const started = Date.now();
  await page.setInputFiles('#file-input', { name: 'huge.stl', mimeType: 'model/stl', buffer: stl });
  const message = await page.locator('.message.error', { hasText: 'huge.stl' }).textContent({ timeout: 60000 });
  assert.match(message, /600,000 triangles, more than the 500,000/);
  assert.match(message, /Simplify/);
  assert.ok(Date.now() - started < 30000, 'refused without a long freeze');
  assert.equal(await stat(page, 'file'), 'spot.obj', 'the design is unchanged');
  // The page stayed responsive meanwhile: the seam panel still answers.
  assert.ok(await page.isVisible('#seam-panel'));
  assertNoErrors(page);
  await page.close();
});
