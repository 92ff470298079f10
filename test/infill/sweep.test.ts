import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { clipLines } from '#strata/geometry/clip.js';
import { clipSweep, sweepConvexRing } from '#strata/infill/sweep.js';
import { regionGeom } from '#strata/infill/region-index.js';
import type { Piece } from '#strata/infill/piece.js';
import { TEST_SHAPES, hull, SHAPE_CENTRE } from './test-shapes.js';

function len(l: readonly Pt[]): number {
  let s = 0;
  for (let i = 1; i < l.length; i++) s += Math.hypot(l[i].x - l[i - 1].x, l[i].y - l[i - 1].y);
  return s;
}

/** The same family as long raw lines, for the facade's general clipper. */
function rawLines(angle: number, spacing: number, origin: Pt): Pt[][] {
  const a = (angle * Math.PI) / 180,
    c = Math.cos(a),
    s = Math.sin(a);
  const out: Pt[][] = [];
  for (let k = -40; k <= 40; k++) {
    const v = k * spacing;
    out.push([
      { x: origin.x - 80_000 * c - v * s, y: origin.y - 80_000 * s + v * c },
      { x: origin.x + 80_000 * c - v * s, y: origin.y + 80_000 * s + v * c },
    ]);
  }
  return out;
}

const shapes = { ...TEST_SHAPES, hull: () => hull(5) };

for (const [name, make] of Object.entries(shapes)) {
  test(`scanline clipper agrees with the facade's clipLines on ${name}`, () => {
    const region = make();
    const geom = regionGeom(region);
    for (const angle of [0, 45, 90, 17.3, 135]) {
      const pieces: Piece[] = [];
      clipSweep(geom, { angle, spacingUm: 1_700, offsetUm: 333 }, SHAPE_CENTRE, pieces);
      // (offset: no line runs exactly along an edge, where either answer is right)
      const o = {
        x: SHAPE_CENTRE.x - 333 * Math.sin((angle * Math.PI) / 180),
        y: SHAPE_CENTRE.y + 333 * Math.cos((angle * Math.PI) / 180),
      };
      const ref = clipLines(rawLines(angle, 1_700, o), region);
      const mine = pieces.map((p) => len(p.pts)).reduce((a, b) => a + b, 0);
      const theirs = ref.map(len).reduce((a, b) => a + b, 0);
      assert.ok(Math.abs(mine - theirs) <= 2 * ref.length + 2, `${name} ${angle}°: ${mine} vs ${theirs}`);
      assert.equal(pieces.length, ref.length, `${name} ${angle}°: piece count`);
    }
  });
}

test('every scanline segment end is anchored on the boundary point it reports', () => {
  const region = TEST_SHAPES['disc with hole']();
  const geom = regionGeom(region);
  const pieces: Piece[] = [];
  clipSweep(geom, { angle: 30, spacingUm: 900, offsetUm: 123 }, SHAPE_CENTRE, pieces);
  assert.ok(pieces.length > 20);
  for (const p of pieces) {
    for (const [pt, a] of [
      [p.pts[0], p.a0],
      [p.pts[p.pts.length - 1], p.a1],
    ] as const) {
      assert.ok(a, 'anchored');
      const ring = geom.rings[a.ring];
      let i = 0;
      while (i + 1 < ring.n && ring.cum[i + 1] <= a.pos) i++;
      const j = (i + 1) % ring.n,
        t = (a.pos - ring.cum[i]) / (ring.cum[i + 1] - ring.cum[i]);
      const x = ring.xs[i] + t * (ring.xs[j] - ring.xs[i]),
        y = ring.ys[i] + t * (ring.ys[j] - ring.ys[i]);
      assert.ok(Math.hypot(x - pt.x, y - pt.y) < 1, `${x},${y} vs ${pt.x},${pt.y}`);
    }
  }
});

test('offset shifts a family along its normal; lines pass through origin + offset·n', () => {
  const region = TEST_SHAPES.square();
  const geom = regionGeom(region);
  const pieces: Piece[] = [];
  clipSweep(geom, { angle: 0, spacingUm: 10_000, offsetUm: 2_500 }, SHAPE_CENTRE, pieces);
  const ys = pieces.map((p) => p.pts[0].y).sort((a, b) => a - b);
  assert.deepEqual(ys, [SHAPE_CENTRE.y - 7_500, SHAPE_CENTRE.y + 2_500, SHAPE_CENTRE.y + 12_500]);
});

test('a scanline through vertices and along edges is counted once', () => {
  // a diamond: the line through the side vertices, and a square whose edges lie on scanlines
  const c = SHAPE_CENTRE;
  const diamond = [
    {
      outer: [
        { x: c.x, y: c.y - 5_000 },
        { x: c.x + 5_000, y: c.y },
        { x: c.x, y: c.y + 5_000 },
        { x: c.x - 5_000, y: c.y },
      ],
      holes: [],
    },
  ];
  const pieces: Piece[] = [];
  clipSweep(regionGeom(diamond), { angle: 0, spacingUm: 5_000, offsetUm: 0 }, c, pieces);
  assert.equal(pieces.length, 1);
  assert.deepEqual(pieces[0].pts, [
    { x: c.x - 5_000, y: c.y },
    { x: c.x + 5_000, y: c.y },
  ]);
  const sq = TEST_SHAPES.square();
  const p2: Piece[] = [];
  clipSweep(regionGeom(sq), { angle: 0, spacingUm: 15_000, offsetUm: 0 }, c, p2);
  assert.ok(p2.length >= 1 && p2.length <= 3);
  for (const p of p2) assert.equal(Math.abs(p.pts[1].x - p.pts[0].x), 30_000);
});

test('a convex ring swept on its own gives the segments the general sweep cuts', () => {
  let seed = 3;
  const rand = () => (seed = (seed * 1664525 + 1013904223) >>> 0) / 2 ** 32;
  let compared = 0;
  for (let round = 0; round < 200; round++) {
    const sides = 3 + Math.floor(rand() * 40);
    const r = 300 + rand() * 8000,
      cx = rand() * 50_000,
      cy = rand() * 50_000;
    const ring: Pt[] = [];
    for (let k = 0; k < sides; k++) {
      const a = (2 * Math.PI * k) / sides;
      ring.push({ x: Math.round(cx + r * Math.cos(a)), y: Math.round(cy + r * Math.sin(a)) });
    }
    const sweep = { angle: rand() * 180, spacingUm: 200 + rand() * 3000, offsetUm: 0 };
    const origin = { x: Math.round(rand() * 1000), y: Math.round(rand() * 1000) };
    const pieces: Piece[] = [];
    clipSweep(regionGeom([{ outer: ring, holes: [] }]), sweep, origin, pieces);
    const want = pieces.map((p) => p.pts).filter((l) => l[0].x !== l[1].x || l[0].y !== l[1].y);
    assert.deepEqual(sweepConvexRing(ring, sweep, origin), want, `round ${round}`);
    compared += want.length;
  }
  assert.ok(compared > 200, `${compared} segments compared`);
});
