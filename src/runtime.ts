/**
 * Where the code runs. Node built-ins are imported through `nodeBuiltin` with a computed specifier, so
 * browser bundlers do not try to resolve them; the browser never takes those paths.
 */
export const isNode = typeof process !== 'undefined' && !!process.versions?.node;

export function nodeBuiltin<T>(name: 'fs' | 'os' | 'worker_threads'): Promise<T> {
  const specifier = `node:${name}`;
  return import(/* @vite-ignore */ /* webpackIgnore: true */ specifier) as Promise<T>;
}

/** Run `fn` soon, after pending messages; not subject to the timer throttling of background tabs. */
export function soon(fn: () => void): void {
  if (typeof setImmediate === 'function') setImmediate(fn);
  else if (typeof MessageChannel === 'function') {
    const ch = new MessageChannel();
    ch.port1.onmessage = () => {
      ch.port1.close();
      fn();
    };
    ch.port2.postMessage(null);
  } else setTimeout(fn, 0);
}
