import { test } from 'node:test';
import assert from 'node:assert/strict';
import { rect } from '../geometry/test-shapes.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { makeEntry } from '#strata/paths/entry.js';
import { entryStyle, flagStyle, overAirMatters } from '#strata/paths/roles.js';

const base = { perimeterSpeed: 30, innerWallSpeed: 50, overhangWallSpeed: 10 };

test('walls over air: without dynamic overhang speeds one slowed style, flags 0 or 1, no overhang fan', () => {
  const style = entryStyle(resolveConfig(base), 'wall', 0);
  assert.equal(style.levels, undefined);
  assert.deepEqual([style.normal.speed, style.overAir.speed, style.overAir.fan], [30, 10, undefined]);
  assert.equal(flagStyle(style, 1), style.overAir);
  assert.equal(flagStyle(style, 0), style.normal);
});

test('dynamic overhang speeds: a style per level, never faster than the wall, levels that print alike one style', () => {
  const cfg = resolveConfig({
    ...base,
    dynamicOverhangSpeeds: true,
    overhangSpeed25: 40,
    overhangSpeed50: 20,
    overhangSpeed75: 20,
  });
  const outer = entryStyle(cfg, 'wall', 0);
  assert.deepEqual(
    outer.levels!.map((s) => s.speed),
    [30, 30, 20, 20, 10],
    'the quarter step (40) is not faster than the outer wall (30)',
  );
  assert.equal(outer.levels![1], outer.normal, "a step that prints as the wall is the wall's style");
  assert.equal(outer.levels![2], outer.levels![3], 'half and three quarters print alike: one style, one run');
  assert.equal(outer.levels![4].speed, outer.overAir.speed);
  assert.ok(overAirMatters(outer));
  const inner = entryStyle(cfg, 'wall', 1);
  assert.deepEqual(
    inner.levels!.map((s) => s.speed),
    [50, 40, 20, 20, 10],
  );
  assert.ok(inner.levels!.every((s) => s.feature === 'WALL-INNER'));
  // extra walls over overhangs grade the same way; skin keeps its bridge style
  assert.deepEqual(
    entryStyle(cfg, 'extra-wall').levels!.map((s) => s.speed),
    [50, 40, 20, 20, 10],
  );
  assert.equal(entryStyle(cfg, 'skin').levels, undefined);
  // every step at the wall's speed or faster, and no fan: nothing to grade
  const none = resolveConfig({
    ...base,
    overhangWallSpeed: 30,
    dynamicOverhangSpeeds: true,
    overhangSpeed25: 30,
    overhangSpeed50: 30,
    overhangSpeed75: 30,
  });
  assert.equal(entryStyle(none, 'wall', 0).levels, undefined);
  assert.ok(!overAirMatters(entryStyle(none, 'wall', 0)));
});

test('overhang fan: every overhanging run of a wall gets it, the wall itself and skin do not', () => {
  const fan = entryStyle(resolveConfig({ ...base, overhangFanSpeed: 40 }), 'wall', 0);
  assert.deepEqual([fan.normal.fan, fan.overAir.fan, fan.levels], [undefined, 0.4, undefined]);
  const graded = entryStyle(resolveConfig({ ...base, overhangFanSpeed: 40, dynamicOverhangSpeeds: true }), 'wall', 0);
  assert.deepEqual(
    graded.levels!.map((s) => s.fan),
    [undefined, 0.4, 0.4, 0.4, 0.4],
  );
  // the fan alone makes runs over air matter, at the wall's speed
  const only = entryStyle(resolveConfig({ ...base, overhangWallSpeed: 30, overhangFanSpeed: 0 }), 'wall', 0);
  assert.deepEqual([only.overAir.speed, only.overAir.fan], [30, 0]);
  assert.equal(
    entryStyle(resolveConfig({ ...base, overhangFanSpeed: 40 }), 'skin').overAir.fan,
    1,
    'bridges keep bridgeFanSpeed',
  );
});

test('a graded wall entry is flagged with levels from the level areas, level 4 from the area over air', () => {
  const cfg = resolveConfig({ ...base, dynamicOverhangSpeeds: true });
  const levels = [
    rect(10_000, -5_000, 40_000, 5_000),
    rect(12_000, -5_000, 40_000, 5_000),
    rect(14_000, -5_000, 40_000, 5_000),
  ];
  const air = [rect(16_000, -5_000, 40_000, 5_000)];
  const e = makeEntry(
    cfg,
    'wall',
    false,
    [
      [
        { x: 0, y: 0 },
        { x: 20_000, y: 0 },
      ],
    ],
    0.4,
    { wall: 0, overAir: air, overhangLevels: levels.map((a) => [a]) },
  );
  assert.deepEqual([...e.overAir![0]!], [0, 1, 2, 3, 4]);
  // without level areas (a layer whose walls have none), the area over air is still level 4
  const only = makeEntry(
    cfg,
    'wall',
    false,
    [
      [
        { x: 0, y: 0 },
        { x: 20_000, y: 0 },
      ],
    ],
    0.4,
    { wall: 0, overAir: air },
  );
  assert.deepEqual([...only.overAir![0]!], [0, 4]);
  // binary flags without dynamic speeds
  const binary = makeEntry(
    resolveConfig(base),
    'wall',
    false,
    [
      [
        { x: 0, y: 0 },
        { x: 20_000, y: 0 },
      ],
    ],
    0.4,
    { wall: 0, overAir: air, overhangLevels: levels.map((a) => [a]) },
  );
  assert.deepEqual([...binary.overAir![0]!], [0, 1]);
});
