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
