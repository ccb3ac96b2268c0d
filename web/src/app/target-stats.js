// The target's statistics box: counts from validation, sizes in real units after the design's scale.
import { formatLength, formatArea, formatVolume } from './units.js';
import { renderStats } from '../views/stats-list.js';

export function renderTargetStats(container, target, scale) {
  if (!target) return container.replaceChildren();
  const st = target.report.stats;
  const size = [0, 1, 2].map((k) => (st.bbox_max[k] - st.bbox_min[k]) * scale);
  const rows = [
    ['File', target.fileName],
    ['Vertices', st.vertices.toLocaleString('en')],
    ['Triangles', st.triangles.toLocaleString('en')],
    ['Genus', String(st.genus)],
    ['Size (W × H × D)', size.map(formatLength).join(' × ')],
    ['Surface', formatArea(st.area * scale * scale)],
    ['Volume', formatVolume(st.volume * scale ** 3)],
  ];
  renderStats(container, rows, (label) => label.toLowerCase().split(' ')[0]);
}
