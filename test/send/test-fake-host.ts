/**
 * A stand-in print host for tests: an HTTP server on 127.0.0.1 that records each request (method, path,
 * headers, multipart fields and file) and answers as the test scripts it.
 */
import { createServer, type IncomingMessage, type ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';

export interface Received {
  method: string;
  path: string;
  headers: IncomingMessage['headers'];
  fields: Record<string, string>;
  file?: { name: string; bytes: Buffer };
  /** The whole body was read before the answer. */
  complete: boolean;
}

export interface Answer {
  status: number;
  body?: string | object;
  /** Answer as soon as the headers arrive, without reading the body, and close (as a host refusing a key may). */
  early?: boolean;
}

/** Multipart fields and the file of a form body. */
function parseForm(body: Buffer, contentType: string): Pick<Received, 'fields' | 'file'> {
  const m = /boundary=(.+)$/.exec(contentType);
  const out: Pick<Received, 'fields' | 'file'> = { fields: {} };
  if (!m) return out;
  const sep = Buffer.from(`--${m[1]}`);
  let at = body.indexOf(sep);
  while (at >= 0) {
    const next = body.indexOf(sep, at + sep.length);
    if (next < 0) break;
    const part = body.subarray(at + sep.length + 2, next - 2);
    const split = part.indexOf('\r\n\r\n');
    const head = part.subarray(0, split).toString();
    const value = part.subarray(split + 4);
    const name = /name="([^"]*)"/.exec(head)?.[1] ?? '';
    const filename = /filename="([^"]*)"/.exec(head)?.[1];
    if (filename !== undefined) out.file = { name: filename, bytes: Buffer.from(value) };
    else out.fields[name] = value.toString();
    at = next;
  }
  return out;
}

export async function fakeHost(
  answer: (r: Received) => Answer,
): Promise<{ url: string; received: Received[]; close: () => Promise<void> }> {
  const received: Received[] = [];
  const handle = (req: IncomingMessage, res: ServerResponse, expectsContinue: boolean) => {
    const base = { method: req.method ?? '', path: req.url ?? '', headers: req.headers, fields: {}, complete: false };
    const probe = answer(base);
    const reply = (a: Answer) => {
      const body = typeof a.body === 'string' ? a.body : JSON.stringify(a.body ?? {});
      res.writeHead(a.status, { 'Content-Type': 'application/json', Connection: 'close' });
      res.end(body);
    };
    if (probe.early) {
      received.push(base);
      reply(probe);
      req.destroy();
      return;
    }
    if (expectsContinue) res.writeContinue();
    const chunks: Buffer[] = [];
    req.on('data', (c: Buffer) => chunks.push(c));
    req.on('end', () => {
      const r: Received = {
        ...base,
        complete: true,
        ...parseForm(Buffer.concat(chunks), String(req.headers['content-type'] ?? '')),
      };
      received.push(r);
      reply(answer(r));
    });
  };
  const server = createServer((req, res) => handle(req, res, false));
  // a client that asks "Expect: 100-continue" is answered before its body when the answer is early
  server.on('checkContinue', (req, res) => handle(req, res, true));
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return {
    url: `http://127.0.0.1:${port}`,
    received,
    close: () => new Promise<void>((resolve) => server.close(() => resolve())),
  };
}

/** A port with nothing listening on it (found by opening and closing one). */
export async function closedPort(): Promise<number> {
  const server = createServer();
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  await new Promise<void>((resolve) => server.close(() => resolve()));
  return port;
}
