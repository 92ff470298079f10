/**
 * `strata-slicer/worker`: for a module worker that runs the slicer, what it needs before the library has
 * loaded. The library's module finishes loading only once its WebAssembly clipping engine is ready (a
 * top-level await), and a message that reaches a worker before it listens is lost; so the worker's entry
 * listens at once with `listenFirst` (this module loads nothing else) and imports its handler, and with it
 * the library, dynamically:
 *
 *   // worker.js, started with new Worker(new URL('./worker.js', import.meta.url), { type: 'module' })
 *   import { listenFirst } from 'strata-slicer/worker';
 *   listenFirst(self, async () => (await import('./slice-work.js')).onMessage);
 *
 *   // slice-work.js
 *   import { Slicer } from 'strata-slicer';
 *   export function onMessage(msg) { … new Slicer(msg.options).slice(msg.bytes).then((r) => postMessage(r)); }
 */
export { listenFirst } from './workers/listen-first.js';
