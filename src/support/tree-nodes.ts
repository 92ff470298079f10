/**
 * Tree-support branches as nodes, one per branch and layer, and the step that takes every branch of a layer
 * one layer down: nearby branches are paired (closest pairs first) and lean towards each other, the rest
 * towards their nearest neighbour, at most one layer's move; two within two moves of each other merge into one; every
 * branch stays out of its avoidance (or, once it can no longer reach the bed, out of the part grown by its
 * radius, and then goes straight down onto the part); radii grow from the tip to the branch radius, and
 * merged trunks further.
 */
import type { Found } from '../geometry/area-index.js';
import { FixedPointGrid } from '../geometry/point-grid.js';
import { classOf, type Blocked, type Keep, type TreeVolumes } from './tree-volumes.js';
import { hypot } from '../geometry/types.js';

/** Neighbours further apart than this are not drawn together, µm. */
export const ATTRACT_MAX_UM = 10000;
/** Each branch is linked to at most this many nearest neighbours before the spanning tree is taken. */
const NEAR_COUNT = 6;
/** Neighbours are first looked for this close, µm. */
const NEAR_FIRST_UM = 4000;
/** A step of the pass handles at most this many branches (or tips, or cross-sections) before it yields. */
export const ITEMS_PER_STEP = 200;
/** Pairs are numbered below this in their sort keys (distances in nm above it stay exact in a double up to ATTRACT_MAX_UM). */
const PAIR_SLOTS = 2 ** 29;
/** Slack on the one-layer move for rounding, µm. */
export const MOVE_SLACK_UM = 1;

export interface TreeNode {
  /** Centre, µm. */
  x: number;
  y: number;
  /** Radius, µm. */
  r: number;
  /** Radius class the centre is checked against. */
  c: number;
  /** What the centre keeps out of ('bed' while the branch can reach the bed). */
  keep: Keep;
  /** Whether the branch came from a merge (then it thickens by the diameter angle). */
  merged: boolean;
  /** Height above the bed of the highest tip the branch carries, µm. */
  topUm: number;
  /** Stuck above the part: goes straight down until it stands on it. */
  landing: boolean;
  /** Indices of the nodes on the layer above that continue into this one. */
  parents: number[];
  dead: boolean;
}

export interface TreeRules {
  radii: readonly number[];
  tipR: number;
  branchR: number;
  maxR: number;
  /** The widest a branch carrying tips up to `topUm` above the bed needs to be, µm (at least the tip's radius). */
  heightCapR: (topUm: number) => number;
  /** Radius growth per layer of a tip, µm. */
  tipGrowth: number;
  /** How near a tip or branch already there a new tip may be, µm (edge tips apart, and from the branches passing). */
  tipGap: number;
  /** Radius growth per layer of a merged trunk on layer j, µm. */
  trunkGrowth: (j: number) => number;
  /** Sideways move allowed between layer j and j - 1, µm. */
  step: (j: number) => number;
  /** Height of layer j above the bed, µm. */
  zUm: (j: number) => number;
  /** Whether branches may end on the part. */
  everywhere: boolean;
  /** Whether a branch of radius r centred at (x, y) on layer j has the part under it. */
  standsOn: (j: number, x: number, y: number, r: number) => boolean;
}

const dist = (ax: number, ay: number, bx: number, by: number) => hypot(bx - ax, by - ay);

/** The radius a node grows to on its next layer, whole µm (as its centre is). */
function wantRadiusUm(n: TreeNode, rules: TreeRules, j: number): number {
  const cap = rules.heightCapR(n.topUm);
  if (n.r >= cap) return n.r;
  if (n.r < rules.branchR) return Math.round(Math.min(rules.branchR, cap, n.r + rules.tipGrowth));
  return n.merged ? Math.round(Math.min(rules.maxR, cap, n.r + rules.trunkGrowth(j))) : n.r;
}

/** Pairs of nearby nodes of one group (each node with its nearest few within range) as [a, b, distance], shortest first. */
export function nearPairs(
  nodes: readonly TreeNode[],
  ids: readonly number[],
  rangeUm: number,
): [number, number, number][] {
  if (ids.length < 2 || rangeUm <= 0) return [];
  const xs = new Float64Array(ids.length),
    ys = new Float64Array(ids.length);
  for (let k = 0; k < ids.length; k++) {
    xs[k] = nodes[ids[k]].x;
    ys[k] = nodes[ids[k]].y;
  }
  const grid = new FixedPointGrid(xs, ys, Math.min(NEAR_FIRST_UM, Math.max(1000, rangeUm / 4)));
  const seen = new Set<number>();
  const out: [number, number, number][] = [];
  const found: number[] = [];
  // the nearest few of a node, kept sorted by (distance, index) as they are found
  const bestId = new Int32Array(NEAR_COUNT);
  const bestD = new Float64Array(NEAR_COUNT);
  for (let a = 0; a < ids.length; a++) {
    const x = grid.xs[a],
      y = grid.ys[a];
    // the nearest few are usually close: look further only when they are not
    let count = grid.near(x, y, Math.min(rangeUm, NEAR_FIRST_UM), found);
    if (count <= NEAR_COUNT && rangeUm > NEAR_FIRST_UM) count = grid.near(x, y, rangeUm, found);
    let kept = 0;
    for (let f = 0; f < count; f++) {
      const b = found[f];
      if (b === a) continue;
      const d = hypot(grid.xs[b] - x, grid.ys[b] - y);
      if (kept === NEAR_COUNT && (d > bestD[kept - 1] || (d === bestD[kept - 1] && b > bestId[kept - 1]))) continue;
      let k = kept < NEAR_COUNT ? kept++ : kept - 1;
      while (k > 0 && (bestD[k - 1] > d || (bestD[k - 1] === d && bestId[k - 1] > b))) {
        bestD[k] = bestD[k - 1];
        bestId[k] = bestId[k - 1];
        k--;
      }
      bestD[k] = d;
      bestId[k] = b;
    }
    for (let k = 0; k < kept; k++) {
      const b = bestId[k];
      const lo = Math.min(a, b),
        hi = Math.max(a, b);
      const key = lo * ids.length + hi;
      if (seen.has(key)) continue;
      seen.add(key);
      out.push([lo, hi, bestD[k]]);
    }
  }
  // shortest first: sorted as numbers, distance (to the nanometre) then the order found
  const keys = new Float64Array(out.length);
  for (let k = 0; k < out.length; k++) keys[k] = Math.round(out[k][2] * 1000) * PAIR_SLOTS + k;
  keys.sort();
  const sorted: [number, number, number][] = new Array(out.length);
  for (let k = 0; k < out.length; k++) {
    const e = out[keys[k] % PAIR_SLOTS];
    e[0] = ids[e[0]];
    e[1] = ids[e[1]];
    sorted[k] = e;
  }
  return sorted;
}

/** A free spot for a centre: the target, or the nearest free point to it or to where the node was, within `m` of (px, py). */
function place(ix: Blocked, tx: number, ty: number, px: number, py: number, m: number): Found | null {
  // centres are whole µm, as the part's points are: the point queries the tree shares with the rest of the
  // slicer stay compiled for integers, and the points the index finds outside are whole µm already
  tx = Math.round(tx);
  ty = Math.round(ty);
  if (!ix.contains(tx, ty)) return { x: tx, y: ty };
  const reach = m + MOVE_SLACK_UM;
  const q = ix.nearestOutside(tx, ty, m);
  if (q && dist(q.x, q.y, px, py) <= reach) return q;
  const s = ix.nearestOutside(px, py, m);
  if (s && dist(s.x, s.y, px, py) <= reach) return s;
  return null;
}

export interface DescendResult {
  /** The nodes of layer j. */
  lower: TreeNode[];
  /** Nodes of layer j + 1 that found no way down (their branches must go). */
  stuck: number[];
}

/** What one layer's descent works on. */
interface Descent {
  upper: readonly TreeNode[];
  j: number;
  vol: TreeVolumes;
  rules: TreeRules;
  /** The one-layer move, µm. */
  m: number;
  lower: TreeNode[];
  stuck: number[];
  /** Nodes already merged into one below. */
  done: Uint8Array;
  /** Whom each node leans towards: its partner (pairs matched closest first), else its nearest neighbour (-1: nobody). */
  toward: Int32Array;
  paired: Uint8Array;
}

/**
 * Take the nodes of layer j + 1 down to layer j; yields every ITEMS_PER_STEP branches. The work is in small
 * plain functions, which the engine optimises early, rather than in this generator.
 */
export function* descend(
  upper: readonly TreeNode[],
  j: number,
  vol: TreeVolumes,
  rules: TreeRules,
): Generator<void, DescendResult> {
  const d: Descent = {
    upper,
    j,
    vol,
    rules,
    m: rules.step(j + 1),
    lower: [],
    stuck: [],
    done: new Uint8Array(upper.length),
    toward: new Int32Array(upper.length).fill(-1),
    paired: new Uint8Array(upper.length),
  };
  const range = Math.min(ATTRACT_MAX_UM, rules.zUm(j));
  for (const keep of ['bed', 'model'] as const) {
    const pairs = nearPairs(upper, freeIds(upper, keep), range);
    // merges: the closest pairs first, each node once per layer
    for (let k = 0; k < pairs.length; k += ITEMS_PER_STEP) {
      if (k > 0) yield;
      mergePairs(d, pairs, k, Math.min(pairs.length, k + ITEMS_PER_STEP));
    }
    leanTowards(d, pairs);
  }
  for (let i = 0; i < upper.length; i += ITEMS_PER_STEP) {
    if (i > 0) yield;
    stepDown(d, i, Math.min(upper.length, i + ITEMS_PER_STEP));
  }
  return { lower: d.lower, stuck: d.stuck };
}

/** The nodes that are alive, not landing, and keep out of `keep`. */
function freeIds(upper: readonly TreeNode[], keep: Keep): number[] {
  const ids: number[] = [];
  for (let i = 0; i < upper.length; i++) if (!upper[i].dead && !upper[i].landing && upper[i].keep === keep) ids.push(i);
  return ids;
}

/** Merge the pairs [from, to) that can meet (closest first, each node once). */
function mergePairs(d: Descent, pairs: readonly [number, number, number][], from: number, to: number): void {
  const { upper, done, m } = d;
  for (let k = from; k < to; k++) {
    const pair = pairs[k];
    const a = pair[0],
      b = pair[1],
      dist = pair[2];
    if (done[a] || done[b] || !(dist <= 2 * m || absorbs(upper[a], upper[b], dist, m))) continue;
    const merged = merge(upper[a], upper[b], a, b, dist, m, d.j, d.vol, d.rules);
    if (!merged) continue;
    d.lower.push(merged);
    done[a] = done[b] = 1;
  }
}

/** Partners (closest pairs first), then each unpaired node towards its nearest neighbour, where the part is not between them. */
function leanTowards(d: Descent, pairs: readonly [number, number, number][]): void {
  const { upper, done, paired, toward } = d;
  const barrier = d.vol.partIndex(d.j);
  // per pair: 0 not asked yet, 1 the part is not between them, 2 it is (each pair asked once)
  const between = new Uint8Array(pairs.length);
  const clear = (k: number) => {
    if (between[k] === 0) {
      const a = upper[pairs[k][0]],
        b = upper[pairs[k][1]];
      between[k] = barrier.crosses(a.x, a.y, b.x, b.y) ? 2 : 1;
    }
    return between[k] === 1;
  };
  for (let k = 0; k < pairs.length; k++) {
    const a = pairs[k][0],
      b = pairs[k][1];
    if (done[a] || done[b] || paired[a] || paired[b] || !clear(k)) continue;
    paired[a] = paired[b] = 1;
    toward[a] = b;
    toward[b] = a;
  }
  for (let k = 0; k < pairs.length; k++) {
    const a = pairs[k][0],
      b = pairs[k][1];
    if (done[a] || done[b]) continue;
    if (toward[a] < 0 && clear(k)) toward[a] = b;
    if (toward[b] < 0 && clear(k)) toward[b] = a;
  }
}

/** Nodes [from, to) not merged: each one layer down, halfway to whom it leans towards and at most a move. */
function stepDown(d: Descent, from: number, to: number): void {
  const { upper, done, toward, m, j, vol, rules, lower, stuck } = d;
  for (let i = from; i < to; i++) {
    const n = upper[i];
    if (n.dead || done[i]) continue;
    if (n.landing) {
      const next = land(n, i, j, vol, rules);
      if (next === 'dead') stuck.push(i);
      else if (next) lower.push(next);
      continue;
    }
    let vx = 0,
      vy = 0;
    const t = toward[i];
    if (t >= 0) {
      const dx = upper[t].x - n.x,
        dy = upper[t].y - n.y;
      const len = hypot(dx, dy);
      const go = Math.min(m, len / 2);
      if (len > 0) {
        vx = (dx * go) / len;
        vy = (dy * go) / len;
      }
    }
    let keep = n.keep;
    let at = place(vol.index(keep, n.c, j), n.x + vx, n.y + vy, n.x, n.y, m);
    if (!at && keep === 'bed') {
      keep = 'model';
      at = place(vol.index(keep, n.c, j), n.x + vx, n.y + vy, n.x, n.y, m);
    }
    if (!at) {
      if (rules.everywhere) {
        // above the part: straight down onto it
        const next = land({ ...n, keep: 'model', landing: true }, i, j, vol, rules);
        if (next === 'dead') stuck.push(i);
        else if (next) lower.push(next);
      } else stuck.push(i);
      continue;
    }
    lower.push(grown(n, i, at, keep, m, j, vol, rules));
  }
}

/** The node at `at` on layer j, its radius grown as far as its class (or a wider one that fits) allows. */
function grown(
  n: TreeNode,
  i: number,
  at: Found,
  keep: Keep,
  m: number,
  j: number,
  vol: TreeVolumes,
  rules: TreeRules,
): TreeNode {
  const want = wantRadiusUm(n, rules, j);
  let c = n.c;
  let r = want;
  const wc = classOf(rules.radii, want);
  if (wc > c) {
    const left = m - dist(at.x, at.y, n.x, n.y);
    // widening is worth a quick look nearby only: the thorough search mostly fails near walls, at a high price
    const q = left >= 0 ? vol.index(keep, wc, j).nearestOutside(at.x, at.y, left, false) : null;
    if (q && dist(q.x, q.y, n.x, n.y) <= m + MOVE_SLACK_UM) {
      at = q;
      c = wc;
    } else r = Math.max(n.r, Math.min(want, rules.radii[c]));
  }
  // a branch kept only off the part that finds itself able to reach the bed again goes for the bed
  if (keep === 'model' && !vol.index('bed', c, j).contains(at.x, at.y)) keep = 'bed';
  return { x: at.x, y: at.y, r, c, keep, merged: n.merged, topUm: n.topUm, landing: false, parents: [i], dead: false };
}

/** Whether the wider of two nodes d apart holds the other within a move (it can take it in where it is). */
function absorbs(a: TreeNode, b: TreeNode, d: number, m: number): boolean {
  return d + Math.min(a.r, b.r) <= Math.max(a.r, b.r) + m;
}

/**
 * Two nodes of layer j + 1 into one on layer j, or null when that does not fit: between them and within a
 * move of each, nearer the wider; or, when the wider holds the other within a move, where the wider is.
 */
function merge(
  a: TreeNode,
  b: TreeNode,
  ia: number,
  ib: number,
  d: number,
  m: number,
  j: number,
  vol: TreeVolumes,
  rules: TreeRules,
): TreeNode | null {
  const big = a.r >= b.r ? a : b,
    small = big === a ? b : a;
  const want = Math.max(wantRadiusUm({ ...big, merged: true, topUm: Math.max(a.topUm, b.topUm) }, rules, j), a.r, b.r);
  let t: number;
  if (d <= 2 * m) {
    const wa = a.r * a.r,
      wb = b.r * b.r;
    t = wb / (wa + wb);
    if (d > 0) t = Math.min(Math.min(1, m / d), Math.max(Math.max(0, 1 - m / d), t));
  } else t = big === a ? 0 : 1;
  const x = Math.round(a.x + t * (b.x - a.x)),
    y = Math.round(a.y + t * (b.y - a.y));
  const reach = m + MOVE_SLACK_UM;
  for (const r of [want, Math.max(a.r, b.r)]) {
    const c = classOf(rules.radii, r);
    const q = vol.index(a.keep, c, j).nearestOutside(x, y, m);
    if (!q) continue;
    const toBig = dist(q.x, q.y, big.x, big.y),
      toSmall = dist(q.x, q.y, small.x, small.y);
    if (toBig > reach || (toSmall > reach && toSmall + small.r > r + reach)) continue;
    return {
      x: q.x,
      y: q.y,
      r,
      c,
      keep: a.keep,
      merged: true,
      topUm: Math.max(a.topUm, b.topUm),
      landing: false,
      parents: [ia, ib],
      dead: false,
    };
  }
  return null;
}

/**
 * A branch that cannot keep clear of the part goes straight down onto it: it ends where its cross-section
 * lies wholly in the part's collision (standing on the part, or dead when there is no part under it), and
 * turns back into a free branch if it comes clear again.
 */
function land(n: TreeNode, i: number, j: number, vol: TreeVolumes, rules: TreeRules): TreeNode | null | 'dead' {
  const free = vol.index('model', n.c, j);
  if (!free.contains(n.x, n.y)) return { ...n, landing: false, keep: 'model', parents: [i] };
  const part = vol.index('part', 0, j);
  const covered = part.contains(n.x, n.y) && part.nearestOutside(n.x, n.y, n.r) === null;
  if (!covered) return { ...n, landing: true, keep: 'model', parents: [i] };
  return rules.everywhere && rules.standsOn(j, n.x, n.y, n.r) ? null : 'dead';
}
