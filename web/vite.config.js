// Vite builds the static site in web/dist. The wasm module comes from the CMake build (build/wasm),
// imported through the @wasm alias. No special headers are needed: cancellation is cooperative.
// base './' keeps every URL relative, so the site works from any folder of any static server; the
// billow-service-worker plugin below writes dist/sw.js for offline use (docs/hosting.md).
import { defineConfig } from 'vite';
import { fileURLToPath } from 'node:url';
import { resolve, relative, join, sep } from 'node:path';
import { createHash } from 'node:crypto';
import { readFile, readdir, writeFile } from 'node:fs/promises';

const root = fileURLToPath(new URL('.', import.meta.url));
const wasmDir = process.env.BILLOW_WASM_DIR || resolve(root, '../build/wasm');

// Every file under dir, as paths relative to it with '/' separators, sorted.
async function filesUnder(dir) {
  const entries = await readdir(dir, { recursive: true, withFileTypes: true });
  return entries
    .filter((e) => e.isFile() && !e.name.startsWith('.'))
    .map((e) => relative(dir, join(e.parentPath ?? e.path, e.name)).split(sep).join('/'))
    .sort();
}

// Writes dist/sw.js once the site is written (public files included): web/sw.js preceded by the list of
// the files to precache with their SHA-256, and a version hashed from them all, so each deployment gets
// its own cache name and a byte-different sw.js, which is how browsers notice an update.
function serviceWorker({ source = resolve(root, 'sw.js'), output = 'sw.js' } = {}) {
  let outDir;
  return {
    name: 'billow-service-worker',
    apply: 'build',
    configResolved(config) {
      outDir = resolve(config.root, config.build.outDir);
    },
    writeBundle: {
      sequential: true,
      order: 'post',
      async handler() {
        const files = {};
        const version = createHash('sha256');
        for (const path of await filesUnder(outDir)) {
          if (path === output || path.endsWith('.map')) continue;
          files[path] = createHash('sha256').update(await readFile(join(outDir, path))).digest('hex');
          version.update(`${path}\0${files[path]}\n`);
        }
        const manifest = { version: version.digest('hex').slice(0, 16), files };
        const template = await readFile(source, 'utf8');
        await writeFile(join(outDir, output), `self.BILLOW_PRECACHE = ${JSON.stringify(manifest)};\n${template}`);
      },
    },
  };
}

export default defineConfig({
  root,
  base: './',
  publicDir: 'public',
  resolve: { alias: { '@wasm': wasmDir } },
  server: { fs: { allow: [root, wasmDir, resolve(root, '../node_modules')] } },
  worker: { format: 'es' },
  plugins: [serviceWorker()],
  build: {
    outDir: process.env.BILLOW_DIST || resolve(root, 'dist'),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1000,
  },
});
