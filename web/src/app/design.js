// The design document: the only saved state (see docs/formats.md). Read with parse-and-default: every
// field is validated, a bad field falls back to its default with a warning, unknown fields are kept.
import { findExample, DEFAULT_EXAMPLE } from './examples.js';
import {
  DEFAULT_MATERIAL, DEFAULT_PRESSURE, MIN_PRESSURE, MAX_PRESSURE, MIN_THICKNESS, MAX_THICKNESS, MIN_YOUNGS, MAX_YOUNGS,
  findMaterialPreset, presetMaterial, formatPressure,
} from './materials.js';
import { fabricationFor, parseFabrication } from './fabrication.js';
import { parseSymmetry, positionOf } from './symmetry.js';
import { parseUp } from './up-axis.js';
import { parseBand } from './band.js';

export const DESIGN_FORMAT = 'billow-design';
export const DESIGN_VERSION = 1;
const MIN_HEIGHT = 0.01;
const MAX_HEIGHT = 100;

export function newDesign(exampleId = DEFAULT_EXAMPLE) {
  const example = findExample(exampleId) ?? findExample(DEFAULT_EXAMPLE);
  return {
    format: DESIGN_FORMAT,
    version: DESIGN_VERSION,
    target: { example: example.id },
    size: { height: example.height },
    seams: [],
    connections: [],
    material: presetMaterial(DEFAULT_MATERIAL),
    pressure: DEFAULT_PRESSURE,
    fabrication: fabricationFor(presetMaterial(DEFAULT_MATERIAL)),
  };
}

const inRange = (v, lo, hi) => typeof v === 'number' && Number.isFinite(v) && v >= lo && v <= hi;

// The material with parse-and-default: a preset's name stands for its figures, given figures override them.
function parseMaterial(value, warnings) {
  if (value === undefined) return presetMaterial(DEFAULT_MATERIAL);
  if (!isObject(value)) {
    warnings.push('The design\'s material is not valid; foil is used instead.');
    return presetMaterial(DEFAULT_MATERIAL);
  }
  const preset = findMaterialPreset(value.name);
  const material = { ...value, ...(preset ? presetMaterial(preset.name) : {}), name: typeof value.name === 'string' ? value.name : 'custom' };
  if (!preset && !(inRange(value.thickness, MIN_THICKNESS, MAX_THICKNESS) && inRange(value.youngs_modulus, MIN_YOUNGS, MAX_YOUNGS))) {
    warnings.push(`The design's material "${material.name}" has no valid thickness and Young's modulus; foil is used instead.`);
    return presetMaterial(DEFAULT_MATERIAL);
  }
  if (value.thickness !== undefined) {
    if (inRange(value.thickness, MIN_THICKNESS, MAX_THICKNESS)) material.thickness = value.thickness;
    else warnings.push(`The material's thickness is not between 0.1 µm and 1 cm; using ${material.thickness} m.`);
  }
  if (value.youngs_modulus !== undefined) {
    if (inRange(value.youngs_modulus, MIN_YOUNGS, MAX_YOUNGS)) material.youngs_modulus = value.youngs_modulus;
    else warnings.push(`The material's Young's modulus is not valid; using ${material.youngs_modulus} Pa.`);
  }
  return material;
}

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// The design as its file is written, beside the designer's mesh file. Billow numbers the faces it adds as it opens
// that file (the caps over its holes, the ends of cut handles) after the file's own, and may cap or cut another way
// in a later version: so a seam point on an added face is written as the 3D point it is (read back, it is projected
// onto the surface), while a point on one of the file's own faces keeps { face, bary }. target: { positions,
// indices, report } as the worker installed it (report.facesRead: the file's own faces, set where faces were added).
export function designForFile(design, target) {
  const own = target?.report?.facesRead;
  if (!Number.isInteger(own) || design.target.example) return design;
  const onAdded = (p) => Number.isInteger(p?.face) && p.face >= own && Array.isArray(p.bary);
  if (!design.seams.some((seam) => seam.points?.some(onAdded))) return design;
  return {
    ...design,
    seams: design.seams.map((seam) => (seam.points?.some(onAdded) ? { ...seam, points: seam.points.map((p) => (onAdded(p) ? positionOf(target, p) : p)) } : seam)),
  };
}

// The last part of a path, as a file picker names the file ("meshes/octopus.obj" -> "octopus.obj").
const baseName = (path) => path.split(/[\\/]/).pop();

// An inline target's mesh ({ vertices: [[x, y, z]...], triangles: [[i, j, k]...] }, 0-based, as the CLI writes
// it: docs/formats.md) as the text of an OBJ file, which the worker reads and checks as any opened mesh; null when
// the arrays are not a mesh's.
function inlineTargetObj(target) {
  const { vertices, triangles } = target;
  const triple = (row, ok) => Array.isArray(row) && row.length === 3 && row.every(ok);
  if (!Array.isArray(vertices) || !Array.isArray(triangles) || vertices.length < 4 || triangles.length < 4) return null;
  if (!vertices.every((v) => triple(v, Number.isFinite))) return null;
  if (!triangles.every((t) => triple(t, (i) => Number.isInteger(i) && i >= 0 && i < vertices.length))) return null;
  return [...vertices.map((v) => `v ${v.join(' ')}`), ...triangles.map((t) => `f ${t[0] + 1} ${t[1] + 1} ${t[2] + 1}`)].join('\n');
}

// Returns { design, warnings, targetKnown, targetObj }. Throws Error with a designer-facing message when it is no
// design at all. The target is one of the app's examples or a mesh file the designer opens by its name ({ file });
// the command line's forms (docs/formats.md) are read as the app's: a path ({ obj }) names the file, an inline mesh
// comes as targetObj (the text of an OBJ file, named by target.file). A design whose target is none of these opens
// on the default example without its seams, which lie on faces of a mesh that is not there (targetKnown false).
export function parseDesign(value, { inlineName = 'target.obj' } = {}) {
  if (!isObject(value) || value.format !== DESIGN_FORMAT)
    throw new Error('This is not a Billow design (its "format" is not "billow-design").');
  if (!Number.isInteger(value.version) || value.version < 1)
    throw new Error('This Billow design has no valid version number.');
  if (value.version > DESIGN_VERSION)
    throw new Error(
      `This design was made by a newer Billow (format version ${value.version}); this one reads up to version ${DESIGN_VERSION}.`,
    );
  const warnings = [];
  const design = { ...value };
  const target = value.target;
  let targetKnown = true, targetObj = null;
  if (isObject(target) && typeof target.example === 'string' && findExample(target.example)) {
    design.target = { ...target };
  } else if (isObject(target) && typeof target.file === 'string' && target.file.length <= 255) {
    design.target = { ...target };
  } else if (isObject(target) && typeof target.obj === 'string' && baseName(target.obj) && baseName(target.obj).length <= 255) {
    const { obj, ...rest } = target;
    design.target = { ...rest, file: baseName(obj) };
  } else if (isObject(target) && (targetObj = inlineTargetObj(target))) {
    const { vertices, triangles, ...rest } = target;
    design.target = { ...rest, file: inlineName };
  } else {
    targetKnown = false;
    warnings.push('The design names no target Billow knows, so its seams cannot be placed: the default example is opened without them.');
    design.target = { example: DEFAULT_EXAMPLE };
  }
  design.target = parseUp(design.target, warnings);
  // What was done to the designer's mesh as it was opened (app.js): its thin handles cut, its holes closed.
  for (const [key, what] of [['cutThinHandles', "the target's thin handles are cut"], ['closeHoles', "the target's holes are closed"]]) {
    if (!(key in design.target) || typeof design.target[key] === 'boolean') continue;
    const { [key]: value, ...rest } = design.target;
    design.target = rest;
    warnings.push(`Whether ${what} (target.${key}) must be true or false, not ${JSON.stringify(value)}: the mesh is used as it is.`);
  }
  const height = value.size?.height;
  if (typeof height === 'number' && Number.isFinite(height) && height >= MIN_HEIGHT && height <= MAX_HEIGHT) {
    design.size = { ...value.size, height };
  } else {
    if (value.size !== undefined) warnings.push(`The design's height is not between ${MIN_HEIGHT} and ${MAX_HEIGHT} m; using 0.6 m.`);
    design.size = { height: 0.6 };
  }
  design.seams = targetKnown && Array.isArray(value.seams) ? value.seams : [];
  // The pair form [i, j] of an internal connection, which the CLI reads too, as the form the app writes.
  design.connections = targetKnown && Array.isArray(value.connections) ? value.connections.map((c) => (Array.isArray(c) ? { seams: c } : c)) : [];
  design.material = parseMaterial(value.material, warnings);
  if (inRange(value.pressure, MIN_PRESSURE, MAX_PRESSURE)) design.pressure = value.pressure;
  else {
    if (value.pressure !== undefined)
      warnings.push(`The design's pressure is not between ${formatPressure(MIN_PRESSURE)} and ${formatPressure(MAX_PRESSURE)}; using ${formatPressure(DEFAULT_PRESSURE)}.`);
    design.pressure = DEFAULT_PRESSURE;
  }
  design.fabrication = parseFabrication(value.fabrication, warnings);
  const symmetry = parseSymmetry(value.symmetry, warnings);
  if (symmetry) design.symmetry = symmetry;
  else delete design.symmetry;
  design.seams = design.seams.map((seam) => {
    // A gusset band's record (band.js) Billow cannot lay again is dropped; the seam stays as drawn.
    if (!isObject(seam) || seam.band === undefined) return seam;
    const band = parseBand(seam.band);
    if (band) return { ...seam, band };
    warnings.push(`The gusset band record of ${typeof seam.name === 'string' ? `"${seam.name}"` : 'a seam'} is not valid: the seam stays as it is, but its band's width can no longer be changed.`);
    const { band: _, ...rest } = seam;
    return rest;
  });
  design.seams = design.seams.map((seam, i) => {
    // A twin link must name another seam that links back; anything else is dropped.
    if (seam === null || typeof seam !== 'object' || seam.mirror === undefined) return seam;
    const twin = design.seams[seam.mirror];
    if (Number.isInteger(seam.mirror) && seam.mirror !== i && twin && twin.mirror === i) return seam;
    const { mirror, ...rest } = seam;
    return rest;
  });
  return { design, warnings, targetKnown, targetObj };
}

export function clampHeight(h) {
  return Math.min(MAX_HEIGHT, Math.max(MIN_HEIGHT, h));
}
