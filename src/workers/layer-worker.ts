/**
 * Worker entry: Node worker_threads or a browser Web Worker (module type). The handler (and with it the
 * clipping engine, WebAssembly that loads asynchronously) comes behind a dynamic import; a browser worker
 * listens before that (listen-first.ts). Node's port holds messages until a listener is added.
 */
import { isNode, nodeBuiltin } from '../runtime.js';
import { listenFirst } from './listen-first.js';
import type { FromWorker, ToWorker } from './protocol.js';

if (isNode) {
  const { parentPort } = await nodeBuiltin<typeof import('node:worker_threads')>('worker_threads');
  if (parentPort) {
    const port = parentPort;
    const { makeHandler } = await import('./handler.js');
    const handle = makeHandler((m: FromWorker) => port.postMessage(m), await threadCpuClock());
    port.on('message', (m: ToWorker) => handle(m));
  }
} else {
  const scope = globalThis as unknown as {
    postMessage(m: unknown): void;
    onmessage: ((e: { data: ToWorker }) => void) | null;
  };
  listenFirst(scope, async () => (await import('./handler.js')).makeHandler((m: FromWorker) => scope.postMessage(m)));
}

/** This thread's CPU time in ms (Node ≥ 23.9, or Linux's /proc), else undefined (wall time is used). */
async function threadCpuClock(): Promise<(() => number) | undefined> {
  const p = process as { threadCpuUsage?: () => { user: number; system: number } };
  if (typeof p.threadCpuUsage === 'function') {
    const usage = p.threadCpuUsage.bind(process);
    return () => {
      const u = usage();
      return (u.user + u.system) / 1000;
    };
  }
  if (process.platform !== 'linux') return undefined;
  const { readFileSync } = await nodeBuiltin<typeof import('node:fs')>('fs');
  const read = () => {
    // fields after the command name: utime and stime are the 12th and 13th, in clock ticks (1/100 s)
    const stat = readFileSync('/proc/thread-self/stat', 'utf8');
    const f = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    return (Number(f[11]) + Number(f[12])) * 10;
  };
  try {
    return Number.isFinite(read()) ? read : undefined;
  } catch {
    return undefined;
  }
}
