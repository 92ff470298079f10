/**
 * Density ↔ spacing. Density means extruded material over the region: per layer, the lines' length × width
 * over the region's area, where two lines crossing both count (the material is there twice). That is the
 * seed's rule (grid: spacing = 2 · width / density, "each direction provides 10 %"), the one CuraEngine and
 * PrusaSlicer turn the setting into line distances with, and what the G-code analyser measures from E
 * (tools/analysis/infill-density.ts). The footprint is smaller wherever lines cross: grid at 20 % covers
 * 2x − x² = 19 % of the area (x = w/s), triangles at 20 % about 18.7 %.
 * F families of parallel lines at spacing s, width w: density = F · w / s.
 */

/** Line spacing (µm) of each of `families` parallel families that extrude `density` of the region (never below a width). */
export function familySpacing(density: number, lineWidth: number, families: number): number {
  const d = Math.min(Math.max(density, 0), 1);
  return d > 0 ? lineWidth * Math.max(1, families / d) : Infinity;
}

/** Density of F families at spacing s (inverse of familySpacing, for reports and tests). */
export function familyDensity(spacing: number, lineWidth: number, families: number): number {
  return (families * lineWidth) / spacing;
}

/** Solve a decreasing function f(s) = target for s in [lo, hi] by bisection (60 steps: ~1e-12 relative). */
export function solveDecreasing(f: (s: number) => number, target: number, lo: number, hi: number): number {
  let a = lo,
    b = hi;
  for (let i = 0; i < 60; i++) {
    const m = Math.sqrt(a * b);
    if (f(m) > target) a = m;
    else b = m;
  }
  return Math.sqrt(a * b);
}
