// Everyday comfort: the help panel lists the keyboard shortcuts (button and "?"), a dark theme that the
// WebGL panes follow too, large type for projectors, both remembered across reloads.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPage, screenshot, useBrowser } from './harness.mjs';

const env = useBrowser();

// The color of the WebGL canvas at the middle of the inflated pane's empty lower right corner.
const paneColor = (page) =>
  page.evaluate(() => {
    const pane = document.querySelector('#pane-inflated').getBoundingClientRect();
    const canvas = document.getElementById('viewport');
    const c = canvas.getBoundingClientRect();
    const scale = canvas.width / c.width;
    const gl = canvas.getContext('webgl2') ?? canvas.getContext('webgl');
    const x = Math.round((pane.right - c.left - 12) * scale);
    const y = Math.round((c.bottom - pane.bottom + 12) * scale);
    const px = new Uint8Array(4);
    gl.readPixels(x, y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    return Array.from(px.slice(0, 3));
  });
const luminance = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

test('help lists the shortcuts; dark theme and large type apply to page and panes and are remembered', async () => {
  const page = await openPage(env.context, env.server.url);
  await page.click('#help-button');
  const dialog = page.locator('#help-dialog');
  await dialog.waitFor({ state: 'visible' });
  const rows = await dialog.locator('tr').count();
  assert.ok(rows >= 10, `${rows} shortcuts listed`);
  for (const key of ['Ctrl', 'Z', 'D', 'E', 'M', 'Esc']) assert.ok(await dialog.locator('kbd', { hasText: new RegExp(`^${key}$`) }).count(), `${key} listed`);
  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'hidden' });
  await page.click('#pane-target .pane-body');
  await page.keyboard.press('?');
  await dialog.waitFor({ state: 'visible' });
  await page.click('#help-dialog .close');
  await dialog.waitFor({ state: 'hidden' });

  const lightPane = await paneColor(page);
  assert.ok(luminance(lightPane) > 200, `light pane ${lightPane}`);
  await page.selectOption('#theme-select', 'dark');
  assert.equal(await page.getAttribute('html', 'data-theme'), 'dark');
  const bodyBg = await page.evaluate(() => getComputedStyle(document.body).backgroundColor);
  assert.match(bodyBg, /rgb\((\d+), (\d+), (\d+)\)/);
  assert.ok(luminance(bodyBg.match(/\d+/g).map(Number)) < 60, `dark page ${bodyBg}`);
  await page.waitForTimeout(100);
  const darkPane = await paneColor(page);
  assert.ok(luminance(darkPane) < 60, `dark pane ${darkPane}`);
  await page.check('#large-type');
  assert.equal(await page.evaluate(() => getComputedStyle(document.documentElement).fontSize), '18px');
  await screenshot(page, 'comfort-dark-large');

  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.getAttribute('html', 'data-theme'), 'dark', 'the theme is remembered');
  assert.equal(await page.inputValue('#theme-select'), 'dark');
  assert.equal(await page.isChecked('#large-type'), true);
  await page.selectOption('#theme-select', 'light');
  await page.uncheck('#large-type');
  assert.equal(await page.getAttribute('html', 'data-theme'), 'light');
  assert.deepEqual(page.errors, []);
  await page.close();
});
