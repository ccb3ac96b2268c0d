// Fabrication figures for makers: parse-and-default of the settings, pattern statistics rows, and the
// balloon figures (envelope mass, helium lift, safety factor) checked against hand computations.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseFabrication, patternStatRows, balloonFigures, balloonRows, formatMillimeters, peakStress } from '../../web/src/app/fabrication.js';

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
});

test('a foil sphere floats on helium when its envelope is lighter than the lift', () => {
  // Two 1 m x 1 m square panels of 25 µm foil (1150 kg/m³): 2 m² x 25e-6 m x 1150 = 57.5 g.
  const square = { vertices: [[0, 0], [1, 0], [1, 1], [0, 1]], triangles: [[0, 1, 2], [0, 2, 3]] };
  const pattern = { material: { name: 'foil', thickness: 25e-6, youngs_modulus: 3e9 }, panels: [square, square] };
  const big = balloonFigures(pattern, 0.1, 20e6); // 100 L of helium lifts 103.8 g
  assert.ok(Math.abs(big.massGrams - 57.5) < 1e-9);
  assert.ok(Math.abs(big.liftGrams - 103.8) < 1e-9);
  assert.equal(big.floats, true);
  assert.equal(big.safetyFactor, 2); // foil's working stress 40 MPa over 20 MPa
  const small = balloonFigures(pattern, 0.04, 50e6);
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
