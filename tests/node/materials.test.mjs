// Materials and pressure: the page's presets are the solver's; the design document reads them with
// parse-and-default; panels built through the worker's handlers carry the design's material and pressure,
// and bad figures are refused with a message.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadApi } from './load-module.mjs';
import { readObjText } from './obj.mjs';
import { MATERIAL_PRESETS, presetMaterial, isPresetMaterial, describeMaterial, formatPressure } from '../../web/src/app/materials.js';
import { newDesign, parseDesign } from '../../web/src/app/design.js';
import { createHandlers } from '../../web/src/worker/handlers.js';
import { Runner } from '../../web/src/worker/runner.js';

const api = await loadApi();

function run(handlers, op, args) {
  return new Promise((resolve, reject) => {
    const runner = new Runner(handlers, (message) => {
      if (message.kind === 'reply') (message.ok ? resolve : reject)(message.ok ? message.result : message.error);
    });
    runner.receive({ kind: 'request', id: 1, op, args });
  });
}

test('the page lists the same material presets as the solver, figure for figure', () => {
  assert.deepEqual(MATERIAL_PRESETS, api.materialPresets());
  assert.deepEqual(
    MATERIAL_PRESETS.map((m) => m.name),
    ['foil', 'pvc', 'ripstop', 'tpu'],
  );
});

test('material descriptions and pressures read as a designer writes them', () => {
  assert.equal(describeMaterial(presetMaterial('foil')), '25 µm, E = 3 GPa');
  assert.equal(describeMaterial(presetMaterial('pvc')), '0.3 mm, E = 20 MPa');
  assert.equal(formatPressure(1500), '1.5 kPa');
  assert.equal(formatPressure(800), '800 Pa');
  assert.ok(isPresetMaterial(presetMaterial('ripstop')));
  assert.ok(!isPresetMaterial({ ...presetMaterial('ripstop'), thickness: 2e-4 }));
});

test('a design without material or pressure gets foil at 1 kPa; bad figures fall back with a warning', () => {
  const old = { format: 'billow-design', version: 1, target: { example: 'sphere' }, size: { height: 0.5 }, seams: [] };
  const { design, warnings } = parseDesign(old);
  assert.deepEqual(design.material, presetMaterial('foil'));
  assert.equal(design.pressure, 1000);
  assert.deepEqual(warnings, []);
  assert.deepEqual(newDesign().material, presetMaterial('foil'));

  const named = parseDesign({ ...old, material: { name: 'pvc' }, pressure: 2500 });
  assert.deepEqual(named.design.material, presetMaterial('pvc'));
  assert.equal(named.design.pressure, 2500);

  const custom = parseDesign({ ...old, material: { name: 'my vinyl', thickness: 4e-4, youngs_modulus: 1.5e7 } });
  assert.deepEqual(custom.design.material, { name: 'my vinyl', thickness: 4e-4, youngs_modulus: 1.5e7 });
  assert.deepEqual(custom.warnings, []);

  const bad = parseDesign({ ...old, material: { name: 'mystery' }, pressure: -3 });
  assert.deepEqual(bad.design.material, presetMaterial('foil'));
  assert.equal(bad.design.pressure, 1000);
  assert.equal(bad.warnings.length, 2);
  assert.match(bad.warnings.join('\n'), /material "mystery"/);
  assert.match(bad.warnings.join('\n'), /pressure is not between 1 Pa and 10000 kPa/);

  const overridden = parseDesign({ ...old, material: { name: 'foil', thickness: 'thick' } });
  assert.equal(overridden.design.material.thickness, 25e-6);
  assert.match(overridden.warnings[0], /thickness/);
});

test('panels built by the worker carry the design\'s material and pressure; bad figures get a message', async () => {
  const sphere = readObjText(readFileSync(new URL('../../web/public/examples/sphere.obj', import.meta.url), 'utf8'));
  const handlers = createHandlers(api);
  await run(handlers, 'setTarget', { positions: sphere.positions, indices: sphere.indices });
  const design = JSON.parse(readFileSync(new URL('../data/sphere-equator.billow.json', import.meta.url), 'utf8'));
  const seams = design.seams.map(({ points, closed, weight }) => ({ points, closed, weight }));
  const args = { seams, scale: 0.25, triangles: 300 };

  const pvc = await run(handlers, 'buildPattern', { ...args, pressure: 2500, material: { name: 'pvc' } });
  assert.equal(pvc.ok, true);
  const pattern = JSON.parse(pvc.patternText);
  assert.equal(pattern.pressure, 2500);
  assert.equal(pattern.material.name, 'pvc');
  assert.equal(pattern.material.thickness, 0.3e-3);
  assert.equal(pattern.material.youngs_modulus, 20e6);

  const custom = await run(handlers, 'buildPattern', { ...args, material: { name: 'x', thickness: 1e-4, youngs_modulus: 5e7 } });
  assert.equal(JSON.parse(custom.patternText).material.youngs_modulus, 5e7);
  assert.equal(JSON.parse(custom.patternText).pressure, 1000);

  // Read by the design document's rules, as the CLI reads them (tests/node/design-reader.test.mjs).
  await assert.rejects(run(handlers, 'buildPattern', { ...args, pressure: 0 }), (e) => e.code === 'design.bad-value' && /between 1 Pa/.test(e.message));
  await assert.rejects(
    run(handlers, 'buildPattern', { ...args, material: { name: 'pvc', thickness: -1 } }),
    (e) => e.code === 'design.bad-value' && /thickness/.test(e.message),
  );
  await assert.rejects(run(handlers, 'buildPattern', { ...args, scale: 'big' }), (e) => e.code === 'pattern.bad-scale');
});
