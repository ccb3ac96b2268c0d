import { readFileSync } from 'node:fs';

// A minimal OBJ reader for tests (v and triangular f lines only, as in ../shared/meshes).
export function readObjText(text) {
  const positions = [];
  const indices = [];
  for (const line of text.split('\n')) {
    const parts = line.trim().split(/\s+/);
    if (parts[0] === 'v') positions.push(+parts[1], +parts[2], +parts[3]);
    else if (parts[0] === 'f') for (const c of parts.slice(1, 4)) indices.push(parseInt(c, 10) - 1);
  }
  return { positions: Float64Array.from(positions), indices: Int32Array.from(indices) };
}

// The meshes of ../shared/meshes (SOURCES.md), by file name.
export const SHARED_MESHES = new URL('../../../shared/meshes/', import.meta.url);
export const loadSharedMesh = (name) => readObjText(readFileSync(new URL(name, SHARED_MESHES), 'utf8'));
