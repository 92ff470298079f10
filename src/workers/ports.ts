/**
 * A layer worker behind one small interface, hosted by Node's worker_threads or a browser Web Worker.
 * Whatever stops a worker from answering (a script that does not load, an uncaught error, a message
 * that cannot be read, an exit) is reported through `listen`'s `onFail`, so a slice fails instead of
 * waiting forever for a reply.
 */
import { nodeBuiltin } from '../runtime.js';
import type { FromWorker, ToWorker } from './protocol.js';

export interface Port {
  post(msg: ToWorker): void;
  /** What happened before this call (a worker started early may already have failed) is delivered now. */
  listen(onMessage: (msg: FromWorker) => void, onFail: (err: Error) => void): void;
  terminate(): Promise<unknown> | void;
}

/** Holds a worker's messages and failures until someone listens. */
function relay() {
  let onMessage: ((msg: FromWorker) => void) | null = null;
  let onFail: ((err: Error) => void) | null = null;
  const early: Array<() => void> = [];
  return {
    message: (m: FromWorker) => (onMessage ? onMessage(m) : early.push(() => onMessage?.(m))),
    fail: (e: Error) => (onFail ? onFail(e) : early.push(() => onFail?.(e))),
    listen(m: (msg: FromWorker) => void, f: (err: Error) => void) {
      onMessage = m;
      onFail = f;
      for (const deliver of early.splice(0)) deliver();
    },
  };
}

/** What the pool uses of a browser `Worker`. */
export interface WebWorkerLike {
  postMessage(msg: unknown): void;
  addEventListener(type: 'message' | 'messageerror' | 'error', fn: (e: WebWorkerEvent) => void): void;
  terminate(): void;
}

/** A MessageEvent or ErrorEvent (a script that fails to load gives a plain Event: no message). */
export interface WebWorkerEvent {
  data?: unknown;
  message?: string;
  filename?: string;
  lineno?: number;
  preventDefault?(): void;
}

export type WebWorkerCtor = new (url: URL, options: { type: 'module' }) => WebWorkerLike;

/** The error a browser worker's `error` event stands for. */
export function webWorkerError(e: WebWorkerEvent, url: URL): Error {
  if (e.message) {
    const where = e.filename ? ` (${e.filename}${e.lineno ? `:${e.lineno}` : ''})` : '';
    return new Error(`layer worker failed: ${e.message}${where}`);
  }
  return new Error(
    `layer worker ${url.href} could not be started: the script did not load as a module worker ` +
      '(serve layer-worker.js next to the bundle that creates it, with a JavaScript MIME type; or slice with threads: 1)',
  );
}

export function webWorkerPort(Ctor: WebWorkerCtor, url: URL): Port {
  const w = new Ctor(url, { type: 'module' });
  const r = relay();
  w.addEventListener('message', (e) => r.message(e.data as FromWorker));
  w.addEventListener('messageerror', () =>
    r.fail(new Error('a layer worker message could not be read (messageerror)')),
  );
  w.addEventListener('error', (e) => {
    e.preventDefault?.();
    r.fail(webWorkerError(e, url));
  });
  return { post: (m) => w.postMessage(m), listen: r.listen, terminate: () => w.terminate() };
}

export async function nodeWorkerPort(url: URL): Promise<Port> {
  const { Worker } = await nodeBuiltin<typeof import('node:worker_threads')>('worker_threads');
  // workers inherit the process's options; --input-type (for `node -e`) would stop the worker file loading
  const w = new Worker(url, { execArgv: process.execArgv.filter((a) => !a.startsWith('--input-type')) });
  w.unref();
  let closing = false;
  const r = relay();
  w.on('message', r.message);
  w.on('messageerror', (e: Error) => r.fail(new Error(`a layer worker message could not be read: ${e.message}`)));
  w.on('error', r.fail);
  w.on('exit', (code: number) => {
    if (!closing) r.fail(new Error(`a layer worker exited unexpectedly (code ${code})`));
  });
  return {
    post: (m) => w.postMessage(m),
    listen: r.listen,
    terminate: () => {
      closing = true;
      return w.terminate();
    },
  };
}
