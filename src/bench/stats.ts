/**
 * Pure helpers for the benchmark report: median of repeated runs and fixed-width text tables.
 */

/** Median of a non-empty list (mean of the two middle values for an even count); null for an empty list. */
export function median(values: readonly number[]): number | null {
  if (values.length === 0) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 === 1 ? sorted[mid]! : (sorted[mid - 1]! + sorted[mid]!) / 2;
}

export type Align = 'left' | 'right';

/**
 * A plain-text table: a header row, a dashed rule, then the rows; every column as wide as its widest cell.
 * `align` gives each column's alignment (default: first column left, the others right).
 */
export function formatTable(header: readonly string[], rows: readonly (readonly string[])[], align?: readonly Align[]): string {
  const columns = header.length;
  const widths = header.map((h, c) => Math.max(h.length, ...rows.map((r) => (r[c] ?? '').length)));
  const alignOf = (c: number): Align => align?.[c] ?? (c === 0 ? 'left' : 'right');
  const line = (cells: readonly string[]) =>
    Array.from({ length: columns }, (_, c) => {
      const cell = cells[c] ?? '';
      return alignOf(c) === 'left' ? cell.padEnd(widths[c]!) : cell.padStart(widths[c]!);
    })
      .join('  ')
      .trimEnd();
  const rule = widths.map((w) => '-'.repeat(w)).join('  ');
  return [line(header), rule, ...rows.map(line)].join('\n');
}

/** Seconds with two decimals ("2.27"), or a placeholder for a missing value. */
export function formatSeconds(seconds: number | null, missing = '-'): string {
  return seconds === null ? missing : seconds.toFixed(2);
}

/** MiB rounded to a whole number. */
export function formatMiB(mib: number | null, missing = '-'): string {
  return mib === null ? missing : mib.toFixed(0);
}

/** A ratio a/b with two decimals and an "x" ("0.85x"); "-" when either side is missing or b is zero. */
export function formatRatio(a: number | null, b: number | null): string {
  if (a === null || b === null || b <= 0) return '-';
  return `${(a / b).toFixed(2)}x`;
}

/** Thousands separated with commas: 225154 → "225,154". */
export function formatCount(n: number | null): string {
  if (n === null) return '-';
  return String(Math.round(n)).replace(/\B(?=(\d{3})+(?!\d))/g, ',');
}
