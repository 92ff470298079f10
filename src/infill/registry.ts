/**
 * The one table from pattern id to implementation. `satisfies` makes the compiler demand a module for
 * every id in PATTERN_IDS; the tests iterate this table, so a new pattern is tested the day it is added.
 *
 * Beside them, custom infill (patterns/custom.ts): an IceSL infiller, a GLSL cellular() shader or a
 * cells.png image, given with the slice (`Slicer.setCustomInfill`, the CLI's --infill-shader and
 * --infill-image, or an infiller folder named as --infill-pattern) instead of named by the infillPattern
 * setting. It fills every region in place of the region's pattern (`regionPattern`). Its module, with the
 * shader compiler, is most of the library's size, so it loads on first use (`loadCustomInfill`: a browser
 * bundle keeps it in a chunk of its own; the Node entry hands it over at once, `provideCustomInfill`, so a
 * broken shader is reported as soon as it is set); each thread then compiles the infiller once
 * (`customPattern(spec, cfg)`).
 */
import type { InfillPattern, PatternId } from './types.js';
import { grid } from './patterns/grid.js';
import { lines } from './patterns/lines.js';
import { triangles } from './patterns/triangles.js';
import { hexagons } from './patterns/hexagons.js';
import { cubic } from './patterns/cubic.js';
import { concentric } from './patterns/concentric.js';
import { gyroid } from './patterns/gyroid.js';
import { spiral } from './patterns/spiral.js';
import { lightning } from './patterns/lightning.js';
import type { CustomInfillSpec } from './patterns/custom.js';

export const PATTERNS = {
  grid,
  lines,
  triangles,
  hexagons,
  cubic,
  concentric,
  gyroid,
  spiral,
  lightning,
} satisfies Record<PatternId, InfillPattern>;

/** The pattern a region is filled with: the slice's custom infill when it has one, else the region's own. */
export function regionPattern(id: PatternId, custom: InfillPattern | undefined): InfillPattern {
  return custom ?? PATTERNS[id];
}

export type CustomInfillModule = typeof import('./patterns/custom.js');

/** The custom infill's module once loaded; the same for every slicer, so sharing it is safe. */
let loaded: CustomInfillModule | undefined;
let loading: Promise<CustomInfillModule> | undefined;

/** The custom infill's module if it is loaded already, else undefined. */
export function loadedCustomInfill(): CustomInfillModule | undefined {
  return loaded;
}

/** Load the custom infill's module and the shader compiler (once; later calls return the same module). */
export function loadCustomInfill(): Promise<CustomInfillModule> {
  if (loaded) return Promise.resolve(loaded);
  loading ??= import('./patterns/custom.js').then((m) => (loaded = m));
  return loading;
}

/** Hand over the module loaded statically (the Node entry does, so nothing waits for it). */
export function provideCustomInfill(m: CustomInfillModule): void {
  loaded = m;
}

/** Whether a custom infill can be sent to workers (plain data only: a JS density function cannot). */
export function isTransferable(spec: CustomInfillSpec): boolean {
  return typeof spec.density !== 'function';
}
