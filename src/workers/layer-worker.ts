/** Worker entry: Node worker_threads or a browser Web Worker (module type). */
import { makeHandler } from './handler.js';
import { isNode, nodeBuiltin } from '../runtime.js';
import type { FromWorker, ToWorker } from './protocol.js';

if (isNode) {
  const { parentPort } = await nodeBuiltin<typeof import('node:worker_threads')>('worker_threads');
  if (parentPort) {
    const port = parentPort;
    const handle = makeHandler((m: FromWorker) => port.postMessage(m));
    port.on('message', (m: ToWorker) => handle(m));
  }
} else {
  const scope = globalThis as unknown as { postMessage(m: unknown): void; onmessage: ((e: { data: ToWorker }) => void) | null };
  const handle = makeHandler((m: FromWorker) => scope.postMessage(m));
  scope.onmessage = (e) => handle(e.data);
}
