import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area, difference, intersection, offset, union } from '#strata/geometry/clip.js';
import { UM_PER_MM, type ExPolygon } from '#strata/geometry/types.js';
import { rect } from '../geometry/test-shapes.js';
import type { LayerRegions } from '#strata/regions/types.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { ModelLayers } from '#strata/support/model-layers.js';
import {
  BOX_ON_POST,
  LEDGE_OVER_STEP,
  LEDGE_OVER_WIDE_STEP,
  T_SHAPE,
  boxLayers,
  heldShare,
  intoPart,
  supportArea,
  supportConfig,
  supported,
  type Box,
} from './test-models.js';
import { CIRCLE_TOLERANCE_UM, circle } from '#strata/support/tree-draw.js';
import { BRANCH_SLENDERNESS, planTree, type TreePlan } from '#strata/support/tree.js';

const MODELS: [string, Box[]][] = [
  ['a box on a thin post', BOX_ON_POST],
  ['a T', T_SHAPE],
  ['a ledge over a lower step', LEDGE_OVER_STEP],
];

/** Tolerance for clipping, µm. */
const TOL_UM = 50;
/**
 * How far a layer's support may reach past the one below beyond the move, µm: a drawn circle lies up to
 * CIRCLE_TOLERANCE_UM inside the true one, so a branch's cross-section above may stand out that much.
 */
const STACK_TOL_UM = Math.max(TOL_UM, CIRCLE_TOLERANCE_UM);
/** Area below which a difference counts as empty (polygon round-off), µm². */
const SLIVER_UM2 = 0.01 * 1e6;
/**
 * What a layer may hang beyond the one below, µm²: a sliver where a branch ending at the edge of the part
 * below was cut to what a line can print.
 */
const HANG_UM2 = 0.05 * 1e6;

/** The tree plan of a model, run to its end. */
function planOf(model: ModelLayers): TreePlan {
  const run = planTree(model);
  let r = run.next();
  while (!r.done) r = run.next();
  return r.value;
}

const totalArea = (layers: readonly LayerRegions[]) => layers.reduce((s, l) => s + area(supportArea(l)), 0);

for (const [name, boxes] of MODELS) {
  test(`tree support holds every overhang point of ${name} right under the top Z gap`, () => {
    const { layers, cfg } = supported(boxes, { supportType: 'tree' });
    const model = new ModelLayers(layers, cfg);
    const w = cfg.supportLineWidthMm * UM_PER_MM;
    const { held, total, missed } = heldShare(layers, cfg, (j) => model.collision(j), w / 2);
    assert.ok(total > 100, `only ${total} overhang points`);
    assert.equal(held, total, `unheld: ${JSON.stringify(missed.slice(0, 5))}`);
  });

  test(`tree support under ${name} keeps the XY gap from the part on every layer`, () => {
    const { layers, cfg } = supported(boxes, { supportType: 'tree' });
    assert.ok(totalArea(layers) > 0);
    assert.equal(intoPart(layers, cfg, TOL_UM), 0);
  });

  test(`tree support under ${name} uses less than normal support`, () => {
    const tree = totalArea(supported(boxes, { supportType: 'tree' }).layers);
    const normal = totalArea(supported(boxes, { supportType: 'normal' }).layers);
    assert.ok(
      tree > 0 && tree < normal,
      `tree ${(tree / 1e6).toFixed(0)} mm², normal ${(normal / 1e6).toFixed(0)} mm²`,
    );
  });

  test(`branches under ${name} lean at most one move a layer and stand on what is below them`, () => {
    const cfg = supportConfig({ supportType: 'tree' });
    const layers = boxLayers(boxes, cfg);
    const model = new ModelLayers(layers, cfg);
    const { nodes, rules } = planOf(model);
    let links = 0;
    for (let j = 0; j + 1 < nodes.length; j++) {
      const m = rules.step(j + 1);
      const collision = model.collision(j);
      for (const child of nodes[j]) {
        if (child.dead) continue;
        // centres and radii in whole µm, as the part's points are
        assert.ok(
          Number.isInteger(child.x) && Number.isInteger(child.y) && Number.isInteger(child.r),
          `layer ${j}: a branch at (${child.x}, ${child.y}) r ${child.r}`,
        );
        // every cross-section of a free branch is clear of the part grown by the XY gap
        const into = child.landing
          ? 0
          : area(intersection([{ outer: circle(child.x, child.y, child.r), holes: [] }], collision));
        assert.equal(
          into,
          0,
          `layer ${j}: a branch cross-section ${(into / 1e6).toFixed(3)} mm² into the part's XY gap`,
        );
        for (const p of child.parents.map((i) => nodes[j + 1][i])) {
          links++;
          const d = Math.hypot(p.x - child.x, p.y - child.y);
          assert.ok(!p.dead, `a live branch on layer ${j} continues a dropped one`);
          // the cross-section above reaches at most a move beyond the one below it: the branch moved at most a
          // move, or (a thin branch taken into a wide one) lies within a move of the wide one
          assert.ok(
            d + p.r <= child.r + m + 2,
            `layer ${j + 1}: overhangs the branch below by ${(d + p.r - child.r).toFixed(0)} µm`,
          );
          assert.ok(
            d <= m + 2 || child.parents.length > 1,
            `layer ${j}: moved ${d.toFixed(0)} µm, more than ${m.toFixed(0)}`,
          );
        }
      }
    }
    assert.ok(links > 100);
  });

  test(`tree support under ${name}: below the tips, each layer lies within the one above grown by a move (and the radius growth)`, () => {
    const { layers, cfg } = supported(boxes, { supportType: 'tree' });
    const model = new ModelLayers(layers, cfg);
    const { nodes, rules } = planOf(model);
    let lowestTip = Infinity;
    nodes.forEach((layer, j) => layer.some((n) => n.parents.length === 0) && (lowestTip = Math.min(lowestTip, j)));
    const grow = Math.max(rules.tipGrowth, rules.trunkGrowth(1));
    let checked = 0;
    for (let j = 0; j + 1 < lowestTip; j++) {
      const here = supportArea(layers[j]),
        above = supportArea(layers[j + 1]);
      if (here.length === 0) continue;
      const m = rules.step(j + 1);
      const spread = area(difference(here, offset(above, m + grow + STACK_TOL_UM)));
      assert.ok(spread <= SLIVER_UM2, `layer ${j} reaches ${(spread / 1e6).toFixed(3)} mm² beyond layer ${j + 1}`);
      // and nothing above hangs further than a move beyond it, or beyond the part it stands on (with its XY
      // gap: a branch ending beside the edge of a step is cut back by the gap on the step's top layer)
      const part: ExPolygon[] = [];
      for (let k = Math.max(0, j - cfg.supportBottomGapLayers); k <= j; k++) part.push(...model.section(k));
      const base = part.length ? union(here, offset(part, cfg.supportXYGap * UM_PER_MM)) : here;
      const hang = area(difference(above, offset(base, m + STACK_TOL_UM)));
      assert.ok(hang <= HANG_UM2, `layer ${j + 1} hangs ${(hang / 1e6).toFixed(3)} mm² over air`);
      checked++;
    }
    assert.ok(checked > 10, `only ${checked} layers checked`);
  });

  test(`tree support of ${name} is the same on a second run`, () => {
    const a = supported(boxes, { supportType: 'tree' }).layers.map((l) => l.support);
    const b = supported(boxes, { supportType: 'tree' }).layers.map((l) => l.support);
    assert.deepEqual(a, b);
  });
}

test('under a ledge over a lower step, tree support stands on the step, the bottom Z gap above it, with a floor', () => {
  const { layers, cfg } = supported(LEDGE_OVER_STEP, { supportType: 'tree' });
  assert.equal(cfg.supportPlacement, 'everywhere');
  const floor = layers.reduce((s, l) => s + (l.support ? area(l.support.floor) : 0), 0);
  assert.ok(floor > 1e6, `floor ${floor / 1e6} mm²`);
  for (let j = 1; j < layers.length; j++) {
    const below = layers[j - 1].islands.map((i) => i.outline);
    const on = area(intersection(supportArea(layers[j]), below));
    assert.ok(on <= SLIVER_UM2, `layer ${j}: support right on the part (${on / 1e6} mm²)`);
  }
});

for (const [name, boxes] of [
  ['a ledge over a lower step', LEDGE_OVER_STEP],
  ['a ledge over a wider step', LEDGE_OVER_WIDE_STEP],
] as const) {
  test(`with build-plate placement, nothing of the tree support under ${name} stands on the part`, () => {
    const options = { supportType: 'tree', supportPlacement: 'buildPlate' } as const;
    const { layers, cfg } = supported(boxes, options);
    for (let j = 1; j < layers.length; j++) {
      assert.equal(layers[j].support?.floor.length ?? 0, 0, `a floor on layer ${j}`);
      const below = layers[j - 1].islands.map((i) => i.outline);
      const on = area(intersection(supportArea(layers[j]), below));
      assert.ok(on <= SLIVER_UM2, `layer ${j}: ${(on / 1e6).toFixed(3)} mm² of support right on the part`);
    }
    // every branch goes on down to the bed
    const { nodes } = planOf(new ModelLayers(boxLayers(boxes, cfg), cfg));
    for (let j = 1; j < nodes.length; j++) {
      const continued = new Set(nodes[j - 1].filter((n) => !n.dead).flatMap((n) => n.parents));
      nodes[j].forEach((n, i) => assert.ok(n.dead || continued.has(i), `a branch ends on layer ${j}`));
    }
  });
}

test('with build-plate placement, the ledge over a lower step is still held where the bed is within reach', () => {
  const { layers } = supported(LEDGE_OVER_STEP, { supportType: 'tree', supportPlacement: 'buildPlate' });
  // the ledge reaches 12 mm beyond the step's edge: a branch under it has room to reach the bed
  const beyond = layers.map((l) =>
    area(
      intersection(supportArea(l), [
        {
          outer: [
            { x: 2000, y: -20000 },
            { x: 20000, y: -20000 },
            { x: 20000, y: 20000 },
            { x: 2000, y: 20000 },
          ],
          holes: [],
        },
      ]),
    ),
  );
  assert.ok(beyond[0] > 0, 'no branch reaches the bed beyond the step');
});

test('a ledge just above a wide step gets no tree support with build-plate placement, and stands on the step with everywhere placement', () => {
  const plate = supported(LEDGE_OVER_WIDE_STEP, { supportType: 'tree', supportPlacement: 'buildPlate' });
  assert.equal(totalArea(plate.layers), 0);
  const everywhere = supported(LEDGE_OVER_WIDE_STEP, { supportType: 'tree' });
  assert.ok(totalArea(everywhere.layers) > 0);
});

test('branches widen with their height: tips 4 mm up stay a tip wide, tips 12 mm up reach the branch diameter', () => {
  const widest = (top: number) => {
    // a 16 mm slab on a 4 mm post, its underside `top` mm up
    const boxes: Box[] = [
      { x: [-2, 2], y: [-2, 2], z: [0, top] },
      { x: [-8, 8], y: [-8, 8], z: [top, top + 2] },
    ];
    const { layers, cfg } = supported(boxes, { supportType: 'tree' });
    const { nodes, rules } = planOf(new ModelLayers(layers, cfg));
    let w = 0;
    for (const layer of nodes) for (const n of layer) if (!n.dead) w = Math.max(w, n.r);
    return { w, rules, cfg };
  };
  const low = widest(4);
  assert.equal(
    low.w,
    low.rules.tipR,
    `under a 4 mm overhang the widest branch is ${low.w} µm in radius, a tip ${low.rules.tipR}`,
  );
  // tips 12 mm up (the roof and gap below the slab) allow 12 / 5 mm: more than the 2 mm branch diameter
  const high = widest(12);
  assert.ok(
    high.w >= high.rules.branchR,
    `under a 12 mm overhang the widest branch is ${high.w} µm in radius, the branch radius ${high.rules.branchR}`,
  );
  assert.ok(high.cfg.supportTreeBranchDiameter * UM_PER_MM < (12 * UM_PER_MM) / BRANCH_SLENDERNESS);
});

test('with no roof the tips stand closer, so that they hold the part: every overhang point within 1 mm of support', () => {
  // the part's first layer then bridges at most about 2 mm between tips
  const heldWithin = (options: SliceOptions) => {
    const { layers, cfg } = supported(T_SHAPE, { supportType: 'tree', supportInterfaceLayers: 0, ...options });
    const model = new ModelLayers(layers, cfg);
    return heldShare(layers, cfg, (j) => model.collision(j), 1 * UM_PER_MM);
  };
  const close = heldWithin({});
  assert.ok(close.total > 100, `only ${close.total} overhang points`);
  assert.equal(close.held, close.total, `unheld: ${JSON.stringify(close.missed.slice(0, 5))}`);
  // at the roof's 3 mm spacing, points lie up to 1.7 mm from the nearest tip's centre
  const sparse = heldWithin({ supportTreeTipSpacing: 3 });
  assert.ok(sparse.held < 0.9 * sparse.total, `3 mm apart: ${sparse.held} of ${sparse.total} held within 1 mm`);
});

test('a slope stepping out less than half a line beyond what holds itself gets tips and no roof; a flatter one gets its roof', () => {
  // a 10 mm post 6 mm high, then fifteen 0.2 mm layers each stepping out `step` mm further in x
  const roofUnder = (step: number) => {
    const boxes: Box[] = [{ x: [-5, 5], y: [-5, 5], z: [0, 6] }];
    for (let k = 0; k < 15; k++)
      boxes.push({ x: [-5, 5 + (k + 1) * step], y: [-5, 5], z: [6 + 0.2 * k, 6 + 0.2 * (k + 1)] });
    const { layers } = supported(boxes, { supportType: 'tree' });
    // the first band stands right over the post's wall, where no tip that is to reach the bed has room: it
    // gets a column beside the wall, with its roof, as normal support gives it (tree-pockets.ts)
    const columns = layers.map((l) => (l.support?.columnBody ? area(l.support.columnBody) : 0));
    const roof = layers.reduce((s, l, j) => s + (l.support && columns[j] === 0 ? area(l.support.roof) : 0), 0) / 1e6;
    const body = layers.reduce((s, l) => s + (l.support ? area(l.support.body) : 0), 0) / 1e6;
    return { roof, body, columnOnBed: columns[0] / 1e6 };
  };
  // 50°: a layer holds itself 0.24 mm out; a 0.35 mm step leaves bands 0.11 mm wide, a 0.8 mm step 0.56 mm
  const steep = roofUnder(0.35);
  assert.ok(steep.body > 1, `tips under the steep slope: ${steep.body.toFixed(1)} mm² of branches`);
  assert.ok(steep.columnOnBed > 1, `a column on the bed beside the post: ${steep.columnOnBed.toFixed(2)} mm²`);
  // what roof there is off the column: the tops of tips right under the part (92 mm² when every band had its roof)
  assert.ok(steep.roof < 2, `no roof under bands a line cannot print: ${steep.roof.toFixed(2)} mm²`);
  const flat = roofUnder(0.8);
  assert.ok(
    flat.roof > 2 * 15 * 0.56 * 10,
    `a roof under the flatter slope's bands, two layers each: ${flat.roof.toFixed(1)} mm²`,
  );
});

test('with build-plate placement, branches lean round a slab to the bed and hold the whole plate above it; none stands on the slab', () => {
  // a slab 30 × 12 mm, 2 mm thick; a post at one end to 20 mm; a plate over all of it, 3 mm beyond the slab
  const boxes: Box[] = [
    { x: [0, 30], y: [-6, 6], z: [0, 2] },
    { x: [26, 30], y: [-6, 6], z: [2, 20] },
    { x: [-3, 30], y: [-6, 6], z: [20, 22] },
  ];
  const { layers, cfg } = supported(boxes, { supportType: 'tree', supportPlacement: 'buildPlate' });
  const model = new ModelLayers(layers, cfg);
  // no point of the plate's underside is further than 6 mm from the slab's long sides: 18 mm up, a branch leans
  // that far; before the avoidance left room to lean, every branch was dropped here (0 of 1392 points held)
  const { held, total, missed } = heldShare(layers, cfg, (j) => model.collision(j), 200);
  assert.ok(total > 1000, `only ${total} overhang points`);
  assert.equal(held, total, `unheld: ${JSON.stringify(missed.slice(0, 5))}`);
  const slab = rect(0, -6000, 30000, 6000);
  // the slab's top is layer 9's: the two layers above it have no support over it (higher up, a branch leaning
  // out may pass over its edge)
  for (let j = 10; j < 12; j++)
    assert.equal(area(intersection(supportArea(layers[j]), [slab])), 0, `support over the slab on layer ${j}`);
});

test('under a bridge 5 mm wide with a roof, the tips stand in one row (none nearer another than the roof reaches) and hold every overhang point', () => {
  // a bar 34 mm long on two posts: its underside between them overhangs
  const bridge: Box[] = [
    { x: [-17, -15], y: [-2.5, 2.5], z: [0, 11] },
    { x: [15, 17], y: [-2.5, 2.5], z: [0, 11] },
    { x: [-17, 17], y: [-2.5, 2.5], z: [10, 11] },
  ];
  const { layers, cfg } = supported(bridge, { supportType: 'tree' });
  const model = new ModelLayers(layers, cfg);
  const plan = planOf(model);
  let top = plan.nodes.length - 1;
  while (top > 0 && plan.nodes[top].length === 0) top--;
  const tips = plan.nodes[top];
  // 30 mm of overhang, tips 3 mm apart: one row is 11 to 13; with edge tips 0.6 of the spacing apart there were 31
  assert.ok(tips.length >= 10 && tips.length <= 15, `${tips.length} tips`);
  for (const a of tips)
    for (const b of tips) if (a !== b) assert.ok(Math.hypot(a.x - b.x, a.y - b.y) >= plan.rules.tipGap - 1);
  const { held, total } = heldShare(layers, cfg, (j) => model.collision(j), (cfg.supportLineWidthMm * UM_PER_MM) / 2);
  assert.ok(total > 500);
  assert.equal(held, total);
});
