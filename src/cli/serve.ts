/**
 * `strata serve [--port N]`: serves the built web page (dist/web/ of the installed package) on
 * 127.0.0.1 and prints its URL. Static files only, GET and HEAD, nothing outside the folder. The
 * page is sent cross-origin isolated (COOP/COEP), so its slicing workers share the mesh in memory.
 */
import { createServer, type Server } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { extname, join, normalize, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { StrataError } from '../errors.js';

/** Port used when none is given. */
export const DEFAULT_PORT = 8080;
const HOST = '127.0.0.1';

/** The built page: dist/web beside dist/cli. */
export function webRoot(): string {
  return fileURLToPath(new URL('../web/', import.meta.url));
}

const MIME: Readonly<Record<string, string>> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.wasm': 'application/wasm',
  '.ico': 'image/x-icon',
  '.glsl': 'text/plain; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.stl': 'model/stl',
};

/** Headers on every answer: cross-origin isolation (SharedArrayBuffer for the workers), no sniffing. */
const COMMON_HEADERS = {
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
  'Cross-Origin-Resource-Policy': 'same-origin',
  'X-Content-Type-Options': 'nosniff',
  'Cache-Control': 'no-cache',
};

/** The file under `root` a URL path names, or null if it would leave the folder. */
export function resolveUnder(root: string, urlPath: string): string | null {
  let path: string;
  try {
    path = decodeURIComponent(urlPath.split('?')[0].split('#')[0]);
  } catch {
    return null;
  }
  if (path.includes('\0')) return null;
  if (path.endsWith('/')) path += 'index.html';
  const full = normalize(join(root, path));
  const base = root.endsWith(sep) ? root : root + sep;
  return full.startsWith(base) ? full : null;
}

export interface ServeOptions {
  port: number;
  root?: string;
}

/** Start the server; resolves once it listens, with its URL. */
export async function startServer(opts: ServeOptions): Promise<{ server: Server; url: string }> {
  const root = opts.root ?? webRoot();
  try {
    if (!(await stat(join(root, 'index.html'))).isFile()) throw new Error('not a file');
  } catch {
    throw new StrataError('BAD_FILE', `the web page is not built (${join(root, 'index.html')} is missing): run npm run build`);
  }
  const server = createServer((req, res) => {
    const send = (status: number, body: string | Uint8Array, type = 'text/plain; charset=utf-8') => {
      res.writeHead(status, { ...COMMON_HEADERS, 'Content-Type': type, 'Content-Length': Buffer.byteLength(body) });
      res.end(req.method === 'HEAD' ? undefined : body);
    };
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.setHeader('Allow', 'GET, HEAD');
      send(405, 'method not allowed\n');
      return;
    }
    const file = resolveUnder(root, req.url ?? '/');
    if (!file) {
      send(400, 'bad path\n');
      return;
    }
    readFile(file).then(
      (body) => send(200, body, MIME[extname(file).toLowerCase()] ?? 'application/octet-stream'),
      () => send(404, 'not found\n'),
    );
  });
  await new Promise<void>((resolve, reject) => {
    server.once('error', (e: NodeJS.ErrnoException) =>
      reject(new StrataError('BAD_SETTING', e.code === 'EADDRINUSE' ? `port ${opts.port} is in use: choose another with --port N` : `cannot listen on ${HOST}:${opts.port}: ${e.message}`)),
    );
    server.listen(opts.port, HOST, () => resolve());
  });
  const address = server.address();
  const port = typeof address === 'object' && address ? address.port : opts.port;
  return { server, url: `http://${HOST}:${port}/` };
}

/** Parse `serve`'s arguments: `--port N` (0 picks a free port). */
export function parseServeArgs(argv: readonly string[]): ServeOptions {
  let port = DEFAULT_PORT;
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const m = /^--port(?:=(.*))?$/.exec(a);
    if (!m) throw new StrataError('BAD_SETTING', `serve: unknown argument "${a}" (usage: strata serve [--port N])`);
    const text = m[1] ?? argv[++i];
    const n = Number(text);
    if (text === undefined || text === '' || !Number.isInteger(n) || n < 0 || n > 65535) {
      throw new StrataError('BAD_SETTING', `--port must be a whole number from 0 to 65535, got ${text === undefined ? 'nothing' : JSON.stringify(text)}`);
    }
    port = n;
  }
  return { port };
}

/** The `serve` command: runs until the process is stopped (Ctrl-C). */
export async function cmdServe(argv: readonly string[]): Promise<void> {
  const { server, url } = await startServer(parseServeArgs(argv));
  process.stdout.write(`Strata web page: ${url}\n(Ctrl-C stops it)\n`);
  await new Promise<void>((resolve) => {
    const stop = () => {
      server.close(() => resolve());
      server.closeAllConnections();
    };
    process.once('SIGINT', stop);
    process.once('SIGTERM', stop);
  });
}
