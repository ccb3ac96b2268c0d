// Suggested seam layouts over the shared meshes (issue 27's table): for each mesh of ../shared/meshes and each
// panel count, `billow suggest` (native, mirror-symmetric where the mesh has a mirror plane) and the best layout's
// panels, distance to the target (the worse way's RMS, % of the diagonal, optimized at 1,000 triangles), seam length
// and the command's wall time; with how many layouts were tried and kept. With --optimize K (more than the eight the
// command optimizes), also which of those the app's rule would have chosen from their first looks (chooseLooks, through
// the wasm module: build/wasm) and the best of those: how much closer a layout was to be had than the rule finds.
//   node bench/suggest-bench.mjs [--panels 2,6,12,24] [--meshes bunny,spot] [--optimize K] [--json-out FILE]
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadApi } from '../tests/node/load-module.mjs';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const MESHES = join(ROOT, '../shared/meshes');
const CLI = join(ROOT, 'build/native/billow');
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const panelCounts = arg('--panels', '2,6,12,24').split(',').map(Number);
const optimize = arg('--optimize', null);
const meshes = arg('--meshes', readdirSync(MESHES).filter((f) => f.endsWith('.obj')).map((f) => f.slice(0, -4)).join(',')).split(',');

const api = optimize ? await loadApi() : null; // the module's chooseLooks, the rule the app asks its worker for
const rows = [];
console.log(`| mesh | panels asked | best layout | panels | distance % | seams m | s | layouts kept / tried |${optimize ? ' the rule\'s pick % |' : ''}`);
console.log(`|---|---|---|---|---|---|---|---|${optimize ? '---|' : ''}`);
let missed = 0;
for (const mesh of meshes) {
  for (const panels of panelCounts) {
    const dir = mkdtempSync(join(tmpdir(), `suggest-${mesh}-${panels}-`));
    const args = ['suggest', join(MESHES, `${mesh}.obj`), '--panels', String(panels), '--out-dir', dir, '--quiet', ...(optimize ? ['--optimize', optimize] : [])];
    const t0 = performance.now();
    // With its mirror plane where it has one (the command refuses --symmetry where it has none).
    let symmetric = true;
    try {
      execFileSync(CLI, [...args, '--symmetry'], { stdio: 'pipe' });
    } catch (error) {
      if (!/mirror image/.test(String(error.stderr))) {
        if (error.status !== 1) throw error;
      } else {
        symmetric = false;
        try {
          execFileSync(CLI, args, { stdio: 'pipe' });
        } catch (again) {
          if (again.status !== 1) throw again;
        }
      }
    }
    const seconds = (performance.now() - t0) / 1000;
    const summary = JSON.parse(readFileSync(join(dir, 'summary.json'), 'utf8'));
    const best = summary.layouts[0];
    const tried = summary.layouts.length + summary.not_used.length;
    const row = { mesh, asked: panels, symmetric, best: best?.name ?? null, panels: best?.panels ?? null, distance: best ? 100 * best.distance.worse_way_rms : null, seamLength: best?.seam_length_m ?? null, seconds, kept: summary.layouts.length, tried };
    if (optimize && best) {
      // The rule's choice among the layouts optimized here (best first, so the first chosen is the closest).
      const looks = summary.layouts.map((l) => ({ lookRank: l.first_look.rank, family: l.first_look.family, distance: l.distance.worse_way_rms }));
      const rule = summary.optimized;
      row.rulePick = 100 * Math.min(...api.chooseLooks(looks.map(({ lookRank, family }) => ({ lookRank, family })), rule.by_default, rule.of_one_family).map((i) => looks[i].distance));
      missed += row.rulePick - row.distance;
    }
    rows.push(row);
    const f = (x, d) => (x === null ? '—' : x.toFixed(d));
    console.log(`| ${mesh}${symmetric ? ' (mirror)' : ''} | ${panels} | ${row.best ?? 'none'} | ${row.panels ?? '—'} | ${f(row.distance, 2)} | ${f(row.seamLength, 2)} | ${seconds.toFixed(1)} | ${row.kept} / ${tried} |${optimize ? ` ${f(row.rulePick ?? null, 2)} |` : ''}`);
  }
}
if (optimize) console.log(`\nThe rule's pick farther than the closest optimized, summed: ${missed.toFixed(2)} points.`);
const out = arg('--json-out', null);
if (out) writeFileSync(out, JSON.stringify(rows, null, 2));
