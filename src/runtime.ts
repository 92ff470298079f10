/**
 * Where the code runs. Node built-ins are imported through `nodeBuiltin` with a computed specifier, so
 * browser bundlers do not try to resolve them; the browser never takes those paths.
 */
export const isNode = typeof process !== 'undefined' && !!process.versions?.node;

export function nodeBuiltin<T>(name: 'fs' | 'os' | 'worker_threads'): Promise<T> {
  const specifier = `node:${name}`;
  return import(/* @vite-ignore */ /* webpackIgnore: true */ specifier) as Promise<T>;
}
