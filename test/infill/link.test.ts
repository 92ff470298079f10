import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { clipSweep } from '#strata/infill/sweep.js';
import { linkPieces } from '#strata/infill/link.js';
import { regionGeom } from '#strata/infill/region-index.js';
import type { Piece } from '#strata/infill/piece.js';
import { TEST_SHAPES, SHAPE_CENTRE } from './test-shapes.js';
import { generateInfill, LINK_REACH } from '#strata/infill/generate.js';
import { testParams } from './test-shapes.js';

function len(l: readonly Pt[]): number {
  let s = 0;
  for (let i = 1; i < l.length; i++) s += Math.hypot(l[i].x - l[i - 1].x, l[i].y - l[i - 1].y);
  return s;
}

test('parallel lines in a convex region link into one zig-zag along the boundary', () => {
  const region = TEST_SHAPES.square();
  const geom = regionGeom(region);
  const pieces: Piece[] = [];
  clipSweep(geom, { angle: 45, spacingUm: 3_000, offsetUm: 0 }, SHAPE_CENTRE, pieces);
  const { lines, connectorLength } = linkPieces(geom, pieces, LINK_REACH * 3_000);
  assert.equal(lines.length, 1);
  const raw = pieces.map((p) => len(p.pts)).reduce((a, b) => a + b, 0);
  assert.ok(Math.abs(len(lines[0]) - raw - connectorLength) < pieces.length * 2);
  // every connector is one gap: 3 mm / sin 45° (or less round a corner)
  assert.ok(connectorLength <= (pieces.length - 1) * 3_000 * Math.SQRT2 + 1);
});

test('ends farther apart than the reach along the boundary stay apart', () => {
  const region = TEST_SHAPES.square();
  const geom = regionGeom(region);
  const pieces: Piece[] = [];
  clipSweep(geom, { angle: 0, spacingUm: 10_000, offsetUm: 0 }, SHAPE_CENTRE, pieces);
  assert.equal(linkPieces(geom, pieces, 9_000).lines.length, pieces.length);
  assert.equal(linkPieces(geom, pieces, 11_000).lines.length, 1);
});

test('a hole: lines cut by it are linked round it without crossing it', () => {
  const region = TEST_SHAPES['disc with hole']();
  const r = generateInfill('lines', { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region }, testParams(0.2));
  const unlinked = generateInfill(
    'lines',
    { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region },
    testParams(0.2, { connect: false }),
  );
  assert.ok(r.lines.length < unlinked.lines.length / 4, `${r.lines.length} vs ${unlinked.lines.length}`);
});
