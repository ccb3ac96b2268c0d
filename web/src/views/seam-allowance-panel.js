// The seam allowance panel of the pattern pane: every seam of the pattern, labelled S1, S2, ... as on the cut
// pieces, with its color in the pane, its panels and length, and its allowance: the seam allowance of the
// pane's header, or its own (typed; 0 for a heat-sealed seam) with a reset to the seam allowance. The free
// edges get a row when the pattern has some. Own allowances of seams this pattern does not have (the seams
// were redrawn) are listed as not in the pattern, to remove. Above the list, how the pieces are joined (sewn
// or heat sealed: then the allowance is the seal band); below it, the fill valves: gaps left open in a seam,
// placed by a click on the seam in the pattern. Text only through textContent.
import { MM_PER_INCH, MAX_ALLOWANCE, MAX_VALVE_WIDTH, formatMillimeters, seamLabel, joiningOf } from '../app/fabrication.js';

const FREE = -1; // the row of the free edges

export class SeamAllowancePanel {
  // container: the panel element (hidden at first); toggle: the header button that opens and closes it.
  // pane: the PatternPane (labels, highlight, picking). onSeamAllowance(id, mm | null) and
  // onFreeEdgeAllowance(mm | null) commit a change (null: back to the seam allowance); onJoining('sewn' |
  // 'sealed'); onAddValve(seam id, share along it), onValveWidth(index, mm), onRemoveValve(index).
  constructor(container, toggle, { pane, onSeamAllowance, onFreeEdgeAllowance, onJoining, onAddValve, onValveWidth, onRemoveValve }) {
    this.container = container;
    this.toggle = toggle;
    this.pane = pane;
    this.onSeamAllowance = onSeamAllowance;
    this.onFreeEdgeAllowance = onFreeEdgeAllowance;
    this.onAddValve = onAddValve;
    this.onValveWidth = onValveWidth;
    this.onRemoveValve = onRemoveValve;
    this.placingValve = false; // the next click on a seam places a fill valve there
    this.seams = null; // the pattern's seams from the exporter's statistics, or null before there are panels
    this.freeLength = 0; // [mm] of free edges
    this.fabrication = null;
    this.rows = new Map(); // id -> { row, input, reset, ... }
    this.selected = null;

    const head = el('div', 'allowance-head');
    const title = el('strong', '', 'Seam allowance');
    title.id = `${container.id}-title`;
    container.setAttribute('aria-labelledby', title.id);
    const close = el('button', 'close', '×');
    close.type = 'button';
    close.title = 'Close the list of seams';
    close.setAttribute('aria-label', 'Close the list of seams');
    close.addEventListener('click', () => this.setOpen(false));
    head.append(title, close);
    this.help = el('p', 'allowance-help', '');
    const table = el('table', 'allowance-list');
    const header = el('tr');
    for (const [text, hint] of [
      ['', ''],
      ['Seam', 'The seam\'s label on the cut pieces'],
      ['Panels', 'The panels it joins (their numbers in the pattern)'],
      ['Length', 'Its length along the sewing line'],
      ['Allowance', 'Material outside the sewing line, on both panels; 0 for heat sealing'],
      ['', ''],
    ]) {
      const th = el('th', '', text);
      if (hint) th.title = hint;
      header.append(th);
    }
    table.append(el('thead'), (this.body = el('tbody')));
    table.tHead.append(header);
    this.table = table;
    this.empty = el('p', 'allowance-empty', 'The seams appear here once there are panels.');
    this.joining = document.createElement('select');
    this.joining.id = `${container.id}-joining`;
    this.joining.append(new Option('Sewn', 'sewn'), new Option('Heat sealed', 'sealed'));
    this.joining.addEventListener('change', () => onJoining(this.joining.value));
    const joiningLabel = el('label', 'allowance-joining', 'Pieces joined ', this.joining);
    joiningLabel.title = 'Sewn: the allowance is extra material outside the sewing line. Heat sealed (foil, PVC, TPU): the allowance is the seal band, drawn on the pieces';
    this.valveHead = el('p', 'valve-head');
    this.valveButton = el('button', 'pane-button', 'Add a fill valve');
    this.valveButton.type = 'button';
    this.valveButton.title = 'Then click a seam in the pattern: a gap is left open there on both pieces, for the valve or a straw';
    this.valveButton.setAttribute('aria-pressed', 'false');
    this.valveButton.addEventListener('click', () => this.setPlacingValve(!this.placingValve));
    this.valveHead.append(el('strong', '', 'Fill valves '), this.valveButton);
    this.valveList = el('ul', 'valve-list');
    container.append(head, joiningLabel, this.help, table, this.empty, this.valveHead, this.valveList);

    toggle.addEventListener('click', () => this.setOpen(container.hidden));
    container.addEventListener('keydown', (e) => {
      if (e.key === 'Escape' && !(e.target instanceof HTMLInputElement)) {
        this.setOpen(false);
        toggle.focus();
      }
    });
    pane.onSeamPick = (id, event) => (this.placingValve && id !== null && id >= 0 ? this.placeValve(id, event) : this.pick(id));
    pane.seamTitle = (id) => this.describe(id);
  }

  setPlacingValve(on) {
    this.placingValve = on;
    this.valveButton.setAttribute('aria-pressed', String(on));
    this.valveButton.textContent = on ? 'Click a seam…' : 'Add a fill valve';
    this.pane.element.classList.toggle('placing-valve', on);
  }

  // A click on seam `id` while placing: the valve goes where the seam was clicked.
  placeValve(id, event) {
    const at = this.pane.seamShareAt(id, event.clientX, event.clientY);
    this.setPlacingValve(false);
    if (at !== null) this.onAddValve(id, at);
  }

  get open() {
    return !this.container.hidden;
  }

  setOpen(open) {
    this.container.hidden = !open;
    this.toggle.setAttribute('aria-expanded', String(open));
    this.pane.setSeamLabelsShown(open);
    if (!open) this.select(null);
  }

  // A click in the pattern pane: on a seam, opens the list at its row, ready to type; beside, deselects.
  pick(id) {
    if (id === null || !this.rows.has(id)) return this.select(null);
    if (!this.open) this.setOpen(true);
    this.select(id);
    const { input } = this.rows.get(id);
    input.focus();
    input.select();
  }

  select(id) {
    this.selected = id;
    for (const [key, { row }] of this.rows) row.classList.toggle('selected', key === id);
    this.pane.setSeamMarks({ selected: id });
  }

  // The pattern's seams changed (statistics: the exporter's; null when there is no pattern).
  setSeams(statistics) {
    this.seams = statistics?.seams ?? null;
    this.freeLength = statistics?.totals.free_edge_mm ?? 0;
    this.render(this.fabrication);
  }

  // Shows the fabrication settings: seam allowance, own allowances, free edges, units.
  render(fabrication) {
    if (!fabrication) return;
    this.fabrication = fabrication;
    const own = fabrication.seam_allowance ?? {};
    const ownCount = Object.keys(own).length;
    this.toggle.textContent = ownCount ? `Seams (${ownCount} own)` : 'Seams';
    this.empty.hidden = Boolean(this.seams);
    this.table.hidden = !this.seams;
    const units = fabrication.units;
    const sealed = joiningOf(fabrication) === 'sealed';
    this.joining.value = joiningOf(fabrication);
    this.table.tHead.rows[0].cells[4].textContent = sealed ? 'Seal band' : 'Allowance';
    this.help.textContent = this.seams
      ? `Click a seam in the pattern or pick it here, and type its ${sealed ? 'seal band' : 'allowance'} in ${units}. An empty field or ↺ gives it the ${sealed ? 'seal band' : 'seam allowance'} (${formatMillimeters(fabrication.allowance, units)}).`
      : '';
    this.renderValves(fabrication);
    if (!this.seams) {
      this.rebuild([]);
      this.pane.setSeamMarks({ own: new Set() });
      return;
    }
    const present = new Set(this.seams.map((s) => s.id));
    const entries = [
      ...this.seams.map((seam) => ({ id: seam.id, seam })),
      ...(this.freeLength > 0 ? [{ id: FREE }] : []),
      ...Object.keys(own).map(Number).filter((id) => !present.has(id)).map((id) => ({ id, missing: true })),
    ];
    this.rebuild(entries);
    for (const entry of entries) this.update(entry, fabrication);
    this.pane.setSeamMarks({ own: new Set(Object.keys(own).map(Number).filter((id) => present.has(id))) });
    if (this.selected !== null && !this.rows.has(this.selected)) this.select(null);
  }

  // Rows for these entries, keeping the existing ones (a focused field stays focused).
  rebuild(entries) {
    const ids = entries.map((e) => e.id);
    const same = ids.length === this.rows.size && ids.every((id, k) => [...this.rows.keys()][k] === id);
    if (same) return;
    const rows = new Map();
    for (const entry of entries) rows.set(entry.id, this.rows.get(entry.id) ?? this.makeRow(entry));
    this.rows = rows;
    this.body.replaceChildren(...[...rows.values()].map((r) => r.row));
  }

  makeRow(entry) {
    const { id } = entry;
    const row = el('tr', 'allowance-row');
    row.dataset.seam = String(id);
    const swatch = el('span', 'swatch');
    const name = el('td', 'name');
    const panels = el('td', 'panels');
    const length = el('td', 'length');
    const input = document.createElement('input');
    input.type = 'number';
    input.min = '0';
    const unit = el('span', 'unit');
    const reset = el('button', 'reset', entry.missing ? '×' : '↺');
    reset.type = 'button';
    const cells = [el('td', '', swatch), name, panels, length, el('td', 'value', input, unit), el('td', '', reset)];
    row.append(...cells);
    const commit = (mm) => (id === FREE ? this.onFreeEdgeAllowance(mm) : this.onSeamAllowance(id, mm));
    input.addEventListener('change', () => {
      const text = input.value.trim();
      commit(text === '' ? null : Number(text) * (this.fabrication.units === 'in' ? MM_PER_INCH : 1));
      // The field shows what is stored now: the width as kept, or the old one when it was refused.
      this.update(this.entryOf(id), this.fabrication, true);
    });
    input.addEventListener('focus', () => this.select(id));
    input.addEventListener('keydown', (e) => {
      if (e.key === 'Escape') {
        this.update(this.entryOf(id), this.fabrication, true);
        input.blur();
        e.stopPropagation();
      }
    });
    reset.addEventListener('click', () => {
      commit(null);
      this.select(id);
    });
    row.addEventListener('click', (e) => {
      if (e.target === input || e.target === reset) return;
      this.select(id);
      input.focus();
      input.select();
    });
    return { row, swatch, name, panels, length, input, unit, reset, entry };
  }

  entryOf(id) {
    return this.rows.get(id)?.entry;
  }

  // Fills a row from the settings; the field is left alone while it is being typed in, unless `force`.
  update(entry, fabrication, force = false) {
    const r = this.rows.get(entry.id);
    if (!r) return;
    r.entry = entry;
    const { id, seam, missing } = entry;
    const units = fabrication.units;
    const ownValue = id === FREE ? fabrication.free_edge_allowance : fabrication.seam_allowance?.[String(id)];
    const own = ownValue !== undefined;
    const mm = own ? ownValue : fabrication.allowance;
    const label = id === FREE ? 'Free edges' : seamLabel(id);
    r.row.classList.toggle('own', own);
    r.row.classList.toggle('missing', Boolean(missing));
    r.name.textContent = label;
    if (missing) r.swatch.style.background = 'transparent';
    else if (this.pane.seams) r.swatch.style.background = `#${this.pane.seamColorOf(id).getHexString()}`; // kept while panels are remade
    if (seam) {
      r.panels.textContent = `${seam.panels[0]}–${seam.panels[1]}`;
      r.length.textContent = formatMillimeters(0.5 * (seam.length_a_mm + seam.length_b_mm), units);
    } else if (id === FREE) {
      r.panels.textContent = '';
      r.length.textContent = formatMillimeters(this.freeLength, units);
    } else {
      r.panels.textContent = 'not in this pattern';
      r.length.textContent = '';
    }
    r.panels.colSpan = missing ? 2 : 1;
    r.length.hidden = Boolean(missing);
    const inches = units === 'in';
    r.input.max = String(inches ? +(MAX_ALLOWANCE / MM_PER_INCH).toFixed(3) : MAX_ALLOWANCE);
    r.input.step = inches ? '0.01' : '1';
    r.input.disabled = Boolean(missing);
    r.input.classList.toggle('inherited', !own);
    if (force || document.activeElement !== r.input) r.input.value = String(+(inches ? mm / MM_PER_INCH : mm).toFixed(inches ? 3 : 1));
    r.unit.textContent = units;
    const where = seam ? ` (panels ${seam.panels[0]} and ${seam.panels[1]})` : '';
    r.input.setAttribute('aria-label', `Allowance of ${id === FREE ? 'the free edges' : `seam ${label}`}${where}, ${units}`);
    r.input.title = own
      ? `${label} has its own allowance; empty the field or press ↺ for the seam allowance (${formatMillimeters(fabrication.allowance, units)})`
      : `${label} has the seam allowance (${formatMillimeters(fabrication.allowance, units)}); type a width to give it its own (0 for heat sealing)`;
    r.reset.disabled = !own;
    r.reset.title = missing
      ? `Remove the allowance of ${label}: this pattern has no seam ${label} now`
      : `Give ${id === FREE ? 'the free edges' : label} the seam allowance (${formatMillimeters(fabrication.allowance, units)})`;
    r.reset.setAttribute('aria-label', r.reset.title);
    r.row.title = missing ? `${label} is not in this pattern (the seams were redrawn); its allowance is not used` : '';
  }

  // One line per fill valve: its seam and place, its width (typed), and a remove button.
  renderValves(fabrication) {
    const valves = fabrication.valves ?? [];
    const units = fabrication.units;
    const inches = units === 'in';
    const present = new Set((this.seams ?? []).map((s) => s.id));
    this.valveButton.disabled = !this.seams;
    if (!this.seams && this.placingValve) this.setPlacingValve(false);
    const focused = this.valveList.contains(document.activeElement) ? document.activeElement.dataset.valve : null;
    this.valveList.replaceChildren(
      ...valves.map((valve, index) => {
        const item = el('li', present.has(valve.seam) ? 'valve' : 'valve missing');
        const where = `On ${seamLabel(valve.seam)} at ${Math.round(100 * valve.at)} %${present.has(valve.seam) ? '' : ' (not in this pattern)'}, gap `;
        const input = document.createElement('input');
        input.type = 'number';
        input.min = '1';
        input.max = String(inches ? +(MAX_VALVE_WIDTH / MM_PER_INCH).toFixed(2) : MAX_VALVE_WIDTH);
        input.step = inches ? '0.05' : '1';
        input.dataset.valve = String(index);
        input.value = String(+(inches ? valve.width / MM_PER_INCH : valve.width).toFixed(inches ? 2 : 0));
        input.setAttribute('aria-label', `Width of the fill valve on seam ${seamLabel(valve.seam)}, ${units}`);
        input.addEventListener('change', () => this.onValveWidth(index, Number(input.value) * (inches ? MM_PER_INCH : 1)));
        const remove = el('button', 'reset', '×');
        remove.type = 'button';
        remove.title = `Remove the fill valve on ${seamLabel(valve.seam)}`;
        remove.setAttribute('aria-label', remove.title);
        remove.addEventListener('click', () => this.onRemoveValve(index));
        item.append(where, input, ` ${units}`, remove);
        return item;
      }),
    );
    if (focused !== null) this.valveList.querySelector(`input[data-valve="${focused}"]`)?.focus();
  }

  // The pane's tooltip over a seam.
  describe(id) {
    const f = this.fabrication;
    if (!f) return '';
    const own = id === FREE ? f.free_edge_allowance : f.seam_allowance?.[String(id)];
    const mm = own ?? f.allowance;
    const seam = this.seams?.find((s) => s.id === id);
    const what = id === FREE ? 'Free edge' : `Seam ${seamLabel(id)}${seam ? `, panels ${seam.panels[0]} and ${seam.panels[1]}` : ''}`;
    if (this.placingValve && id !== FREE) return `${what}: click to place the fill valve here.`;
    const band = joiningOf(f) === 'sealed';
    return `${what}: ${band ? 'seal band' : 'allowance'} ${formatMillimeters(mm, f.units)}${own === undefined ? (band ? ' (the seal band)' : ' (the seam allowance)') : ''}. Click to change it.`;
  }
}

function el(tag, className = '', ...children) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  for (const c of children) e.append(c);
  return e;
}
