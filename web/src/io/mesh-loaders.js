// Target mesh files, welded into an indexed mesh: OBJ and STL through the three.js loaders, PLY through the command
// line's reader (io/ply_reader.cpp, which knows the triangle strips of scanned meshes). Runs inside the worker: large
// files never freeze the page.
import { BufferGeometry, Float32BufferAttribute } from 'three';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { STLLoader } from 'three/addons/loaders/STLLoader.js';
import { mergeVertices } from 'three/addons/utils/BufferGeometryUtils.js';
import { SolverError } from '../worker/protocol.js';

export const MAX_FILE_BYTES = 256 * 1024 * 1024;
export const MAX_TRIANGLES = 500000; // the solver's interactive budget (also checked in C++ validation)
export const MESH_EXTENSIONS = ['obj', 'stl', 'ply'];

export function extensionOf(fileName) {
  const dot = fileName.lastIndexOf('.');
  return dot < 0 ? '' : fileName.slice(dot + 1).toLowerCase();
}

function fail(code, message) {
  throw new SolverError(code, message);
}

// Geometries from the loader, whatever it returns (OBJ gives a Group of meshes, STL one geometry; PLY one mesh from
// readMeshFile, the solver's reader: (fileName, bytes, maxTriangles) -> { positions, indices }).
function geometriesOf(fileName, bytes, readMeshFile) {
  const ext = extensionOf(fileName);
  if (ext === 'obj') {
    const text = new TextDecoder().decode(bytes);
    if (!/^\s*v\s/m.test(text))
      fail('mesh.unreadable', `"${fileName}" does not look like an OBJ mesh: it has no vertex lines.`);
    const group = new OBJLoader().parse(text);
    const out = [];
    group.traverse((object) => object.isMesh && out.push(object.geometry));
    return out;
  }
  if (ext === 'stl') return [new STLLoader().parse(bytes)];
  if (ext === 'ply') return [readMeshFile(fileName, bytes, MAX_TRIANGLES)];
  return fail(
    'mesh.unknown-format',
    `Billow cannot open "${fileName}": use a mesh in OBJ, STL or PLY format (.obj, .stl, .ply).`,
  );
}

// Non-indexed soups (OBJ, STL) and indexed PLY alike -> one position array and one index array.
function positionsAndIndices(geometries) {
  const positions = [];
  const indices = [];
  for (const g of geometries) {
    if (g.indices) {
      const base = positions.length / 3;
      for (const p of g.positions) positions.push(p);
      for (const i of g.indices) indices.push(base + i);
      continue;
    }
    const pos = g.getAttribute('position');
    if (!pos) continue;
    const base = positions.length / 3;
    for (let i = 0; i < pos.count * 3; i++) positions.push(pos.array[i]);
    if (g.index) for (let i = 0; i < g.index.count; i++) indices.push(base + g.index.array[i]);
    else for (let i = 0; i < pos.count; i++) indices.push(base + i);
  }
  return { positions, indices };
}

// Parses bytes (ArrayBuffer) named fileName into { positions: Float32Array, indices: Uint32Array }; readMeshFile as
// geometriesOf's.
export function parseMesh(fileName, bytes, readMeshFile) {
  if (bytes.byteLength === 0) fail('mesh.empty-file', `"${fileName}" is empty.`);
  if (bytes.byteLength > MAX_FILE_BYTES)
    fail('mesh.file-too-large', `"${fileName}" is larger than ${MAX_FILE_BYTES >> 20} MB, more than Billow can open.`);
  let geometries;
  try {
    geometries = geometriesOf(fileName, bytes, readMeshFile);
  } catch (error) {
    if (error instanceof SolverError) throw error;
    fail('mesh.unreadable', `"${fileName}" could not be read as a ${extensionOf(fileName).toUpperCase()} mesh. The file may be damaged.`);
  }
  const { positions, indices } = positionsAndIndices(geometries);
  if (indices.length < 3) fail('mesh.empty', `"${fileName}" contains no triangles, so there is no shape to design on.`);
  if (indices.length / 3 > MAX_TRIANGLES)
    fail(
      'mesh.too-large',
      `"${fileName}" has ${(indices.length / 3).toLocaleString('en')} triangles; Billow works interactively up to ${MAX_TRIANGLES.toLocaleString('en')}. Simplify it (for example with Decimate in Blender or MeshLab) and open it again.`,
    );
  for (const p of positions)
    if (!Number.isFinite(p))
      fail('mesh.not-finite', `"${fileName}" has vertices with invalid coordinates (not a number). The file is damaged.`);
  for (const i of indices)
    if (!(i >= 0 && i < positions.length / 3))
      fail('mesh.bad-index', `"${fileName}" refers to vertices that do not exist. The file is damaged.`);
  return weld(positions, indices);
}

// Merges coincident vertices (tolerance relative to the size) so triangles share corners.
export function weld(positions, indices) {
  const soup = new BufferGeometry();
  const corners = new Float32Array(indices.length * 3);
  for (let k = 0; k < indices.length; k++)
    for (let c = 0; c < 3; c++) corners[3 * k + c] = positions[3 * indices[k] + c];
  soup.setAttribute('position', new Float32BufferAttribute(corners, 3));
  soup.computeBoundingBox();
  const diagonal = soup.boundingBox.max.distanceTo(soup.boundingBox.min) || 1;
  const welded = mergeVertices(soup, diagonal * 1e-7);
  return {
    positions: new Float32Array(welded.getAttribute('position').array),
    indices: new Uint32Array(welded.index.array),
  };
}
