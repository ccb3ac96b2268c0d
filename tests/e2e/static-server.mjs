// A plain static file server (node:http) for the built site, as any host would run it: files of a folder
// (BILLOW_DIST, else web/dist, as in harness.mjs) under a sub-path, with a Content-Type from the file's
// extension and no other headers (no COOP/COEP, no caching rules). types overrides Content-Types, e.g.
// { '.wasm': 'application/octet-stream' } for a host that does not know wasm. Every request is recorded in
// `requests` ({ method, path }), so a test can tell what reached the network.
// Used by tests/e2e/site.test.mjs and bench/site-bench.mjs.
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { join, extname, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';

export const DIST = process.env.BILLOW_DIST || fileURLToPath(new URL('../../web/dist', import.meta.url));

export const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.wasm': 'application/wasm', '.json': 'application/json',
  '.obj': 'text/plain; charset=utf-8', '.md': 'text/markdown; charset=utf-8', '.png': 'image/png', '.svg': 'image/svg+xml',
};

// Serves root under base (which starts and ends with '/'); resolves with { url, origin, requests, close }.
export async function serveStatic({ root = DIST, base = '/', types = {}, port = 0 } = {}) {
  const mime = { ...TYPES, ...types };
  const requests = [];
  const server = createServer(async (req, res) => {
    const pathname = new URL(req.url, 'http://x').pathname;
    requests.push({ method: req.method, path: pathname });
    try {
      if (req.method !== 'GET' && req.method !== 'HEAD') return void res.writeHead(405).end();
      if (`${pathname}/` === base) return void res.writeHead(301, { location: base }).end(); // like real servers
      const path = decodeURIComponent(pathname);
      if (!path.startsWith(base)) throw new Error('outside');
      let file = normalize(path.slice(base.length) || '.');
      if (file.startsWith('..')) throw new Error('outside');
      if (file === '.' || path.endsWith('/') || (await stat(join(root, file))).isDirectory()) file = join(file, 'index.html');
      const body = await readFile(join(root, file));
      res.writeHead(200, { 'content-type': mime[extname(file)] || 'application/octet-stream', 'content-length': body.length });
      res.end(req.method === 'HEAD' ? undefined : body);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain' }).end('not found');
    }
  });
  await new Promise((resolve) => server.listen(port, '127.0.0.1', resolve));
  const origin = `http://127.0.0.1:${server.address().port}`;
  return {
    url: origin + base,
    origin,
    requests,
    close: () => new Promise((resolve) => {
      server.close(resolve);
      server.closeAllConnections();
    }),
  };
}
