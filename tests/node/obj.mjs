import { readFileSync } from 'node:fs';

// A minimal OBJ reader for tests (v and triangular f lines only, as in ../shared/meshes), its vertices numbered as the
// file lists them. The app and the command line read a file with the module's reader (io/mesh_file.cpp, welded, the
// vertices numbered as the faces first use them: 7 of the 12 shared meshes otherwise); a test of the app's own
// numbering opens the file through loadTarget or readMeshFile.
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

// Each triangle split in four at its edges' midpoints: the same surface, four times the triangles.
export function splitInFour({ positions, indices }) {
  const P = Array.from(positions), F = [], middle = new Map();
  const mid = (a, b) => {
    const key = a < b ? `${a},${b}` : `${b},${a}`;
    if (!middle.has(key)) {
      middle.set(key, P.length / 3);
      for (let d = 0; d < 3; d++) P.push((P[3 * a + d] + P[3 * b + d]) / 2);
    }
    return middle.get(key);
  };
  for (let f = 0; f < indices.length; f += 3) {
    const [a, b, c] = [indices[f], indices[f + 1], indices[f + 2]];
    const [ab, bc, ca] = [mid(a, b), mid(b, c), mid(c, a)];
    F.push(a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca);
  }
  return { positions: Float64Array.from(P), indices: Int32Array.from(F) };
}
