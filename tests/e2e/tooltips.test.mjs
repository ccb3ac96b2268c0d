// Tooltips and names: every control the designer can see (buttons, selects, inputs, toggles, menu items,
// the Export menu's summary) has a tooltip that says what it does, and a name for screen readers. The
// page is walked through its states (a fresh page, the Export menu, a design with its seams, panels and
// result, Compare, the pattern's seam allowances, a selected seam, mirror symmetry, drawing a seam, the
// gallery, help, a message, the classroom walk), and in each the visible controls are listed with any that
// lack either.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openFreshPage, optimizedResultShown, useBrowser } from './harness.mjs';

const env = useBrowser();

// The visible controls without a tooltip or without a name, as short descriptions, and how many controls
// were looked at. A control's tooltip is its own title or, as the browser shows it over the control, the
// title of the <label> around it; a tooltip that only repeats the control's visible text does not count.
// Its name: aria-label, aria-labelledby, its <label>'s text, its own text, an image's alt, or its title.
const audit = (page) =>
  page.evaluate(() => {
    const CONTROLS = 'button, select, input:not([type="hidden"]), textarea, summary, a[href], [role="button"], [role="menuitem"], [role="switch"], [role="checkbox"], [role="tab"]';
    const text = (s) => (s ?? '').replace(/\s+/g, ' ').trim();
    const visible = (el) => {
      if (!el.checkVisibility({ checkOpacity: true, checkVisibilityCSS: true })) return false;
      const r = el.getBoundingClientRect();
      return r.width > 0 && r.height > 0;
    };
    const ownText = (el) => {
      if (el instanceof HTMLSelectElement || el instanceof HTMLInputElement || el instanceof HTMLTextAreaElement) return '';
      return text([...el.querySelectorAll('img')].map((img) => img.alt).join(' ') + ' ' + el.textContent);
    };
    const describe = (el) => {
      const id = el.id ? `#${el.id}` : '';
      const cls = typeof el.className === 'string' && el.className ? `.${el.className.trim().split(/\s+/).join('.')}` : '';
      const data = Object.entries(el.dataset).map(([k, v]) => `[data-${k}="${v}"]`).join('');
      const where = el.closest('[id]')?.id ?? '';
      return `${el.tagName.toLowerCase()}${id}${cls}${data}${el.type && el.tagName === 'INPUT' ? `[type=${el.type}]` : ''} "${ownText(el).slice(0, 30)}" in #${where}`;
    };
    const missing = [];
    const controls = [...document.querySelectorAll(CONTROLS)].filter(visible);
    for (const el of controls) {
      const label = el.closest('label');
      const tooltip = text(el.getAttribute('title')) || text(label?.getAttribute('title'));
      const own = ownText(el);
      const labelled = text(el.getAttribute('aria-labelledby')?.split(/\s+/).map((id) => document.getElementById(id)?.textContent).join(' '));
      const name = text(el.getAttribute('aria-label')) || labelled || text([...(el.labels ?? [])].map((l) => l.textContent).join(' ')) || own || text(el.getAttribute('title'));
      if (!tooltip) missing.push(`no tooltip: ${describe(el)}`);
      else if (own && tooltip.toLowerCase() === own.toLowerCase()) missing.push(`tooltip only repeats the text: ${describe(el)}`);
      if (!name) missing.push(`no name: ${describe(el)}`);
    }
    return { count: controls.length, missing };
  });

const resultShown = (page) => optimizedResultShown(page);

test('every visible control has a tooltip and a name, in every state of the page', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  const found = new Set();
  let seen = 0;
  const check = async (state) => {
    const { count, missing } = await audit(page);
    assert.ok(count > 0, `${state}: controls found`);
    seen += count;
    for (const m of missing) found.add(m);
  };

  await check('a fresh page');
  await page.click('#export-menu summary');
  await check('the Export menu');
  await page.click('#export-menu summary');

  await page.evaluate(() => window.billow.test.openGalleryDesign('sphere3'));
  await resultShown(page);
  await check('a design with its result');
  // The pattern pane's list of seams with their own allowances.
  if (await page.isVisible('#seams-button')) {
    await page.click('#seams-button');
    await page.waitForSelector('#seam-allowance-panel input');
    await check('the seams and their allowances');
    await page.click('#seams-button');
  }
  await page.click('#compare-button');
  await page.waitForSelector('dialog.compare-dialog[open]');
  await page.click('dialog.compare-dialog [data-keep="A"]:not([disabled])');
  await page.waitForSelector('.compare-card[data-layout="A"] .compare-use');
  await check('Compare');
  await page.click('dialog.compare-dialog .compare-close');

  await page.click('#seam-panel .seam-list .name >> nth=0');
  await page.waitForSelector('#seam-panel .seam-list .connect');
  await check('a seam selected');
  await page.selectOption('#seam-panel select.symmetry', 'x');
  await page.waitForSelector('#seam-panel .seam-list .mirror');
  await check('mirror symmetry');
  await page.selectOption('#seam-panel select.symmetry', '');
  await page.click('#seam-panel button[data-tool="draw"]');
  const square = await page.evaluate(() => window.billow.test.panes.target.square); // where the target is framed
  await page.mouse.click(square.left + square.side / 2, square.top + square.side / 2);
  await page.waitForSelector('#seam-panel .drawbar:not([hidden])');
  await check('drawing a seam');
  await page.keyboard.press('Escape');
  await page.click('#seam-panel button[data-tool="orbit"]');

  await page.click('#gallery-button');
  await page.waitForSelector('dialog.gallery[open]');
  await check('the gallery');
  await page.click('dialog.gallery .gallery-close');

  await page.click('#help-button');
  await page.waitForSelector('#help-dialog[open]');
  await check('help');
  await page.click('#help-dialog .close');

  await page.evaluate(() => window.billow.test.showMessage('notice', 'A message to dismiss.'));
  await check('a message');
  await page.click('#messages .message button');

  await page.click('#classroom-button');
  await page.waitForSelector('aside.classroom:not([hidden])');
  await check('the classroom walk');
  await page.click('aside.classroom .classroom-leave');
  await page.waitForSelector('aside.classroom', { state: 'hidden' });

  console.log(`${seen} controls checked`);
  assert.deepEqual([...found], [], 'controls without a tooltip or a name');
  assert.deepEqual(page.errors, []);
  await page.close();
});
