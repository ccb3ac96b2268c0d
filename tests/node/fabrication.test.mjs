// Fabrication figures for makers: parse-and-default of the settings, pattern statistics rows, and the
// balloon figures (envelope mass, helium lift, safety factor) checked against hand computations.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseFabrication, patternStatRows, balloonFigures, balloonRows, formatMillimeters } from '../../web/src/app/fabrication.js';

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
  assert.deepEqual(balloonRows(custom).map(([label]) => label), ['Helium lift']);
});
