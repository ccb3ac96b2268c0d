// The sizes of the production site, raw and gzipped (node:zlib, level 9), by kind: JS, wasm, CSS, the
// page (index.html and the service worker), their total (what a first visit downloads before the example),
// and the example meshes (fetched when chosen, precached for offline use).
//   node scripts/site-report.mjs [DIST]      (default web/dist); scripts/build.sh runs it after vite build
// siteSizes() is also used by bench/site-bench.mjs.
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative, sep, extname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';

const DEFAULT_DIST = fileURLToPath(new URL('../web/dist', import.meta.url));

const KINDS = [
  { key: 'js', label: 'JS', test: (p) => /\.m?js$/.test(p) && p !== 'sw.js' },
  { key: 'wasm', label: 'wasm', test: (p) => p.endsWith('.wasm') },
  { key: 'css', label: 'CSS', test: (p) => p.endsWith('.css') },
  { key: 'page', label: 'HTML + service worker', test: (p) => p.endsWith('.html') || p === 'sw.js' },
  { key: 'examples', label: 'example meshes', test: (p) => p.startsWith('examples/') && extname(p) !== '.md' },
];

function filesUnder(dir) {
  return readdirSync(dir, { recursive: true, withFileTypes: true })
    .filter((e) => e.isFile())
    .map((e) => relative(dir, join(e.parentPath ?? e.path, e.name)).split(sep).join('/'))
    .sort();
}

// { js, wasm, css, page, examples, total, other }: each { files, raw, gzip } in bytes. total is JS + wasm +
// CSS + page; other is whatever fits no kind (e.g. CREDITS.md).
export function siteSizes(dist = DEFAULT_DIST) {
  const sizes = Object.fromEntries([...KINDS.map((k) => k.key), 'total', 'other'].map((k) => [k, { files: 0, raw: 0, gzip: 0 }]));
  for (const path of filesUnder(dist)) {
    const bytes = readFileSync(join(dist, path));
    const kind = KINDS.find((k) => k.test(path))?.key ?? 'other';
    const add = (entry) => {
      entry.files += 1;
      entry.raw += bytes.length;
      entry.gzip += gzipSync(bytes, { level: 9 }).length;
    };
    add(sizes[kind]);
    if (['js', 'wasm', 'css', 'page'].includes(kind)) add(sizes.total);
  }
  return sizes;
}

export const kB = (bytes) => `${(bytes / 1000).toLocaleString('en-US', { minimumFractionDigits: 1, maximumFractionDigits: 1 })} kB`;

export function formatSizes(sizes) {
  const rows = [...KINDS.slice(0, 4), { key: 'total', label: 'total' }, KINDS[4]].map(({ key, label }) => {
    const s = sizes[key];
    return [`${label} (${s.files} file${s.files === 1 ? '' : 's'})`, kB(s.raw), kB(s.gzip)];
  });
  const width = Math.max(...rows.map((r) => r[0].length));
  const line = (a, b, c) => `  ${a.padEnd(width)}  ${b.padStart(12)}  ${c.padStart(10)}`;
  return [line('', 'raw', 'gzip'), ...rows.map((r) => line(...r))].join('\n');
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const dist = process.argv[2] || DEFAULT_DIST;
  console.log(`production site (${relative(process.cwd(), dist) || '.'}):`);
  console.log(formatSizes(siteSizes(dist)));
}
