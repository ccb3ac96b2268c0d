// The free part of a pane. Boxes are docked at a pane's sides (the .dock columns of web/index.html: seams,
// figures, legend, the pattern's seam allowances and the messages beside it), and a view frames its content
// in what they leave, so no box hides the model. Rectangles are { left, top, right, bottom } in client pixels.

const visible = (el) => el.getClientRects().length > 0 && getComputedStyle(el).visibility !== 'hidden';
const rectOf = (el) => {
  const r = el.getBoundingClientRect();
  return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
};

// What a view in `pane` (its <section>) keeps clear of. An open box takes its dock's whole column, so a seam
// or a problem more in the list, or new figures, do not move the view; a collapsed box (its title only) or a
// legend takes its own rectangle. A dock marked data-reserve="always" is kept clear even when empty (the
// messages' column beside the pattern). A dock whose --keep-clear is 0 (the classroom's panes) counts for
// nothing.
export function overlayRects(pane) {
  const rects = [];
  for (const dock of pane.querySelectorAll('.dock')) {
    const style = getComputedStyle(dock);
    if (style.display === 'none' || style.getPropertyValue('--keep-clear').trim() === '0') continue;
    const shown = [...dock.children].filter(visible);
    if (dock.dataset.reserve === 'always' || shown.some((el) => el.matches('.box:not(.collapsed), .allowance-panel'))) rects.push(rectOf(dock));
    else rects.push(...shown.map(rectOf));
  }
  return rects;
}

const overlaps = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

// The rectangle of `area` that none of `obstacles` overlaps and where content of the given aspect (width /
// height) is shown largest; of those, the largest. Its edges are among the area's and the obstacles', so
// trying every pair of them finds it (a few boxes: a few hundred candidates).
export function largestFreeRect(area, obstacles, aspect = 1) {
  const inside = obstacles.filter((o) => overlaps(o, area));
  if (!inside.length) return { ...area };
  const edges = (lo, hi, a, b) => [...new Set([lo, hi, ...inside.flatMap((o) => [o[a], o[b]])])]
    .filter((v) => v >= lo && v <= hi)
    .sort((p, q) => p - q);
  const xs = edges(area.left, area.right, 'left', 'right');
  const ys = edges(area.top, area.bottom, 'top', 'bottom');
  let best = null;
  let bestSize = -1;
  let bestArea = -1;
  for (let i = 0; i < xs.length; i++)
    for (let j = i + 1; j < xs.length; j++)
      for (let k = 0; k < ys.length; k++)
        for (let l = k + 1; l < ys.length; l++) {
          const r = { left: xs[i], right: xs[j], top: ys[k], bottom: ys[l] };
          if (inside.some((o) => overlaps(o, r))) continue;
          const w = r.right - r.left, h = r.bottom - r.top;
          const size = Math.min(w / aspect, h); // the content's height when it fits
          if (size > bestSize + 0.5 || (size > bestSize - 0.5 && w * h > bestArea)) {
            best = r;
            bestSize = size;
            bestArea = w * h;
          }
        }
  return best ?? { ...area };
}

// Calls onChange when a box of the pane's docks changes size: opened, collapsed, shown, hidden, or a box put
// into a dock later (the inflated pane's legend).
export function watchOverlays(pane, onChange) {
  const sizes = new ResizeObserver(onChange);
  const watch = (dock) => {
    for (const el of dock.children) sizes.observe(el);
  };
  const docks = new MutationObserver((changes) => changes.forEach((c) => watch(c.target)));
  for (const dock of pane.querySelectorAll('.dock')) {
    watch(dock);
    docks.observe(dock, { childList: true });
  }
}

// The free rectangle of a pane's body (the element its view is drawn in) for content of `aspect`.
export function freeArea(body, aspect = 1) {
  return largestFreeRect(rectOf(body), overlayRects(body.parentElement), aspect);
}
