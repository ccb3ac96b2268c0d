// A small figures box: label/value rows as a definition list (text only). Each value gets a data-stat
// key for tests and styling.
export function renderStats(container, rows, keyOf = (label) => label.toLowerCase().replace(/\s+/g, '-')) {
  const dl = document.createElement('dl');
  for (const [label, value] of rows) {
    const dt = document.createElement('dt');
    dt.textContent = label;
    const dd = document.createElement('dd');
    dd.textContent = value;
    dd.dataset.stat = keyOf(label);
    dl.append(dt, dd);
  }
  container.replaceChildren(dl);
}
