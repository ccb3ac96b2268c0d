// Vite builds the static site in web/dist. The wasm module comes from the CMake build (build/wasm),
// imported through the @wasm alias. No special headers are needed: cancellation is cooperative.
import { defineConfig } from 'vite';
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';

const root = fileURLToPath(new URL('.', import.meta.url));
const wasmDir = process.env.BILLOW_WASM_DIR || resolve(root, '../build/wasm');

export default defineConfig({
  root,
  base: './',
  publicDir: 'public',
  resolve: { alias: { '@wasm': wasmDir } },
  server: { fs: { allow: [root, wasmDir, resolve(root, '../node_modules')] } },
  worker: { format: 'es' },
  build: {
    outDir: resolve(root, 'dist'),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1000,
  },
});
