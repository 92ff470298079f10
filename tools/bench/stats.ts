/**
 * Pure helpers for the benchmark report: medians, per-pair ratios, number formats and Markdown tables.
 */

/** Median of a non-empty list (mean of the two middle values for an even count); null for an empty list. */
export function median(values: readonly number[]): number | null {
  if (values.length === 0) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 === 1 ? sorted[mid]! : (sorted[mid - 1]! + sorted[mid]!) / 2;
}

/**
 * Median of the ratios a[i] / b[i] over the pairs both lists have (runs of one interleaved round form a pair,
 * so a change of machine speed between rounds cancels out in each ratio). Pairs with a missing value or a
 * divisor ≤ 0 are left out; null when no pair is left.
 */
export function medianOfRatios(a: readonly (number | null)[], b: readonly (number | null)[]): number | null {
  const ratios: number[] = [];
  for (let i = 0; i < Math.min(a.length, b.length); i++) {
    const x = a[i];
    const y = b[i];
    if (x === null || x === undefined || y === null || y === undefined || !(y > 0)) continue;
    ratios.push(x / y);
  }
  return median(ratios);
}

export type Align = 'left' | 'right';

/**
 * A Markdown table (GitHub style): header, alignment row, rows; cells padded so the source reads as a table
 * too. `align` gives each column's alignment (default: first column left, the others right). Pipes in cells
 * are escaped.
 */
export function markdownTable(
  header: readonly string[],
  rows: readonly (readonly string[])[],
  align?: readonly Align[],
): string {
  const esc = (s: string) => s.replace(/\|/g, '\\|');
  const head = header.map(esc);
  const body = rows.map((r) => head.map((_, c) => esc(r[c] ?? '')));
  const alignOf = (c: number): Align => align?.[c] ?? (c === 0 ? 'left' : 'right');
  const widths = head.map((h, c) => Math.max(3, [...h].length, ...body.map((r) => [...r[c]!].length)));
  const pad = (cell: string, c: number) => {
    const fill = ' '.repeat(widths[c]! - [...cell].length);
    return alignOf(c) === 'left' ? cell + fill : fill + cell;
  };
  const line = (cells: readonly string[]) => `| ${cells.map(pad).join(' | ')} |`;
  const rule = `|${widths.map((w, c) => (alignOf(c) === 'left' ? `:${'-'.repeat(w + 1)}` : `${'-'.repeat(w + 1)}:`)).join('|')}|`;
  return [line(head), rule, ...body.map(line)].join('\n');
}

/** Seconds: two decimals below 10 s ("1.67 s"), one above ("12.3 s"); a placeholder for a missing value. */
export function formatSeconds(seconds: number | null, missing = '–'): string {
  if (seconds === null) return missing;
  return `${seconds < 10 ? seconds.toFixed(2) : seconds.toFixed(1)} s`;
}

/** MiB rounded to a whole number ("159 MiB"). */
export function formatMiB(mib: number | null, missing = '–'): string {
  return mib === null ? missing : `${mib.toFixed(0)} MiB`;
}

/** A ratio with two decimals and a times sign ("0.85×"); a placeholder when missing. */
export function formatRatio(ratio: number | null, missing = '–'): string {
  return ratio === null ? missing : `${ratio.toFixed(2)}×`;
}

/** Triangle counts as the issue writes them: 136, 5,856, 69 k, 225 k, 1.2 M. */
export function formatTriangles(n: number | null): string {
  if (n === null) return '?';
  if (n < 10_000) return String(Math.round(n)).replace(/\B(?=(\d{3})+(?!\d))/g, ',');
  if (n < 1_000_000) return `${Math.round(n / 1000)} k`;
  return `${(n / 1_000_000).toFixed(2)} M`;
}
