/** The print-host transport for Node: node:http and node:https, streaming the upload with progress. */
import * as http from 'node:http';
import * as https from 'node:https';
import { cancelled } from '../errors.js';
import { multipartBody, Unreachable, type FormFile, type HttpReply, type Transport } from './transport.js';

/** A host that says nothing for this long is given up, ms. */
const IDLE_MS = 30_000;
/** Upload pieces, bytes: progress is reported after each. */
const PIECE = 64 * 1024;
/** How long an upload waits for the host's "100 Continue" before sending the body anyway (RFC 9110), ms. */
const CONTINUE_MS = 1000;

/** A network error in words (the code in brackets). */
export function describeNetworkError(e: NodeJS.ErrnoException): string {
  const words: Record<string, string> = {
    ECONNREFUSED: 'connection refused (nothing listens at that address and port)',
    ENOTFOUND: 'no such host name',
    EAI_AGAIN: 'the host name could not be looked up',
    ETIMEDOUT: 'no answer (timed out)',
    EHOSTUNREACH: 'host unreachable',
    ENETUNREACH: 'network unreachable',
    ECONNRESET: 'the connection was closed by the host',
    EPIPE: 'the connection was closed by the host',
  };
  const code = e.code ?? '';
  return words[code] ? `${words[code]} (${code})` : e.message || code || 'unknown network error';
}

function send(
  url: URL,
  method: string,
  headers: Record<string, string>,
  writeBody: (req: http.ClientRequest, stop: () => boolean) => Promise<void>,
  signal?: AbortSignal,
): Promise<HttpReply> {
  return new Promise<HttpReply>((resolve, reject) => {
    if (signal?.aborted) return reject(cancelled(signal));
    const lib = url.protocol === 'https:' ? https : http;
    let answered = false;
    let settled = false;
    const done = (f: () => void) => {
      if (settled) return;
      settled = true;
      signal?.removeEventListener('abort', onAbort);
      f();
    };
    const req = lib.request(url, { method, headers });
    const onAbort = () => {
      req.destroy();
      done(() => reject(cancelled(signal)));
    };
    signal?.addEventListener('abort', onAbort, { once: true });
    req.setTimeout(IDLE_MS, () => req.destroy(Object.assign(new Error('timed out'), { code: 'ETIMEDOUT' })));
    req.on('response', (res) => {
      answered = true;
      const chunks: Buffer[] = [];
      res.on('data', (c: Buffer) => chunks.push(c));
      res.on('end', () =>
        done(() =>
          resolve({
            status: res.statusCode ?? 0,
            statusText: res.statusMessage ?? '',
            body: Buffer.concat(chunks).toString('utf8'),
          }),
        ),
      );
      res.on('error', (e) => done(() => reject(new Unreachable(describeNetworkError(e)))));
    });
    // a host may answer (401, 413) and close before the whole body is sent: its answer is what counts
    req.on('error', (e: NodeJS.ErrnoException) => {
      if (!answered) done(() => reject(new Unreachable(describeNetworkError(e))));
    });
    writeBody(req, () => answered || settled).then(
      () => req.end(),
      () => {
        // a write failed: the 'error' or 'response' event says why
      },
    );
  });
}

/** Write `chunk`, resolving once it is handed to the socket (and waiting for 'drain' when it is full). */
function write(req: http.ClientRequest, chunk: Uint8Array): Promise<void> {
  return new Promise((resolve, reject) => {
    const ok = req.write(chunk, (e) => (e ? reject(e) : ok ? resolve() : undefined));
    if (!ok) req.once('drain', () => resolve());
  });
}

export const nodeTransport: Transport = {
  request(method, url, headers, body, signal) {
    const data = body === undefined ? undefined : Buffer.from(body, 'utf8');
    const h = data ? { ...headers, 'Content-Length': String(data.length) } : headers;
    return send(
      new URL(url),
      method,
      h,
      async (req) => {
        if (data) await write(req, data);
      },
      signal,
    );
  },

  upload(url, headers, fields, file: FormFile, onProgress, signal) {
    const body = multipartBody(fields, file);
    // "Expect: 100-continue": a host that refuses the upload (a wrong key) answers before the body is sent,
    // instead of closing the connection while it arrives (which can lose its answer)
    const h = {
      ...headers,
      'Content-Type': body.contentType,
      'Content-Length': String(body.total),
      Expect: '100-continue',
    };
    return send(
      new URL(url),
      'POST',
      h,
      async (req, stop) => {
        req.flushHeaders();
        await new Promise<void>((resolve) => {
          const timer = setTimeout(resolve, CONTINUE_MS);
          const go = () => {
            clearTimeout(timer);
            resolve();
          };
          req.once('continue', go);
          req.once('response', go);
          req.once('close', go);
        });
        let sent = 0;
        const put = async (chunk: Uint8Array) => {
          if (stop()) throw new Error('answered');
          await write(req, chunk);
          sent += chunk.length;
          onProgress?.(sent, body.total);
        };
        await put(body.head);
        for (let at = 0; at < file.bytes.length; at += PIECE) await put(file.bytes.subarray(at, at + PIECE));
        await put(body.tail);
      },
      signal,
    );
  },
};
