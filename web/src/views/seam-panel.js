// The seam panel beside the target: tool buttons, the list of seams (select, weight σ, delete), the
// segment count and the problems the segmentation found. Text only through textContent.
import { seamWidth } from './seam-layer.js';
import { SECTION_AXES } from '../tools/seam-tool.js';

const TOOLS = [
  ['orbit', 'View', 'Orbit the view (V)'],
  ['draw', 'Draw seam', 'Click points on the surface; Enter or double-click finishes; click the first point to close a loop (D)'],
  ['section', 'Section', 'Click the target: a seam all around it where a plane through that point cuts it, across the axis chosen beside (S)'],
  ['edit', 'Edit', 'Drag control points; double-click a seam to add a point; Delete removes the selected point (E)'],
];

export class SeamPanel {
  constructor(container, { tool, editor }) {
    this.container = container;
    this.tool = tool;
    this.editor = editor;
    this.toolbar = el('div', 'toolbar');
    this.toolButtons = TOOLS.map(([mode, label, title]) => {
      const b = el('button', 'tool', label);
      b.type = 'button';
      b.title = title;
      b.dataset.tool = mode;
      b.addEventListener('click', () => {
        tool.setMode(mode);
        this.render();
      });
      this.toolbar.append(b);
      return b;
    });
    // The outline as seen: laid at once, not a mode.
    const outline = el('button', 'tool outline', 'Outline');
    outline.type = 'button';
    outline.title = 'Lay a seam around the shape as seen from here: a front and a back panel, as foil balloons are made (O)';
    outline.addEventListener('click', () => tool.layOutline());
    this.toolbar.append(outline);
    // The section tool's plane: across the model's x, y or z as it is shown, or across the view.
    this.sectionAxis = document.createElement('select');
    this.sectionAxis.className = 'section-axis';
    this.sectionAxis.title = 'The plane of a section seam: across the width (X), the height (Y) or the depth (Z) of the model as it stands, or across the view';
    this.sectionAxis.setAttribute('aria-label', 'Section plane');
    const labels = { x: 'Across X', y: 'Across Y', z: 'Across Z', view: 'Across the view' };
    for (const axis of SECTION_AXES) this.sectionAxis.append(new Option(labels[axis], axis));
    this.sectionAxis.addEventListener('change', () => tool.setSectionAxis(this.sectionAxis.value));
    this.toolbar.append(this.sectionAxis);
    // A gusset band: two sections this far apart on the cut pattern, a strip panel between them.
    this.band = document.createElement('label');
    this.band.className = 'section-band';
    this.band.title = 'A gusset band: a Section click or Outline lays two seams this far apart, with a strip panel between them for thickness (0: one seam)';
    this.bandInput = document.createElement('input');
    this.bandInput.type = 'number';
    this.bandInput.min = '0';
    this.bandInput.step = '5';
    this.bandInput.value = '0';
    this.bandInput.setAttribute('aria-label', 'Gusset band width, mm');
    this.bandInput.addEventListener('change', () => tool.setBandWidth(Number(this.bandInput.value)));
    this.band.append('Band ', this.bandInput, ' mm');
    this.toolbar.append(this.band);
    // Mirror symmetry (symmetry.js): new seams get a twin across the chosen plane of the target.
    this.symmetry = document.createElement('select');
    this.symmetry.className = 'symmetry';
    this.symmetry.title = 'Mirror symmetry: seams drawn or edited on one side are mirrored to the other (M cycles)';
    this.symmetry.setAttribute('aria-label', 'Mirror symmetry');
    for (const [value, label] of [['', 'No symmetry'], ['x', 'Mirror across X'], ['y', 'Mirror across Y'], ['z', 'Mirror across Z']])
      this.symmetry.append(new Option(label, value));
    this.symmetry.addEventListener('change', () => editor.setSymmetry(this.symmetry.value || null));
    this.toolbar.append(this.symmetry);
    // While a seam is being drawn: buttons for what Enter, a click on the first point and Esc do (touch).
    this.drawbar = el('div', 'drawbar');
    const action = (label, title, fn) => {
      const b = el('button', 'tool', label);
      b.type = 'button';
      b.title = title;
      b.addEventListener('click', () => {
        fn();
        this.render();
      });
      this.drawbar.append(b);
      return b;
    };
    this.finishButton = action('Finish', 'End the seam here (Enter)', () => tool.finish(false));
    this.closeButton = action('Close loop', 'Join the last point to the first (click the first point)', () => tool.finish(true));
    action('Cancel', 'Drop the seam being drawn (Esc)', () => tool.cancel());
    this.summary = el('div', 'summary');
    this.list = el('ol', 'seam-list');
    this.connections = el('ul', 'connection-list');
    this.problems = el('ul', 'problems');
    container.append(this.toolbar, this.drawbar, this.summary, this.list, this.connections, this.problems);
    editor.onChange(() => this.render());
    this.render();
  }

  render() {
    for (const b of this.toolButtons) b.setAttribute('aria-pressed', String(b.dataset.tool === this.tool.mode));
    const { design, segmentation, selection } = this.editor;
    this.symmetry.value = design.symmetry?.axis ?? '';
    this.sectionAxis.hidden = this.tool.mode !== 'section';
    this.sectionAxis.value = this.tool.sectionAxis;
    this.drawbar.hidden = !this.tool.drawing;
    this.finishButton.disabled = !this.tool.canFinish;
    this.closeButton.disabled = !this.tool.canClose;
    const count = segmentation?.segments?.length;
    this.summary.textContent = design.seams.length
      ? `${design.seams.length} seam${design.seams.length === 1 ? '' : 's'}${count ? `, ${count} segment${count === 1 ? '' : 's'}` : ''}`
      : 'No seams yet: choose "Draw seam" and click on the target, or "Section" for a seam all around it in one click.';
    this.list.replaceChildren(...design.seams.map((s, i) => this.seamRow(s, i, selection)));
    this.connections.replaceChildren(...design.connections.map((c, i) => this.connectionRow(c, i)));
    this.problems.replaceChildren(
      ...(segmentation?.problems ?? []).map((p) => {
        const li = el('li', `problem ${p.severity}`);
        li.dataset.code = p.code ?? '';
        // Clicked, a problem turns the view to its place and marks it (and selects its seam).
        const show = el('button', 'problem-text', p.message);
        show.type = 'button';
        show.title = 'Show where on the model';
        show.addEventListener('click', () => this.editor.showProblem(p));
        li.append(show);
        return li;
      }),
    );
  }

  connectionRow(connection, i) {
    const names = connection.seams.map((k) => this.editor.design.seams[k]?.name ?? `Seam ${k + 1}`);
    const li = el('li', 'connection', `Internal panel: ${names[0]} ↔ ${names[1]}`);
    const remove = el('button', 'delete', '×');
    remove.type = 'button';
    remove.title = 'Delete this internal connection';
    remove.setAttribute('aria-label', `Delete the internal panel between ${names[0]} and ${names[1]}`);
    remove.addEventListener('click', () => this.editor.deleteConnection(i));
    li.append(remove);
    return li;
  }

  seamRow(seam, i, selection) {
    const selected = selection?.seam === i;
    const li = el('li', selected ? 'seam selected' : 'seam');
    const name = el('button', 'name', seam.name ?? `Seam ${i + 1}`);
    name.type = 'button';
    name.title = `${seam.name ?? `Seam ${i + 1}`}: select this seam`; // the whole name, where the row cuts it short
    name.addEventListener('click', () => this.editor.selectSeam(i));
    const swatch = el('span', 'swatch');
    swatch.style.height = `${seamWidth(seam.weight)}px`;
    const weight = document.createElement('input');
    weight.type = 'range';
    weight.min = '0';
    weight.max = '10';
    weight.step = '0.1';
    weight.value = String(seam.weight);
    weight.title = `Weight σ = ${seam.weight}: how firmly the seam stays where it is drawn; below 0.1 it slides to where the shape fits best, and the panels take longer to optimize`;
    weight.setAttribute('aria-label', `Weight of ${seam.name ?? `seam ${i + 1}`}`);
    weight.addEventListener('input', () => this.editor.setWeight(i, Number(weight.value)));
    const remove = el('button', 'delete', '×');
    remove.type = 'button';
    remove.title = 'Delete this seam';
    remove.setAttribute('aria-label', `Delete ${seam.name ?? `seam ${i + 1}`}`);
    remove.addEventListener('click', () => this.editor.deleteSeam(i));
    const smooth = el('button', 'smooth', seam.smooth ? '∿' : '⌇');
    smooth.type = 'button';
    smooth.setAttribute('aria-pressed', String(Boolean(seam.smooth)));
    smooth.title = seam.smooth
      ? 'Smooth: a spline through the points. Click for shortest paths between the points (straight gores)'
      : 'Shortest paths between the points. Click for a smooth spline through them';
    smooth.setAttribute('aria-label', `Smooth ${seam.name ?? `seam ${i + 1}`}`);
    smooth.addEventListener('click', () => this.editor.setSmooth(i, !seam.smooth));
    li.append(swatch, name, weight, remove, smooth);
    const band = selected ? this.editor.bandOf(i) : null;
    if (band) li.append(this.bandWidthRow(i, band));
    if (this.editor.canMirror(i)) {
      const mirror = el('button', 'mirror', '⇋');
      mirror.type = 'button';
      mirror.title = 'Add a mirrored twin of this seam across the symmetry plane';
      mirror.setAttribute('aria-label', `Mirror ${seam.name ?? `seam ${i + 1}`}`);
      mirror.addEventListener('click', () => this.editor.mirrorSeam(i));
      li.append(mirror);
    }
    if (selection && !selected) {
      // With a seam selected, any other seam can be joined to it by an internal panel.
      const connect = el('button', 'connect', '⇄');
      connect.type = 'button';
      connect.title = `Join this seam to the selected seam with an internal panel`;
      connect.setAttribute('aria-label', `Connect ${seam.name ?? `seam ${i + 1}`} to the selected seam`);
      connect.addEventListener('click', () => this.editor.connect(selection.seam, i));
      li.append(connect);
    }
    return li;
  }

  // The selected band's width: changed, the band is laid again at it (SeamEditor.setBandWidth).
  bandWidthRow(i, band) {
    const row = el('label', 'band-width');
    row.title = 'The gusset band\'s width on the cut pattern: changed, both its sides and the seam across are laid again (points moved by hand are replaced)';
    const input = document.createElement('input');
    input.type = 'number';
    input.min = '1';
    input.step = '5';
    input.value = String(+band.width_mm.toFixed(1));
    input.setAttribute('aria-label', 'Band width of the selected band, mm');
    input.addEventListener('change', () => {
      const width = Number(input.value);
      if (width > 0) this.editor.setBandWidth(i, width);
      else input.value = String(+band.width_mm.toFixed(1));
    });
    row.append('Band width ', input, ' mm');
    return row;
  }
}

function el(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}
