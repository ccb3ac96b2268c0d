// bench/table1.mjs: the paper's Table 1 beside Billow's native and wasm runs of the same rows.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { table1, PAPER_ROWS } from '../../bench/table1.mjs';

const run = (design, elements, iterations, previewSeconds, seconds, distanceRms) => ({ design, elements, iterations, previewSeconds, seconds, distanceRms });

test('each of the paper\'s rows stands beside Billow\'s runs of its design, native and wasm', () => {
  const native = [run('sphere3s-700', 690, 300, 3.48, 15.29, 0.00572), run('teddy', 2960, 65, 0.4, 9.7, 0.00511)];
  const wasm = [run('sphere3s-700', 690, 300, 21.36, 22.3, 0.00518), { design: 'teddy', error: 'out of memory' }];
  const lines = table1(native, wasm);
  assert.equal(lines.length, 1 + PAPER_ROWS.length);
  const cells = (line) => line.trim().split(/\s{2,}/);
  const [sphere, teddy, elephant] = lines.slice(1).map(cells);
  assert.deepEqual(sphere, ['Sphere (sliding seams)', '692', '3', '8 / 4', '128 / 21', '690', '300', '3.5', '15.3', '0.572', '690', '300', '21.4', '22.3', '0.518']);
  assert.deepEqual(teddy.slice(0, 10), ['Teddy', '2974', '17', '23 / 17', '193 / 258', '2960', '65', '0.4', '9.7', '0.511']);
  assert.equal(teddy.at(-1), 'failed', 'a run that failed says so');
  assert.deepEqual(elephant.slice(-2), ['—', 'not run'], 'a row not run says so');
  assert.equal(new Set(lines.map((l) => l.length)).size, 1, 'the columns line up');
});

test('every row of the paper names a design of the bench', async () => {
  const { readFile } = await import('node:fs/promises');
  const manifest = JSON.parse(await readFile(new URL('../../bench/designs/manifest.json', import.meta.url), 'utf8'));
  for (const row of PAPER_ROWS) assert.ok(manifest.designs.some((d) => d.name === row.design), row.design);
});
