// The application controller: owns the design document, talks to the worker, updates the panes.
import { Op } from '../worker/protocol.js';
import { EXAMPLES, findExample } from './examples.js';
import { newDesign, parseDesign, clampHeight } from './design.js';
import { autosave } from './autosave.js';
import { formatLength, formatArea, formatVolume } from './units.js';

const AUTOSAVE_KEY = 'current';

export class App {
  constructor({ client, panes, messages, elements, baseUrl }) {
    this.client = client;
    this.panes = panes;
    this.messages = messages;
    this.el = elements;
    this.baseUrl = baseUrl;
    this.design = newDesign();
    this.target = null; // { positions, indices, report, fileName }
    this.busy = 0;
    this.loadCounter = 0;
  }

  async start() {
    this.populateExamples();
    const saved = await autosave.load(AUTOSAVE_KEY).catch(() => null);
    if (saved?.design) {
      try {
        const { design, warnings } = parseDesign(saved.design);
        for (const w of warnings) this.messages.show('warning', w);
        if (design.target.example) await this.loadExample(design.target.example, design);
        else if (saved.mesh) await this.installSavedMesh(design, saved.mesh);
        else await this.loadExample(newDesign().target.example);
        return;
      } catch (error) {
        this.messages.show('warning', `The autosaved design could not be restored: ${error.message}`);
      }
    }
    await this.loadExample(this.design.target.example);
  }

  populateExamples() {
    const select = this.el.exampleSelect;
    select.replaceChildren();
    const placeholder = new Option('Choose…', '');
    select.append(placeholder);
    for (const e of EXAMPLES) select.append(new Option(e.name, e.id));
  }

  setStatus(text) {
    this.el.status.textContent = text;
  }

  async track(label, fn) {
    this.busy += 1;
    this.setStatus(label);
    try {
      return await fn();
    } finally {
      this.busy -= 1;
      if (this.busy === 0) this.setStatus(this.target ? 'Ready' : '');
    }
  }

  async loadExample(id, design = null) {
    const example = findExample(id);
    if (!example) return this.messages.show('error', `There is no example called "${id}".`);
    this.el.exampleSelect.value = id;
    const response = await fetch(new URL(`examples/${example.file}`, this.baseUrl));
    if (!response.ok) return this.messages.show('error', `The example "${example.name}" could not be loaded.`);
    const bytes = await response.arrayBuffer();
    const next = design ?? { ...newDesign(id) };
    return this.loadTargetBytes(example.file, bytes, next, { quiet: true });
  }

  // A file the designer picked or dropped.
  async openFile(file) {
    const bytes = await file.arrayBuffer();
    const design = { ...newDesign(), target: { file: file.name }, size: { height: this.design.size.height } };
    this.el.exampleSelect.value = '';
    return this.loadTargetBytes(file.name, bytes, design, { quiet: false });
  }

  async loadTargetBytes(fileName, bytes, design, { quiet }) {
    const ticket = ++this.loadCounter;
    try {
      const result = await this.track(`Opening ${fileName}…`, () =>
        this.client.request(Op.loadTarget, { fileName, bytes }, {
          transfer: [bytes],
          onProgress: (p) => this.setStatus(`Opening ${fileName}: ${p.stage}…`),
        }),
      );
      if (ticket !== this.loadCounter) return; // a newer load won
      this.client.remember(Op.setTarget, { positions: result.positions, indices: result.indices });
      this.installTarget(fileName, result, design);
      this.setStatus('Ready');
      const shown = result.report.issues.filter((i) => i.severity !== 'error');
      for (const issue of shown) if (!quiet || issue.severity !== 'notice') this.messages.show(issue.severity, issue.message);
      this.save();
    } catch (error) {
      const report = error.details?.report;
      const items = report ? report.issues.filter((i) => i.severity === 'error').map((i) => i.message) : [];
      const text = report
        ? `"${fileName}" cannot be used as a target. Your current design is unchanged.`
        : `${error.message}${this.target ? ' Your current design is unchanged.' : ''}`;
      this.messages.show('error', text, items);
    }
  }

  async installSavedMesh(design, mesh) {
    const result = await this.client.request(Op.setTarget, mesh);
    this.installTarget(design.target.file, result, design);
  }

  installTarget(fileName, result, design) {
    this.design = design;
    this.target = { fileName, positions: result.positions, indices: result.indices, report: result.report };
    this.el.heightInput.value = String(this.design.size.height);
    this.panes.target.setTarget(this.target, this.scale());
    this.renderStats();
  }

  // Mesh files carry no units: the design's height (m) fixes the scale of the target's own units.
  scale() {
    const st = this.target?.report.stats;
    if (!st) return 1;
    const height = st.bbox_max[1] - st.bbox_min[1];
    return height > 0 ? this.design.size.height / height : 1;
  }

  setHeight(meters) {
    if (!Number.isFinite(meters) || meters <= 0) {
      this.messages.show('warning', 'The height must be a positive number of meters.');
      this.el.heightInput.value = String(this.design.size.height);
      return;
    }
    this.design = { ...this.design, size: { ...this.design.size, height: clampHeight(meters) } };
    this.el.heightInput.value = String(this.design.size.height);
    this.panes.target.setScale(this.scale());
    this.renderStats();
    this.save();
  }

  renderStats() {
    const st = this.target.report.stats;
    const s = this.scale();
    const size = [0, 1, 2].map((k) => (st.bbox_max[k] - st.bbox_min[k]) * s);
    const rows = [
      ['File', this.target.fileName],
      ['Vertices', st.vertices.toLocaleString('en')],
      ['Triangles', st.triangles.toLocaleString('en')],
      ['Genus', String(st.genus)],
      ['Size (W × H × D)', size.map(formatLength).join(' × ')],
      ['Surface', formatArea(st.area * s * s)],
      ['Volume', formatVolume(st.volume * s * s * s)],
    ];
    const dl = document.createElement('dl');
    for (const [k, v] of rows) {
      const dt = document.createElement('dt');
      dt.textContent = k;
      const dd = document.createElement('dd');
      dd.textContent = v;
      dd.dataset.stat = k.toLowerCase().split(' ')[0];
      dl.append(dt, dd);
    }
    this.el.stats.replaceChildren(dl);
  }

  save() {
    const mesh = this.design.target.example ? undefined : { positions: this.target.positions, indices: this.target.indices };
    autosave.save(AUTOSAVE_KEY, { design: this.design, mesh }).catch((error) =>
      this.messages.show('warning', `Autosave failed (${error?.message || error}); save your design to a file.`),
    );
  }
}
