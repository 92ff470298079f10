/**
 * Object labels: the lines that tell a host or the firmware which object the moves between them belong
 * to, so one object can be cancelled mid-print.
 *
 * - Klipper (`firmware`): `EXCLUDE_OBJECT_DEFINE NAME=… CENTER=x,y POLYGON=[[x,y],…]` for every object
 *   before the start G-code (so start macros can use them, e.g. for an adaptive bed mesh), then
 *   `EXCLUDE_OBJECT_START NAME=…` / `EXCLUDE_OBJECT_END NAME=…` around each object's moves per layer.
 *   Names are parameters there: only letters, digits, `_`, `.` and `-` are kept (others become `_`), and
 *   they are made unique ignoring case, as Klipper compares them upper-cased.
 * - Marlin (`firmware`): `M486 T<count>` before the start G-code, `M486 S<index>` before an object's
 *   moves and `M486 S-1` after them (Marlin's "not an object" index).
 * - RepRapFirmware (`firmware`): the same with the name, `M486 S<index> A"name"`.
 * - Marlin and RepRap also get the comments, and `comments` writes only them: `; printing object NAME`
 *   and `; stop printing object NAME`, which OctoPrint's Cancelobject plugin and RepRapFirmware read.
 */
import type { PlanObject } from '../plan/types.js';
import type { Settings } from '../settings/schema.js';
import { mm } from './format.js';

export type LabelMode = 'off' | 'comments' | 'firmware';

/** The label mode `labelObjects` asks for with this flavour (`auto`: firmware for Klipper, comments otherwise). */
export function labelMode(s: Pick<Settings, 'labelObjects' | 'gcodeFlavor'>): LabelMode {
  if (s.labelObjects !== 'auto') return s.labelObjects;
  return s.gcodeFlavor === 'klipper' ? 'firmware' : 'comments';
}

/** Klipper-safe names, unique ignoring case. */
export function klipperNames(objects: readonly PlanObject[]): string[] {
  const used = new Set<string>();
  return objects.map((o) => {
    const base = o.name.replace(/[^A-Za-z0-9_.-]+/g, '_').replace(/^_+|_+$/g, '') || 'object';
    let name = base;
    for (let k = 2; used.has(name.toUpperCase()); k++) name = `${base}_${k}`;
    used.add(name.toUpperCase());
    return name;
  });
}

/** Names for comments and M486 A"…": one line each, no quotes. */
function commentNames(objects: readonly PlanObject[]): string[] {
  return objects.map((o) => o.name.replace(/[\r\n"]+/g, ' ').trim() || 'object');
}

/** The label lines of one print: what goes before the start G-code, and around each object's moves. */
export interface ObjectLabels {
  /** Lines before the start G-code (definitions, counts). */
  readonly preamble: readonly string[];
  start(index: number): readonly string[];
  end(index: number): readonly string[];
}

const point = (x: number, y: number) => `${mm(x)},${mm(y)}`;

/** The labels for `objects` in this mode and flavour, or null when nothing is to be written. */
export function objectLabels(
  objects: readonly PlanObject[],
  mode: LabelMode,
  flavor: Settings['gcodeFlavor'],
): ObjectLabels | null {
  if (mode === 'off' || objects.length === 0) return null;
  const names = commentNames(objects);
  const comment = (i: number) => [`; printing object ${names[i]}`];
  const stopComment = (i: number) => [`; stop printing object ${names[i]}`];
  if (mode === 'comments') return { preamble: [], start: comment, end: stopComment };
  if (flavor === 'klipper') {
    const ids = klipperNames(objects);
    const preamble = objects.map((o, i) => {
      const polygon = o.polygon.map(([x, y]) => `[${point(x, y)}]`).join(',');
      return `EXCLUDE_OBJECT_DEFINE NAME=${ids[i]} CENTER=${point(o.center[0], o.center[1])} POLYGON=[${polygon}]`;
    });
    return {
      preamble,
      start: (i) => [`EXCLUDE_OBJECT_START NAME=${ids[i]}`],
      end: (i) => [`EXCLUDE_OBJECT_END NAME=${ids[i]}`],
    };
  }
  const named = flavor === 'reprap';
  return {
    preamble: [`M486 T${objects.length}`],
    start: (i) => [...comment(i), named ? `M486 S${i} A"${names[i]}"` : `M486 S${i}`],
    end: (i) => [...stopComment(i), 'M486 S-1'],
  };
}
