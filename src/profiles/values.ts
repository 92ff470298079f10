/**
 * Reading other slicers' values: numbers, percentages, booleans, lists (the first entry is the first
 * extruder's), and escaped multi-line text. Every reader returns undefined for what it cannot read.
 */

/** The first entry of a comma-separated list (or the value itself); `nil` (Orca's "not set") is nothing. */
export function first(value: string | undefined): string | undefined {
  if (value === undefined) return undefined;
  const v = value
    .split(',')[0]!
    .trim()
    .replace(/^"(.*)"$/, '$1');
  return v === '' || v === 'nil' ? undefined : v;
}

/** A plain number (the first of a list). */
export function num(value: string | undefined): number | undefined {
  const v = first(value);
  if (v === undefined || v.endsWith('%')) return undefined;
  const n = Number(v);
  return Number.isFinite(n) ? n : undefined;
}

/** A number or a percentage: `{ value, percent }`. */
export function numOrPercent(value: string | undefined): { value: number; percent: boolean } | undefined {
  const v = first(value);
  if (v === undefined) return undefined;
  const percent = v.endsWith('%');
  const n = Number(percent ? v.slice(0, -1) : v);
  return Number.isFinite(n) ? { value: n, percent } : undefined;
}

/** A percentage written as `20%` or `20`, returned as 20. Old Slic3r densities written as fractions (0.2) too. */
export function percent(value: string | undefined, fractions = false): number | undefined {
  const p = numOrPercent(value);
  if (!p) return undefined;
  return !p.percent && fractions && p.value > 0 && p.value <= 1 ? p.value * 100 : p.value;
}

/**
 * Tree-support tip spacing (mm, to the hundredth) for a branch density (%): a support line's width over the
 * density, as CuraEngine (and PrusaSlicer's organic support after it) lays its tips. Undefined for none.
 */
export function tipSpacingOfDensity(lineWidthMm: number, densityPercent: number): number | undefined {
  return densityPercent > 0 ? Math.round(((100 * lineWidthMm) / densityPercent) * 100) / 100 : undefined;
}

/** A length in mm as a percentage of the nozzle diameter, to the hundredth (0.1 mm of a 0.4 mm nozzle: 25). */
export function percentOfNozzle(mm: number, nozzleMm: number): number {
  return Math.round(((100 * mm) / nozzleMm) * 100) / 100;
}

/** `1`/`0`, `true`/`false`. */
export function bool(value: string | undefined): boolean | undefined {
  const v = first(value)?.toLowerCase();
  if (v === '1' || v === 'true' || v === 'yes' || v === 'on') return true;
  if (v === '0' || v === 'false' || v === 'no' || v === 'off') return false;
  return undefined;
}

/**
 * Multi-line text written on one line with C-style escapes (PrusaSlicer), possibly quoted: `\n` is a
 * line end, `\r` a carriage return, `\t` a tab, a backslash before any other character stands for that
 * character (`\"` is `"`, `\\` a backslash), as PrusaSlicer unescapes them.
 */
export function text(value: string | undefined): string | undefined {
  if (value === undefined) return undefined;
  let v = value;
  if (v.length >= 2 && v.startsWith('"') && v.endsWith('"')) v = v.slice(1, -1);
  return v
    .replace(/\\r\\n/g, '\n')
    .replace(/\\(.)/g, (_w, c: string) => (c === 'n' ? '\n' : c === 'r' ? '\r' : c === 't' ? '\t' : c));
}

/** Points `0x0,250x0,250x210,0x210` (a bed outline) → [x, y] pairs. */
export function points(value: string | undefined): Array<[number, number]> | undefined {
  if (value === undefined) return undefined;
  const out: Array<[number, number]> = [];
  for (const item of value.split(',')) {
    const m = /^\s*"?(-?[\d.]+)\s*x\s*(-?[\d.]+)"?\s*$/.exec(item);
    if (!m) return undefined;
    out.push([Number(m[1]), Number(m[2])]);
  }
  return out.length >= 3 ? out : undefined;
}
