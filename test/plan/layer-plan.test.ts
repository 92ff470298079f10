import { test } from 'node:test';
import assert from 'node:assert/strict';
import { rect } from '../geometry/test-shapes.js';
import type { ExPolygon } from '#strata/geometry/types.js';
import { entryStyle } from '#strata/paths/roles.js';
import type { LayerPaths, PathEntry, PathGroup } from '#strata/paths/types.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { planLayer } from '#strata/plan/layer-plan.js';
import type { ExtrudeStep } from '#strata/plan/types.js';

const BASE: SliceOptions = {
  wallOrder: 'inner-first',
  perimeterSpeed: 30,
  innerWallSpeed: 50,
  overhangWallSpeed: 12,
  bridgeSpeed: 20,
  bridgeFlow: 90,
  bridgeFanSpeed: 100,
  fanSpeed: 40,
  supportSpeed: 45,
};
const cfg = resolveConfig(BASE);
const sq = (x: number, y: number, s: number) => rect(x, y, x + s, y + s).outer;

/** A group as written here: its entries' styles come from the role table. */
type TestGroup = Omit<PathGroup, 'entries'> & { entries: Omit<PathEntry, 'style'>[] };

function layer(groups: TestGroup[]): LayerPaths {
  const styled = groups.map(
    (g): PathGroup => ({ ...g, entries: g.entries.map((e) => ({ ...e, style: entryStyle(cfg, e.role, e.wall) })) }),
  );
  return { index: 5, z: 1.2, height: 0.2, sliceZ: 1.1, lineWidthMm: 0.4, groups: styled };
}

const island: TestGroup = {
  kind: 'island',
  object: 0,
  area: rect(0, 0, 20_000, 20_000),
  boundary: [sq(200, 200, 19_600)],
  entries: [
    {
      role: 'skin',
      closed: false,
      paths: [
        [
          { x: 1_000, y: 5_000 },
          { x: 10_000, y: 5_000 },
          { x: 19_000, y: 5_000 },
        ],
      ],
      width: 0.4,
      overAir: [Uint8Array.from([0, 1])],
    },
    {
      role: 'wall',
      wall: 0,
      closed: true,
      paths: [sq(200, 200, 19_600)],
      width: 0.4,
      overAir: [Uint8Array.from([0, 1, 0, 0])],
    },
    { role: 'wall', wall: 1, closed: true, paths: [sq(600, 600, 18_800)], width: 0.4 },
    {
      role: 'infill',
      closed: false,
      paths: [
        [
          { x: 2_000, y: 2_000 },
          { x: 18_000, y: 18_000 },
        ],
      ],
      width: 0.4,
    },
  ],
};
const support: TestGroup = {
  kind: 'support',
  area: rect(30_000, 0, 40_000, 10_000),
  entries: [
    {
      role: 'support',
      closed: false,
      paths: [
        [
          { x: 31_000, y: 1_000 },
          { x: 39_000, y: 1_000 },
        ],
      ],
      width: 0.4,
    },
  ],
};

test('groups print support first, entries in print order (inner wall, outer wall, infill, skin), each extrusion tagged with its object', () => {
  const plan = planLayer(layer([island, support]), cfg, { at: { x: 0, y: 0 } });
  const ex = plan.steps.filter((s): s is ExtrudeStep => s.kind === 'extrude');
  const order = ex.map((s) => s.feature).filter((f, i, a) => i === 0 || a[i - 1] !== f);
  assert.deepEqual(order, ['SUPPORT', 'WALL-INNER', 'WALL-OUTER', 'FILL', 'SKIN', 'BRIDGE']);
  assert.equal(ex[0].speed, 45);
  assert.ok(ex.filter((s) => s.feature !== 'SUPPORT').every((s) => s.object === 0));
  assert.equal(ex[0].object, undefined);
});

test('runs over air: the overhanging wall edge slowed, bridge skin with its own speed, flow and fan', () => {
  const plan = planLayer(layer([island]), cfg, { at: { x: 0, y: 0 } });
  const ex = plan.steps.filter((s): s is ExtrudeStep => s.kind === 'extrude');
  const outer = ex.filter((s) => s.feature === 'WALL-OUTER');
  // the seam decides where the loop starts: two or three runs, the flagged edge (19.6 mm) at overhangWallSpeed
  assert.ok(
    outer.length >= 2 && outer.every((s) => s.speed === 12 || s.speed === 30),
    `speeds ${outer.map((s) => s.speed)}`,
  );
  const len = (s: ExtrudeStep) =>
    s.points.slice(1).reduce((l, p, i) => l + Math.hypot(p.x - s.points[i].x, p.y - s.points[i].y), 0);
  assert.deepEqual(outer.filter((s) => s.speed === 12).map(len), [19_600]);
  assert.equal(
    outer.filter((s) => s.speed === 30).reduce((l, s) => l + len(s), 0),
    3 * 19_600,
  );
  // the three runs join up: each starts where the previous ended
  for (let k = 1; k < outer.length; k++)
    assert.deepEqual(outer[k].points[0], outer[k - 1].points[outer[k - 1].points.length - 1]);
  const bridge = ex.filter((s) => s.feature === 'BRIDGE');
  assert.equal(bridge.length, 1);
  assert.deepEqual([bridge[0].speed, bridge[0].flow, bridge[0].fan], [20, 0.9, 1]);
  const skin = ex.find((s) => s.feature === 'SKIN')!;
  assert.equal(skin.fan, undefined, 'skin on solid ground keeps the layer fan');
  assert.equal(plan.fan, 0.4);
});

test('the first layer prints everything at first-layer speed and sets no over-air style', () => {
  const plan = planLayer(layer([island]), cfg, { at: { x: 0, y: 0 } }, 0);
  const ex = plan.steps.filter((s): s is ExtrudeStep => s.kind === 'extrude');
  assert.ok(ex.every((s) => s.speed === cfg.firstLayerSpeed && s.feature !== 'BRIDGE'));
});

test('a travel from support to support retracts only where it would pass over the part (this layer or the one below), or with the setting off', () => {
  const line = (x0: number, x1: number) => [
    { x: x0, y: 5_000 },
    { x: x1, y: 5_000 },
  ];
  const a: TestGroup = {
    kind: 'support',
    area: rect(30_000, 0, 40_000, 10_000),
    entries: [{ role: 'support', closed: false, paths: [line(31_000, 39_000)], width: 0.4 }],
  };
  const b: TestGroup = {
    kind: 'support',
    area: rect(50_000, 0, 60_000, 10_000),
    entries: [{ role: 'support', closed: false, paths: [line(51_000, 59_000)], width: 0.4 }],
  };
  const between: TestGroup = {
    kind: 'island',
    object: 0,
    area: rect(42_000, 0, 48_000, 10_000),
    entries: [
      {
        role: 'infill',
        closed: false,
        paths: [
          [
            { x: 43_000, y: 1_000 },
            { x: 47_000, y: 9_000 },
          ],
        ],
        width: 0.4,
      },
    ],
  };
  const inside: TestGroup = { kind: 'island', object: 0, area: rect(20_000, -20_000, 70_000, 30_000), entries: [] };
  const start = { x: 30_000, y: 5_000 };
  // whether the travel from a to b (after the first extrusion) retracts
  const retracts = (groups: TestGroup[], c = cfg, below?: ExPolygon[]) => {
    const plan = planLayer(layer(groups), c, { at: start, below });
    const first = plan.steps.findIndex((s) => s.kind === 'extrude');
    const hop = plan.steps.slice(first).find((s) => s.kind === 'travel');
    assert.ok(hop && hop.kind === 'travel');
    assert.deepEqual(hop.points[hop.points.length - 1], { x: 51_000, y: 5_000 });
    return hop.retract;
  };
  assert.equal(retracts([a, b]), false, 'over air between two support areas');
  assert.equal(retracts([a, b, between]), true, 'across an island of this layer');
  assert.equal(retracts([a, b], cfg, [between.area!]), true, 'across an island of the layer below');
  assert.equal(retracts([a, b], cfg, [inside.area!]), true, 'over the top of the part below, crossing no edge of it');
  assert.equal(
    retracts([a, b], resolveConfig({ supportEnabled: true, supportLimitRetractions: false })),
    true,
    'with the setting off',
  );
});

test('a wall graded by how much of it hangs over nothing: each level at its own speed, levels that print alike one run, the overhang fan on them', () => {
  const graded = resolveConfig({
    perimeterSpeed: 30,
    dynamicOverhangSpeeds: true,
    overhangSpeed25: 24,
    overhangSpeed50: 18,
    overhangSpeed75: 18,
    overhangWallSpeed: 6,
    overhangFanSpeed: 60,
  });
  const line = [0, 10_000, 12_000, 14_000, 16_000, 20_000, 22_000].map((x) => ({ x, y: 5_000 }));
  const entry: PathEntry = {
    role: 'wall',
    wall: 0,
    closed: false,
    paths: [line],
    width: 0.4,
    overAir: [Uint8Array.from([0, 1, 2, 3, 4, 0])],
    style: entryStyle(graded, 'wall', 0),
  };
  const plan = planLayer(
    {
      index: 5,
      z: 1.2,
      height: 0.2,
      sliceZ: 1.1,
      lineWidthMm: 0.4,
      groups: [{ kind: 'island', object: 0, entries: [entry] }],
    },
    graded,
    { at: { x: 0, y: 5_000 } },
  );
  const ex = plan.steps.filter((s): s is ExtrudeStep => s.kind === 'extrude');
  assert.deepEqual(
    ex.map((s) => [s.points[0].x, s.points[s.points.length - 1].x, s.speed, s.fan]),
    [
      [0, 10_000, 30, undefined],
      [10_000, 12_000, 24, 0.6],
      [12_000, 16_000, 18, 0.6],
      [16_000, 20_000, 6, 0.6],
      [20_000, 22_000, 30, undefined],
    ],
  );
  // the first layer prints every level at the first-layer speed
  const first = planLayer(
    {
      index: 0,
      z: 0.2,
      height: 0.2,
      sliceZ: 0.1,
      lineWidthMm: 0.4,
      groups: [{ kind: 'island', object: 0, entries: [entry] }],
    },
    graded,
    { at: { x: 0, y: 5_000 } },
    0,
  );
  assert.deepEqual(
    first.steps.filter((s): s is ExtrudeStep => s.kind === 'extrude').map((s) => s.speed),
    [graded.firstLayerSpeed],
  );
});

test('a long travel inside the innermost wall does not retract; one that crosses the walls does; retractCrossingWallsOnly off, combingMaxDistance', () => {
  const inner = sq(600, 600, 18_800);
  // two infill lines 15 mm apart, both inside the inner wall; a third outside it (in the walls' band, as a thin part's gap fill is)
  const lines = (extra: boolean): TestGroup => ({
    ...island,
    inner: [inner],
    entries: [
      {
        role: 'infill',
        closed: false,
        ordered: true,
        paths: [
          [
            { x: 2_000, y: 2_000 },
            { x: 2_000, y: 3_000 },
          ],
          [
            { x: 17_000, y: 17_000 },
            { x: 17_000, y: 18_000 },
          ],
          ...(extra
            ? [
                [
                  { x: 300, y: 10_000 },
                  { x: 300, y: 11_000 },
                ],
              ]
            : []),
        ],
        width: 0.4,
      },
    ],
  });
  const retracts = (c: typeof cfg, g: TestGroup) =>
    planLayer(layer([g]), c, { at: { x: 2_000, y: 2_000 } })
      .steps.filter((s) => s.kind === 'travel')
      .map((s) => s.kind === 'travel' && s.retract);
  // the first travel arrives at the layer (a layer change retracts); the one between the lines stays inside
  assert.deepEqual(retracts(cfg, lines(false)), [true, false]);
  assert.deepEqual(
    retracts(cfg, lines(true)),
    [true, false, true],
    "to the line in the walls' band: crosses the inner wall",
  );
  assert.deepEqual(
    retracts(resolveConfig({ ...BASE, retractCrossingWallsOnly: false }), lines(false)),
    [true, true],
    'off: long travels retract',
  );
  assert.deepEqual(
    retracts(resolveConfig({ ...BASE, combingMaxDistance: 10 }), lines(false)),
    [true, true],
    'longer than combingMaxDistance',
  );
  // without the group's innermost loops: the length rule
  assert.deepEqual(retracts(cfg, { ...lines(false), inner: undefined }), [true, true]);
});

test('retractOnLayerChange off: a layer that starts over the island it is above travels in without a retraction', () => {
  const g: TestGroup = {
    ...island,
    inner: [sq(600, 600, 18_800)],
    entries: [
      {
        role: 'infill',
        closed: false,
        ordered: true,
        paths: [
          [
            { x: 5_000, y: 5_000 },
            { x: 5_000, y: 6_000 },
          ],
        ],
        width: 0.4,
      },
    ],
  };
  const first = (c: typeof cfg, at: { x: number; y: number }) =>
    planLayer(layer([g]), c, { at }).steps.find((s) => s.kind === 'travel');
  const off = resolveConfig({ ...BASE, retractOnLayerChange: false });
  assert.equal(
    first(cfg, { x: 15_000, y: 15_000 })?.kind === 'travel' && first(cfg, { x: 15_000, y: 15_000 })!.retract,
    true,
  );
  const inside = first(off, { x: 15_000, y: 15_000 });
  assert.ok(inside?.kind === 'travel' && !inside.retract, 'from above the island: no retraction');
  const outside = first(off, { x: 50_000, y: 50_000 });
  assert.ok(outside?.kind === 'travel' && outside.retract, 'from outside it: the usual retraction');
});

test('infill, skin lines and skin gap loops of an island print as one nearest-first tour', () => {
  const g: TestGroup = {
    ...island,
    entries: [
      {
        role: 'infill',
        closed: false,
        paths: [
          [
            { x: 1_000, y: 1_000 },
            { x: 5_000, y: 1_000 },
          ],
        ],
        width: 0.4,
      },
      {
        role: 'skin',
        closed: false,
        paths: [
          [
            { x: 15_000, y: 15_000 },
            { x: 18_000, y: 15_000 },
          ],
        ],
        width: 0.4,
      },
      { role: 'skin-gap', closed: true, paths: [sq(5_500, 1_200, 300)], width: 0.4 },
    ],
  };
  const plan = planLayer(layer([g]), cfg, { at: { x: 1_000, y: 1_000 } });
  const ex = plan.steps.filter((s): s is ExtrudeStep => s.kind === 'extrude');
  // the gap loop beside the infill's end before the far skin line (by role alone it would come last)
  assert.deepEqual(
    ex.map((s) => [s.feature, s.closed]),
    [
      ['FILL', false],
      ['SKIN', true],
      ['SKIN', false],
    ],
  );
  let travel = 0;
  let at = { x: 1_000, y: 1_000 };
  for (const s of plan.steps) {
    if (s.kind === 'travel') for (const p of s.points) (travel += Math.hypot(p.x - at.x, p.y - at.y)), (at = p);
    else at = s.closed ? s.points[0] : s.points[s.points.length - 1];
  }
  assert.ok(travel < 20_000, `travel ${travel} µm`);
});
