// What the end-to-end tests (tests/e2e) read and do besides the pointer and the keyboard: the design, what the
// panes show, and whether work is under way, as values; a few actions a designer takes through several
// clicks. Tests go through here and never through the app's own fields, so the app can change inside without
// its tests changing. window.billow.test in the page (main.js).
export function testFacade({ app, seamTool, gallery, classroom, compare, tabGuard, client }) {
  return {
    // The design document on screen and its undo steps.
    get design() {
      return app.design;
    },
    get undoSteps() {
      return app.store.history.past.length;
    },
    // Counts the design's changes that make new panels (a fabrication edit leaves it): results carry it.
    get revision() {
      return app.revision;
    },
    // The target mesh: { fileName, positions, indices, report }, or null before one is open.
    get target() {
      return app.target;
    },
    // Meters per target unit at the design's height.
    get scale() {
      return app.scaleFor(app.design);
    },
    get status() {
      return app.store.status;
    },
    // True while the walk shows its example and the designer's autosave is left alone.
    get autosavePaused() {
      return Boolean(app.autosavePaused);
    },

    // Seams: their traced curves (aligned with design.seams), the seam being drawn, the selection, the
    // segmentation they make (null before it is back or without seams).
    seamTraces() {
      return app.seams.seamTraces();
    },
    get seamPreview() {
      return app.seams.preview;
    },
    get selection() {
      return app.seams.selection;
    },
    get segmentation() {
      return app.seams.segmentation;
    },
    positionOf(point) {
      return app.seams.positionOf(point);
    },
    // The points of the seam being drawn (0 when none is).
    get drawnPoints() {
      return seamTool.drawing?.points.length ?? 0;
    },
    get toolMode() {
      return seamTool.mode;
    },

    // Panels: the optimization and the inflation under way, the optimized result of this design (null before
    // it is made, or when it belongs to an earlier revision), the pattern the panes show, its cut figures.
    get optimizing() {
      return app.store.isWorking('panels');
    },
    get inflating() {
      return app.store.isWorking('inflation');
    },
    get optimized() {
      return app.store.result('optimized');
    },
    get shownPattern() {
      return app.store.shown.pattern;
    },
    get shownPatternText() {
      return app.store.shown.patternText;
    },
    get cutStatistics() {
      return app.store.shown.cut;
    },
    // The gallery's stored result is on screen: nothing was edited since it was shown.
    get storedShown() {
      return app.panels.storedShown();
    },
    // The gallery's stored result on record, as { revision, value } (the revision it was shown for); null once
    // the live result has replaced it (or when none was shown).
    get stored() {
      return app.store.results.get('stored') ?? null;
    },
    // The optimized panels of the design on screen are made, inflated and shown, and nothing runs.
    get resultShown() {
      return Boolean(app.store.optimizedShown());
    },

    // The three views, to look at what they draw (their meshes, cameras and overlays).
    get panes() {
      return app.panes;
    },
    // Which inflated shape the inflated pane shows: a count that grows with each new shape it is given.
    get inflatedSerial() {
      return app.panes.inflated.serial;
    },

    // Actions a designer takes through fields and menus.
    undo: () => app.undo(),
    shareLink: () => app.shareLink(),
    setHeight: (meters) => app.setHeight(meters),
    setPressure: (pascals) => app.setPressure(pascals),
    setJoining: (joining) => app.setJoining(joining),
    setSeamAllowance: (id, mm) => app.setSeamAllowance(id, mm),
    addValve: (seam, at) => app.addValve(seam, at),
    setSymmetry: (axis) => app.seams.setSymmetry(axis),
    // A seam as a design file writes it, added in one undo step; the seams are traced and segmented again.
    addSeam(seam) {
      app.commitDesign({ ...app.design, seams: [...app.design.seams, seam] });
      app.seams.refresh();
    },
    // Stops making and inflating panels (a test that leaves nothing running).
    stopWork: () => app.panels.stop(),
    openGalleryDesign: (id) => gallery.open(id),

    // What the app says: messages and the status line, as the app would set them (layout tests of long texts).
    showMessage: (severity, text, items, options) => app.messages.show(severity, text, items, options),
    resolveMessages: (cause, options) => app.messages.resolve(cause, options),
    clearMessages: () => app.messages.clear(),
    setStatus: (text) => app.setStatus(text),
    showPanelProblems: (error) => app.panels.showFailure(error),
    warnUncovered: (regions) => app.panels.warnUncovered(regions),

    // The classroom walk's figures of a step ([label, value] rows).
    classroomFigures: (step) => classroom.targetFigures(step),
    // How often the layout comparison draws itself within `millis` (it follows the app's changes, no timer), and
    // the app's changes in that time ('work', 'shown', ...: what a draw would follow).
    async compareRenders(millis) {
      const render = compare.render;
      let renders = 0;
      compare.render = function counted() {
        renders += 1;
        return render.call(this);
      };
      const changes = [];
      const unsubscribe = app.store.subscribe((what) => changes.push(what));
      await new Promise((resolve) => setTimeout(resolve, millis));
      compare.render = render;
      unsubscribe();
      return { renders, changes };
    },
    get isPrimaryTab() {
      return tabGuard.isPrimary;
    },
    // A request straight to the worker (example patterns, memory figures, a crash on purpose).
    request: (op, args = {}) => client.request(op, args),
  };
}
