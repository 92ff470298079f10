import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { generateInfill } from '#strata/infill/generate.js';
import { hexSide } from '#strata/infill/patterns/hexagons.js';
import { TEST_SHAPES, testParams } from '../test-shapes.js';

function segments(lines: Pt[][]): Array<[Pt, Pt]> {
  const out: Array<[Pt, Pt]> = [];
  for (const l of lines) for (let i = 1; i < l.length; i++) out.push([l[i - 1], l[i]]);
  return out;
}

function cross(a: Pt, b: Pt, c: Pt): number {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

test('hexagons: continuous chains, no crossing or overlapping segments, neighbours one width apart', () => {
  const params = testParams(0.3, { connect: false });
  const r = generateInfill(
    'hexagons',
    { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region: TEST_SHAPES.square() },
    params,
  );
  const segs = segments(r.lines);
  // chains: far fewer paths than segments
  assert.ok(r.lines.length * 10 < segs.length, `${r.lines.length} paths, ${segs.length} segments`);
  for (let i = 0; i < segs.length; i++) {
    for (let j = i + 1; j < segs.length; j++) {
      const [a, b] = segs[i],
        [c, d] = segs[j];
      const d1 = cross(a, b, c),
        d2 = cross(a, b, d),
        d3 = cross(c, d, a),
        d4 = cross(c, d, b);
      const proper = ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
      assert.ok(!proper, `segments ${i} and ${j} cross`);
    }
  }
  // the honeycomb's cell side follows the density
  assert.ok(hexSide(0.3, params.lineWidthUm) > 4 * params.lineWidthUm);
});
