// The design document in the browser: undo/redo, sharing by link into a fresh page, damaged links,
// saving and reopening a design file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { serve, launch, openPage, useBrowser } from './harness.mjs';

const env = useBrowser();

const stat = (page, name) => page.textContent(`#target-stats dd[data-stat="${name}"]`);

async function setHeight(page, value) {
  await page.fill('#height-input', String(value));
  await page.press('#height-input', 'Enter');
}

test('height edits undo and redo with buttons and keyboard', async () => {
  const page = await openPage(env.context, env.server.url);
  await page.selectOption('#example-select', 'sphere');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'sphere.obj');
  assert.equal(await page.isDisabled('#undo-button'), true);
  await setHeight(page, 0.7);
  await page.waitForTimeout(900); // a separate step, not merged with the next edit
  await setHeight(page, 1.2);
  assert.match(await stat(page, 'size'), /1\.20 m/);
  await page.click('#undo-button');
  assert.match(await stat(page, 'size'), /70\.0 cm/);
  await page.click('#pane-target .pane-body'); // focus out of the field: shortcuts apply to the page
  await page.keyboard.press('Control+z');
  assert.match(await stat(page, 'size'), /50\.0 cm/);
  assert.equal(await page.isDisabled('#undo-button'), true);
  await page.keyboard.press('Control+Shift+z');
  assert.match(await stat(page, 'size'), /70\.0 cm/);
  await page.click('#redo-button');
  assert.match(await stat(page, 'size'), /1\.20 m/);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a shared link opens the same design in a fresh page; a damaged link gets a message', async () => {
  const page = await openPage(env.context, env.server.url);
  await page.selectOption('#example-select', 'blub');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'blub.obj');
  await setHeight(page, 0.75);
  const url = await page.evaluate(() => window.billow.test.shareLink());
  assert.match(url, /#design=/);
  await page.locator('.message.notice', { hasText: 'link' }).waitFor();
  await page.close();

  const other = await launch(); // a different browser profile: no autosave to fall back on
  try {
    const fresh = await openPage(other, url);
    assert.equal(await stat(fresh, 'file'), 'blub.obj');
    assert.equal(await fresh.inputValue('#height-input'), '0.75');
    assert.doesNotMatch(await fresh.evaluate(() => location.href), /#design=/, 'the hash is consumed');
    assert.deepEqual(fresh.errors, []);
    const broken = await openPage(other, `${url.slice(0, url.indexOf('#design=') + 20)}`);
    const message = await broken.locator('.message.error').textContent();
    assert.match(message, /readable Billow design/);
    assert.ok(await broken.isVisible('#pane-target'), 'the page still works');
    assert.deepEqual(broken.errors, []);
  } finally {
    await other.close();
  }
});

test('a design saved to a file opens again', async () => {
  const page = await openPage(env.context, env.server.url);
  await page.selectOption('#example-select', 'penguin');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'penguin.obj');
  await setHeight(page, 1.5);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-button')]);
  assert.match(download.suggestedFilename(), /^penguin\.billow\.json$/);
  const saved = JSON.parse(readFileSync(await download.path(), 'utf8'));
  assert.equal(saved.format, 'billow-design');
  assert.equal(saved.size.height, 1.5);
  await page.selectOption('#example-select', 'sphere');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'sphere.obj');
  await page.setInputFiles('#file-input', { name: 'penguin.billow.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(saved)) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'penguin.obj');
  assert.equal(await page.inputValue('#height-input'), '1.5');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('markup in a seam name shows as text and never runs', async () => {
  const page = await openPage(env.context, env.server.url);
  const evil = '<img src=x onerror="window.__pwned = 1">';
  const design = {
    format: 'billow-design', version: 1, target: { example: 'sphere' }, size: { height: 0.5 },
    seams: [{ name: evil, closed: false, weight: 1, points: [{ face: 10, bary: [0.3, 0.3, 0.4] }, { face: 300, bary: [0.3, 0.3, 0.4] }] }],
  };
  await page.setInputFiles('#file-input', { name: 'evil.billow.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(design)) });
  await page.waitForFunction(() => document.querySelector('#seam-panel .seam .name'));
  assert.equal(await page.textContent('#seam-panel .seam .name'), evil);
  assert.equal(await page.evaluate(() => document.querySelectorAll('#seam-panel img').length), 0);
  await page.waitForTimeout(300);
  assert.equal(await page.evaluate(() => window.__pwned), undefined);
  assert.deepEqual(page.errors, []);
  await page.close();
});
