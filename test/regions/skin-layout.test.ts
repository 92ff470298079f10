import { test } from 'node:test';
import assert from 'node:assert/strict';
import { skinLayout } from '#strata/regions/skin-layout.js';
import type { RegionFill } from '#strata/regions/types.js';
import { area, difference, offset, union } from '#strata/geometry/clip.js';
import type { ExPolygon } from '#strata/geometry/types.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { rect } from '../geometry/test-shapes.js';

const W = 400;
const MM2 = 1e6;

/** A region whose skin is `top` and `bottom` (bottom skin over air where `bridge`, anchored as `anchored`). */
function region(top: ExPolygon[], bottom: ExPolygon[], extra: Partial<RegionFill> = {}): RegionFill {
  const skin = top.length && bottom.length ? union(top, bottom) : top.length ? top : bottom;
  return {
    region: 0,
    topSkin: top,
    bottomSkin: bottom,
    skin,
    exposed: skin,
    bridge: [],
    bridgeAngle: null,
    sparse: [],
    ...extra,
  };
}

/** Area of the part of `a` outside `b`, mm². */
const outside = (a: ExPolygon[], b: ExPolygon[]) => area(difference(a, b)) / MM2;

test('skin walls run half a line in from the skin, its lines fill inside them, overlapping them by skinOverlap', () => {
  const cfg = resolveConfig({ skinWall: true, skinOverlap: 10 });
  const skin = [rect(0, 0, 20000, 10000)];
  const layout = skinLayout(region(skin, []), cfg, W, []);
  assert.equal(layout.walls.length, 1);
  const wall = layout.walls[0]!;
  assert.deepEqual(
    [Math.min(...wall.map((p) => p.x)), Math.max(...wall.map((p) => p.y))],
    [W / 2, 10000 - W / 2],
    'the wall’s centreline is half a line in',
  );
  assert.equal(layout.parts.length, 1);
  assert.equal(layout.parts[0]!.pattern, 'lines');
  // lines' centres: a line and a half in from the skin's edge, less the overlap
  const expected = offset(skin, -(W / 2 + W - 0.1 * W));
  assert.ok(Math.abs(area(layout.parts[0]!.area) - area(expected)) < 1000, 'fill area inside the wall');
  assert.equal(layout.bridge, null);
  assert.deepEqual(layout.overAir, []);
  // without a skin wall, lines start half a line in
  const plain = skinLayout(region(skin, []), resolveConfig({ skinWall: false, skinOverlap: 10 }), W, []);
  assert.deepEqual(plain.walls, []);
  assert.ok(Math.abs(area(plain.parts[0]!.area) - area(offset(skin, -(W / 2 - 0.1 * W)))) < 1000);
});

test('an anchored bridge prints as its own lines; the rest of the skin and gap fill leave it to them', () => {
  const cfg = resolveConfig({ skinWall: false });
  const bridge = [rect(5000, 0, 15000, 10000)];
  const bottom = [rect(0, 0, 20000, 10000)];
  const fill = region([], bottom, { bridge, bridgeAngle: 0, bridgeFill: { area: bridge, angle: 0 } });
  const layout = skinLayout(fill, cfg, W, []);
  assert.ok(layout.bridge, 'the bridge prints as bridge lines');
  assert.equal(layout.bridge.angle, 0);
  assert.equal(layout.bridge.spacingUm, Math.round((cfg.nozzleDiameter + 0.05) * 1000));
  assert.ok(outside(layout.bridge.centres, bridge) < 0.01, 'bridge beads inside the bridge');
  const skin = layout.parts.flatMap((p) => p.area);
  assert.ok(area(skin) > 0, 'the skin either side of the bridge has lines');
  assert.ok(area(difference(skin, difference(bottom, bridge))) < 1000, 'no skin line inside the bridge');
  assert.ok(outside(layout.exposed, difference(bottom, offset(bridge, W / 2))) < 0.01, 'gap fill leaves the bridge');
  assert.deepEqual(layout.overAir, bridge, 'the bridge is over air');
});

test('support right below holds part of a bridge up: that part is no bridge, and the bridge prints as skin', () => {
  const cfg = resolveConfig({ skinWall: false });
  const bridge = [rect(5000, 0, 15000, 10000)];
  const bottom = [rect(0, 0, 20000, 10000)];
  const fill = region([], bottom, { bridge, bridgeAngle: 0, bridgeFill: { area: bridge, angle: 0 } });
  const support = [rect(5000, 0, 8000, 10000)];
  const layout = skinLayout(fill, cfg, W, support);
  assert.equal(layout.bridge, null, 'no bridge lines');
  assert.ok(
    Math.abs(area(layout.overAir) - area(difference(bridge, support))) < 1000,
    'over air: the bridge less the support',
  );
  assert.ok(outside(offset(bottom, -W), layout.parts[0]!.area) < 0.01, 'skin lines over all the skin, bridge included');
  // support not under the bridge changes nothing
  const aside = skinLayout(fill, cfg, W, [rect(30000, 0, 31000, 1000)]);
  assert.ok(aside.bridge);
  assert.equal(area(aside.overAir), area(bridge));
});

test('top and bottom patterns that differ split the fill area where they meet, half a line short of each other', () => {
  const cfg = resolveConfig({ skinWall: false, topSkinPattern: 'lines', bottomSkinPattern: 'concentric' });
  const top = [rect(0, 0, 10000, 10000)];
  const bottom = [rect(10000, 0, 20000, 10000)];
  const layout = skinLayout(region(top, bottom), cfg, W, []);
  assert.deepEqual(
    layout.parts.map((p) => p.pattern),
    ['concentric', 'lines'],
    'bottom first',
  );
  const [b, t] = layout.parts.map((p) => p.area);
  assert.ok(outside(b!, offset(bottom, 0)) < 0.01 && outside(t!, top) < 0.01, 'each part within its own skin');
  assert.ok(
    outside(b!, difference(bottom, offset(top, W / 2))) < 0.01,
    'the bottom part stops half a line short of the top',
  );
  // a bridging region lays its concentric bottom skin as lines: then one pattern, one part
  const bridging = skinLayout(region(top, bottom, { bridgeAngle: 30 }), cfg, W, []);
  assert.deepEqual(
    bridging.parts.map((p) => p.pattern),
    ['lines'],
  );
});

test('no skin and nothing exposed: nothing laid out', () => {
  const layout = skinLayout(region([], []), resolveConfig(), W, []);
  assert.deepEqual(layout, { overAir: [], bridge: null, walls: [], parts: [], exposed: [] });
});
