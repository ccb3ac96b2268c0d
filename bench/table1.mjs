// The paper's Table 1 beside Billow's runs of the same rows, native and wasm (issue 26): read from the design
// benches' --json-out files (bench/design_bench.cpp, bench/design-bench-wasm.mjs).
//   node bench/table1.mjs NATIVE.json WASM.json
// A row Billow did not run says so. The paper's figures: C++ on a 12-core 3.2 GHz desktop, "full" = the
// objective's gradient below 1e-3 and forces below 1e-5; Billow's native bench runs the CLI's rule, the wasm
// bench the app's (optimize/stopping_rule.hpp).
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

// Skouras et al. 2014, Table 1: elements, panels, preview and full (iterations, seconds); `design`: the bench
// design of that row (bench/designs/manifest.json).
export const PAPER_ROWS = [
  { model: 'Sphere (sliding seams)', elements: 692, panels: 3, preview: [8, 4], full: [128, 21], design: 'sphere3s-700' },
  { model: 'Teddy', elements: 2974, panels: 17, preview: [23, 17], full: [193, 258], design: 'teddy' },
  { model: 'Elephant', elements: 14436, panels: 40, preview: [30, 137], full: [401, 1768], design: 'elephant' },
];

const seconds = (s) => (s >= 100 ? s.toFixed(0) : s.toFixed(1));

// One run's cells: elements, iterations, preview s, full s, rms %; '—' for a row not run (or failed).
function runCells(row) {
  if (!row || row.error) return ['—', '—', '—', '—', row?.error ? 'failed' : 'not run'];
  return [String(row.elements), String(row.iterations), seconds(row.previewSeconds), seconds(row.seconds), (100 * row.distanceRms).toFixed(3)];
}

// The table as text lines: the paper's figures, then Billow's native and wasm runs of the same rows.
export function table1(nativeRows = [], wasmRows = []) {
  const find = (rows, design) => rows.find((r) => r.design === design);
  const header = ['model', 'paper el', 'panels', 'paper preview its/s', 'paper full its/s',
    'native el', 'its', 'preview s', 'full s', 'rms %', 'wasm el', 'its', 'preview s', 'full s', 'rms %'];
  const body = PAPER_ROWS.map((p) => [
    p.model, String(p.elements), String(p.panels), `${p.preview[0]} / ${p.preview[1]}`, `${p.full[0]} / ${p.full[1]}`,
    ...runCells(find(nativeRows, p.design)), ...runCells(find(wasmRows, p.design)),
  ]);
  const widths = header.map((h, i) => Math.max(h.length, ...body.map((r) => r[i].length)));
  const line = (cells) => cells.map((c, i) => (i === 0 ? c.padEnd(widths[i]) : c.padStart(widths[i]))).join('  ');
  return [line(header), ...body.map(line)];
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const rowsOf = (path) => (path ? JSON.parse(readFileSync(path, 'utf8')).rows : []);
  for (const l of table1(rowsOf(process.argv[2]), rowsOf(process.argv[3]))) console.log(l);
}
