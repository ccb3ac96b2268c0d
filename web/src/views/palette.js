// Colors that colorblind designers can tell apart (Okabe–Ito), and light tints of them for fills.
import { Color } from 'three';

export const SEAM_COLORS = ['#0072B2', '#E69F00', '#009E73', '#CC79A7', '#D55E00', '#56B4E9', '#F0E442', '#000000'];

export function seamColor(i) {
  return new Color(SEAM_COLORS[i % SEAM_COLORS.length]);
}

// A light tint for panel fills: the seam color mixed with white.
export function panelTint(i) {
  return seamColor(i).lerp(new Color('#ffffff'), 0.75);
}

// Segment fills: light, distinct, colorblind-safe hues; a red tint marks a segment that is not a disk.
// Ordered so that any two within two places differ by ΔE > 11 even with protanopia, deuteranopia or
// tritanopia (tests/node/color-vision.test.mjs).
const SEGMENT_FILLS = ['#d9d27a', '#e0b9a0', '#a8d8f0', '#f0a77a', '#e3a6c8', '#8fd1b4', '#b9a6e0', '#f2c879', '#9fc7a0', '#8fb3e0'];
export const PROBLEM_COLOR = new Color('#e05a4f');

export function segmentColor(i) {
  return new Color(SEGMENT_FILLS[i % SEGMENT_FILLS.length]);
}
