// Which of the target's own axes points up (the design's target.up, docs/formats.md): mesh files carry no
// reliable up, and a Z-up file (CAD, 3D printing) shown Y up lies on its side with Height along its length.
// The target keeps its own coordinates (seams are {face, bary} on its triangles, the solver works in them);
// the views turn it to stand on its up axis (views/up-frame.js), and every figure shown is read in that frame.

export const DEFAULT_UP = '+y';

// The choices of the toolbar's Up select, in the designer's words.
export const UP_AXES = [
  { value: '+y', label: 'Y up' },
  { value: '+z', label: 'Z up' },
  { value: '+x', label: 'X up' },
  { value: '-y', label: '−Y up' },
  { value: '-z', label: '−Z up' },
  { value: '-x', label: '−X up' },
];

export const isUpAxis = (value) => UP_AXES.some((a) => a.value === value);

export const upLabel = (up) => UP_AXES.find((a) => a.value === up)?.label ?? up;
const axisName = (up) => up.slice(1).toUpperCase();

// The design's up axis ('+y' when it names none).
export const upOf = (design) => design?.target?.up ?? DEFAULT_UP;

// Parse-and-default of target.up (design.js): a valid axis is kept, anything else is dropped with a warning.
export function parseUp(target, warnings) {
  if (target.up === undefined || isUpAxis(target.up)) return target;
  warnings.push(`The design's up axis ${JSON.stringify(target.up)} is not one of +y, -y, +z, -z, +x, -x; the target stands Y up instead.`);
  const { up, ...rest } = target;
  return rest;
}

// The rotation from the target's own coordinates to the up frame (x right, y up, z towards the viewer), as
// its rows: up-frame coordinate i is UP_FRAMES[up][i] · p. Proper rotations, so the target is not mirrored;
// '+z' undoes the usual Y-up to Z-up conversion (x, y, z) -> (x, -z, y) exactly.
export const UP_FRAMES = {
  '+y': [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  '-y': [[1, 0, 0], [0, -1, 0], [0, 0, -1]],
  '+z': [[1, 0, 0], [0, 0, 1], [0, -1, 0]],
  '-z': [[1, 0, 0], [0, 0, -1], [0, 1, 0]],
  '+x': [[0, -1, 0], [1, 0, 0], [0, 0, 1]],
  '-x': [[0, 1, 0], [-1, 0, 0], [0, 0, 1]],
};

// The target's own axis (0 x, 1 y, 2 z) that is up-frame axis `i` (0 width, 1 height, 2 depth).
const ownAxis = (up, i) => UP_FRAMES[up][i].findIndex((c) => c !== 0);

// The target's size in its own units as width × height × depth in the up frame, from the validation stats'
// bounding box.
export function upFrameSize(stats, up = DEFAULT_UP) {
  const frame = UP_FRAMES[up] ? up : DEFAULT_UP;
  return [0, 1, 2].map((i) => {
    const k = ownAxis(frame, i);
    return stats.bbox_max[k] - stats.bbox_min[k];
  });
}

// Meters per target unit: the design's height over the target's extent along its up axis. The C++ reader's
// designScale (wasm/src/io/design_json.cpp) has the same rule.
export function heightScale(design, stats) {
  if (!stats) return 1;
  const height = upFrameSize(stats, upOf(design))[1];
  return height > 0 ? design.size.height / height : 1;
}

// A newly opened mesh file's design with the up axis the validation report guessed (stats.up: Y up unless the shape
// cannot stand on its Y bottom and can on its Z bottom, wasm/src/mesh/up_axis.hpp guessUp), and the notice that says
// so (null when the file's Y stays up). design: the new design for the file; report: its validation report.
export function withGuessedUp(design, report, fileName) {
  const up = isUpAxis(report?.stats?.up) ? report.stats.up : DEFAULT_UP;
  if (up === upOf(design)) return { design, notice: null };
  return {
    design: { ...design, target: { ...design.target, up } },
    notice: `"${fileName}" looks made ${upLabel(up)}, as files from CAD and 3D printing often are: it stands on its ${axisName(up)} bottom and would tip over on its Y bottom. Billow shows it ${upLabel(up)} and measures Height along ${axisName(up)}. If it stands wrong, choose another axis in Up, next to Height.`,
  };
}
