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
  listen(onMessage: (msg: FromWorker) => void, onFail: (err: Error) => void): void;
  terminate(): Promise<unknown> | void;
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
  return {
    post: (m) => w.postMessage(m),
    listen(onMessage, onFail) {
      w.addEventListener('message', (e) => onMessage(e.data as FromWorker));
      w.addEventListener('messageerror', () => onFail(new Error('a layer worker message could not be read (messageerror)')));
      w.addEventListener('error', (e) => {
        e.preventDefault?.();
        onFail(webWorkerError(e, url));
      });
    },
    terminate: () => w.terminate(),
  };
}

export async function nodeWorkerPort(url: URL): Promise<Port> {
  const { Worker } = await nodeBuiltin<typeof import('node:worker_threads')>('worker_threads');
  const w = new Worker(url);
  w.unref();
  let closing = false;
  return {
    post: (m) => w.postMessage(m),
    listen(onMessage, onFail) {
      w.on('message', onMessage);
      w.on('messageerror', (e: Error) => onFail(new Error(`a layer worker message could not be read: ${e.message}`)));
      w.on('error', onFail);
      w.on('exit', (code: number) => {
        if (!closing) onFail(new Error(`a layer worker exited unexpectedly (code ${code})`));
      });
    },
    terminate: () => {
      closing = true;
      return w.terminate();
    },
  };
}
