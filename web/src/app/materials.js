// Sheet materials and pressure of the design. The presets mirror wasm/src/simulate/materials.cpp (a Node
// test compares the two); the design stores the figures as well as the name, so a design made with a
// preset keeps its material if the preset's figures change.
export const MATERIAL_PRESETS = Object.freeze([
  { name: 'foil', label: 'Foil (metallized nylon, 25 µm)', thickness: 25e-6, youngs_modulus: 3.0e9, density: 1150, strength: 80e6 },
  { name: 'pvc', label: 'PVC sheet (0.3 mm)', thickness: 0.3e-3, youngs_modulus: 20e6, density: 1300, strength: 16e6 },
  { name: 'ripstop', label: 'Coated ripstop nylon (0.1 mm)', thickness: 0.1e-3, youngs_modulus: 1.0e9, density: 700, strength: 120e6 },
  { name: 'tpu', label: 'TPU film (0.2 mm)', thickness: 0.2e-3, youngs_modulus: 25e6, density: 1200, strength: 30e6 },
]);

export const DEFAULT_MATERIAL = 'foil';
export const DEFAULT_PRESSURE = 1000; // [Pa]
export const MIN_PRESSURE = 1;
export const MAX_PRESSURE = 1e7;
export const MIN_THICKNESS = 1e-7;
export const MAX_THICKNESS = 0.01;
export const MIN_YOUNGS = 1e3;
export const MAX_YOUNGS = 1e13;

export function findMaterialPreset(name) {
  return MATERIAL_PRESETS.find((m) => m.name === name) ?? null;
}

// The design's material object for a preset: { name, thickness, youngs_modulus, density }.
export function presetMaterial(name) {
  const { label, strength, ...material } = findMaterialPreset(name) ?? findMaterialPreset(DEFAULT_MATERIAL);
  return material;
}

// True when the design's material has a preset's figures (it shows under the preset's name).
export function isPresetMaterial(material) {
  const preset = findMaterialPreset(material?.name);
  return !!preset && preset.thickness === material.thickness && preset.youngs_modulus === material.youngs_modulus;
}

// "25 µm, E = 3 GPa": what a designer reads for a material's figures.
export function describeMaterial(material) {
  const h = material.thickness;
  const thickness = h < 1e-4 ? `${+(h * 1e6).toPrecision(3)} µm` : `${+(h * 1e3).toPrecision(3)} mm`;
  const e = material.youngs_modulus;
  const modulus = e >= 1e9 ? `${+(e / 1e9).toPrecision(3)} GPa` : `${+(e / 1e6).toPrecision(3)} MPa`;
  return `${thickness}, E = ${modulus}`;
}

// Pressure for display: "1.5 kPa" or "800 Pa".
export function formatPressure(pa) {
  return pa >= 1000 ? `${+(pa / 1000).toPrecision(4)} kPa` : `${+pa.toPrecision(4)} Pa`;
}
