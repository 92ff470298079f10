/**
 * Where tree-support tips go under an overhang: a hexagonal lattice `spacing` apart, fixed to the origin (so
 * the lattices of neighbouring layers line up rather than crowd), and points along the area's edges, so that
 * the rim of a roof and overhangs too thin for a lattice point are held too.
 */
import { offset } from '../geometry/clip.js';
import { hypot, type ExPolygon, type Pt } from '../geometry/types.js';
import { AreaIndex } from '../geometry/area-index.js';
import { PointGrid } from '../geometry/point-grid.js';

/**
 * With no roof (the tips hold the part themselves), edge points closer than this share of the spacing to a
 * point already chosen are left out, and so are tips that close to a branch already there. Under a roof the
 * gap is the roof's own reach beyond the branches (ROOF_REACH_SHARE in tree.ts): a tip nearer a branch than
 * the roof reaches holds nothing the roof does not. Under the narrow bridges of BridgeTest, edge points 0.6 of
 * the spacing apart made two rows of tips where one holds them (the same share of every shared model's overhang
 * held; tree support 4–12 % less material on them).
 */
export const TIP_MIN_GAP_SHARE = 0.6;

/**
 * Tip candidates in `area`, in a fixed order (lattice rows bottom-up, then edges ring by ring): edge points
 * nearer than `gapUm` to one already chosen are left out.
 */
export function tipCandidates(area: readonly ExPolygon[], spacingUm: number, edgeInsetUm: number, gapUm: number): Pt[] {
  if (area.length === 0) return [];
  const index = new AreaIndex(area);
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (const a of area) {
    for (const p of a.outer) {
      if (p.x < minX) minX = p.x;
      if (p.x > maxX) maxX = p.x;
      if (p.y < minY) minY = p.y;
      if (p.y > maxY) maxY = p.y;
    }
  }
  const out: Pt[] = [];
  const gap = gapUm;
  const chosen = new PointGrid(spacingUm);
  const rowStep = (spacingUm * Math.sqrt(3)) / 2;
  for (let k = Math.ceil(minY / rowStep); k * rowStep <= maxY; k++) {
    const y = Math.round(k * rowStep);
    const shift = (k & 1) === 0 ? 0 : spacingUm / 2;
    for (let i = Math.ceil((minX - shift) / spacingUm); i * spacingUm + shift <= maxX; i++) {
      const x = Math.round(i * spacingUm + shift);
      if (!index.contains(x, y)) continue;
      out.push({ x, y });
      chosen.add(x, y);
    }
  }
  const inset = edgeInsetUm > 0 ? offset(area, -edgeInsetUm) : [];
  const rims = inset.length ? inset : area;
  for (const a of rims) {
    for (const ring of [a.outer, ...a.holes]) {
      for (const p of alongRing(ring, spacingUm)) {
        if (chosen.nearest(p.x, p.y, gap) >= 0) continue;
        out.push(p);
        chosen.add(p.x, p.y);
      }
    }
  }
  return out;
}

/** Points along a closed ring, `step` apart, from its first vertex. */
export function alongRing(ring: readonly Pt[], step: number): Pt[] {
  const out: Pt[] = [];
  let carry = 0;
  for (let i = 0; i < ring.length; i++) {
    const a = ring[i],
      b = ring[(i + 1) % ring.length];
    const len = hypot(b.x - a.x, b.y - a.y);
    let t = carry;
    while (t < len) {
      out.push({ x: Math.round(a.x + ((b.x - a.x) * t) / len), y: Math.round(a.y + ((b.y - a.y) * t) / len) });
      t += step;
    }
    carry = t - len;
  }
  return out;
}
