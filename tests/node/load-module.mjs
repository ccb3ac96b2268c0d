// Loads the Node build of the wasm module (build/wasm/billow_node.cjs) the way TOOLCHAIN.md §4 says:
// wasmBinary from the file, since Node's fetch cannot read file paths.
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { SolverApi } from '../../web/src/worker/solver-api.js';

const require = createRequire(import.meta.url);
export const WASM_DIR = process.env.BILLOW_WASM_DIR || fileURLToPath(new URL('../../build/wasm', import.meta.url));

export async function loadModule() {
  const createBillow = require(`${WASM_DIR}/billow_node.cjs`);
  return createBillow({ wasmBinary: readFileSync(`${WASM_DIR}/billow_node.wasm`) });
}

export async function loadApi() {
  return new SolverApi(await loadModule());
}
