// Loads the app's wasm module (build/wasm/billow.mjs, ENVIRONMENT=web,worker) in Node the way TOOLCHAIN.md §4
// says (option b): wasmBinary from the file, since the module has no Node code and Node's fetch cannot read file
// paths. It needs a Release build: with ASSERTIONS the module refuses an environment that is neither web nor worker.
import { readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { SolverApi } from '../../web/src/worker/solver-api.js';

export const WASM_DIR = process.env.BILLOW_WASM_DIR || fileURLToPath(new URL('../../build/wasm', import.meta.url));

export async function loadModule() {
  const { default: createBillow } = await import(pathToFileURL(`${WASM_DIR}/billow.mjs`).href);
  return createBillow({ wasmBinary: readFileSync(`${WASM_DIR}/billow.wasm`) });
}

export async function loadApi() {
  return new SolverApi(await loadModule());
}
