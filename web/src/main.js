// Entry point: builds the panes, the worker client and the app, and wires the page's controls.
import { Viewport } from './views/viewport.js';
import { linkViews } from './views/pane3d.js';
import { TargetPane } from './views/target-pane.js';
import { PatternPane } from './views/pattern-pane.js';
import { InflatedPane } from './views/inflated-pane.js';
import { SolverClient } from './worker/client.js';
import { Messages } from './app/messages.js';
import { App } from './app/app.js';
import { SeamTool } from './tools/seam-tool.js';
import { SeamPanel } from './views/seam-panel.js';
import { SeamAllowancePanel } from './views/seam-allowance-panel.js';
import { Exporter } from './app/exporter.js';
import { MM_PER_INCH } from './app/fabrication.js';
import { TabGuard, secondaryTabMessage } from './app/tab-guard.js';
import { registerServiceWorker, updateReadyMessage } from './app/offline.js';
import { Gallery } from './app/gallery.js';
import { Theme } from './app/theme.js';
import { Help } from './app/help.js';
import { Classroom, classroomRequested } from './app/classroom.js';
import { LayoutCompare } from './app/compare.js';
import { SeamSuggestions } from './app/suggest.js';
import { statusTooltip } from './views/status-line.js';
import { dockBoxes } from './views/boxes.js';
import { testFacade } from './app/test-facade.js';

const $ = (id) => document.getElementById(id);
const body = (id) => $(id).querySelector('.pane-body');

const viewport = new Viewport($('viewport'));
const panes = {
  target: new TargetPane(body('pane-target'), viewport),
  inflated: new InflatedPane(body('pane-inflated'), viewport),
  pattern: new PatternPane(body('pane-pattern'), viewport),
};
linkViews(panes.target, panes.inflated); // the target and its inflated shape, seen from the same side
$('inflated-dock').append(panes.inflated.legend); // the colors' legend under the figures, beside the shape
dockBoxes();
statusTooltip($('status'));
const messages = new Messages($('messages'));
const theme = new Theme({
  onChange: (t) => {
    viewport.setColors({ pane: t.color('--pane-bg'), page: t.color('--bg') });
    panes.pattern.setGridColors(...(t.resolved === 'dark' ? [0x56607a, 0x353c4a] : [0xb8c0cc, 0xd8dde5]));
    $('large-type').checked = t.largeType; // also when the classroom walk changes it
  },
});
$('theme-select').value = theme.choice;
$('theme-select').addEventListener('change', (e) => theme.set(e.target.value));
$('large-type').checked = theme.largeType;
$('large-type').addEventListener('change', (e) => theme.setLargeType(e.target.checked));
const help = new Help($('help-dialog'));
$('help-button').addEventListener('click', () => help.open());

const createWorker = () => new Worker(new URL('./worker/solver.worker.js', import.meta.url), { type: 'module' });
const client = new SolverClient(
  createWorker,
  {
    onCrash: ({ broken }) => {
      if (broken) messages.show('error', 'The solver keeps stopping, so Billow stopped restarting it. Your design is safe: reload the page.');
      else messages.show('warning', 'The solver stopped unexpectedly and was restarted. Your design is safe.');
    },
  },
);

const app = new App({
  client,
  panes,
  messages,
  baseUrl: document.baseURI,
  elements: {
    status: $('status'),
    inflatedStats: $('inflated-stats'),
    patternStats: $('pattern-stats'),
    compareGroup: $('compare-group'),
    showOptimized: $('show-optimized'),
    showFlattened: $('show-flattened'),
    resolutionSelect: $('resolution-select'),
  },
  fields: {
    exampleSelect: $('example-select'),
    heightInput: $('height-input'),
    upSelect: $('up-select'),
    materialSelect: $('material-select'),
    pressureInput: $('pressure-input'),
    pressureUnit: $('pressure-unit'),
    allowanceInput: $('allowance-input'),
    allowanceLabel: $('allowance-input').parentElement,
    sheetInput: $('sheet-input'),
    unitsSelect: $('units-select'),
    grainSelect: $('grain-select'),
    stats: $('target-stats'),
    undoButton: $('undo-button'),
    redoButton: $('redo-button'),
  },
});

const seamTool = new SeamTool(panes.target, app.seams);
const seamPanel = new SeamPanel($('seam-panel'), { tool: seamTool, editor: app.seams });

$('open-button').addEventListener('click', () => $('file-input').click());
$('file-input').addEventListener('change', (event) => {
  const file = event.target.files?.[0];
  if (file) app.openFile(file);
  event.target.value = '';
});
$('example-select').addEventListener('change', (event) => event.target.value && app.openExample(event.target.value));
$('height-input').addEventListener('change', (event) => app.setHeight(Number(event.target.value)));
$('up-select').addEventListener('change', (event) => app.setUp(event.target.value));
$('material-select').addEventListener('change', (event) => app.setMaterialPreset(event.target.value));
const pressureChanged = () => app.setPressure(Number($('pressure-input').value) * Number($('pressure-unit').value));
$('pressure-input').addEventListener('change', pressureChanged);
$('pressure-unit').addEventListener('change', () => app.showDesign());
// Fabrication settings: lengths typed in the chosen units, stored in mm.
const typedMillimeters = (input) => Number(input.value) * ($('units-select').value === 'in' ? MM_PER_INCH : 1);
$('allowance-input').addEventListener('change', (e) => app.setFabrication({ allowance: typedMillimeters(e.target) }));
$('sheet-input').addEventListener('change', (e) => app.setFabrication({ sheet_width: typedMillimeters(e.target) }));
$('units-select').addEventListener('change', (e) => app.setFabrication({ units: e.target.value }));
$('grain-select').addEventListener('change', (e) => app.setGrain(e.target.value));
// Seam allowance per seam: the list beside the pattern, opened by its button or a click on a seam.
app.allowancePanel = new SeamAllowancePanel($('seam-allowance-panel'), $('seams-button'), {
  pane: panes.pattern,
  onSeamAllowance: (id, mm) => app.setSeamAllowance(id, mm),
  onFreeEdgeAllowance: (mm) => app.setFreeEdgeAllowance(mm),
  onJoining: (joining) => app.setJoining(joining),
  onAddValve: (seam, at) => app.addValve(seam, at),
  onValveWidth: (index, mm) => app.setValveWidth(index, mm),
  onRemoveValve: (index) => app.removeValves([index]),
});
app.allowancePanel.render(app.design.fabrication);
const exporter = new Exporter(app, viewport);
const exportMenu = $('export-menu');
exportMenu.addEventListener('click', (event) => {
  const kind = event.target.closest('[data-export]')?.dataset.export;
  if (!kind) return;
  exportMenu.open = false;
  exporter.run(kind);
});
document.addEventListener('click', (event) => {
  if (exportMenu.open && !exportMenu.contains(event.target)) exportMenu.open = false;
});
$('resolution-select').addEventListener('change', (event) => app.setResolution(Number(event.target.value)));
$('show-optimized').addEventListener('click', () => app.panels.showVersion('optimized'));
$('show-flattened').addEventListener('click', () => app.panels.showVersion('flattened'));
// The inflated pane's colors: wrinkles, stress, distance to target (only for the target's own panels).
const colorSelect = $('color-select');
const setColorMode = (mode) => {
  colorSelect.value = mode;
  panes.inflated.setColorMode(mode);
};
colorSelect.addEventListener('change', () => setColorMode(colorSelect.value));
app.setColorMode = setColorMode; // a problem's "Show where" picks the colors that show it
panes.inflated.onFieldsChanged = () => {
  colorSelect.querySelector('option[value="distance"]').disabled = !panes.inflated.hasDistances;
};
const cycleColorMode = () => {
  const modes = [...colorSelect.options].filter((o) => !o.disabled).map((o) => o.value);
  setColorMode(modes[(modes.indexOf(colorSelect.value) + 1) % modes.length]);
};
// The target pane's named views (front, sides, top, bottom): an Outline seam laid straight on. The menu names
// the action and goes back to its title, so the same view can be chosen again after turning.
const viewSelect = $('view-select');
viewSelect.addEventListener('change', () => {
  if (viewSelect.value) panes.target.showView(viewSelect.value);
  viewSelect.value = '';
  viewSelect.blur(); // the keys (1, 3, 7, O) go to the views again
});
const VIEW_KEYS = { 1: 'front', 3: 'right', 7: 'top' };
// The pattern pane's view: the panels side by side, or nested on the sheet; remembered on this device.
const patternView = $('pattern-view');
const setPatternView = (view) => {
  panes.pattern.setView(view);
  for (const b of patternView.querySelectorAll('button')) b.setAttribute('aria-pressed', String(b.dataset.view === view));
  try {
    localStorage.setItem('billow.patternView', view);
  } catch {
    // Private browsing: the choice lasts this visit only.
  }
};
patternView.addEventListener('click', (e) => {
  const view = e.target.closest('[data-view]')?.dataset.view;
  if (view) setPatternView(view);
});
const cyclePatternView = () => setPatternView(panes.pattern.view === 'sheet' ? 'panels' : 'sheet');
try {
  if (localStorage.getItem('billow.patternView') === 'sheet') setPatternView('sheet');
} catch {
  // As above.
}
$('undo-button').addEventListener('click', () => app.undo());
$('redo-button').addEventListener('click', () => app.redo());
$('save-button').addEventListener('click', () => app.saveDesignFile());
$('share-button').addEventListener('click', () => app.shareLink());
window.addEventListener('hashchange', () => app.openFromLink(location.hash));

// Keyboard shortcuts (not while typing in a field).
window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
  if (seamTool.onKey(e)) {
    seamPanel.render();
    e.preventDefault();
    return;
  }
  const mod = e.ctrlKey || e.metaKey;
  const key = e.key.toLowerCase();
  const tools = { v: 'orbit', d: 'draw', s: 'section', e: 'edit' };
  if (!mod && !e.altKey && tools[key]) {
    seamTool.setMode(tools[key]);
    seamPanel.render();
  } else if (!mod && !e.altKey && key === 'o') {
    seamTool.layOutline();
  } else if (e.key === '?') {
    help.open();
  } else if (!mod && !e.altKey && key === 'm') {
    const axes = ['', 'x', 'y', 'z'];
    app.seams.setSymmetry(axes[(axes.indexOf(app.design.symmetry?.axis ?? '') + 1) % axes.length] || null);
  } else if (!mod && !e.altKey && VIEW_KEYS[key]) {
    panes.target.showView(VIEW_KEYS[key]);
  } else if (!mod && !e.altKey && key === '9') {
    panes.target.turnTo(panes.target.viewDirection().negate()); // the opposite side, as 9 does in Blender
  } else if (!mod && !e.altKey && key === 'c') {
    cycleColorMode();
  } else if (!mod && !e.altKey && key === 'n') {
    cyclePatternView();
  } else if (mod && key === 'z' && !e.shiftKey) app.undo();
  else if (mod && ((key === 'z' && e.shiftKey) || key === 'y')) app.redo();
  else if (mod && key === 's') app.saveDesignFile();
  else if (mod && key === 'o') $('file-input').click();
  else return;
  e.preventDefault();
});

// Drag and drop anywhere on the page.
const overlay = $('drop-overlay');
let dragDepth = 0;
window.addEventListener('dragenter', (e) => {
  e.preventDefault();
  dragDepth += 1;
  overlay.hidden = false;
});
window.addEventListener('dragleave', () => {
  dragDepth = Math.max(0, dragDepth - 1);
  if (dragDepth === 0) overlay.hidden = true;
});
window.addEventListener('dragover', (e) => e.preventDefault());
window.addEventListener('drop', (e) => {
  e.preventDefault();
  dragDepth = 0;
  overlay.hidden = true;
  const file = e.dataTransfer?.files?.[0];
  if (file) app.openFile(file);
});

// Only one tab autosaves, so two tabs never overwrite each other's design.
const tabGuard = new TabGuard({
  onChange: (primary) => {
    if (!primary) return messages.show('warning', secondaryTabMessage());
    messages.show('notice', 'This tab autosaves your design again.');
    app.becamePrimary();
  },
});
app.tabGuard = tabGuard;

const gallery = new Gallery(app, $('gallery-button'));
const compare = new LayoutCompare({ app, viewport, button: $('compare-button') });
const suggestions = new SeamSuggestions({ app, button: $('suggest-button'), createWorker });
const classroom = new Classroom({ app, viewport, theme, exporter, seamTool });
$('classroom-button').addEventListener('click', () => {
  compare.close();
  suggestions.close();
  classroom.start();
});
window.addEventListener('hashchange', () => {
  if (location.hash === '#classroom' && document.body.dataset.ready) {
    compare.close();
    suggestions.close();
    classroom.start();
  }
});
// The end-to-end tests' way in (test-facade.js).
window.billow = { test: testFacade({ app, seamTool, gallery, classroom, compare, tabGuard, client }) };
tabGuard
  .start()
  .then(() => app.start())
  .then(() => {
    document.body.setAttribute('data-ready', 'true');
    if (classroomRequested()) classroom.start(); // a #classroom link opens the walk
  });
registerServiceWorker({ onUpdate: () => messages.show('notice', updateReadyMessage()) }); // offline use, once started
