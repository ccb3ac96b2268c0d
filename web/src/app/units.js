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
