// Display of SI quantities in units a designer reads at a glance.
export function formatLength(m) {
  if (m >= 1) return `${m.toFixed(2)} m`;
  if (m >= 0.01) return `${(m * 100).toFixed(1)} cm`;
  return `${(m * 1000).toFixed(1)} mm`;
}

export function formatArea(m2) {
  return m2 >= 0.1 ? `${m2.toFixed(2)} m²` : `${(m2 * 1e4).toFixed(0)} cm²`;
}

export function formatVolume(m3) {
  return m3 >= 1 ? `${m3.toFixed(2)} m³` : `${(m3 * 1000).toFixed(m3 >= 0.01 ? 1 : 2)} L`;
}

// "1.4 %": a fraction (a distance over the target's size, a share of the sheet wrinkled) as the app shows it.
export function formatPercent(fraction) {
  return `${(100 * fraction).toFixed(1)} %`;
}

// The distance between an inflated shape and its target, both ways ({ rms, targetRms } over the target's size),
// the worse first: "6.70 % target → inflated, 0.35 % inflated → target". One way alone reads close for a
// shape that leaves out a whole wing, since every point it has lies on the target.
export function formatDistance({ rms, targetRms }, digits = 2) {
  const percent = (f) => `${(100 * f).toFixed(digits)} %`;
  if (targetRms === undefined || targetRms === null) return percent(rms);
  const ways = [
    [targetRms, `${percent(targetRms)} target → inflated`],
    [rms, `${percent(rms)} inflated → target`],
  ];
  if (rms > targetRms) ways.reverse();
  return ways.map((w) => w[1]).join(', ');
}

// The worse of the two ways (formatDistance), for comparisons and a single figure.
export function worseDistance({ rms, targetRms }) {
  return Math.max(rms, targetRms ?? 0);
}
