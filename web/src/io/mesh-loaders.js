// Target mesh files (OBJ, STL, PLY, OFF), read inside the worker by the command line's reader (io/mesh_file.cpp, through the
// module's readMeshFile), so a file opens in the app as `billow check` reads it: the same triangles, welded alike, and
// the reader's message naming the line or byte where a file is damaged. Large files never freeze the page.
import { SolverError } from '../worker/protocol.js';

export const MAX_FILE_BYTES = 256 * 1024 * 1024;
export const MAX_TRIANGLES = 500000; // the solver's interactive budget (also checked in C++ validation)

function fail(code, message) {
  throw new SolverError(code, message);
}

// Parses bytes (ArrayBuffer) named fileName into { positions: Float32Array, indices: Uint32Array }; readMeshFile is the
// solver's reader: (fileName, bytes, maxTriangles) -> { positions, indices }. What the reader leaves (coordinates that
// are not numbers, collapsed triangles, too many of them) the target's validation reports.
export function parseMesh(fileName, bytes, readMeshFile) {
  if (bytes.byteLength > MAX_FILE_BYTES)
    fail('mesh.file-too-large', `"${fileName}" is larger than ${MAX_FILE_BYTES >> 20} MB, more than Billow can open.`);
  const { positions, indices } = readMeshFile(fileName, bytes, MAX_TRIANGLES);
  return { positions: Float32Array.from(positions), indices };
}
