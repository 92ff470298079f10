/**
 * Islands straight from raw offset rings when no clean-up union is needed: the rings are simple
 * (no edge meets another except neighbours at their shared point), keep their winding, and keep
 * the nesting of the islands they came from (each hole inside its own outer ring, no ring inside
 * any other). Then the positive-fill union would return the same rings, so it is skipped.
 */
import type { ExPolygon, Polygon, Pt } from './types.js';
import { pointInRing, ringBounds, segmentsMeet, twiceArea } from './contain.js';

/** Above this many rings the pairwise nesting check is left to the union. */
export const MAX_RINGS = 12;

/**
 * The islands the raw rings make, or null when the union has work to do (or this cannot tell).
 * @param raw one ring per ring of `areas`, in flatten() order (outer, then its holes, per island)
 * @param areas the islands that were offset
 * @param work the working arrays (a fresh set when not given)
 */
export function islandsIfSimple(
  raw: readonly Pt[][],
  areas: readonly ExPolygon[],
  work: EdgeWork = new EdgeWork(),
): ExPolygon[] | null {
  if (raw.length > MAX_RINGS) return null;
  const rings: Polygon[] = [];
  for (const r of raw) {
    const c = cleanRing(r);
    if (!c) return null;
    rings.push(c);
  }
  // winding kept: outer rings counter-clockwise, holes clockwise
  let k = 0;
  for (const a of areas) {
    if (!(twiceArea(rings[k++]) > 0)) return null;
    for (let h = 0; h < a.holes.length; h++) if (!(twiceArea(rings[k++]) < 0)) return null;
  }
  if (!edgesSimple(rings, work)) return null;
  // nesting: with no contacts, ring j is inside ring i iff its first point is; the only nesting
  // allowed is each island's holes inside its own outer ring
  const ownerOf = new Int32Array(rings.length).fill(-1);
  let k2 = 0;
  for (const a of areas) {
    for (let h = 1; h <= a.holes.length; h++) ownerOf[k2 + h] = k2;
    k2 += 1 + a.holes.length;
  }
  for (let i = 0; i < rings.length; i++) {
    for (let j = 0; j < rings.length; j++) {
      if (i !== j && pointInRing(rings[j][0], rings[i]) !== (ownerOf[j] === i)) return null;
    }
  }
  const out: ExPolygon[] = [];
  k = 0;
  for (const a of areas) {
    out.push({ outer: rings[k], holes: rings.slice(k + 1, k + 1 + a.holes.length) });
    k += 1 + a.holes.length;
  }
  return out;
}

/**
 * The ring without repeated points and without points exactly on the line through their
 * neighbours; null when it turns back on itself (a spike) or has fewer than three points left.
 */
function cleanRing(r: readonly Pt[]): Polygon | null {
  const pts: Pt[] = [];
  for (const p of r) {
    const last = pts[pts.length - 1];
    if (!last || last.x !== p.x || last.y !== p.y) pts.push(p);
  }
  while (pts.length > 1 && pts[0].x === pts[pts.length - 1].x && pts[0].y === pts[pts.length - 1].y) pts.pop();
  // drop collinear points until none is left (a removal can make its neighbours collinear)
  let n = pts.length;
  let changed = true;
  let ring = pts;
  while (changed && n >= 3) {
    changed = false;
    const next: Pt[] = [];
    for (let i = 0; i < n; i++) {
      const a = ring[(i + n - 1) % n],
        b = ring[i],
        c = ring[(i + 1) % n];
      const cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
      if (cross === 0) {
        // straight on: drop; turning back: a spike the union would cut off
        if ((b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0) return null;
        changed = true;
        continue;
      }
      next.push(b);
    }
    ring = next;
    n = ring.length;
  }
  return n >= 3 ? ring : null;
}

/** Edge sort keys pack the lower y with the edge index: at most this many edges. */
const KEY_SPAN = 65536;

/**
 * The working arrays of the simplicity test, per edge its ends, ring and index in the ring, and its sort key,
 * for as many edges as the most it has met (grown as needed): whoever makes one owns it and hands it to each
 * call, which overwrites what it reads (the clip operations keep one; see clip.ts).
 */
export class EdgeWork {
  ax = new Float64Array(0);
  ay = new Float64Array(0);
  bx = new Float64Array(0);
  by = new Float64Array(0);
  maxY = new Float64Array(0);
  key = new Float64Array(0);
  ring = new Int32Array(0);
  at = new Int32Array(0);
  ringLen = new Int32Array(0);
  open = new Int32Array(0);

  /** Room for n edges. */
  reserve(n: number): void {
    if (this.ax.length >= n) return;
    const m = Math.max(n, 2 * this.ax.length, 256);
    this.ax = new Float64Array(m);
    this.ay = new Float64Array(m);
    this.bx = new Float64Array(m);
    this.by = new Float64Array(m);
    this.maxY = new Float64Array(m);
    this.key = new Float64Array(m);
    this.ring = new Int32Array(m);
    this.at = new Int32Array(m);
    this.ringLen = new Int32Array(m);
    this.open = new Int32Array(m);
  }
}

/**
 * Whether no two edges of the rings meet, other than consecutive edges of one ring at their shared
 * point. A sweep over y: edges sorted by their lower end, each tested against the edges still open.
 */
function edgesSimple(rings: readonly Polygon[], work: EdgeWork): boolean {
  let total = 0;
  for (const r of rings) total += r.length;
  if (total >= KEY_SPAN) return false;
  work.reserve(total);
  const { ax, ay, bx, by, maxY, ring, at, ringLen, open } = work;
  const key = work.key.subarray(0, total);
  let e = 0;
  for (let ri = 0; ri < rings.length; ri++) {
    const r = rings[ri];
    for (let i = 0; i < r.length; i++) {
      const p = r[i],
        q = r[i + 1 === r.length ? 0 : i + 1];
      ax[e] = p.x;
      ay[e] = p.y;
      bx[e] = q.x;
      by[e] = q.y;
      ring[e] = ri;
      at[e] = i;
      ringLen[e] = r.length;
      maxY[e] = p.y < q.y ? q.y : p.y;
      key[e] = (p.y < q.y ? p.y : q.y) * KEY_SPAN + e;
      e++;
    }
  }
  key.sort();
  let openCount = 0;
  for (let o = 0; o < total; o++) {
    const i = ((key[o] % KEY_SPAN) + KEY_SPAN) % KEY_SPAN;
    const lowY = ay[i] < by[i] ? ay[i] : by[i];
    let w = 0;
    for (let t = 0; t < openCount; t++) {
      const j = open[t];
      if (maxY[j] < lowY) continue; // ended below this edge
      open[w++] = j;
      if (ring[i] === ring[j]) {
        const d = at[i] > at[j] ? at[i] - at[j] : at[j] - at[i];
        if (d === 1 || d === ringLen[i] - 1) continue; // neighbours: they share one point and are not collinear
      }
      if (segmentsMeet(ax[i], ay[i], bx[i], by[i], ax[j], ay[j], bx[j], by[j])) return false;
    }
    open[w++] = i;
    openCount = w;
  }
  return true;
}

/**
 * The islands of a raw offset of many islands, without one union over all of them: an island whose raw
 * rings' bounds meet no other island's is made on its own (straight from its rings when they are simple,
 * else by the union of its rings alone); the rest are united together. Islands on their own come first,
 * in their order, then the union's.
 * @param raw one ring per ring of `areas`, in flatten() order
 * @param unite the clean-up union of some raw rings
 * @param work the working arrays of the simplicity test (a fresh set when not given)
 */
export function islandsApart(
  raw: readonly Pt[][],
  areas: readonly ExPolygon[],
  unite: (rings: Pt[][]) => ExPolygon[],
  work: EdgeWork = new EdgeWork(),
): ExPolygon[] {
  const n = areas.length;
  const first = new Int32Array(n + 1);
  for (let i = 0; i < n; i++) first[i + 1] = first[i] + 1 + areas[i].holes.length;
  // an island's bounds are its raw outer ring's
  const box = Array.from({ length: n }, (_, i) => ringBounds(raw[first[i]]));
  // a sweep in x: every pair of islands whose bounds meet loses its "apart"
  const order = Array.from({ length: n }, (_, i) => i).sort((a, b) => box[a].minX - box[b].minX || a - b);
  const apart = new Uint8Array(n).fill(1);
  const active: number[] = [];
  for (const i of order) {
    let w = 0;
    for (const k of active) {
      if (box[k].maxX < box[i].minX) continue;
      active[w++] = k;
      if (box[k].minY <= box[i].maxY && box[k].maxY >= box[i].minY) apart[i] = apart[k] = 0;
    }
    active.length = w;
    active.push(i);
  }
  const out: ExPolygon[] = [];
  const rest: Pt[][] = [];
  for (let i = 0; i < n; i++) {
    const rings = raw.slice(first[i], first[i + 1]);
    if (!apart[i]) {
      for (const r of rings) rest.push(r);
      continue;
    }
    const simple = islandsIfSimple(rings, [areas[i]], work);
    if (simple) out.push(...simple);
    else out.push(...unite(rings));
  }
  if (rest.length) out.push(...unite(rest));
  return out;
}
