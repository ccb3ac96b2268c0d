// The design document: the only saved state (see docs/formats.md). Read with parse-and-default: every
// field is validated, a bad field falls back to its default with a warning, unknown fields are kept.
import { findExample, DEFAULT_EXAMPLE } from './examples.js';

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
  };
}

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// Returns { design, warnings }. Throws Error with a designer-facing message when it is no design at all.
export function parseDesign(value) {
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
  if (isObject(target) && typeof target.example === 'string' && findExample(target.example)) {
    design.target = { ...target };
  } else if (isObject(target) && typeof target.file === 'string' && target.file.length <= 255) {
    design.target = { ...target };
  } else {
    warnings.push('The design names no target Billow knows; the default example is used instead.');
    design.target = { example: DEFAULT_EXAMPLE };
  }
  const height = value.size?.height;
  if (typeof height === 'number' && Number.isFinite(height) && height >= MIN_HEIGHT && height <= MAX_HEIGHT) {
    design.size = { ...value.size, height };
  } else {
    if (value.size !== undefined) warnings.push(`The design's height is not between ${MIN_HEIGHT} and ${MAX_HEIGHT} m; using 0.6 m.`);
    design.size = { height: 0.6 };
  }
  design.seams = Array.isArray(value.seams) ? value.seams : [];
  design.connections = Array.isArray(value.connections) ? value.connections : [];
  return { design, warnings };
}

export function clampHeight(h) {
  return Math.min(MAX_HEIGHT, Math.max(MIN_HEIGHT, h));
}
