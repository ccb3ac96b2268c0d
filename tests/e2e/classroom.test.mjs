// Classroom mode: the walk through the method (Classroom button or a #classroom link) steps forward and
// back with keys and buttons, each step showing the app's real state (seams, segments, flattened panels,
// the first try inflated with its distance to the target, the optimized panels, the wrinkles, the cut
// outlines with the Export actions); Escape gives the designer's own design back, undo steps and autosave
// untouched. The layout comparison keeps Layout A, compares it with changed seams (panels, distance to
// target) and puts either layout back, undoably.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { autosavedDesign, openFreshPage, openPage, optimizedResultShown, paintedFraction, screenshot, useBrowser } from './harness.mjs';

const env = useBrowser();
const LONG = { timeout: 180000 }; // the panels are optimized on two shared cores

// The walk's step counter, title and figures ({ 'distance-to-target': '6.1 %', ... }).
const walkState = (page) =>
  page.evaluate(() => {
    const aside = document.querySelector('aside.classroom');
    const figures = {};
    for (const row of aside.querySelectorAll('.classroom-figure-row')) figures[row.dataset.figure] = row.querySelector('.value').textContent;
    const visible = (id) => getComputedStyle(document.getElementById(id)).display !== 'none';
    return {
      counter: aside.querySelector('.classroom-counter').textContent,
      title: aside.querySelector('.classroom-title').textContent,
      figures,
      panes: ['pane-target', 'pane-inflated', 'pane-pattern'].filter(visible).map((id) => id.slice(5)),
    };
  });

const waitCounter = (page, text) =>
  page.waitForFunction((t) => document.querySelector('aside.classroom .classroom-counter')?.textContent === t, text);
const waitFigure = (page, name, pattern) =>
  page.waitForFunction(
    ([n, p]) => new RegExp(p).test(document.querySelector(`aside.classroom [data-figure="${n}"] .value`)?.textContent ?? ''),
    [name, pattern.source],
    LONG,
  );
const percent = (text) => Number(text.replace(/[^\d.]/g, ''));

// The designer's state that leaving the walk must give back.
const designerState = (page) =>
  page.evaluate(() => {
    const t = window.billow.test;
    return { design: JSON.stringify(t.design), past: t.undoSteps, example: t.design.target.example };
  });

// The design in the autosave record every new tab opens.
const autosaved = async (page) => JSON.stringify(await autosavedDesign(page));

const resultShown = (page) => optimizedResultShown(page, LONG.timeout);

test('the classroom walk shows each step of the method and gives the design back', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  // The designer's own work: the penguin with its seam and its panels made, and one edit to undo (heat sealed).
  await page.evaluate(() => window.billow.test.openGalleryDesign('toy'));
  await resultShown(page);
  await page.evaluate(() => window.billow.test.setJoining('sealed'));
  const mine = await designerState(page);
  assert.equal(mine.past, 1, 'one undo step');
  await page.waitForFunction(async (design) => {
    const read = () => new Promise((resolve) => {
      const open = indexedDB.open('billow', 1);
      open.onsuccess = () => {
        const get = open.result.transaction('autosave').objectStore('autosave').get('current');
        get.onsuccess = () => { resolve(JSON.stringify(get.result?.design)); open.result.close(); };
      };
    });
    return (await read()) === design;
  }, mine.design);

  await page.click('#classroom-button');
  await page.waitForSelector('aside.classroom:not([hidden])');
  assert.equal(new URL(page.url()).hash, '#classroom', 'the address is a link to the walk');
  await page.waitForFunction(() => window.billow.test.design.target.example === 'sphere' && window.billow.test.design.seams.length === 3, null, LONG);
  let s = await walkState(page);
  assert.equal(s.counter, '1 / 8');
  assert.equal(s.title, 'The target shape');
  assert.deepEqual(s.panes, ['target'], 'only the target pane');
  assert.equal(await page.isVisible('.topbar'), false, 'the top bar makes room');
  // The bare target: no seams drawn, no segments colored (even once the seams are traced).
  await page.waitForFunction(() => window.billow.test.segmentation, null, LONG);
  assert.equal(await page.evaluate(() => window.billow.test.panes.target.seams.items.children.length), 0, 'no seams on step 1');
  assert.equal(await page.evaluate(() => Boolean(window.billow.test.panes.target.segmentsMesh)), false, 'no segments on step 1');
  await screenshot(page, 'classroom-1-target');

  await page.keyboard.press('ArrowRight');
  await waitCounter(page, '2 / 8');
  await waitFigure(page, 'seams', /^3$/);
  assert.ok(await page.evaluate(() => window.billow.test.panes.target.seams.items.children.length) > 0, 'the seams are drawn');
  assert.equal(await page.evaluate(() => Boolean(window.billow.test.panes.target.segmentsMesh)), false, 'no segments yet');
  // Editing shortcuts do nothing in the walk: D would switch to drawing seams.
  await page.keyboard.press('d');
  assert.equal(await page.evaluate(() => window.billow.test.toolMode), 'orbit');

  await page.keyboard.press(' ');
  await waitCounter(page, '3 / 8');
  await waitFigure(page, 'segments', /^3$/);
  assert.equal(await page.evaluate(() => Boolean(window.billow.test.panes.target.segmentsMesh)), true, 'the segments are colored');
  await screenshot(page, 'classroom-3-segments');

  await page.click('aside.classroom .classroom-next');
  await waitCounter(page, '4 / 8');
  await waitFigure(page, 'panels', /^3$/);
  s = await walkState(page);
  assert.deepEqual(s.panes, ['target', 'pattern']);
  assert.equal(await page.evaluate(() => window.billow.test.panes.pattern.pattern.panels.length), 3, 'three panels in the pattern pane');
  await screenshot(page, 'classroom-4-flattened');

  await page.keyboard.press('PageDown');
  await waitCounter(page, '5 / 8');
  await waitFigure(page, 'distance-to-target', /^\d+\.\d %$/);
  s = await walkState(page);
  assert.deepEqual(s.panes, ['target', 'inflated']);
  const naive = percent(s.figures['distance-to-target']);
  assert.ok(await page.evaluate(() => window.billow.test.shownPatternText === window.billow.test.optimized.flattenedText), 'the flattened panels are inflated');
  await page.waitForTimeout(100); // the frame after the reframe
  assert.ok((await paintedFraction(page, '#pane-inflated .pane-body')) > 0.02, 'the first try is drawn');
  await screenshot(page, 'classroom-5-naive');

  await page.keyboard.press('ArrowRight');
  await waitCounter(page, '6 / 8');
  await waitFigure(page, 'distance-to-target', /^\d+\.\d %$/);
  await waitFigure(page, 'first-try', /%$/);
  s = await walkState(page);
  assert.deepEqual(s.panes, ['target', 'inflated', 'pattern']);
  const optimized = percent(s.figures['distance-to-target']);
  assert.ok(optimized < naive, `the optimized panels come closer: ${optimized} % < ${naive} %`);
  assert.equal(percent(s.figures['first-try']), naive);
  const solver = await page.evaluate(() => Math.max(window.billow.test.optimized.status.distanceRms, window.billow.test.optimized.status.targetDistanceRms) * 100);
  assert.ok(Math.abs(optimized - solver) < 0.5 * solver, `the walk's measure (${optimized} %) agrees with the optimizer's (${solver.toFixed(2)} %)`);
  assert.ok(await page.evaluate(() => window.billow.test.shownPatternText === window.billow.test.optimized.patternText), 'the optimized panels are inflated');
  await screenshot(page, 'classroom-6-optimized');

  await page.keyboard.press('ArrowRight');
  await waitCounter(page, '7 / 8');
  await waitFigure(page, 'most-wrinkled', /%$/);
  assert.deepEqual((await walkState(page)).panes, ['inflated']);
  assert.equal(await page.isVisible('#pane-inflated .legend'), true, 'the wrinkle colors are explained');
  await screenshot(page, 'classroom-7-wrinkles');

  await page.keyboard.press('End');
  await waitCounter(page, '8 / 8');
  await waitFigure(page, 'panels', /^3$/);
  assert.deepEqual((await walkState(page)).panes, ['pattern']);
  assert.equal(await page.locator('aside.classroom [data-export]').count(), 3, 'the Export actions');
  await page.waitForFunction(() => Boolean(window.billow.test.panes.pattern.cutLines), null, LONG);
  assert.equal(await page.isDisabled('aside.classroom .classroom-next'), true);
  await page.waitForTimeout(100);
  await screenshot(page, 'classroom-8-cut');
  const download = page.waitForEvent('download');
  await page.click('aside.classroom [data-export="svg"]');
  assert.match((await download).suggestedFilename(), /\.svg$/);

  await page.keyboard.press('ArrowLeft');
  await waitCounter(page, '7 / 8');
  await page.keyboard.press('PageUp');
  await waitCounter(page, '6 / 8');
  await page.click('aside.classroom .classroom-back');
  await waitCounter(page, '5 / 8');
  await waitFigure(page, 'distance-to-target', /^\d+\.\d %$/);
  await page.keyboard.press('Home');
  await waitCounter(page, '1 / 8');
  assert.equal(await page.isDisabled('aside.classroom .classroom-back'), true);
  assert.equal(await page.evaluate(() => window.billow.test.panes.target.seams.items.children.length), 0, 'step 1 again: no seams');

  // Escape: the penguin comes back with its undo step and its panels at once, not optimized again; the autosave
  // never held the walk's example.
  await page.evaluate(() => {
    const status = document.querySelector('#status');
    window.statusSeen = [];
    new MutationObserver(() => window.statusSeen.push(status.textContent)).observe(status, { childList: true, characterData: true, subtree: true });
  });
  await page.keyboard.press('Escape');
  await page.waitForSelector('aside.classroom', { state: 'hidden' });
  await page.waitForFunction(() => window.billow.test.design.target.example === 'penguin' && !window.billow.test.autosavePaused, null, LONG);
  assert.deepEqual(await designerState(page), mine);
  assert.equal(await page.isEnabled('#undo-button'), true);
  assert.equal(await page.isVisible('.topbar'), true);
  assert.equal(new URL(page.url()).hash, '', 'the #classroom link is gone');
  assert.equal(await page.evaluate(() => window.billow.test.toolMode), 'orbit');
  assert.equal(await autosaved(page), mine.design, 'the autosave still holds the designer\'s design');
  await resultShown(page);
  assert.equal(await page.evaluate(() => window.billow.test.shownPattern.panels.length), 2);
  const seen = await page.evaluate(() => window.statusSeen);
  assert.ok(!seen.some((text) => /^(Making|Optimizing) the panels/.test(text)), JSON.stringify(seen));
  await page.click('#undo-button');
  assert.equal(await page.evaluate(() => window.billow.test.design.fabrication.joining ?? 'sewn'), 'sewn', 'their undo step works');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a #classroom link opens the walk; full screen and larger text for a projector', async () => {
  const fresh = await openFreshPage(env.context, env.server.url);
  const url = `${env.server.url}#classroom`;
  await fresh.close();
  const page = await openPage(env.context, url);
  await page.waitForSelector('aside.classroom:not([hidden])');
  await waitCounter(page, '1 / 8');
  const before = await page.evaluate(() => getComputedStyle(document.querySelector('.classroom-text p')).fontSize);
  await page.click('aside.classroom .classroom-large');
  assert.equal(await page.getAttribute('html', 'data-large-type'), 'true');
  const after = await page.evaluate(() => getComputedStyle(document.querySelector('.classroom-text p')).fontSize);
  assert.ok(parseFloat(after) > parseFloat(before), `larger text: ${before} -> ${after}`);
  assert.equal(await page.isChecked('#large-type'), true, 'the top bar setting follows');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  await waitCounter(page, '3 / 8');
  await waitFigure(page, 'segments', /^3$/);
  await screenshot(page, 'classroom-3-large-type');
  // Full screen: granted, or refused with a note saying what to do instead.
  await page.click('aside.classroom .classroom-fullscreen');
  await page.waitForFunction(() => Boolean(document.fullscreenElement) || !document.querySelector('.classroom-note').hidden);
  if (await page.evaluate(() => Boolean(document.fullscreenElement))) {
    assert.equal(await page.textContent('aside.classroom .classroom-fullscreen'), 'Exit full screen');
    await page.click('aside.classroom .classroom-fullscreen');
    await page.waitForFunction(() => !document.fullscreenElement);
  }
  await page.click('aside.classroom .classroom-large');
  assert.equal(await page.getAttribute('html', 'data-large-type'), 'false');
  await page.click('aside.classroom .classroom-leave');
  await page.waitForSelector('aside.classroom', { state: 'hidden' });
  await page.waitForFunction(() => !window.billow.test.autosavePaused, null, LONG);
  assert.equal(await page.evaluate(() => window.billow.test.design.target.example), 'spot', 'the default design is back');
  assert.deepEqual(page.errors, []);
  await page.close();
});

// The figures of the comparison's cards: [{ layout, panels, distance, current }].
const cards = (page) =>
  page.evaluate(() => [...document.querySelectorAll('dialog.compare-dialog .compare-card')].map((card) => ({
    layout: card.dataset.layout,
    panels: card.querySelector('[data-figure="panels"]')?.textContent ?? null,
    distance: card.querySelector('[data-figure="distance"]')?.textContent ?? null,
    current: card.classList.contains('current'),
    thumbnail: Boolean(card.querySelector('img')?.naturalWidth),
  })));

test('two seam layouts compared side by side; either one can be put back, undoably', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.evaluate(() => window.billow.test.openGalleryDesign('sphere3'));
  await resultShown(page);
  await page.click('#compare-button');
  await page.waitForSelector('dialog.compare-dialog[open]');
  await page.click('dialog.compare-dialog [data-keep="A"]:not([disabled])');
  await page.waitForSelector('.compare-card[data-layout="A"].current');

  // Layout B: one meridian fewer, so two panels.
  await page.locator('#seam-panel .seam-list .delete').nth(2).click();
  await page.waitForFunction(() => window.billow.test.design.seams.length === 2);
  await page.waitForSelector('.compare-card[data-layout="current"] [data-figure="panels"]', LONG);
  let shown = await cards(page);
  assert.equal(shown.length, 2, 'two layouts side by side');
  const [a, now] = shown;
  assert.deepEqual([a.layout, a.panels, a.current], ['A', '3', false]);
  assert.deepEqual([now.layout, now.panels, now.current], ['current', '2', true]);
  for (const card of shown) {
    assert.match(card.distance, /^\d+\.\d % (target → inflated|inflated → target), \d+\.\d % (inflated → target|target → inflated)$/, `${card.layout}: distance to target, both ways`);
    assert.ok(card.thumbnail, `${card.layout}: thumbnail`);
  }
  await screenshot(page, 'compare-two-layouts');

  // Back to A: the two-seam layout is kept as B, so it is one click away too.
  await page.click('.compare-card[data-layout="A"] .compare-use');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 3);
  await page.waitForSelector('.compare-card[data-layout="A"].current');
  shown = await cards(page);
  assert.deepEqual(shown.map((c) => [c.layout, c.panels]), [['A', '3'], ['B', '2']]);
  await resultShown(page);
  assert.equal(await page.evaluate(() => window.billow.test.shownPattern.panels.length), 3, 'layout A\'s panels are made again');
  // Undo returns to the layout that was replaced.
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 2);
  await page.waitForSelector('.compare-card[data-layout="B"].current');
  await page.click('.compare-card[data-layout="A"] .compare-use');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 3);
  await resultShown(page);
  // While the app is idle the panel does nothing: it follows the app's changes, it does not poll. A change the app
  // makes just after its result is shown is followed, so the panel is judged over a quiet spell, the first of up to
  // three: a poller draws in every one.
  const windows = [];
  for (let k = 0; k < 3 && (windows.length === 0 || windows.at(-1).renders > 0); ++k)
    windows.push(await page.evaluate(() => window.billow.test.compareRenders(1500)));
  if (windows.length > 1) console.log(`# the comparison drew after the result was shown: ${JSON.stringify(windows)}`);
  const quiet = windows.at(-1);
  assert.equal(quiet.renders, 0, `no renders while idle: ${JSON.stringify(windows)}`);
  for (const w of windows) assert.ok(w.renders <= w.changes.length, `a draw only on a change of the app: ${JSON.stringify(w)}`);
  await page.click('dialog.compare-dialog .compare-close');
  assert.equal(await page.isVisible('dialog.compare-dialog'), false);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('the comparison stays off the pattern pane, and its Keep buttons stay ready when only the mirror plane changes', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.evaluate(() => window.billow.test.openGalleryDesign('sphere3'));
  await resultShown(page);
  await page.click('#compare-button');
  await page.waitForSelector('dialog.compare-dialog [data-keep="A"]:not([disabled])');
  const boxes = await page.evaluate(() => ({
    dialog: document.querySelector('dialog.compare-dialog').getBoundingClientRect().toJSON(),
    pattern: document.getElementById('pane-pattern').getBoundingClientRect().toJSON(),
  }));
  assert.ok(boxes.dialog.bottom <= boxes.pattern.top, `the dialog ends at ${boxes.dialog.bottom}, above the pattern pane at ${boxes.pattern.top}`);
  // Keep: its whole card and the buttons show without scrolling.
  await page.click('dialog.compare-dialog [data-keep="A"]');
  await page.waitForSelector('.compare-card[data-layout="A"].current');
  const scroll = await page.evaluate(() => { const b = document.querySelector('.compare-body'); return b.scrollHeight - b.clientHeight; });
  assert.ok(scroll <= 1, `the comparison fits without scrolling (${scroll} px more)`);
  await screenshot(page, 'compare-beside-pattern');
  // The mirror plane is not something the panels are made from: they stay, and so do the figures.
  for (const axis of ['x', null]) {
    const revision = await page.evaluate(() => window.billow.test.revision);
    await page.evaluate((a) => window.billow.test.setSymmetry(a), axis);
    assert.equal(await page.evaluate(() => window.billow.test.design.symmetry?.axis ?? null), axis);
    assert.equal(await page.evaluate(() => window.billow.test.revision), revision, 'the panels still belong to the design');
    await page.waitForSelector('dialog.compare-dialog [data-keep="B"]:not([disabled])', { timeout: 5000 });
    assert.equal(await page.isDisabled('dialog.compare-dialog [data-keep="A"]'), false, `Keep after symmetry ${axis}`);
  }
  // A seam edit still makes the panels stale until they are made again.
  await page.evaluate(() => window.billow.test.setPressure(1500));
  assert.equal(await page.isDisabled('dialog.compare-dialog [data-keep="B"]'), true, 'Keep waits for the new panels');
  await resultShown(page);
  await page.waitForSelector('dialog.compare-dialog [data-keep="B"]:not([disabled])');
  assert.deepEqual(page.errors, []);
  await page.close();
});
