// Linked into the wasm GoogleTest build (--pre-js): Emscripten gives the program a fixed environment, so
// GoogleTest's sharding variables are copied from node's, letting ctest run the suite in a few processes
// instead of one node start-up (and one compile of the module) per test.
Module['preRun'] = () => {
  for (const name of ['GTEST_TOTAL_SHARDS', 'GTEST_SHARD_INDEX']) {
    if (process.env[name] !== undefined) ENV[name] = process.env[name];
  }
};
