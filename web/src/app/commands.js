// Commands: pure functions (design, ...args) -> design. The History stores the results; nothing here
// mutates its input. Seams hold control points as surface points { face, bary } on the target.
import { fabricationWithMaterial } from './fabrication.js';

const replaceAt = (list, i, value) => list.map((x, k) => (k === i ? value : x));

export const DEFAULT_SEAM_WEIGHT = 1;

// New seams are smooth: a cubic Hermite spline through the control points, carried onto the surface
// (seams/seam_curve.hpp); a seam that is not smooth runs along the shortest paths between its points.
// band: the gusset band the seam belongs to (band.js), kept so the band can be laid again at another width.
export function addSeam(design, { points, closed, smooth = true, name = `Seam ${design.seams.length + 1}`, band }) {
  const seam = { name, closed: Boolean(closed), smooth: Boolean(smooth), weight: DEFAULT_SEAM_WEIGHT, points, ...(band ? { band } : {}) };
  return { ...design, seams: [...design.seams, seam] };
}

// A number for a new gusset band: one more than any band's of the design. Bands are known by number, not by
// their seams' places, so deleting or renumbering seams leaves them as they are.
export const nextBandId = (design) => 1 + design.seams.reduce((most, s) => Math.max(most, s.band?.id ?? 0), 0);

// The seams of band `id` by part ({ 'side 1': i, 'side 2': j, across: k }; a part deleted is missing).
export function bandMembers(design, id) {
  const members = {};
  design.seams.forEach((s, i) => {
    if (s.band?.id === id && members[s.band.part] === undefined) members[s.band.part] = i;
  });
  return members;
}

// "Band 40 mm, side 1" at another width: "Band 60 mm, side 1"; a name the designer gave stays.
export const bandSeamName = (name, widthMm) => (typeof name === 'string' ? name.replace(/^Band [\d.]+ mm\b/, `Band ${+widthMm.toFixed(1)} mm`) : name);

// A seam laid again in one action: its points replaced, its name and band if given.
export function relaySeam(design, seam, { points, name, band }) {
  const s = design.seams[seam];
  if (!s) return design;
  return { ...design, seams: replaceAt(design.seams, seam, { ...s, points, ...(name !== undefined ? { name } : {}), ...(band ? { band } : {}) }) };
}

// Band `id` laid again at another width: points: per part ('side 1', 'side 2', 'across') its new control points;
// each of its seams takes them, the width in its band record and in its name. Parts missing from the design or
// from `points` are left out.
export function relayBand(design, id, { width_mm: widthMm, points }) {
  let next = design;
  for (const [part, seam] of Object.entries(bandMembers(design, id))) {
    if (!points[part]) continue;
    const s = design.seams[seam];
    next = relaySeam(next, seam, { points: points[part], name: bandSeamName(s.name, widthMm), band: { ...s.band, width_mm: widthMm } });
  }
  return next;
}

export function setSeamSmooth(design, seam, smooth) {
  const s = design.seams[seam];
  if (!s) return design;
  return { ...design, seams: replaceAt(design.seams, seam, { ...s, smooth: Boolean(smooth) }) };
}

// Points attached to another seam ({ ..., on: seam }) lose the attachment when that seam goes, and
// follow the renumbering of the others.
function renumberAttachments(point, removed) {
  if (point.on === undefined) return point;
  if (point.on === removed) {
    const { on, ...free } = point;
    return free;
  }
  return point.on > removed ? { ...point, on: point.on - 1 } : point;
}

// A mirrored twin link (seam.mirror) to the removed seam goes; links past it follow the renumbering.
function renumberMirror(seam, removed) {
  if (seam.mirror === undefined) return seam;
  const { mirror, ...rest } = seam;
  if (mirror === removed) return rest;
  return { ...rest, mirror: mirror > removed ? mirror - 1 : mirror };
}

export function deleteSeam(design, seam) {
  if (!design.seams[seam]) return design;
  return {
    ...design,
    seams: design.seams
      .filter((_, k) => k !== seam)
      .map((s) => renumberMirror({ ...s, points: s.points.map((p) => renumberAttachments(p, seam)) }, seam)),
    // Internal connections that used the seam go with it; the others are renumbered.
    connections: design.connections
      .filter((c) => !c.seams.includes(seam))
      .map((c) => ({ ...c, seams: c.seams.map((s) => (s > seam ? s - 1 : s)) })),
  };
}

export function moveControlPoint(design, seam, index, point) {
  const s = design.seams[seam];
  if (!s || !s.points[index]) return design;
  return { ...design, seams: replaceAt(design.seams, seam, { ...s, points: replaceAt(s.points, index, point) }) };
}

export function insertControlPoint(design, seam, index, point) {
  const s = design.seams[seam];
  if (!s) return design;
  const points = [...s.points.slice(0, index), point, ...s.points.slice(index)];
  return { ...design, seams: replaceAt(design.seams, seam, { ...s, points }) };
}

// Deleting a point of a two-point seam deletes the seam (a seam needs two points).
export function deleteControlPoint(design, seam, index) {
  const s = design.seams[seam];
  if (!s || !s.points[index]) return design;
  if (s.points.length <= 2) return deleteSeam(design, seam);
  const points = s.points.filter((_, k) => k !== index);
  return { ...design, seams: replaceAt(design.seams, seam, { ...s, points, closed: s.closed && points.length >= 3 }) };
}

export function setSeamWeight(design, seam, weight) {
  const s = design.seams[seam];
  if (!s || !(weight >= 0)) return design;
  return { ...design, seams: replaceAt(design.seams, seam, { ...s, weight }) };
}

// axis: 'x' | 'y' | 'z' turns mirror symmetry on across that plane (symmetry.js); null turns it off.
export function setSymmetry(design, axis) {
  const { symmetry, ...rest } = design;
  return axis ? { ...rest, symmetry: { axis } } : rest;
}

export function setHeight(design, height) {
  return { ...design, size: { ...design.size, height } };
}

// up: which of the target's own axes points up ('+y', '-y', '+z', '-z', '+x', '-x'; up-axis.js). Y up, the
// default, is written by leaving the field out, so designs made before it existed keep their stored results.
export function setUp(design, up) {
  const { up: old, ...target } = design.target;
  if ((old ?? '+y') === up) return design;
  return { ...design, target: up === '+y' ? target : { ...target, up } };
}

// material: { name, thickness [m], youngs_modulus [Pa], density? }
// The joining (sewn or sealed) follows the material (fabrication.js).
export function setMaterial(design, material) {
  return { ...design, material: { ...material }, fabrication: fabricationWithMaterial(design.fabrication, material) };
}

// Fill valves (design.fabrication.valves, each { seam: exporter seam id, at: share of its length, width: mm }).
export function addValve(design, valve) {
  const valves = [...(design.fabrication.valves ?? []), { seam: valve.seam, at: valve.at, width: valve.width }];
  return { ...design, fabrication: { ...design.fabrication, valves } };
}

export function setValveWidth(design, index, width) {
  const valves = design.fabrication.valves ?? [];
  if (!valves[index]) return design;
  return { ...design, fabrication: { ...design.fabrication, valves: replaceAt(valves, index, { ...valves[index], width }) } };
}

export function removeValve(design, index) {
  const valves = (design.fabrication.valves ?? []).filter((_, k) => k !== index);
  const fabrication = { ...design.fabrication, valves };
  if (!valves.length) delete fabrication.valves;
  return { ...design, fabrication };
}

// changes: some of { allowance [mm], sheet_width [mm], units: 'mm' | 'in', free_edge_allowance [mm],
// grain_lock, rotate }; a field set to undefined is removed (its default applies).
export function setFabrication(design, changes) {
  const fabrication = { ...design.fabrication, ...changes };
  for (const [key, value] of Object.entries(changes)) if (value === undefined) delete fabrication[key];
  return { ...design, fabrication };
}

// One seam's own allowance [mm] (seam id as in the exporter's statistics), or null: back to the seam
// allowance. Returns the same design when nothing changes.
export function setSeamAllowance(design, id, mm) {
  const key = String(id);
  const current = design.fabrication.seam_allowance ?? {};
  if ((current[key] ?? null) === mm) return design;
  const seams = { ...current };
  if (mm === null) delete seams[key];
  else seams[key] = mm;
  const sorted = Object.fromEntries(Object.entries(seams).sort(([a], [b]) => a - b));
  return setFabrication(design, { seam_allowance: Object.keys(sorted).length ? sorted : undefined });
}

export function setPressure(design, pascals) {
  return { ...design, pressure: pascals };
}

// Seam ends attached to another seam follow it: a point whose host curve no longer passes through it is
// moved to the host curve's closest sample. traces: per seam { curve, faces, barys } (null: unknown);
// positionOf(point) -> [x, y, z]. Returns the same design when nothing moved.
export function reattachSeamEnds(design, traces, positionOf) {
  let changed = false;
  const seams = design.seams.map((seam, i) => {
    const points = seam.points.map((p) => {
      const host = p.on !== undefined && p.on !== i ? traces[p.on] : null;
      if (!host || liesOnCurve(p, host)) return p;
      const [x, y, z] = positionOf(p);
      let best = 0;
      let bestDistance = Infinity;
      for (let k = 0; k < host.faces.length; k++) {
        const d = (host.curve[3 * k] - x) ** 2 + (host.curve[3 * k + 1] - y) ** 2 + (host.curve[3 * k + 2] - z) ** 2;
        if (d < bestDistance) {
          bestDistance = d;
          best = k;
        }
      }
      changed = true;
      return { face: host.faces[best], bary: Array.from(host.barys.slice(3 * best, 3 * best + 3)), on: p.on };
    });
    return points === seam.points ? seam : { ...seam, points };
  });
  return changed ? { ...design, seams } : design;
}

function liesOnCurve(p, host) {
  for (let k = 0; k < host.faces.length; k++) {
    if (host.faces[k] !== p.face) continue;
    if (Math.abs(host.barys[3 * k] - p.bary[0]) + Math.abs(host.barys[3 * k + 1] - p.bary[1]) < 1e-12) return true;
  }
  return false;
}

// Internal connections (paper Sec. 3.2): an internal panel spanning two seams.
export function addConnection(design, a, b) {
  if (a === b || !design.seams[a] || !design.seams[b]) return design;
  const exists = design.connections.some((c) => c.seams.includes(a) && c.seams.includes(b));
  if (exists) return design;
  return { ...design, connections: [...design.connections, { seams: [a, b] }] };
}

export function deleteConnection(design, index) {
  if (!design.connections[index]) return design;
  return { ...design, connections: design.connections.filter((_, k) => k !== index) };
}
