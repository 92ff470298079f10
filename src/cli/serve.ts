/**
 * `strata serve [--port N]`: serves the built web page (dist/web/ of the installed package) on
 * 127.0.0.1 and prints its URL. Static files only, GET and HEAD, nothing outside the folder. The
 * page is sent cross-origin isolated (COOP/COEP), so its slicing workers share the mesh in memory;
 * with a Content-Security-Policy (its own scripts only; eval only in the workers, where custom infill
 * shaders are compiled to JavaScript), never inside another site's frame, only to requests addressed
 * to this machine by name (a Host header of another name is a DNS-rebinding page's), and with ETags,
 * so a reload revalidates the scripts instead of fetching them again.
 */
import { createServer, type IncomingMessage, type Server } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import type { Stats } from 'node:fs';
import { extname, join, normalize, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { StrataError } from '../errors.js';
import { parseDecimal } from '../settings/resolve.js';

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

/**
 * The page's Content-Security-Policy: scripts, workers, styles and images from this server only
 * (WebAssembly compiled from them), fetches from it and from print hosts (OctoPrint, Moonraker: any http or
 * https address, which the user types), inline style attributes (three.js and the page set some),
 * no plugins, forms or base URL, and no framing.
 */
const PAGE_CSP = [
  "default-src 'self'",
  "script-src 'self' 'wasm-unsafe-eval'",
  "worker-src 'self'",
  "style-src 'self' 'unsafe-inline'",
  "img-src 'self' data: blob:",
  // "Send to printer": the print host's API, at whatever address the user gives (send-panel.ts)
  "connect-src 'self' http: https:",
  "object-src 'none'",
  "base-uri 'none'",
  "form-action 'none'",
  "frame-ancestors 'none'",
].join('; ');

/** The workers' policy: the same, and eval, which custom infill needs (IceSL shaders are compiled to JavaScript). */
const WORKER_CSP = PAGE_CSP.replace(
  "script-src 'self' 'wasm-unsafe-eval'",
  "script-src 'self' 'wasm-unsafe-eval' 'unsafe-eval'",
);

/** The scripts that start a worker (the policy a worker runs under is its script's). */
const WORKER_SCRIPTS = new Set(['slice-worker.js', 'layer-worker.js']);

/** Headers on every answer: cross-origin isolation (SharedArrayBuffer for the workers), no sniffing, no framing. */
const COMMON_HEADERS = {
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
  'Cross-Origin-Resource-Policy': 'same-origin',
  'X-Content-Type-Options': 'nosniff',
  'X-Frame-Options': 'DENY',
  'Referrer-Policy': 'no-referrer',
  'Cache-Control': 'no-cache',
};

/** The host names this server answers to: this machine by name or loopback address, and the address it listens on. */
export function allowedHosts(bound: string): Set<string> {
  return new Set(['localhost', '127.0.0.1', '[::1]', bound.includes(':') ? `[${bound}]` : bound]);
}

/** The name a Host header gives (without its port, lower case), or null when it has none or is malformed. */
export function hostName(header: string | undefined): string | null {
  if (!header) return null;
  const m = /^(\[[0-9a-f:.]+\]|[^:[\]]+)(?::\d{1,5})?$/i.exec(header.trim());
  return m ? m[1].toLowerCase().replace(/\.$/, '') : null;
}

/** A strong validator from the file's size and modification time (as nginx makes them). */
export function etagOf(s: Stats): string {
  return `"${s.size.toString(16)}-${Math.floor(s.mtimeMs).toString(16)}"`;
}

/** Whether an If-None-Match header names this ETag (weak comparison, as RFC 9110 asks for GET and HEAD). */
export function matchesEtag(header: string | undefined, etag: string): boolean {
  if (!header) return false;
  if (header.trim() === '*') return true;
  const bare = (t: string) => t.trim().replace(/^W\//, '');
  return header.split(',').some((t) => bare(t) === bare(etag));
}

function cspFor(file: string): string {
  return WORKER_SCRIPTS.has(file.slice(file.lastIndexOf(sep) + 1)) ? WORKER_CSP : PAGE_CSP;
}

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
    throw new StrataError(
      'BAD_FILE',
      `the web page is not built (${join(root, 'index.html')} is missing): run npm run build`,
    );
  }
  const hosts = allowedHosts(HOST);
  const server = createServer((req, res) => {
    const send: Send = (status, body, type = 'text/plain; charset=utf-8', extra = {}) => {
      // 304 Not Modified: the headers only, the browser keeps what it has
      const content = status === 304 ? {} : { 'Content-Type': type, 'Content-Length': Buffer.byteLength(body) };
      res.writeHead(status, { ...COMMON_HEADERS, 'Content-Security-Policy': PAGE_CSP, ...content, ...extra });
      res.end(req.method === 'HEAD' || status === 304 ? undefined : body);
    };
    if (!hosts.has(hostName(req.headers.host) ?? '')) {
      send(403, `this server answers only to ${[...hosts].join(', ')}\n`);
      return;
    }
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
    void serveFile(req, file, send);
  });
  await new Promise<void>((resolve, reject) => {
    server.once('error', (e: NodeJS.ErrnoException) =>
      reject(
        new StrataError(
          'BAD_SETTING',
          e.code === 'EADDRINUSE'
            ? `port ${opts.port} is in use: choose another with --port N`
            : `cannot listen on ${HOST}:${opts.port}: ${e.message}`,
        ),
      ),
    );
    server.listen(opts.port, HOST, () => resolve());
  });
  const address = server.address();
  const port = typeof address === 'object' && address ? address.port : opts.port;
  return { server, url: `http://${HOST}:${port}/` };
}

type Send = (status: number, body: string | Uint8Array, type?: string, extra?: Record<string, string>) => void;

/** A file with its ETag, or 304 when the browser already has this version. */
async function serveFile(req: IncomingMessage, file: string, send: Send): Promise<void> {
  let s: Stats;
  try {
    s = await stat(file);
    if (!s.isFile()) throw new Error('not a file');
  } catch {
    send(404, 'not found\n');
    return;
  }
  const type = MIME[extname(file).toLowerCase()] ?? 'application/octet-stream';
  const headers = { ETag: etagOf(s), 'Content-Security-Policy': cspFor(file) };
  if (matchesEtag(req.headers['if-none-match'], headers.ETag)) {
    send(304, '', type, headers);
    return;
  }
  let body: Buffer;
  try {
    body = await readFile(file);
  } catch {
    send(404, 'not found\n');
    return;
  }
  send(200, body, type, headers);
}

/** Parse `serve`'s arguments: `--port N` (0 picks a free port). */
export function parseServeArgs(argv: readonly string[]): ServeOptions {
  let port = DEFAULT_PORT;
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const m = /^--port(?:=(.*))?$/.exec(a);
    if (!m) throw new StrataError('BAD_SETTING', `serve: unknown argument "${a}" (usage: strata serve [--port N])`);
    const text = m[1] ?? argv[++i];
    const n = parseDecimal(text ?? '');
    if (text === undefined || text === '' || !Number.isInteger(n) || n < 0 || n > 65535) {
      throw new StrataError(
        'BAD_SETTING',
        `--port must be a whole number from 0 to 65535, got ${text === undefined ? 'nothing' : JSON.stringify(text)}`,
      );
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
