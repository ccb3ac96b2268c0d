// Fabrication settings of the design (seam allowance, per seam and of free edges, sheet width, grain, display
// units) and the figures a maker reads: pattern statistics from the exporter, and for balloons the envelope
// mass, helium lift and the stress safety factor. Pure functions; the Exporter (exporter.js) does the downloads.
import { findMaterialPreset } from './materials.js';

// Optional fields, absent unless the designer sets them: seam_allowance { "<seam id>": mm } (a seam's own
// allowance; ids as in the exporter's statistics, labelled S<id + 1>), free_edge_allowance [mm] (edges sewn
// to nothing; absent: as the seams), grain_lock (true: panels keep their y axis along the roll), rotate
// (false: panels are nested as drawn), joining ('sewn' or 'sealed': heat sealed, the allowance is the seal
// band; absent: sewn, as designs were before sealing), valves [{ seam: id, at: share of the seam's length
// from its start, width: mm }] (fill valves: gaps left open in their seams).
export const DEFAULT_FABRICATION = Object.freeze({ allowance: 10, sheet_width: 1000, units: 'mm' });
export const MAX_ALLOWANCE = 100; // [mm]
export const JOININGS = Object.freeze(['sewn', 'sealed']);
export const DEFAULT_ALLOWANCE = Object.freeze({ sewn: 10, sealed: 5 }); // [mm]; a seal band is a few mm
export const DEFAULT_VALVE_WIDTH = 20; // [mm]: a foil balloon's valve strip, or a drinking straw with room
export const MAX_VALVE_WIDTH = 200; // [mm], as the exporter
// Foil, PVC and TPU are heat sealed (the paper's PVC prototypes were hot sealed); coated ripstop is sewn.
const SEALED_MATERIALS = new Set(['foil', 'pvc', 'tpu']);
export const MIN_SHEET = 100;
export const MAX_SHEET = 10000;
export const MM_PER_INCH = 25.4;

// Air at 20 °C and helium at 20 °C, 1 atm [kg/m³]: the lift of helium is their difference.
const AIR_DENSITY = 1.204;
const HELIUM_DENSITY = 0.166;

const inRange = (v, lo, hi) => typeof v === 'number' && Number.isFinite(v) && v >= lo && v <= hi;
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// A seam id as a key of seam_allowance: "0", "12".
export const isSeamId = (key) => /^(0|[1-9]\d{0,5})$/.test(String(key));
export const seamLabel = (id) => `S${Number(id) + 1}`;

export const joiningOf = (fabrication) => fabrication.joining ?? 'sewn';
export const joiningFor = (material) => (SEALED_MATERIALS.has(material?.name) ? 'sealed' : 'sewn');

// The fabrication of a new design in `material`: joined as the material is, with that joining's allowance.
export function fabricationFor(material) {
  const joining = joiningFor(material);
  return { ...DEFAULT_FABRICATION, joining, allowance: DEFAULT_ALLOWANCE[joining] };
}

// The fabrication once the material changes: the joining follows the material, and an allowance left at
// its joining's default follows too (one the designer typed stays).
export function fabricationWithMaterial(fabrication, material) {
  return fabricationWithJoining(fabrication, joiningFor(material));
}

// The fabrication joined another way ('sewn' | 'sealed'); an allowance left at its joining's default follows.
export function fabricationWithJoining(fabrication, joining) {
  if (joining === joiningOf(fabrication) || !DEFAULT_ALLOWANCE[joining]) return fabrication;
  const allowance = fabrication.allowance === DEFAULT_ALLOWANCE[joiningOf(fabrication)] ? DEFAULT_ALLOWANCE[joining] : fabrication.allowance;
  return { ...fabrication, joining, allowance };
}

// Parse-and-default of design.fabrication; returns the settings and pushes warnings.
export function parseFabrication(value, warnings) {
  const out = { ...DEFAULT_FABRICATION };
  if (value === undefined) return out;
  if (!isObject(value)) {
    warnings.push('The design\'s fabrication settings are not valid; the defaults are used.');
    return out;
  }
  const fields = [
    ['allowance', inRange(value.allowance, 0, MAX_ALLOWANCE), `The seam allowance is not between 0 and ${MAX_ALLOWANCE} mm; using 10 mm.`],
    ['sheet_width', inRange(value.sheet_width, MIN_SHEET, MAX_SHEET), `The sheet width is not between ${MIN_SHEET} and ${MAX_SHEET} mm; using 1000 mm.`],
    ['units', value.units === 'mm' || value.units === 'in', 'The display units are mm or in; using mm.'],
  ];
  for (const [key, ok, warning] of fields) {
    if (ok) out[key] = value[key];
    else if (value[key] !== undefined) warnings.push(warning);
  }
  const result = { ...value, ...out };
  // Optional fields: a bad one is dropped (the default applies) with a warning.
  const optional = [
    ['free_edge_allowance', inRange(value.free_edge_allowance, 0, MAX_ALLOWANCE), `The allowance of free edges is not between 0 and ${MAX_ALLOWANCE} mm; free edges get the seam allowance.`],
    ['grain_lock', typeof value.grain_lock === 'boolean', 'The grain setting (grain_lock) is not true or false; panels may turn when nested.'],
    ['rotate', typeof value.rotate === 'boolean', 'The rotation setting (rotate) is not true or false; panels may turn when nested.'],
  ];
  for (const [key, ok, warning] of optional) {
    if (value[key] === undefined || ok) continue;
    delete result[key];
    warnings.push(warning);
  }
  if (value.joining !== undefined && !JOININGS.includes(value.joining)) {
    delete result.joining;
    warnings.push('The design says its pieces are joined neither sewn nor sealed; they are taken as sewn.');
  }
  if (value.valves !== undefined) {
    const valves = parseValves(value.valves, warnings);
    if (valves.length) result.valves = valves;
    else delete result.valves;
  }
  if (value.seam_allowance !== undefined) {
    const seams = parseSeamAllowance(value.seam_allowance, warnings);
    if (seams) result.seam_allowance = seams;
    else delete result.seam_allowance;
  }
  return result;
}

// design.fabrication.seam_allowance: the valid entries sorted by seam id (null when none is left); each bad
// entry is dropped with a warning that names it.
function parseSeamAllowance(value, warnings) {
  if (!isObject(value)) {
    warnings.push('The seam allowances per seam (seam_allowance) are not a list of seam ids and widths; every seam gets the seam allowance.');
    return null;
  }
  const out = {};
  for (const key of Object.keys(value).filter(isSeamId).sort((a, b) => a - b)) {
    if (inRange(value[key], 0, MAX_ALLOWANCE)) out[key] = value[key];
    else warnings.push(`The allowance of seam ${seamLabel(key)} is not between 0 and ${MAX_ALLOWANCE} mm; it gets the seam allowance.`);
  }
  for (const key of Object.keys(value).filter((k) => !isSeamId(k)))
    warnings.push(`The seam allowance names the seam "${key.slice(0, 40)}", which is no seam id (a whole number from 0); it is ignored.`);
  return Object.keys(out).length ? out : null;
}

// design.fabrication.valves: the valid ones; each bad one is dropped with a warning that names it.
function parseValves(value, warnings) {
  if (!Array.isArray(value)) {
    warnings.push('The fill valves of the design are not a list; they are left out.');
    return [];
  }
  const out = [];
  value.forEach((v, k) => {
    const ok = isObject(v) && Number.isInteger(v.seam) && isSeamId(v.seam) && inRange(v.at, 0, 1) && inRange(v.width, 0, MAX_VALVE_WIDTH) && v.width > 0;
    if (ok) out.push({ seam: v.seam, at: v.at, width: v.width });
    else warnings.push(`Fill valve ${k + 1} of the design is not on a seam with a width from 0 to ${MAX_VALVE_WIDTH} mm; it is left out.`);
  });
  return out;
}

// The grain setting as one of 'free' (panels turn as they nest best), 'grain' (kept along the roll: turned
// 0° or 180° only) or 'fixed' (as drawn), and the fabrication fields of each.
export function grainMode(fabrication) {
  return fabrication.grain_lock ? 'grain' : fabrication.rotate === false ? 'fixed' : 'free';
}
export const GRAIN_FIELDS = Object.freeze({
  free: { grain_lock: undefined, rotate: undefined },
  grain: { grain_lock: true, rotate: undefined },
  fixed: { grain_lock: undefined, rotate: false },
});

// The allowance of one seam [mm]: its own, else the seam allowance.
export function seamAllowanceOf(fabrication, id) {
  const own = fabrication.seam_allowance?.[String(id)];
  return own ?? fabrication.allowance;
}

// The exporter's options (wasm/src/export, lengths in mm) from the design's fabrication settings.
export function exportOptions(fabrication, extra = {}) {
  const options = { allowance: fabrication.allowance, sheet_width: fabrication.sheet_width, units: fabrication.units };
  if (fabrication.seam_allowance && Object.keys(fabrication.seam_allowance).length) options.seam_allowance = { ...fabrication.seam_allowance };
  if (fabrication.free_edge_allowance !== undefined) options.free_edge_allowance = fabrication.free_edge_allowance;
  if (fabrication.grain_lock !== undefined) options.grain_lock = fabrication.grain_lock;
  if (fabrication.rotate !== undefined) options.rotate = fabrication.rotate;
  if (fabrication.joining !== undefined) options.joining = fabrication.joining;
  if (fabrication.valves?.length) options.valves = fabrication.valves.map((v) => ({ ...v }));
  return { ...options, ...extra };
}

// A length given in mm, in the designer's units: "123 mm" or "4.84 in".
export function formatMillimeters(mm, units = 'mm') {
  return units === 'in' ? `${(mm / MM_PER_INCH).toFixed(2)} in` : `${mm.toFixed(0)} mm`;
}

// A panel's size (width by height, given in mm) in the designer's units: "412 × 380 mm" or "16.2 × 15.0 in".
export function formatSize(widthMm, heightMm, units = 'mm') {
  return units === 'in'
    ? `${(widthMm / MM_PER_INCH).toFixed(1)} × ${(heightMm / MM_PER_INCH).toFixed(1)} in`
    : `${widthMm.toFixed(0)} × ${heightMm.toFixed(0)} mm`;
}

// Rows for the pattern pane's figures box from the exporter's statistics (wasm/src/export/statistics.hpp).
export function patternStatRows(statistics, units = 'mm') {
  const t = statistics.totals;
  const minutes = Math.round(t.sewing_minutes);
  return [
    ['Panels', String(statistics.panels.length)],
    ['Material', `${t.material_area_m2.toFixed(2)} m² with allowance`],
    ['Sheet', `${formatMillimeters(t.sheet_width_mm, units)} × ${formatMillimeters(t.sheet_length_mm, units)} (${Math.round(100 * t.utilisation)} % used)`],
    // A heat-sealed pattern is not sewn: the sewing time is for sewn ones.
    ['Seams', `${(t.seam_length_mm / 1000).toFixed(2)} m${statistics.joining === 'sealed' ? '' : `, about ${minutes >= 90 ? `${(minutes / 60).toFixed(1)} h` : `${minutes} min`} to sew`}`],
    ['Seam mismatch', `${formatMillimeters(t.max_seam_mismatch_mm, units === 'in' ? 'in' : 'mm').replace(/^0 mm$/, '< 1 mm')}`],
  ];
}

// Signed area of a panel [m²] from its triangles.
function panelArea(panel) {
  let area = 0;
  for (const [a, b, c] of panel.triangles) {
    const [ax, ay] = panel.vertices[a], [bx, by] = panel.vertices[b], [cx, cy] = panel.vertices[c];
    area += 0.5 * ((bx - ax) * (cy - ay) - (cx - ax) * (by - ay));
  }
  return Math.abs(area);
}

// The stress that the most stressed `share` of the outer surface reaches [Pa]: the figure to judge bursting
// by. The single highest triangle is often a sliver where panels meet (a spike of the simulation mesh,
// not of the sheet), so it is not used alone. result: { positions #V*3, triangles #F*3, outer #F,
// stress #F*2 (max principal stress first) }.
export function peakStress(result, share = 0.01) {
  const { positions: x, triangles: t, outer, stress } = result;
  if (!stress?.length) return 0;
  const faces = [];
  let total = 0;
  for (let f = 0; f < outer.length; f++) {
    if (!outer[f]) continue;
    const [a, b, c] = [3 * t[3 * f], 3 * t[3 * f + 1], 3 * t[3 * f + 2]];
    const u = [x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]];
    const v = [x[c] - x[a], x[c + 1] - x[a + 1], x[c + 2] - x[a + 2]];
    const area = 0.5 * Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    faces.push([stress[2 * f], area]);
    total += area;
  }
  faces.sort((p, q) => q[0] - p[0]);
  let covered = 0;
  for (const [sigma, area] of faces) {
    covered += area;
    if (covered >= share * total) return sigma;
  }
  return faces.length ? faces[faces.length - 1][0] : 0;
}

// What a balloon maker asks of an inflated pattern. pattern: panels in meters with its material
// { name, thickness, youngs_modulus, density? }; volume [m³]; maxStress [Pa].
// Returns { massGrams, liftGrams, floats, safetyFactor, blowerPascals } (null figures when the material's
// density or strength is unknown; blowerPascals only for structures a blower can keep up).
export function balloonFigures(pattern, volume, maxStress) {
  const material = pattern.material ?? {};
  const preset = findMaterialPreset(material.name);
  const density = material.density ?? preset?.density;
  const strength = preset?.strength;
  const sheetArea = pattern.panels.reduce((sum, p) => sum + panelArea(p), 0);
  const massGrams = density ? sheetArea * material.thickness * density * 1000 : null;
  const liftGrams = volume * (AIR_DENSITY - HELIUM_DENSITY) * 1000;
  return {
    massGrams,
    liftGrams,
    floats: massGrams === null ? null : liftGrams > massGrams,
    safetyFactor: strength && maxStress > 0 ? strength / maxStress : null,
    // Fabric and plastic structures are often kept up by a fan blower: its static pressure must reach the
    // design's. Foil balloons are sealed (helium or a straw), so they get none.
    blowerPascals: material.name !== 'foil' && pattern.pressure > 0 ? pattern.pressure : null,
  };
}

// About the most static pressure a fan blower for inflatables gives (a 1 HP bounce-house blower: 1.2 kPa).
export const BLOWER_MAX_PA = 1200;

// Rows for the inflated pane's figures box.
export function balloonRows(figures) {
  const rows = [];
  if (figures.massGrams !== null) rows.push(['Envelope mass', `${figures.massGrams.toFixed(figures.massGrams < 10 ? 1 : 0)} g`]);
  const lift = `${figures.liftGrams.toFixed(figures.liftGrams < 10 ? 1 : 0)} g`;
  rows.push(['Helium lift', figures.floats === null ? lift : `${lift}, ${figures.floats ? 'floats' : 'does not float'} (net ${(figures.liftGrams - figures.massGrams).toFixed(0)} g)`]);
  if (figures.blowerPascals !== null) {
    const p = figures.blowerPascals;
    const text = p < 1000 ? `${Math.round(p)} Pa` : `${(p / 1000).toFixed(1)} kPa`;
    rows.push(['Blower', p <= BLOWER_MAX_PA ? `${text} static pressure (a fan blower gives up to about 1.2 kPa)` : `${text}: more than a fan blower gives; seal it and use a pump`]);
  }
  if (figures.safetyFactor !== null)
    rows.push(['Safety factor', `${figures.safetyFactor.toFixed(1)}${figures.safetyFactor < 1 ? ' — it would burst' : figures.safetyFactor < 2 ? ' — too close to bursting' : ''}`]);
  return rows;
}
