/**
 * Compact, locale-free number formatting for G-code words. Values are turned into integers at a fixed
 * scale first (µm for positions, 1e-5 mm for E), so the text is exact and deterministic: `10.5`, never
 * `10.500`, never `1e-7`, never `-0`.
 */

/** Positions are written in whole micrometres: 3 decimals of a millimetre. */
export const POSITION_SCALE = 1000;
/** Extrusion is written in units of 1e-5 mm of filament: 5 decimals. */
export const E_SCALE = 100000;

/**
 * Write the integer `units` (a value times `scale`, scale a power of ten) as a decimal with no
 * trailing zeros: `fixedDecimal(10500, 1000)` is `"10.5"`.
 */
export function fixedDecimal(units: number, scale: number): string {
  if (units === 0) return '0';
  const negative = units < 0;
  const magnitude = negative ? -units : units;
  const whole = Math.floor(magnitude / scale);
  let fraction = magnitude - whole * scale;
  const head = negative ? '-' + whole : '' + whole;
  if (fraction === 0) return head;
  let width = 0;
  for (let s = scale; s > 1; s /= 10) width++;
  while (fraction % 10 === 0) {
    fraction /= 10;
    width--;
  }
  let digits = '' + fraction;
  while (digits.length < width) digits = '0' + digits;
  return head + '.' + digits;
}

/** Millimetres rounded to the micrometre, e.g. a Z height or a bounds value: `0.2`, `12.345`. */
export function mm(value: number): string {
  return fixedDecimal(Math.round(value * POSITION_SCALE), POSITION_SCALE);
}

/** Any finite number with up to `decimals` (0..9) decimals and no trailing zeros. */
export function compact(value: number, decimals = 5): string {
  const scale = 10 ** decimals;
  return fixedDecimal(Math.round(value * scale), scale);
}

/** A feed rate word value: mm/s turned into whole mm/min. */
export function feedrate(speedMmPerS: number): number {
  return Math.round(speedMmPerS * 60);
}

/** Seconds as `1h 2m 3s` (or `2m 3s`, `3s`), for human-readable comments. */
export function humanDuration(seconds: number): string {
  const total = Math.max(0, Math.round(seconds));
  const h = Math.floor(total / 3600);
  const m = Math.floor((total % 3600) / 60);
  const s = total % 60;
  if (h > 0) return `${h}h ${m}m ${s}s`;
  if (m > 0) return `${m}m ${s}s`;
  return `${s}s`;
}
