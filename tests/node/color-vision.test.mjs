// Colors a designer with any color vision can tell apart: the seam colors, the segment fills and the
// inflated pane's three color ramps, seen through simulated protanopia, deuteranopia and tritanopia
// (Machado, Oliveira and Fernandes 2009, severity 1), keep a visible difference (CIELAB ΔE76).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Color } from 'three';
import { SEAM_COLORS, segmentColor } from '../../web/src/views/palette.js';
import { compressionColor, stressColor, distanceColor } from '../../web/src/views/inflated-pane.js';

// Machado et al. 2009, Table 1 at severity 1.0, on linear RGB.
const VISION = {
  normal: [1, 0, 0, 0, 1, 0, 0, 0, 1],
  protanopia: [0.152286, 1.052583, -0.204868, 0.114503, 0.786281, 0.099216, -0.003882, -0.048116, 1.051998],
  deuteranopia: [0.367322, 0.860646, -0.227968, 0.280085, 0.672501, 0.047413, -0.01182, 0.04294, 0.968881],
  tritanopia: [1.255528, -0.076749, -0.178779, -0.078411, 0.930809, 0.147602, 0.004733, 0.691367, 0.3039],
};

// CIELAB (D65) of a three.js Color (its components are linear RGB) as seen with `vision`.
function lab(color, vision) {
  const lin = [color.r, color.g, color.b];
  const m = VISION[vision];
  const seen = [0, 1, 2].map((i) => Math.min(1, Math.max(0, m[3 * i] * lin[0] + m[3 * i + 1] * lin[1] + m[3 * i + 2] * lin[2])));
  const [r, g, b] = seen;
  const X = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const Y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const Z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const f = (t) => (t > 216 / 24389 ? Math.cbrt(t) : (24389 / 27 * t + 16) / 116);
  return [116 * f(Y) - 16, 500 * (f(X) - f(Y)), 200 * (f(Y) - f(Z))];
}

const deltaE = (a, b, vision) => Math.hypot(...lab(a, vision).map((x, i) => x - lab(b, vision)[i]));
const visions = Object.keys(VISION);

test('seam colors stay apart for every color vision', () => {
  const colors = SEAM_COLORS.map((hex) => new Color(hex));
  for (const vision of visions) {
    let worst = Infinity;
    for (let i = 0; i < colors.length; i++) for (let j = i + 1; j < colors.length; j++) worst = Math.min(worst, deltaE(colors[i], colors[j], vision));
    assert.ok(worst > 10, `${vision}: the closest two seam colors differ by ΔE ${worst.toFixed(1)}`);
  }
});

test('neighbouring segment fills stay apart for every color vision', () => {
  // Segments are colored by index (segments next to each other often have near indices): any two fills
  // within two places must differ clearly.
  for (const vision of visions) {
    let worst = Infinity;
    for (let i = 0; i < 10; i++) for (let k = 1; k <= 2; k++) worst = Math.min(worst, deltaE(segmentColor(i), segmentColor(i + k), vision));
    assert.ok(worst > 11, `${vision}: segment fills within two places differ by ΔE ${worst.toFixed(1)}`);
  }
});

test('the wrinkle, stress and distance ramps read from end to end for every color vision', () => {
  const ramps = {
    wrinkles: (t) => compressionColor(0.05 * t),
    stress: (t) => stressColor(t),
    distance: (t) => distanceColor(2 * t - 1),
  };
  for (const [name, ramp] of Object.entries(ramps))
    for (const vision of visions) {
      const [low, mid, high] = [ramp(0), ramp(0.5), ramp(1)];
      const steps = [deltaE(low, mid, vision), deltaE(mid, high, vision), deltaE(low, high, vision)];
      assert.ok(Math.min(...steps) > 12, `${name}, ${vision}: low/middle/high differ by ΔE ${steps.map((d) => d.toFixed(1)).join(', ')}`);
    }
});
