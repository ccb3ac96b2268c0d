// The target's statistics box: counts from validation, sizes in real units after the design's scale, width ×
// height × depth as the target stands on its up axis (up-axis.js).
import { formatLength, formatArea, formatVolume } from './units.js';
import { upFrameSize } from './up-axis.js';
import { renderStats } from '../views/stats-list.js';

export function renderTargetStats(container, target, scale, up = '+y') {
  if (!target) return container.replaceChildren();
  const st = target.report.stats;
  const size = upFrameSize(st, up).map((extent) => extent * scale);
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
