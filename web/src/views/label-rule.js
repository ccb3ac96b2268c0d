// Labels over a view never overlap. Taken in order of importance, each is shown whole, else in its short form
// (a panel's number: its data-short, in place of its first text node's data-full), else not at all (class
// "crowded") until zooming in makes room: small pieces crowded together stay readable. A label marked
// `always` keeps its place whatever it covers (the sheet's size, the selected seam); one with `room` (pixels: its
// piece's width on screen) takes its short form where its whole one is over 1.5 times that wide.
export function unclutterLabels(items) {
  const kept = [];
  const GAP = 2; // pixels between two labels, so that they do not touch either
  const hits = (b) => kept.some((k) => b.left < k.right + GAP && k.left < b.right + GAP && b.top < k.bottom + GAP && k.top < b.bottom + GAP);
  for (const { label, always = false, room = Infinity } of items) {
    const short = label.dataset.short;
    const form = (compact) => {
      if (short !== undefined) {
        label.classList.toggle('compact', compact);
        label.firstChild.textContent = compact ? short : label.dataset.full;
      }
      return label.getBoundingClientRect();
    };
    label.classList.remove('crowded');
    let box = form(false);
    if (!always && short !== undefined && (hits(box) || box.width > 1.5 * room)) box = form(true);
    if (!always && hits(box)) label.classList.add('crowded');
    else kept.push(box);
  }
}
