/**
 * Density ↔ spacing. Density means the extruded footprint over the region area (crossings counted once).
 * The seed's rules (spacing = nozzle / density × k) ignore the line width and the overlap at crossings, so
 * they miss the target (grid at 40 % with width = nozzle gives 36 %). Here each pattern states its coverage
 * exactly and the spacing is solved for:
 *   F families of parallel lines, spacing s, width w:  coverage = F·x − c·x², x = w/s,
 * where c·w² is the area lost per crossing-cell: every pair of families loses w² per unit s² whatever its
 * angle (crossings per area sin φ/s², overlap w²/sin φ each), so c = 1 (grid), 3 for three families in
 * general position (cubic), and 2.25 for three families through common points (triangles, where each
 * crossing is a regular-hexagon triple overlap: 3·(2/√3)w² − (√3/2)w² per point, √3/(2s²) points per area).
 */

/** Solve F·x − c·x² = d for x = w/s (smallest root), clamped to solid. */
export function familyFraction(density: number, families: number, c: number): number {
  const d = Math.min(Math.max(density, 0), 1);
  if (c === 0) return Math.min(1, d / families);
  const disc = families * families - 4 * c * d;
  const x = disc <= 0 ? families / (2 * c) : (families - Math.sqrt(disc)) / (2 * c);
  return Math.min(1, x);
}

/** Line spacing (µm) of each of `families` parallel families so their union covers `density` of the area. */
export function familySpacing(density: number, lineWidth: number, families: number, c: number): number {
  const x = familyFraction(density, families, c);
  return x > 0 ? lineWidth / x : Infinity;
}

/** Coverage of F families at spacing s (inverse of familySpacing, for reports and tests). */
export function familyCoverage(spacing: number, lineWidth: number, families: number, c: number): number {
  const x = lineWidth / spacing;
  return families * x - c * x * x;
}

/** Solve a decreasing function f(s) = target for s in [lo, hi] by bisection (40 steps: ~1e-12 relative). */
export function solveDecreasing(f: (s: number) => number, target: number, lo: number, hi: number): number {
  let a = lo, b = hi;
  for (let i = 0; i < 60; i++) {
    const m = Math.sqrt(a * b);
    if (f(m) > target) a = m;
    else b = m;
  }
  return Math.sqrt(a * b);
}

/** Fraction of F families' length × width lost at crossings: c·x² of F·x. */
export function familyOverlap(spacing: number, lineWidth: number, families: number, c: number): number {
  const x = lineWidth / spacing;
  return families > 0 && isFinite(spacing) ? (c * x) / families : 0;
}
