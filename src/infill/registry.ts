/**
 * The one table from pattern id to implementation. `satisfies` makes the compiler demand a module for
 * every id in PATTERN_IDS; the tests iterate this table, so a new pattern is tested the day it is added.
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
