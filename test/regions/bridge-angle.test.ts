import { test } from 'node:test';
import assert from 'node:assert/strict';
import { bridgeAngle } from '#strata/regions/bridge-angle.js';
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import { solidFill } from '#strata/infill/solid-fill.js';

const W = 400;

/** A rectangle `length` × `width` µm from `at` along direction `deg` (its near edge's midpoint at `at`). */
function bar(at: Pt, deg: number, from: number, to: number, width: number): ExPolygon {
  const a = (deg * Math.PI) / 180;
  const u = { x: Math.cos(a), y: Math.sin(a) },
    n = { x: -Math.sin(a), y: Math.cos(a) };
  const p = (s: number, t: number) => ({
    x: Math.round(at.x + s * u.x + t * n.x),
    y: Math.round(at.y + s * u.y + t * n.y),
  });
  return { outer: [p(from, -width / 2), p(to, -width / 2), p(to, width / 2), p(from, width / 2)], holes: [] };
}

const mod180 = (d: number) => ((d % 180) + 180) % 180;
const AT = { x: 100_000, y: 100_000 };

test('a bridge between two supports: skin lines run from one support to the other', () => {
  // the bridge's skin (inside its walls) spans 30 mm at 38°; pillars hold both ends on the layer below
  const skin = [bar(AT, 38, 1_000, 29_000, 4_000)];
  const below = [bar(AT, 38, -5_000, 500, 6_000), bar(AT, 38, 29_500, 35_000, 6_000)];
  const angle = bridgeAngle(skin, below, W);
  assert.ok(angle !== null);
  assert.ok(Math.abs(mod180(angle) - 38) < 1, `angle ${angle}`);
  // every line of the fill runs along the span (the zig-zag's short connectors aside)
  const lines = solidFill(skin, angle, W, { x: 0, y: 0 });
  let along = 0,
    across = 0;
  for (const l of lines) {
    for (let k = 1; k < l.length; k++) {
      const len = Math.hypot(l[k].x - l[k - 1].x, l[k].y - l[k - 1].y);
      const d = mod180((Math.atan2(l[k].y - l[k - 1].y, l[k].x - l[k - 1].x) * 180) / Math.PI);
      if (Math.min(Math.abs(d - 38), 180 - Math.abs(d - 38)) < 2) along += len;
      else across += len;
    }
  }
  assert.ok(along > 20 * across, `along ${along}, across ${across}`);
});

test('no bridge direction for skin resting mostly on the layer below, or held at one end only', () => {
  const skin = [bar(AT, 10, 0, 20_000, 4_000)];
  assert.equal(bridgeAngle(skin, [bar(AT, 10, -1_000, 21_000, 6_000)], W), null);
  assert.equal(bridgeAngle(skin, [bar(AT, 10, -5_000, 500, 6_000)], W), null);
  assert.equal(bridgeAngle([], [], W), null);
});
