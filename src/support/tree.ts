/**
 * Tree support, in the manner of CuraEngine's tree support and PrusaSlicer's organic support:
 * 1. model volumes (tree-volumes.ts): per layer and radius class, where a branch centre may not be so as to
 *    keep clear of the part, and where it may not be if it is to reach the bed (avoidance), from the bed up;
 * 2. tips (tree-tips.ts) under every overhang, below a dense roof of supportInterfaceLayers (none under steps
 *    narrower than ROOF_MIN_STEP_WIDTHS), `tip spacing` apart; then, from the top layer down, every branch
 *    steps one layer down (tree-nodes.ts): leaning towards
 *    its neighbours by at most layerHeight · tan(branch angle), merging with those it meets, thickening from
 *    the tip diameter to the branch diameter (merged trunks further, by the diameter angle; none wider than
 *    its highest tip's height over BRANCH_SLENDERNESS), always outside
 *    its avoidance, so that it reaches the bed; in 'everywhere' placement a branch that cannot reach the bed
 *    keeps clear of the part until it stands on it (the bottom Z gap above it, with a floor); in 'buildPlate'
 *    placement such branches are dropped, with every tip they carried;
 * 3. from the bed up (tree-draw.ts), each layer's branch cross-sections and roof, the roof only where what is
 *    below holds it, off the part, split into body, roof and floor.
 */
import { area, boundsOf, intersection, offset, union } from '../geometry/clip.js';
import { hypot, UM_PER_MM, type ExPolygon, type Pt } from '../geometry/types.js';
import type { SupportAreas } from '../regions/types.js';
import type { ModelLayers } from './model-layers.js';
import { PointGrid } from '../geometry/point-grid.js';
import { circle, cutAway, drawLayer, meetsAny, type Disc } from './tree-draw.js';
import { VERTEX_ROUNDING_UM, type RegularPolygon } from '../geometry/regular-polygon.js';
import { descend, ITEMS_PER_STEP, type TreeNode, type TreeRules } from './tree-nodes.js';
import { TIP_MIN_GAP_SHARE, tipCandidates } from './tree-tips.js';
import { findPockets, pocketAreas } from './tree-pockets.js';
import { radiusClasses, TreeVolumes, type Keep } from './tree-volumes.js';

/** A tip widens at this angle (of its sides from vertical) until it has the branch diameter: thin tips merge before they grow thick. */
export const TIP_WIDEN_DEG = 12;
/** Merged trunks grow to at most this many times the branch radius. */
export const TRUNK_MAX_BRANCH_RADII = 1.5;
/**
 * A roof reaches at most this share of the tip spacing beyond the branches under it; and under a roof, a tip
 * goes no nearer than this to another tip or a branch already there (see TIP_MIN_GAP_SHARE).
 */
export const ROOF_REACH_SHARE = 0.75;
/** The roof reaches this many support line widths beyond the overhang it holds. */
export const ROOF_GROW_WIDTHS = 0.5;
/**
 * Steps of the overhang narrower than this many support line widths get no roof, only tips: the bands of a
 * slope steeper than about 65° from vertical (at 0.2 mm layers and a 50° threshold) step out less than the part
 * holds itself by plus half a line, and tips touch them directly, as CuraEngine's tree tips touch the part.
 */
export const ROOF_MIN_STEP_WIDTHS = 0.5;
/** A tip may move this share of the tip spacing to find room. */
export const TIP_SHIFT_SHARE = 0.5;
/**
 * A branch grows no wider than the height of the highest tip it carries over this (and never thinner than a
 * tip): a pin 4 mm tall stays 0.8 mm across, one 10 mm tall widens to 2 mm. Under low overhangs (a sphere's
 * underside) the tips stand a few millimetres each, too short to merge, and widening them only adds material.
 */
export const BRANCH_SLENDERNESS = 5;
/** A branch ends on the part when at least this share of its cross-section has the part under it. */
export const STAND_SHARE = 0.2;

const rad = (deg: number) => (deg * Math.PI) / 180;

/** The branches of a tree support, layer by layer, and what drawing them needs. */
export interface TreePlan {
  /** nodes[j]: the branches' cross-sections on layer j (dead ones carried tips that could not be held). */
  nodes: TreeNode[][];
  /** The overhang each layer's tree must hold (pockets left out). */
  overhangs: ExPolygon[][];
  /** Per layer, the columns under pockets (tree-pockets.ts). */
  pockets: ExPolygon[][];
  vol: TreeVolumes;
  rules: TreeRules;
}

/** The tree support areas of every layer; yields after each layer of each phase. */
export function* treeSupport(model: ModelLayers): Generator<void, SupportAreas[]> {
  const plan = yield* planTree(model);
  return yield* drawTree(model, plan);
}

/** Volumes, tips and branches, from the top down; yields per layer. */
export function* planTree(model: ModelLayers): Generator<void, TreePlan> {
  const cfg = model.cfg;
  const n = model.count;
  const roofLayers = cfg.supportInterfaceLayers;
  const rules = treeRules(model);
  const vol = new TreeVolumes(model, rules.radii, rules.step);
  const nodes: TreeNode[][] = [];
  for (let j = 0; j < n; j++) nodes.push([]);

  // the overhang each layer must hold; its tips start under the top gap and the roof
  const all: ExPolygon[][] = [];
  // the highest layer support reaches up to (under the top Z gap of the highest overhang)
  let highest = -1,
    highestTop = -Infinity;
  for (let m = 0; m < n; m++) {
    all.push(model.overhang(m));
    if (all[m].length) {
      highest = m;
      highestTop = Math.max(highestTop, model.supportTop(m));
    }
  }
  if (highest < 0) return { nodes, overhangs: all, pockets: all.map(() => []), vol, rules };
  const tipTop = highestTop - roofLayers;
  const roofTop = Math.min(n - 1, highestTop);
  yield* vol.build(Math.max(roofTop, tipTop), tipTop);
  const spacing = cfg.supportTreeTipSpacingMm * UM_PER_MM;
  const { overhangs, columns: pockets } = yield* findPockets(
    {
      model,
      collision: (j) => vol.collision(j),
      collisionIndex: (j) => vol.partIndex(j),
      avoidance: (j) => vol.avoidance(j),
      tipRUm: rules.tipR,
    },
    all,
  );

  for (let j = tipTop; j >= 0; j--) {
    const { lower, stuck } = j < tipTop ? yield* descend(nodes[j + 1], j, vol, rules) : { lower: [], stuck: [] };
    for (const i of stuck) kill(nodes, j + 1, i);
    for (const m of model.overhangLayersOver(j + roofLayers))
      if (m < n && overhangs[m].length) yield* addTips(lower, overhangs[m], j, spacing, vol, rules);
    nodes[j] = lower;
    vol.release(j);
    yield;
  }
  return { nodes, overhangs, pockets, vol, rules };
}

/** Each layer's support areas from the plan, from the bed up; yields per layer. */
export function* drawTree(model: ModelLayers, plan: TreePlan): Generator<void, SupportAreas[]> {
  const cfg = model.cfg;
  const n = model.count;
  const { nodes, overhangs, pockets, vol, rules } = plan;
  const roofLayers = cfg.supportInterfaceLayers;
  const everywhere = cfg.supportPlacement === 'everywhere';
  const spacing = cfg.supportTreeTipSpacingMm * UM_PER_MM;
  const out: SupportAreas[] = [];
  for (let j = 0; j < n; j++) out.push({ body: [], roof: [], floor: [] });
  // areas, from the bed up
  const w = model.widthUm;
  let below: ExPolygon[] = [];
  for (let j = 0; j < n; j++) {
    const discs = discsOf(nodes[j], rules);
    const roofWanted: ExPolygon[] = [];
    // the first layer also holds the overhang within the top Z gap over it, with no gap (ModelLayers.gapOverhang)
    // (the overhang layers whose support reaches up to layers j .. j + roofLayers − 1)
    if (j === 0)
      for (let m = 1; m < n && model.supportTop(m) < 0; m++) for (const p of overhangs[m]) roofWanted.push(p);
    for (let t = j; t < j + roofLayers; t++)
      for (const m of model.overhangLayersOver(t)) if (m < n) for (const p of overhangs[m]) roofWanted.push(p);
    if (discs.length === 0 && roofWanted.length === 0) {
      below = [];
      out[j] = pocketAreas(model, j, pockets[j], []) ?? out[j];
      continue;
    }
    const collision = vol.collision(j);
    // steps of the overhang narrower than ROOF_MIN_STEP_WIDTHS left to the tips (an opening), the rest grown a
    // little, so that the narrow steps of a sloping overhang make a roof a line can print: the opening's growth
    // and this one in one offset
    // (none on the first layer: no tip stands under the overhang whose roof is there)
    const open = j === 0 ? 0 : (ROOF_MIN_STEP_WIDTHS * w) / 2;
    const steps = roofWanted.length ? offset(union(roofWanted), -open) : [];
    const roof = steps.length ? cutAway(offset(steps, open + ROOF_GROW_WIDTHS * w), collision) : [];
    // what may carry the roof: last layer's support, and in 'everywhere' placement the part within the gap below
    const bottom = model.bottomGap(j);
    const base =
      j > 0 && roof.length ? [...below, ...(everywhere ? model.sectionsBetween(j, -(bottom + 1), -1) : [])] : null;
    const gapBelow = everywhere && bottom > 0 ? model.sectionsBetween(j, -bottom, -1) : [];
    const gapIndex = () => model.indexBetween(j, -bottom, -1);
    const { areas: s, circles } = yield* drawLayer({
      discs,
      roof,
      base,
      roofReachUm: ROOF_REACH_SHARE * spacing,
      collision,
      gapBelow,
      gapIndex,
      widthUm: w,
    });
    below = s;
    out[j] = withPockets(
      { ...(yield* splitNear(model, j, s, circles)), whole: s, circles },
      pocketAreas(model, j, pockets[j], s),
    );
    yield;
  }
  return out;
}

/** A layer's tree areas and its pockets' columns (off the tree's areas) together. */
function withPockets(tree: SupportAreas, p: SupportAreas | null): SupportAreas {
  if (!p) return tree;
  const n = p.whole?.length ?? 0;
  return {
    body: [...tree.body, ...p.body],
    roof: [...tree.roof, ...p.roof],
    floor: [...tree.floor, ...p.floor],
    columnBody: p.body,
    whole: [...(tree.whole ?? []), ...(p.whole ?? [])],
    circles: [...(tree.circles ?? []), ...new Array<null>(n).fill(null)],
  };
}

/** The cross-sections of a layer's live branches (a plain function: a generator's own loop runs unoptimised). */
function discsOf(nodes: readonly TreeNode[], rules: TreeRules): Disc[] {
  const discs: Disc[] = [];
  for (let i = 0; i < nodes.length; i++) {
    const c = nodes[i];
    if (!c.dead) discs.push({ x: c.x, y: c.y, r: c.r, clear: !c.landing && c.r <= rules.radii[c.c] + 0.5 });
  }
  return discs;
}

/** The islands of s that meet the part on one of the `nearby` layers (near), and the rest (far). */
function nearOrFar(
  model: ModelLayers,
  nearby: readonly number[],
  s: readonly ExPolygon[],
  circles: readonly (RegularPolygon | null)[],
): { near: ExPolygon[]; far: ExPolygon[] } {
  const near: ExPolygon[] = [],
    far: ExPolygon[] = [];
  for (let i = 0; i < s.length; i++) {
    const a = s[i];
    // an island whose bounds meet no island of a layer's section cannot meet that section
    const box = boundsOf([a]);
    let hit = false;
    // a lone branch's polygon lies within its circle (grown by a micrometre for its vertices' rounding): a
    // circle clear of a section is clear of it at once
    const c = circles[i];
    for (let t = 0; t < nearby.length && !hit; t++) {
      if (!meetsAny(box, model.sectionBoxes(nearby[t]))) continue;
      const ix = model.sectionIndex(nearby[t]);
      hit = (!c || ix.meetsDisc(c.x, c.y, c.r + VERTEX_ROUNDING_UM)) && ix.meets(a);
    }
    (hit ? near : far).push(a);
  }
  return { near, far };
}

/**
 * model.split, run only on the islands that meet the part within the roof layers above or the floor layers
 * below: the others are body. `circles[i]`, when set, is the regular polygon island i is drawn as.
 */
function* splitNear(
  model: ModelLayers,
  j: number,
  s: ExPolygon[],
  circles: readonly (RegularPolygon | null)[],
): Generator<void, SupportAreas> {
  const cfg = model.cfg;
  const nearby: number[] = [];
  const top = model.topGap(j),
    bottom = model.bottomGap(j);
  for (let k = j + 1; k <= j + top + cfg.supportInterfaceLayers; k++) if (model.section(k).length) nearby.push(k);
  // floors only where support may stand on the part (model.split makes none in 'buildPlate' placement)
  if (cfg.supportPlacement === 'everywhere') {
    for (let k = j - bottom - cfg.supportFloorLayers; k < j - bottom; k++) if (model.section(k).length) nearby.push(k);
  }
  model.releaseBelow(j - bottom - cfg.supportFloorLayers);
  if (nearby.length === 0 || s.length === 0) return { body: s, roof: [], floor: [] };
  const { near, far } = nearOrFar(model, nearby, s, circles);
  // islands apart split apart: a few at a time
  const out: SupportAreas = { body: far, roof: [], floor: [] };
  for (let k = 0; k < near.length; k += ITEMS_PER_STEP) {
    if (k > 0) yield;
    const split = model.split(j, near.slice(k, k + ITEMS_PER_STEP));
    out.body.push(...split.body);
    out.roof.push(...split.roof);
    out.floor.push(...split.floor);
  }
  return out;
}

/** The tree's sizes and steps from the settings, µm. */
export function treeRules(model: ModelLayers): TreeRules {
  const cfg = model.cfg;
  // radii in whole µm, as the centres are
  const tipR = Math.round((cfg.supportTreeTipDiameter * UM_PER_MM) / 2);
  const branchR = Math.max(tipR, Math.round((cfg.supportTreeBranchDiameter * UM_PER_MM) / 2));
  const tanMove = Math.tan(rad(cfg.supportTreeBranchAngle));
  const tanGrow = Math.tan(rad(cfg.supportTreeDiameterAngle));
  const height = (j: number) => model.layers[j].height * UM_PER_MM;
  const maxR = Math.round(TRUNK_MAX_BRANCH_RADII * branchR);
  // one more class for the widest trunks, so that every branch is checked against a class as wide as it is
  const radii = radiusClasses(tipR, branchR);
  if (maxR > branchR + 0.5) radii.push(maxR);
  return {
    radii,
    tipR,
    branchR,
    maxR,
    heightCapR: (topUm) => Math.max(tipR, Math.round(topUm / (2 * BRANCH_SLENDERNESS))),
    tipGrowth: cfg.layerHeight * UM_PER_MM * Math.tan(rad(TIP_WIDEN_DEG)),
    tipGap:
      (cfg.supportInterfaceLayers > 0 ? ROOF_REACH_SHARE : TIP_MIN_GAP_SHARE) * cfg.supportTreeTipSpacingMm * UM_PER_MM,
    trunkGrowth: (j) => height(j) * tanGrow,
    step: (j) => (j > 0 && j < model.count ? height(j) * tanMove : 0),
    zUm: (j) => model.layers[j].z * UM_PER_MM,
    everywhere: cfg.supportPlacement === 'everywhere',
    standsOn: (j, x, y, r) => {
      const under = intersection([{ outer: circle(x, y, r), holes: [] }], model.section(j));
      return area(under) >= STAND_SHARE * Math.PI * r * r;
    },
  };
}

/** What placing one layer's tips works on. */
interface TipPlacing {
  lower: TreeNode[];
  candidates: readonly Pt[];
  /** Every branch's and placed tip's centre. */
  existing: PointGrid;
  found: number[];
  /** The widest branch already on the layer, µm. */
  widest: number;
  keeps: readonly Keep[];
  j: number;
  spacing: number;
  vol: TreeVolumes;
  rules: TreeRules;
}

/** Where the step of tip placing that starts at candidate `from` ends: before candidate ITEMS_PER_STEP - 1, then every ITEMS_PER_STEP. */
const tipStepEnd = (from: number) => (from < ITEMS_PER_STEP - 1 ? ITEMS_PER_STEP - 1 : from + ITEMS_PER_STEP);

/** Tips under the overhang `over`, on layer j, where no branch already passes. */
function* addTips(
  lower: TreeNode[],
  over: readonly ExPolygon[],
  j: number,
  spacing: number,
  vol: TreeVolumes,
  rules: TreeRules,
): Generator<void, void> {
  const existing = new PointGrid(spacing);
  const t: TipPlacing = {
    lower,
    candidates: tipCandidates(over, spacing, rules.tipR, rules.tipGap),
    existing,
    found: [],
    widest: gridOfNodes(existing, lower),
    keeps: rules.everywhere ? ['bed', 'model'] : ['bed'],
    j,
    spacing,
    vol,
    rules,
  };
  const n = t.candidates.length;
  for (let from = 0; from < n; from = tipStepEnd(from)) {
    if (from > 0) yield;
    placeTips(t, from, Math.min(n, tipStepEnd(from)));
  }
}

/** Every node's centre into the grid; returns the widest radius. */
function gridOfNodes(grid: PointGrid, nodes: readonly TreeNode[]): number {
  let widest = 0;
  for (let i = 0; i < nodes.length; i++) {
    grid.add(nodes[i].x, nodes[i].y);
    widest = Math.max(widest, nodes[i].r);
  }
  return widest;
}

/** Place the tips of candidates [from, to) that no branch is too close to. */
function placeTips(t: TipPlacing, from: number, to: number): void {
  const { lower, existing, found, vol, rules } = t;
  const gap = rules.tipGap;
  for (let i = from; i < to; i++) {
    const p = t.candidates[i];
    if (tooClose(existing, found, existing.near(p.x, p.y, Math.max(gap, t.widest), found), p, gap, lower)) continue;
    for (const keep of t.keeps) {
      const q = vol.index(keep, 0, t.j).nearestOutside(p.x, p.y, TIP_SHIFT_SHARE * t.spacing);
      if (!q) continue;
      lower.push({
        x: q.x,
        y: q.y,
        r: rules.tipR,
        c: 0,
        keep,
        merged: false,
        topUm: rules.zUm(t.j),
        landing: false,
        parents: [],
        dead: false,
      });
      existing.add(q.x, q.y);
      break;
    }
  }
}

/** Whether any of the first `count` ids in `found` is a node nearer p than the gap or its own radius. */
function tooClose(
  grid: PointGrid,
  found: readonly number[],
  count: number,
  p: Pt,
  gap: number,
  nodes: readonly TreeNode[],
): boolean {
  for (let f = 0; f < count; f++) {
    const k = found[f];
    if (hypot(grid.xs[k] - p.x, grid.ys[k] - p.y) < Math.max(gap, nodes[k].r)) return true;
  }
  return false;
}

/** Drop node i of layer j and every node above that leads into it. */
function kill(nodes: TreeNode[][], j: number, i: number): void {
  const todo: [number, number][] = [[j, i]];
  while (todo.length) {
    const [l, k] = todo.pop()!;
    const node = nodes[l][k];
    if (node.dead) continue;
    node.dead = true;
    for (const p of node.parents) todo.push([l + 1, p]);
  }
}
