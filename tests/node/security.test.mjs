// The front end never turns user strings into markup or code: no innerHTML, outerHTML, insertAdjacentHTML,
// document.write, eval or Function constructor anywhere in web/src. And the page's Content-Security-Policy
// forbids inline scripts and remote origins.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const WEB = fileURLToPath(new URL('../../web', import.meta.url));

function sources(dir) {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? sources(path) : path.endsWith('.js') ? [path] : [];
  });
}

test('no HTML or code is built from strings in web/src', () => {
  const files = sources(join(WEB, 'src'));
  assert.ok(files.length > 10);
  const forbidden = /\.innerHTML\b|\.outerHTML\b|insertAdjacentHTML|document\.write|\beval\(|new Function\(/;
  for (const file of files) {
    const text = readFileSync(file, 'utf8');
    assert.doesNotMatch(text, forbidden, file);
  }
});

test('the page sets a strict Content-Security-Policy', () => {
  const html = readFileSync(join(WEB, 'index.html'), 'utf8');
  const csp = html.match(/http-equiv="Content-Security-Policy"\s+content="([^"]+)"/)?.[1];
  assert.ok(csp, 'a CSP meta tag');
  assert.match(csp, /default-src 'self'/);
  assert.match(csp, /script-src 'self'( 'wasm-unsafe-eval')?;/);
  assert.doesNotMatch(csp, /unsafe-inline|https?:/);
  assert.doesNotMatch(html, /<script>(?!\s*<\/script>)/, 'no inline script');
});
