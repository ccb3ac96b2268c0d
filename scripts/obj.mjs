// Vertices and triangles of an OBJ file (faces triangulated as fans), for the scripts that make designs.
import { readFileSync } from 'node:fs';

export function readObj(path) {
  const v = [], t = [];
  for (const line of readFileSync(path, 'utf8').split('\n')) {
    const f = line.trim().split(/\s+/);
    if (f[0] === 'v') v.push(f.slice(1, 4).map(Number));
    else if (f[0] === 'f') {
      const ids = f.slice(1).map((s) => parseInt(s, 10) - 1);
      for (let k = 1; k + 1 < ids.length; k++) t.push([ids[0], ids[k], ids[k + 1]]);
    }
  }
  return { v, t };
}
