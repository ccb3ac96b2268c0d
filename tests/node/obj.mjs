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
