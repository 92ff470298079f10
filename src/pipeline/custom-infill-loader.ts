/**
 * The IceSL shader compiler (a GLSL parser, a PNG decoder and the compiler itself) is most of the
 * library's size, and only custom infill needs it. It is imported on first use, so a browser bundle
 * keeps it in a chunk of its own that loads only when a custom infill is sliced. The Node entry
 * (index.ts) hands it over at once, so there a broken shader is reported as soon as it is set.
 */
import type { CustomInfillSpec } from './custom-infill.js';

export type CustomInfillModule = typeof import('./custom-infill.js');

/** The compiler once loaded; the same for every slicer, so sharing it is safe. */
let loaded: CustomInfillModule | undefined;
let loading: Promise<CustomInfillModule> | undefined;

/** The compiler if it is loaded already, else undefined. */
export function loadedCustomInfill(): CustomInfillModule | undefined {
  return loaded;
}

/** Load the compiler (once; later calls return the same module). */
export function loadCustomInfill(): Promise<CustomInfillModule> {
  if (loaded) return Promise.resolve(loaded);
  loading ??= import('./custom-infill.js').then((m) => (loaded = m));
  return loading;
}

/** Hand over a compiler loaded statically (the Node entry does, so nothing waits for it). */
export function provideCustomInfill(m: CustomInfillModule): void {
  loaded = m;
}

/** Whether the spec can be sent to workers (plain data only: a JS density function cannot). */
export function isTransferable(spec: CustomInfillSpec): boolean {
  return typeof spec.density !== 'function';
}
