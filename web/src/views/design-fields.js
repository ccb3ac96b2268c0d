// The design's fields on the page: the examples menu, height, up axis, material, pressure, the fabrication
// settings (units, allowance or seal band, sheet width, grain), the target's figures and the undo buttons. It
// only shows: what the designer types goes to the App (wired in main.js), which checks it and shows the design
// again.
import { EXAMPLES } from '../app/examples.js';
import { PATTERN_EXAMPLES } from '../app/pattern-session.js';
import { MATERIAL_PRESETS, isPresetMaterial, describeMaterial } from '../app/materials.js';
import { MM_PER_INCH, grainMode, joiningOf } from '../app/fabrication.js';
import { upOf } from '../app/up-axis.js';
import { renderTargetStats } from '../app/target-stats.js';

export class DesignFields {
  // el: { exampleSelect, heightInput, upSelect, materialSelect, pressureInput, pressureUnit, allowanceInput,
  // allowanceLabel, sheetInput, unitsSelect, grainSelect, stats, undoButton, redoButton }
  constructor(el) {
    this.el = el;
    this.populateExamples();
    this.populateMaterials();
  }

  populateExamples() {
    const select = this.el.exampleSelect;
    select.replaceChildren();
    select.append(new Option('Choose…', ''));
    const targets = document.createElement('optgroup');
    targets.label = 'Targets';
    for (const e of EXAMPLES) targets.append(new Option(e.name, e.id));
    const patterns = document.createElement('optgroup');
    patterns.label = 'Patterns to inflate';
    for (const e of PATTERN_EXAMPLES) patterns.append(new Option(e.name, `pattern:${e.id}`));
    select.append(targets, patterns);
  }

  populateMaterials() {
    const select = this.el.materialSelect;
    select.replaceChildren(
      ...MATERIAL_PRESETS.map((m) => {
        const option = new Option(m.label, m.name);
        option.title = describeMaterial(m);
        return option;
      }),
      Object.assign(new Option('Custom (from the design file)', 'custom'), { disabled: true }),
    );
  }

  // The examples menu's choice: an example's id, 'pattern:<id>', or '' for the designer's own file.
  get example() {
    return this.el.exampleSelect.value;
  }

  set example(value) {
    this.el.exampleSelect.value = value;
  }

  // scale: meters per target unit; history: the undo history (for the buttons).
  render({ design, target, scale, history }) {
    const { el } = this;
    el.heightInput.value = String(design.size.height);
    const material = design.material;
    el.materialSelect.value = isPresetMaterial(material) ? material.name : 'custom';
    el.materialSelect.title = `The sheet the panels are cut from: ${describeMaterial(material)}`;
    const f = design.fabrication;
    const inches = f.units === 'in';
    el.unitsSelect.value = f.units;
    el.allowanceInput.value = String(+(inches ? f.allowance / MM_PER_INCH : f.allowance).toFixed(inches ? 3 : 1));
    const sealed = joiningOf(f) === 'sealed';
    el.allowanceLabel.firstChild.textContent = sealed ? 'Seal band ' : 'Allowance ';
    el.allowanceLabel.title = sealed
      ? 'Heat sealed: the band along the outline where the two pieces are sealed; the cut line runs at its outer edge'
      : 'Extra material outside the sewing line, on every seam without its own allowance; 0 for heat sealing';
    el.sheetInput.value = String(+(inches ? f.sheet_width / MM_PER_INCH : f.sheet_width).toFixed(inches ? 2 : 0));
    el.grainSelect.value = grainMode(f);
    const unit = Number(el.pressureUnit.value) || 1000;
    el.pressureInput.value = String(+(design.pressure / unit).toPrecision(6));
    el.upSelect.value = upOf(design);
    renderTargetStats(el.stats, target, scale, upOf(design));
    el.undoButton.disabled = !history.canUndo;
    el.redoButton.disabled = !history.canRedo;
  }
}
