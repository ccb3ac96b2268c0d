// Fabrication figures for makers: parse-and-default of the settings, pattern statistics rows, and the
// balloon figures (envelope mass, helium lift, safety factor) checked against hand computations.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  parseFabrication, patternStatRows, balloonFigures, balloonRows, formatMillimeters, peakStress, exportOptions, grainMode, GRAIN_FIELDS,
  seamAllowanceOf, DEFAULT_ALLOWANCE, joiningOf, joiningFor,
} from '../../web/src/app/fabrication.js';
import { setFabrication, setSeamAllowance, setMaterial, addValve, setValveWidth, removeValve } from '../../web/src/app/commands.js';
import { presetMaterial } from '../../web/src/app/materials.js';
import { parseDesign, newDesign } from '../../web/src/app/design.js';
import { loadApi } from './load-module.mjs';
import { SolverError } from '../../web/src/worker/protocol.js';

test('fabrication settings default, keep good fields and warn about bad ones', () => {
  const warnings = [];
  assert.deepEqual(parseFabrication(undefined, warnings), { allowance: 10, sheet_width: 1000, units: 'mm' });
  assert.deepEqual(parseFabrication({ allowance: 0, sheet_width: 1500, units: 'in' }, warnings), { allowance: 0, sheet_width: 1500, units: 'in' });
  assert.deepEqual(warnings, []);
  const bad = parseFabrication({ allowance: -1, sheet_width: 'wide', units: 'cubits' }, warnings);
  assert.deepEqual(bad, { allowance: 10, sheet_width: 1000, units: 'mm' });
  assert.equal(warnings.length, 3);
  assert.deepEqual(parseFabrication([], warnings), { allowance: 10, sheet_width: 1000, units: 'mm' });
  assert.equal(warnings.length, 4);
  assert.equal(formatMillimeters(254, 'in'), '10.00 in');
  assert.equal(formatMillimeters(254.4, 'mm'), '254 mm');
});

test('per-seam and free-edge allowances and the grain are read with warnings for bad values', () => {
  const warnings = [];
  const good = parseFabrication(
    { allowance: 10, sheet_width: 1000, units: 'mm', seam_allowance: { 5: 15, 3: 0 }, free_edge_allowance: 4, grain_lock: true, rotate: false, note: 'kept' },
    warnings,
  );
  assert.deepEqual(warnings, []);
  assert.deepEqual(good.seam_allowance, { 3: 0, 5: 15 });
  assert.deepEqual(Object.keys(good.seam_allowance), ['3', '5']);
  assert.equal(good.free_edge_allowance, 4);
  assert.equal(good.grain_lock, true);
  assert.equal(good.rotate, false);
  assert.equal(good.note, 'kept'); // unknown fields survive
  assert.equal(seamAllowanceOf(good, 3), 0);
  assert.equal(seamAllowanceOf(good, 4), 10);
  // Bad entries are dropped one by one, each with a warning that names it; the good ones stay.
  const mixed = parseFabrication({ seam_allowance: { 2: 101, 4: -1, 6: 'wide', 7: 12, S3: 0, '-1': 5, '1.5': 5, '007': 5 } }, warnings);
  assert.deepEqual(mixed.seam_allowance, { 7: 12 });
  assert.equal(warnings.length, 7);
  assert.match(warnings[0], /seam S3 is not between 0 and 100 mm/);
  assert.ok(warnings.some((w) => /"S3", which is no seam id/.test(w)));
  warnings.length = 0;
  const bad = parseFabrication({ seam_allowance: [[3, 0]], free_edge_allowance: 500, grain_lock: 'yes', rotate: 1 }, warnings);
  assert.equal(warnings.length, 4);
  for (const key of ['seam_allowance', 'free_edge_allowance', 'grain_lock', 'rotate']) assert.equal(key in bad, false, key);
  assert.deepEqual(bad, { allowance: 10, sheet_width: 1000, units: 'mm' });
  // Nothing valid left: no empty object.
  assert.equal('seam_allowance' in parseFabrication({ seam_allowance: { x: 1 } }, []), false);
  // A design document keeps them through parseDesign, with its warnings.
  const { design, warnings: designWarnings } = parseDesign({ ...newDesign(), fabrication: { allowance: 8, seam_allowance: { 3: 0, 4: 200 } } });
  assert.deepEqual(design.fabrication.seam_allowance, { 3: 0 });
  assert.equal(designWarnings.length, 1);
});

test('the exporter\'s options carry the per-seam allowances, free edges and grain; the commands set and reset them', () => {
  const plain = setMaterial(newDesign(), presetMaterial('ripstop')); // sewn, with the sewn default allowance
  assert.deepEqual(exportOptions(plain.fabrication), { allowance: 10, sheet_width: 1000, units: 'mm', joining: 'sewn' });
  let d = setSeamAllowance(plain, 5, 15);
  d = setSeamAllowance(d, 3, 0);
  assert.deepEqual(Object.entries(d.fabrication.seam_allowance), [['3', 0], ['5', 15]]);
  assert.equal(setSeamAllowance(d, 3, 0), d, 'no change, same design');
  d = setFabrication(d, { free_edge_allowance: 4, ...GRAIN_FIELDS.grain });
  assert.equal(grainMode(d.fabrication), 'grain');
  assert.deepEqual(exportOptions(d.fabrication, { paper: 'letter' }), {
    allowance: 10, sheet_width: 1000, units: 'mm', joining: 'sewn', seam_allowance: { 3: 0, 5: 15 }, free_edge_allowance: 4, grain_lock: true, paper: 'letter',
  });
  d = setFabrication(d, GRAIN_FIELDS.fixed);
  assert.equal(grainMode(d.fabrication), 'fixed');
  assert.equal(exportOptions(d.fabrication).rotate, false);
  assert.equal('grain_lock' in d.fabrication, false);
  d = setFabrication(d, { ...GRAIN_FIELDS.free, free_edge_allowance: undefined });
  assert.equal(grainMode(d.fabrication), 'free');
  d = setSeamAllowance(setSeamAllowance(d, 3, null), 5, null);
  assert.deepEqual(d.fabrication, plain.fabrication); // back to the defaults: no leftover fields
  assert.deepEqual(plain.fabrication, { allowance: 10, sheet_width: 1000, units: 'mm', joining: 'sewn' }); // not mutated
});

test('foil is heat sealed: a new design has a seal band, the joining follows the material, and fill valves are kept', () => {
  const foil = newDesign();
  assert.equal(foil.material.name, 'foil');
  assert.deepEqual(foil.fabrication, { allowance: DEFAULT_ALLOWANCE.sealed, sheet_width: 1000, units: 'mm', joining: 'sealed' });
  assert.equal(joiningFor(presetMaterial('pvc')), 'sealed');
  // To ripstop and back: sewn with 10 mm, then sealed with the band again; one step each, nothing else moves.
  const ripstop = setMaterial(foil, presetMaterial('ripstop'));
  assert.equal(joiningOf(ripstop.fabrication), 'sewn');
  assert.equal(ripstop.fabrication.allowance, DEFAULT_ALLOWANCE.sewn);
  assert.deepEqual(setMaterial(ripstop, presetMaterial('foil')).fabrication, foil.fabrication);
  // A band the designer typed stays when the material changes.
  const typed = setMaterial(setFabrication(foil, { allowance: 7 }), presetMaterial('ripstop'));
  assert.equal(typed.fabrication.allowance, 7);
  // Designs from before sealing, with no joining, are sewn.
  assert.equal(joiningOf(parseFabrication({ allowance: 10 }, [])), 'sewn');
  // Valves: added, widened, removed (the last one takes the field with it); the design is never mutated.
  let d = addValve(foil, { seam: 0, at: 0.25, width: 20 });
  d = addValve(d, { seam: 2, at: 0.5, width: 15 });
  assert.deepEqual(exportOptions(d.fabrication).valves, [{ seam: 0, at: 0.25, width: 20 }, { seam: 2, at: 0.5, width: 15 }]);
  d = setValveWidth(d, 1, 30);
  assert.equal(d.fabrication.valves[1].width, 30);
  assert.equal(setValveWidth(d, 5, 30), d);
  d = removeValve(removeValve(d, 0), 0);
  assert.equal('valves' in d.fabrication, false);
  assert.equal('valves' in foil.fabrication, false);
  // Read back with parse-and-default: bad valves and joinings are dropped with warnings in plain words.
  const warnings = [];
  const parsed = parseFabrication({ joining: 'glued', valves: [{ seam: 1, at: 0.5, width: 20 }, { seam: -1, at: 0.5, width: 20 }, { seam: 1, at: 2, width: 20 }] }, warnings);
  assert.equal('joining' in parsed, false);
  assert.deepEqual(parsed.valves, [{ seam: 1, at: 0.5, width: 20 }]);
  assert.equal(warnings.length, 3);
  assert.match(warnings[0], /neither sewn nor sealed/);
  assert.match(warnings[1], /Fill valve 2/);
  assert.equal('valves' in parseFabrication({ valves: 'one' }, []), false);
});

test('the exporter draws the seal band and the valve gap, and says where along a seam each side runs', async () => {
  const api = await loadApi();
  const pattern = api.examplePattern('mylar', 600);
  const text = JSON.stringify(pattern);
  const result = api.exportPattern(text, { joining: 'sealed', allowance: 5, valves: [{ seam: 0, at: 0.4, width: 25 }, { seam: 4, at: 0.5, width: 20 }] });
  assert.equal(result.statistics.joining, 'sealed');
  assert.deepEqual(result.statistics.valves.map((v) => v.placed), [true, false]);
  assert.match(result.svg, /id="seal-band"/);
  assert.doesNotMatch(result.svg, /id="sew"/);
  // One gap per piece of the seam, each 25 mm along the sealing line.
  assert.deepEqual(result.valves.map((marks) => marks.length), [1, 1]);
  for (const [mark] of result.valves) {
    const half = mark.length / 4;
    let along = 0;
    for (let k = 0; k + 1 < half; k++) along += Math.hypot(mark[2 * k + 2] - mark[2 * k], mark[2 * k + 3] - mark[2 * k + 1]);
    assert.ok(Math.abs(1000 * along - 25) < 0.5, `${1000 * along} mm`);
  }
  // The seam's two sides, each with its loop edges in the seam's order and its length.
  assert.equal(result.seamSides.length, 1);
  const [seam] = result.seamSides;
  assert.deepEqual(seam.sides.map((s) => s.panel).sort(), [0, 1]);
  for (const side of seam.sides) {
    assert.equal(side.edges.length, result.outlines[side.panel].loop.length);
    assert.ok(Math.abs(side.length - Math.PI * 0.6) < 0.05 * Math.PI * 0.6, `${side.length} m`);
  }
  // Sewn, the pattern keeps its sewing line and draws no band.
  assert.match(api.exportPattern(text, {}).svg, /id="sew"/);
});

// Distance from point (x, y) to a closed polyline [x0, y0, x1, y1, ...].
function distanceToLoop(x, y, xy) {
  let best = Infinity;
  for (let i = 0; i < xy.length; i += 2) {
    const j = (i + 2) % xy.length;
    const [ax, ay, bx, by] = [xy[i], xy[i + 1], xy[j], xy[j + 1]];
    const len2 = (bx - ax) ** 2 + (by - ay) ** 2;
    const t = len2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / len2)) : 0;
    best = Math.min(best, Math.hypot(x - ax - t * (bx - ax), y - ay - t * (by - ay)));
  }
  return best;
}

// Per seam id (-1 free): the distances [mm] from the middles of its edges (away from its ends) to the cut line.
function cutWidths(pattern, result) {
  const widths = new Map();
  result.outlines.forEach(({ loop, seams }, p) => {
    const n = loop.length;
    for (let e = 0; e < n; e++) {
      if ([-2, -1, 1, 2].some((k) => seams[(e + k + n) % n] !== seams[e])) continue;
      const [ax, ay] = pattern.panels[p].vertices[loop[e]], [bx, by] = pattern.panels[p].vertices[loop[(e + 1) % n]];
      const d = 1000 * distanceToLoop((ax + bx) / 2, (ay + by) / 2, result.cutLines[p]);
      if (!widths.has(seams[e])) widths.set(seams[e], []);
      widths.get(seams[e]).push(d);
    }
  });
  return widths;
}

test('the exporter honours seam_allowance: the cut line moves by the given width near that seam only', async () => {
  const api = await loadApi();
  const pattern = api.examplePattern('sphere3', 900);
  const text = JSON.stringify(pattern);
  const plain = api.exportPattern(text, {});
  assert.equal(plain.statistics.seams.length, 3);
  assert.equal(plain.outlines.length, 3);
  // Every outline edge has a seam (a closed sphere has no free edges).
  assert.ok(plain.outlines.every((o) => o.loop.length === o.seams.length && o.seams.every((id) => id >= 0 && id < 3)));
  assert.equal(plain.statistics.totals.free_edge_mm, 0);
  const own = api.exportPattern(text, { seam_allowance: { 1: 0, 2: 25 } });
  const before = cutWidths(pattern, plain), after = cutWidths(pattern, own);
  const expected = { 0: 10, 1: 0, 2: 25 };
  for (const [id, list] of after) {
    assert.ok(list.length >= 10, `seam ${id}: ${list.length} edges checked`);
    for (const d of list) assert.ok(Math.abs(d - expected[id]) < 0.05, `seam S${id + 1}: ${d} mm from the sewing line, not ${expected[id]}`);
    for (const d of before.get(id)) assert.ok(Math.abs(d - 10) < 0.05);
  }
  assert.deepEqual(own.statistics.seams.map((s) => s.allowance_mm), [10, 0, 25]);
  // A seam the pattern does not have (the seams were redrawn) is ignored.
  const stale = api.exportPattern(text, { seam_allowance: { 9: 0 } });
  assert.deepEqual(stale.cutLines, plain.cutLines);
  // Grain lock: every panel turned 0 or 180 degrees on the sheet.
  const grain = api.exportPattern(text, { grain_lock: true });
  for (const p of grain.statistics.panels) assert.ok([0, 180].includes(Math.round(Math.abs(p.rotation_deg))), `${p.rotation_deg}°`);
});

test('the exporter refuses bad seam allowances with a message that names the seam', async () => {
  const api = await loadApi();
  const text = JSON.stringify(api.examplePattern('sphere3', 600));
  const refused = (options, pattern) => {
    assert.throws(() => api.exportPattern(text, options), (e) => {
      assert.ok(e instanceof SolverError);
      assert.equal(e.code, 'export.bad-value');
      assert.match(e.message, pattern);
      return true;
    });
  };
  refused({ seam_allowance: { 1: 101 } }, /seam S2 must be a width from 0 to 100 mm/);
  refused({ seam_allowance: { 1: -2 } }, /seam S2/);
  refused({ seam_allowance: { 1: '5' } }, /seam S2/);
  refused({ seam_allowance: { S2: 5 } }, /"S2".*whole number/);
  refused({ seam_allowance: { '-1': 5 } }, /whole number/);
  refused({ seam_allowance: [[1, 5]] }, /seam ids and widths/);
  refused({ seam_allowance: 5 }, /seam ids and widths/);
  refused({ free_edge_allowance: -1 }, /free edges/);
  refused({ grain_lock: 'yes' }, /grain_lock is true or false/);
});

test('pattern statistics read in the chosen units', () => {
  const statistics = {
    panels: [{}, {}],
    totals: { material_area_m2: 0.5, sheet_width_mm: 1000, sheet_length_mm: 800, utilisation: 0.42, seam_length_mm: 2500, sewing_minutes: 9.2, max_seam_mismatch_mm: 0.2 },
  };
  const rows = Object.fromEntries(patternStatRows(statistics, 'mm'));
  assert.equal(rows.Panels, '2');
  assert.equal(rows.Sheet, '1000 mm × 800 mm (42 % used)');
  assert.equal(rows.Seams, '2.50 m, about 9 min to sew');
  assert.equal(rows['Seam mismatch'], '< 1 mm');
  assert.match(Object.fromEntries(patternStatRows(statistics, 'in')).Sheet, /^39\.37 in × 31\.50 in/);
  assert.equal(Object.fromEntries(patternStatRows({ ...statistics, joining: 'sealed' })).Seams, '2.50 m', 'a sealed pattern is not sewn');
});

test('a foil sphere floats on helium when its envelope is lighter than the lift', () => {
  // Two 1 m x 1 m square panels of 25 µm foil (1150 kg/m³): 2 m² x 25e-6 m x 1150 = 57.5 g.
  const square = { vertices: [[0, 0], [1, 0], [1, 1], [0, 1]], triangles: [[0, 1, 2], [0, 2, 3]] };
  const pattern = { material: { name: 'foil', thickness: 25e-6, youngs_modulus: 3e9 }, panels: [square, square] };
  const big = balloonFigures(pattern, 0.1, 40e6); // 100 L of helium lifts 103.8 g
  assert.ok(Math.abs(big.massGrams - 57.5) < 1e-9);
  assert.ok(Math.abs(big.liftGrams - 103.8) < 1e-9);
  assert.equal(big.floats, true);
  assert.equal(big.safetyFactor, 2); // foil's strength 80 MPa over 40 MPa, its safe working stress
  assert.match(Object.fromEntries(balloonRows(big))['Safety factor'], /^2\.0$/);
  const small = balloonFigures(pattern, 0.04, 90e6);
  assert.equal(small.floats, false);
  const rows = Object.fromEntries(balloonRows(small));
  assert.match(rows['Helium lift'], /does not float/);
  assert.match(rows['Safety factor'], /it would burst/);
  // A custom material with no density: no mass, lift only.
  const custom = balloonFigures({ ...pattern, material: { name: 'mine', thickness: 1e-4, youngs_modulus: 1e8 } }, 0.1, 1e6);
  assert.equal(custom.massGrams, null);
  assert.equal(custom.safetyFactor, null);
  assert.deepEqual(balloonRows(custom).map(([label]) => label), ['Helium lift']); // no pressure given: no blower
  // Foil is sealed: no blower row. Ripstop at 400 Pa: a fan blower does; PVC at 5 kPa needs a pump.
  assert.equal(big.blowerPascals, null);
  assert.ok(!Object.fromEntries(balloonRows(big)).Blower);
  const ripstop = { ...pattern, pressure: 400, material: { name: 'ripstop', thickness: 1e-4, youngs_modulus: 5e8 } };
  assert.match(Object.fromEntries(balloonRows(balloonFigures(ripstop, 2, 1e6))).Blower, /^400 Pa static pressure/);
  const pvc = { ...pattern, pressure: 5000, material: { name: 'pvc', thickness: 3e-4, youngs_modulus: 2e7 } };
  assert.match(Object.fromEntries(balloonRows(balloonFigures(pvc, 0.5, 1e6))).Blower, /^5\.0 kPa: more than a fan blower gives/);
});

test('the peak stress is what the most stressed 1 % of the surface reaches, not a single sliver', () => {
  // 100 right triangles of area 0.5 at 1 MPa, one sliver of area 5e-4 at 100 MPa, one internal at 500 MPa.
  const positions = [];
  const triangles = [];
  const stress = [];
  const outer = [];
  const add = (p, q, r, sigma, isOuter = 1) => {
    const base = positions.length / 3;
    positions.push(...p, ...q, ...r);
    triangles.push(base, base + 1, base + 2);
    stress.push(sigma, 0);
    outer.push(isOuter);
  };
  for (let i = 0; i < 100; i++) add([i, 0, 0], [i + 1, 0, 0], [i, 1, 0], 1e6);
  add([0, 0, 1], [1, 0, 1], [0, 0.001, 1], 100e6);
  add([0, 0, 2], [1, 0, 2], [0, 1, 2], 500e6, 0);
  const result = { positions, triangles, outer, stress };
  assert.equal(peakStress(result), 1e6);
  // When 5 % of the surface (5 triangles) is at 10 MPa, that is the peak.
  for (let f = 0; f < 5; f++) stress[2 * f] = 10e6;
  assert.equal(peakStress(result), 10e6);
  assert.equal(peakStress({ ...result, stress: [] }), 0);
});
