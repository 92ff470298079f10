/**
 * The paths of a layer's support: the body filled with straight lines (zigzag, lines or grid) in one direction
 * on every layer so they stack into thin walls, the roof and floor with dense lines that turn every layer, and
 * optional walls round the body. One group per connected support area, so travel within it combs
 * and travel between areas retracts, as between islands.
 */
import { boundsOf, flatten, offset, pointInArea, union } from '../geometry/clip.js';
import { UM_PER_MM, type Bounds, type ExPolygon, type Polyline, type Pt } from '../geometry/types.js';
import { solidFill } from '../infill/index.js';
import { sweepConvexRing } from '../infill/sweep.js';
import type { SupportAreas } from '../regions/types.js';
import { shrunkRegularPolygon, type RegularPolygon } from '../geometry/regular-polygon.js';
import type { Config } from '../settings/resolve.js';
import type { LayerZ } from '../slice/types.js';
import { entryStyle } from './roles.js';
import type { PathEntry, PathGroup, PathRole } from './types.js';

/**
 * The islands shrunk by d µm, in one offset (on the WebAssembly engine one call for a layer's dozens of tree
 * islands beat one call each); islands whose bounds are no wider than 2·d, which shrinking removes, are left
 * out at once.
 */
function shrink(areas: readonly ExPolygon[], d: number): ExPolygon[] {
  const wide: ExPolygon[] = [];
  for (const a of areas) {
    const b = boundsOf([a]);
    if (b.maxX - b.minX <= 2 * d || b.maxY - b.minY <= 2 * d) continue;
    wide.push(a);
  }
  return offset(wide, -d);
}

/**
 * Whether any line of the family (at `angle`, `spacing` apart, phase at `origin`) can cross the island
 * shrunk by d: the shrunk island lies within its extent across the lines less d on each side. Sparse
 * support lines miss most thin tree branches: those need no shrink and no fill at all.
 */
function mayHoldLines(a: ExPolygon, d: number, angle: number, spacingUm: number, origin: Pt): boolean {
  const t = (angle * Math.PI) / 180;
  const c = Math.cos(t),
    s = Math.sin(t);
  let lo = Infinity,
    hi = -Infinity;
  for (const p of a.outer) {
    const v = -p.x * s + p.y * c;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  // a micrometre of slack for rounding: the test only ever keeps too much
  return familyCrosses(lo + (d - 1), hi - (d - 1), c, s, spacingUm, origin);
}

/** mayHoldLines for a regular polygon, from its circumcircle (its extent across the lines is at most the diameter). */
function circleMayHoldLines(p: RegularPolygon, d: number, angle: number, spacingUm: number, origin: Pt): boolean {
  const t = (angle * Math.PI) / 180;
  const c = Math.cos(t),
    s = Math.sin(t);
  const v = -p.x * s + p.y * c;
  return familyCrosses(v - p.r + d - 1, v + p.r - d + 1, c, s, spacingUm, origin);
}

/** Whether a line of the family (direction cos c, sin s; `spacing` apart, phase at `origin`) lies within [lo, hi] across the lines. */
function familyCrosses(lo: number, hi: number, c: number, s: number, spacingUm: number, origin: Pt): boolean {
  if (lo > hi) return false;
  const v0 = -origin.x * s + origin.y * c;
  return Math.floor((hi - v0) / spacingUm) >= Math.ceil((lo - v0) / spacingUm);
}

/** Where a line goes: the area it lies in when that is known (a lone branch's chord), else null. */
type Emit = (line: Polyline, area: ExPolygon | null) => void;

/** Lines of one family `spacing` apart over `area` (shrunk so the beads stay inside it). */
function fill(
  area: readonly ExPolygon[],
  insetUm: number,
  angle: number,
  spacingUm: number,
  origin: Pt,
  connect: boolean,
  emit: Emit,
  circles?: ReadonlyMap<ExPolygon, RegularPolygon>,
): void {
  const region: ExPolygon[] = [];
  const others: ExPolygon[] = [];
  for (const a of area) {
    const c = circles?.get(a);
    if (!c) {
      if (mayHoldLines(a, insetUm, angle, spacingUm, origin)) others.push(a);
    } else if (circleMayHoldLines(c, insetUm, angle, spacingUm, origin)) {
      const ring = shrunkRegularPolygon(c, insetUm);
      if (!ring) continue;
      // a branch crossed by one line needs no linking: its chord is the whole fill
      const chords = sweepConvexRing(ring, { angle, spacingUm, offsetUm: 0 }, origin);
      if (chords.length <= 1) for (const line of chords) emit(line, a);
      else region.push({ outer: ring, holes: [] });
    }
  }
  if (others.length) region.push(...shrink(others, insetUm));
  // the planner orders each support area's lines itself
  if (region.length)
    for (const line of solidFill(region, angle, spacingUm, origin, { connect, order: false })) emit(line, null);
}

function bodyLines(
  body: readonly ExPolygon[],
  cfg: Config,
  insetUm: number,
  w: number,
  origin: Pt,
  circles: ReadonlyMap<ExPolygon, RegularPolygon>,
  emit: Emit,
): void {
  const d = cfg.supportDensity / 100;
  switch (cfg.supportPattern) {
    case 'grid': {
      const s = (2 * w) / d;
      fill(body, insetUm, cfg.supportAngle, s, origin, true, emit, circles);
      fill(body, insetUm, cfg.supportAngle + 90, s, origin, true, emit, circles);
      return;
    }
    case 'lines':
      return fill(body, insetUm, cfg.supportAngle, w / d, origin, false, emit, circles);
    case 'zigzag':
      return fill(body, insetUm, cfg.supportAngle, w / d, origin, true, emit, circles);
  }
}

interface Component {
  area: ExPolygon;
  box: Bounds;
  /** Entries by role and closedness, in the order first met (a few at most: a list, not a map per area). */
  entries: { role: PathRole; closed: boolean; paths: Pt[][] }[];
}

function add(c: Component, role: PathRole, closed: boolean, path: Pt[]): void {
  const entries = c.entries;
  for (let i = 0; i < entries.length; i++) {
    const e = entries[i];
    if (e.role === role && e.closed === closed) {
      e.paths.push(path);
      return;
    }
  }
  entries.push({ role, closed, paths: [path] });
}

/** The component holding `p` (the nearest by bounds when none holds it exactly: a point on an edge). */
function owner(components: readonly Component[], p: Pt): Component {
  if (components.length === 1) return components[0];
  let best = components[0];
  let bestD = Infinity;
  for (const c of components) {
    const b = c.box;
    const dx = Math.max(b.minX - p.x, 0, p.x - b.maxX),
      dy = Math.max(b.minY - p.y, 0, p.y - b.maxY);
    const d = dx * dx + dy * dy;
    if (d === 0 && pointInArea(p, c.area)) return c;
    if (d < bestD) {
      bestD = d;
      best = c;
    }
  }
  return best;
}

/** `count` walls round the body pieces `pieces`, each added to the component that holds it. */
function addWalls(pieces: readonly ExPolygon[], count: number, w: number, plain: readonly Component[]): void {
  let inside = pieces;
  for (let k = 0; k < count && inside.length; k++) {
    const centre = shrink(inside, w / 2);
    for (const ring of flatten(centre)) add(owner(plain, ring[0]), 'support', true, ring);
    // the next wall's outline (the fill is inset from the kinds themselves)
    if (k + 1 < count) inside = shrink(centre, w / 2);
  }
}

/** The support groups of one layer (none when the layer has no support). */
export function supportGroups(s: SupportAreas | null, cfg: Config, layer: LayerZ, origin: Pt): PathGroup[] {
  if (!s || (s.body.length === 0 && s.roof.length === 0 && s.floor.length === 0)) return [];
  const w = Math.round(cfg.supportLineWidthMm * UM_PER_MM);
  // each kind is already a union of disjoint islands: only kinds side by side need joining into components
  const kinds = [s.body, s.roof, s.floor].filter((k) => k.length > 0);
  const all = s.whole ?? (kinds.length === 1 ? kinds[0] : union(kinds.flat()));
  const components: Component[] = all.map((area) => ({ area, box: boundsOf([area]), entries: [] }));
  // lone tree branches are regular polygons: their walls and fill are made straight from the circle
  const circles = new Map<ExPolygon, RegularPolygon>();
  const body = new Set(s.body);
  // the components whose walls come from their body pieces (all but the lone branches that are body whole)
  const plain: Component[] = [];
  for (let i = 0; i < all.length; i++) {
    const c = s.whole && s.circles ? s.circles[i] : null;
    if (c) circles.set(all[i], c);
    if (!c || !body.has(all[i])) plain.push(components[i]);
  }
  // walls round the body only: roof and floor are dense lines of their own, as without walls (a wall round a
  // roof a few lines wide would print it solid)
  for (let i = 0; i < all.length && cfg.supportWallCount > 0; i++) {
    const c = circles.get(all[i]);
    if (!c || !body.has(all[i])) continue;
    for (let k = 0; k < cfg.supportWallCount; k++) {
      const ring = shrunkRegularPolygon(c, w / 2 + k * w);
      if (!ring) break;
      add(components[i], 'support', true, ring);
    }
  }
  // straight columns (a tree's pockets) have the walls normal support has, the rest the support's own
  const columns = new Set(s.columnBody ?? []);
  const walled = s.body.filter((a) => !circles.has(a) && !columns.has(a));
  addWalls(walled, cfg.supportWallCount, w, plain);
  if (s.columnBody?.length) addWalls(s.columnBody, cfg.supportColumnWallCount, w, plain);
  const byArea = new Map<ExPolygon, Component>();
  for (const c of components) byArea.set(c.area, c);
  const to =
    (role: PathRole): Emit =>
    (line, a) =>
      add((a && byArea.get(a)) || owner(components, line[0]), role, false, line);
  // the body's lines start inside its innermost wall, the roof's and floor's half a line in
  const branches = columns.size ? s.body.filter((a) => !columns.has(a)) : s.body;
  bodyLines(branches, cfg, w / 2 + cfg.supportWallCount * w, w, origin, circles, to('support'));
  if (s.columnBody?.length)
    bodyLines(s.columnBody, cfg, w / 2 + cfg.supportColumnWallCount * w, w, origin, circles, to('support'));
  const iface = w / (cfg.supportInterfaceDensity / 100);
  const ifaceAngle = cfg.supportAngle + 90 + (layer.index % 2 === 1 ? 90 : 0);
  for (const [kind, role] of [
    [s.roof, 'support-roof'],
    [s.floor, 'support-floor'],
  ] as const) {
    // a piece no line of the family crosses (a sliver of a sloping overhang's roof) is printed as its outline
    const lined: ExPolygon[] = [],
      slivers: ExPolygon[] = [];
    for (const a of kind) (mayHoldLines(a, w / 2, ifaceAngle, iface, origin) ? lined : slivers).push(a);
    if (slivers.length)
      for (const ring of flatten(shrink(slivers, w / 2))) add(owner(components, ring[0]), role, true, ring);
    fill(lined, w / 2, ifaceAngle, iface, origin, true, to(role));
  }
  const width = w / UM_PER_MM;
  const groups: PathGroup[] = [];
  for (const c of components) {
    if (c.entries.length === 0) continue;
    const entries: PathEntry[] = [];
    for (const e of c.entries)
      entries.push({ role: e.role, closed: e.closed, paths: e.paths, width, style: entryStyle(cfg, e.role) });
    groups.push({ kind: 'support', area: c.area, convex: circles.has(c.area), entries });
  }
  return groups;
}
