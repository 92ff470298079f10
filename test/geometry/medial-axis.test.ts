import { test } from 'node:test';
import assert from 'node:assert/strict';
import { medialAxis, medialScratch, type MedialChain } from '#strata/geometry/medial-axis.js';
import { pointInRing } from '#strata/geometry/contain.js';
import { rect } from './test-shapes.js';
import type { ExPolygon, Polygon, Pt } from '#strata/geometry/types.js';

// ---------------------------------------------------------------------------------------------------------
// helpers

const P = (x: number, y: number): Pt => ({ x, y });

/** Distance from p to segment ab. */
function segDist(p: Pt, a: Pt, b: Pt): number {
  const dx = b.x - a.x,
    dy = b.y - a.y,
    l2 = dx * dx + dy * dy;
  const t = l2 > 0 ? Math.max(0, Math.min(1, ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2)) : 0;
  return Math.hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

/** True distance from p to the area's boundary, by brute force over every boundary segment. */
function boundaryDist(area: ExPolygon, p: Pt): number {
  let d = Infinity;
  for (const r of [area.outer, ...area.holes])
    for (let i = 0; i < r.length; i++) d = Math.min(d, segDist(p, r[i], r[(i + 1) % r.length]));
  return d;
}

function inArea(area: ExPolygon, p: Pt): boolean {
  return pointInRing(p, area.outer) && !area.holes.some((h) => pointInRing(p, h));
}

/** Every point of every chain is in one of the areas (or on a boundary within 1 µm), and every radius is
 * positive and at most the true distance to the boundary + 10 µm. */
function assertSound(chains: readonly MedialChain[], areas: readonly ExPolygon[]): void {
  for (const c of chains) {
    assert.equal(c.radii.length, c.points.length);
    c.points.forEach((p, i) => {
      assert.ok(Number.isInteger(p.x) && Number.isInteger(p.y), `integer point ${p.x},${p.y}`);
      const host = areas.find((a) => inArea(a, p) || boundaryDist(a, p) <= 1);
      assert.ok(host, `point ${p.x},${p.y} outside every area`);
      const r = c.radii[i];
      assert.ok(r > 0, `radius ${r} at ${p.x},${p.y}`);
      const d = boundaryDist(host, p);
      assert.ok(r <= d + 10, `radius ${r.toFixed(1)} beyond the true distance ${d.toFixed(1)} at ${p.x},${p.y}`);
    });
  }
}

const ends = (c: MedialChain): Pt[] => [c.points[0], c.points[c.points.length - 1]];
const same = (a: Pt, b: Pt): boolean => a.x === b.x && a.y === b.y;
const near = (a: Pt, b: Pt, tol: number): boolean => Math.hypot(a.x - b.x, a.y - b.y) <= tol;

/** A regular polygon of `n` sides round (cx, cy), counter-clockwise. */
function ngon(cx: number, cy: number, r: number, n: number): Polygon {
  return Array.from({ length: n }, (_, k) =>
    P(Math.round(cx + r * Math.cos((2 * Math.PI * k) / n)), Math.round(cy + r * Math.sin((2 * Math.PI * k) / n))),
  );
}

/** Strip [0, len] × [-t/2, t/2] whose left end is a point of full angle `deg` (tip at x < 0). */
function pointedStrip(deg: number, t: number, len: number): { area: ExPolygon; tip: Pt } {
  const d = Math.round(t / 2 / Math.tan((deg * Math.PI) / 360));
  return {
    area: { outer: [P(-d, 0), P(0, -t / 2), P(len, -t / 2), P(len, t / 2), P(0, t / 2)], holes: [] },
    tip: P(-d, 0),
  };
}

/** The T: a bar [-5, 5] × [-0.25, 0.25] mm and a stem [-0.25, 0.25] × [-5, -0.25] mm. */
const tee: ExPolygon = {
  outer: [
    P(-5000, -250),
    P(-250, -250),
    P(-250, -5000),
    P(250, -5000),
    P(250, -250),
    P(5000, -250),
    P(5000, 250),
    P(-5000, 250),
  ],
  holes: [],
};

/** An L of two 0.5 mm arms, 8 and 6 mm long. */
const ell: ExPolygon = { outer: [P(0, 0), P(8000, 0), P(8000, 500), P(500, 500), P(500, 6000), P(0, 6000)], holes: [] };

/** A star of `arms` strips of width 2w and length len from the origin. */
function star(arms: number, w: number, len: number): ExPolygon {
  const outer: Pt[] = [];
  for (let k = 0; k < arms; k++) {
    const a = (2 * Math.PI * k) / arms,
      b = (2 * Math.PI * (k + 1)) / arms;
    const dx = Math.cos(a),
      dy = Math.sin(a),
      nx = -dy,
      ny = dx;
    outer.push(
      P(Math.round(len * dx - w * nx), Math.round(len * dy - w * ny)),
      P(Math.round(len * dx + w * nx), Math.round(len * dy + w * ny)),
    );
    // the inner corner where this arm's left edge (p·n = w) meets the next arm's right edge (p·m = -w)
    const mx = -Math.sin(b),
      my = Math.cos(b),
      det = nx * my - ny * mx;
    outer.push(P(Math.round((w * my + ny * w) / det), Math.round((-nx * w - w * mx) / det)));
  }
  return { outer, holes: [] };
}

/** Square ring: outer 20 mm, hole 19 mm, both centred on the origin (walls 0.5 mm). */
const squareRing: ExPolygon = {
  outer: [P(-10000, -10000), P(10000, -10000), P(10000, 10000), P(-10000, 10000)],
  holes: [[P(-9500, -9500), P(-9500, 9500), P(9500, 9500), P(9500, -9500)]],
};

/** Circular ring of 180-gons, radii 10 and 9.5 mm. */
const circleRing: ExPolygon = { outer: ngon(0, 0, 10000, 180), holes: [ngon(0, 0, 9500, 180).reverse()] };

// ---------------------------------------------------------------------------------------------------------
// strips

for (const t of [100, 250, 450, 800, 1600]) {
  test(`a 10 mm × ${t / 1000} mm rectangle has one open chain along its centre line, radius t/2`, () => {
    const L = 10000;
    const chains = medialAxis([rect(0, 0, L, t)]);
    assert.equal(chains.length, 1);
    const [c] = chains;
    assert.equal(c.closed, false);
    for (const [i, p] of c.points.entries()) {
      assert.ok(Math.abs(p.y - t / 2) <= t / 20 + 10, `off the centre line: ${p.x},${p.y}`);
      if (p.x >= t && p.x <= L - t)
        assert.ok(Math.abs(c.radii[i] - t / 2) <= 0.05 * (t / 2), `radius ${c.radii[i]} at x ${p.x}`);
    }
    const xs = c.points.map((p) => p.x);
    assert.ok(
      Math.min(...xs) <= 1.2 * t && Math.max(...xs) >= L - 1.2 * t,
      `ends ${Math.min(...xs)} .. ${Math.max(...xs)}`,
    );
  });

  test(`the same ${t / 1000} mm strip turned by 30° (off-axis samples): one chain, on the centre line, radius t/2`, () => {
    const L = 10000,
      c30 = Math.cos(Math.PI / 6),
      s30 = Math.sin(Math.PI / 6);
    const turn = (x: number, y: number): Pt =>
      P(Math.round(500 + x * c30 - y * s30), Math.round(-300 + x * s30 + y * c30));
    const area: ExPolygon = { outer: [turn(0, 0), turn(L, 0), turn(L, t), turn(0, t)], holes: [] };
    const chains = medialAxis([area]);
    assert.equal(chains.length, 1);
    assert.equal(chains[0].closed, false);
    const along: number[] = [];
    chains[0].points.forEach((p, i) => {
      const dx = p.x - 500,
        dy = p.y + 300;
      const u = dx * c30 + dy * s30,
        v = -dx * s30 + dy * c30;
      along.push(u);
      assert.ok(Math.abs(v - t / 2) <= t / 20 + 10, `off the centre line by ${(v - t / 2).toFixed(1)}`);
      if (u >= t && u <= L - t)
        assert.ok(Math.abs(chains[0].radii[i] - t / 2) <= 0.05 * (t / 2), `radius ${chains[0].radii[i]}`);
    });
    assert.ok(Math.min(...along) <= 1.2 * t && Math.max(...along) >= L - 1.2 * t);
    assertSound(chains, [area]);
  });
}

test('staggered samples on the two sides of a strip (an extra vertex on one side): nodes centred, one straight line of radius t/2', () => {
  // with the spacing set by the radius, uncentred circumcentres zigzag about the centre line by up to s²/(8t)
  // and their radii are up to s²/(4t²) short: simplification at 1 µm would keep most of them
  for (const t of [60, 200, 400]) {
    const L = 5000;
    const area: ExPolygon = { outer: [P(0, 0), P(L, 0), P(L, t), P(1234, t), P(0, t)], holes: [] };
    const chains = medialAxis([area], { sampleUm: t / 2, toleranceUm: 1 });
    assert.equal(chains.length, 1);
    const [c] = chains;
    assert.ok(c.points.length <= 4, `${c.points.length} points for t = ${t}`);
    c.points.forEach((p, i) => {
      assert.ok(Math.abs(p.y - t / 2) <= 2, `off the centre line: ${p.x},${p.y}`);
      assert.ok(Math.abs(c.radii[i] - t / 2) <= 0.01 * (t / 2), `radius ${c.radii[i]} at x ${p.x}, t ${t}`);
    });
    assert.ok(c.points[0].x <= t && c.points[c.points.length - 1].x >= L - t);
    assertSound(chains, [area]);
  }
});

test('a strip given with 200 vertices along its sides (too many for ear clipping) has the axis it has with 4', () => {
  const few: ExPolygon = { outer: [P(0, 0), P(10000, 0), P(10000, 400), P(0, 400)], holes: [] };
  const dense: Pt[] = [];
  for (let i = 0; i < 100; i++) dense.push(P(i * 100, 0));
  dense.push(P(10000, 0), P(10000, 400));
  for (let i = 100; i > 0; i--) dense.push(P(i * 100 - 37, 400));
  dense.push(P(0, 400));
  const a = medialAxis([few]),
    b = medialAxis([{ outer: dense, holes: [] }]);
  assert.equal(a.length, 1);
  assert.equal(b.length, 1);
  for (let k = 0; k < 2; k++)
    assert.ok(
      near(ends(a[0])[k], ends(b[0])[k], 3),
      `ends ${JSON.stringify(ends(a[0]))} and ${JSON.stringify(ends(b[0]))}`,
    );
  for (const c of [...a, ...b]) for (const r of c.radii) assert.ok(Math.abs(r - 200) <= 0.01 * 200, `radius ${r}`);
});

// ---------------------------------------------------------------------------------------------------------
// rings

test('square ring (20 mm, hole 19 mm): one closed chain on the midline, radius 0.25 mm', () => {
  const chains = medialAxis([squareRing]);
  assert.equal(chains.length, 1);
  const [c] = chains;
  assert.equal(c.closed, true);
  assert.ok(!same(c.points[0], c.points[c.points.length - 1]), 'the first point is not repeated');
  const midline = [P(-9750, -9750), P(9750, -9750), P(9750, 9750), P(-9750, 9750)];
  const toMid = (p: Pt): number => Math.min(...midline.map((a, i) => segDist(p, a, midline[(i + 1) % 4])));
  c.points.forEach((p, i) => {
    const r = c.radii[i];
    // at the corners the axis bends in towards the hole's corner, where the circle touches both outer sides
    // and that corner: 0.5 mm / (1 + √2) · √2 = 0.293 mm at most
    assert.ok(r >= 0.95 * 250 && r <= 295, `radius ${r}`);
    assert.ok(toMid(p) <= 70, `far off the midline: ${p.x},${p.y}`);
    const fromCorner = Math.min(...midline.map((q) => Math.hypot(p.x - q.x, p.y - q.y)));
    if (fromCorner > 500) {
      assert.ok(Math.abs(r - 250) <= 0.05 * 250, `radius ${r} away from the corners`);
      assert.ok(toMid(p) <= 15, `off the midline: ${p.x},${p.y}`);
    }
  });
  // it goes all the way round
  for (const [sx, sy] of [
    [1, 1],
    [1, -1],
    [-1, 1],
    [-1, -1],
  ])
    assert.ok(
      c.points.some((p) => sx * p.x > 9000 && sy * p.y > 9000),
      `corner ${sx},${sy}`,
    );
  assertSound(chains, [squareRing]);
});

test('circular ring (180-gons, 10 and 9.5 mm): one closed chain on the 9.75 mm circle, radius 0.25 mm', () => {
  const chains = medialAxis([circleRing]);
  assert.equal(chains.length, 1);
  const [c] = chains;
  assert.equal(c.closed, true);
  const angles: number[] = [];
  c.points.forEach((p, i) => {
    assert.ok(
      Math.abs(Math.hypot(p.x, p.y) - 9750) <= 15,
      `off the midline circle: ${Math.hypot(p.x, p.y).toFixed(1)}`,
    );
    assert.ok(Math.abs(c.radii[i] - 250) <= 0.05 * 250, `radius ${c.radii[i]}`);
    angles.push(Math.atan2(p.y, p.x));
  });
  angles.sort((a, b) => a - b);
  let gap = angles[0] + 2 * Math.PI - angles[angles.length - 1];
  for (let k = 1; k < angles.length; k++) gap = Math.max(gap, angles[k] - angles[k - 1]);
  assert.ok(gap < Math.PI / 12, 'points all round the circle');
  assertSound(chains, [circleRing]);
});

test('a ring with a spur: a closed cycle and an open chain that ends on one of its points', () => {
  const area: ExPolygon = {
    outer: [P(0, 0), P(5000, 0), P(5000, 2250), P(8000, 2250), P(8000, 2750), P(5000, 2750), P(5000, 5000), P(0, 5000)],
    holes: [[P(500, 500), P(500, 4500), P(4500, 4500), P(4500, 500)]],
  };
  const chains = medialAxis([area]);
  assert.equal(chains.length, 2);
  const loop = chains.find((c) => c.closed),
    spur = chains.find((c) => !c.closed);
  assert.ok(loop && spur);
  const joint = ends(spur).find((e) => loop.points.some((p) => same(p, e)));
  assert.ok(joint, 'the spur ends on a point of the cycle');
  assert.ok(near(joint, P(4750, 2500), 100));
  assert.ok(ends(spur).some((e) => near(e, P(7750, 2500), 20)));
  assertSound(chains, [area]);
});

test('a plate with two holes side by side: three chains between the two junctions of the bar between the holes', () => {
  const area: ExPolygon = {
    outer: rect(0, 0, 6000, 2000).outer,
    holes: [rect(500, 500, 2700, 1500).outer.reverse(), rect(3300, 500, 5500, 1500).outer.reverse()],
  };
  const chains = medialAxis([area]);
  assert.equal(chains.length, 3);
  assert.ok(chains.every((c) => !c.closed));
  for (const want of [P(3000, 340), P(3000, 1660)]) {
    assert.ok(
      chains.every((c) => ends(c).some((e) => near(e, want, 15))),
      `every chain ends near ${want.x},${want.y}`,
    );
  }
  for (const c of chains) for (const r of c.radii) assert.ok(r >= 0.95 * 250 && r <= 345, `radius ${r}`);
  assertSound(chains, [area]);
});

test('a hole level with a notch in the outer ring: one closed chain round it', () => {
  const area: ExPolygon = {
    outer: [P(0, 0), P(3000, 0), P(3000, 400), P(2600, 500), P(3000, 600), P(3000, 1000), P(0, 1000)],
    holes: [[P(500, 300), P(500, 700), P(2000, 500)]],
  };
  const chains = medialAxis([area]);
  assert.equal(chains.length, 1);
  assert.equal(chains[0].closed, true);
  const xs = chains[0].points.map((p) => p.x),
    ys = chains[0].points.map((p) => p.y);
  assert.ok(
    Math.min(...xs) < 500 && Math.max(...xs) > 2000 && Math.min(...ys) < 300 && Math.max(...ys) > 700,
    'round the hole',
  );
  assertSound(chains, [area]);
});

// ---------------------------------------------------------------------------------------------------------
// wedges and tips

test('a 5° wedge keeps one chain to its sharp tip, radius growing linearly from it', () => {
  const L = 20000,
    h = Math.round(L * Math.tan((2.5 * Math.PI) / 180));
  const area: ExPolygon = { outer: [P(0, 0), P(L, -h), P(L, h)], holes: [] };
  const chains = medialAxis([area]);
  assert.equal(chains.length, 1);
  const [c] = chains;
  assert.ok(near(c.points[0], P(0, 0), 100), `reaches the tip: ${c.points[0].x},${c.points[0].y}`);
  const s = Math.sin((2.5 * Math.PI) / 180);
  c.points.forEach((p, i) => {
    assert.ok(Math.abs(p.y) <= 10, 'on the bisector');
    assert.ok(
      Math.abs(c.radii[i] - p.x * s) <= 0.03 * p.x * s + 3,
      `radius ${c.radii[i].toFixed(1)} at x ${p.x}, wedge ${(p.x * s).toFixed(1)}`,
    );
  });
  // the other end is the incentre, where the branches into the two blunt base corners were pruned
  const side = Math.hypot(L, h),
    inradius = (L * h) / (side + h);
  const last = c.points[c.points.length - 1];
  assert.ok(Math.abs(last.x - inradius / s) <= 100, `ends at the incentre, x ${last.x}`);
  assert.ok(Math.abs(c.radii[c.radii.length - 1] - inradius) <= 0.02 * inradius);
  assertSound(chains, [area]);
});

test('a 40° triangle: every branch (into corners blunter than 10°) is pruned, leaving its incentre as one point', () => {
  const L = 5000,
    h = Math.round(L * Math.tan((20 * Math.PI) / 180));
  const area: ExPolygon = { outer: [P(0, 0), P(L, -h), P(L, h)], holes: [] };
  const chains = medialAxis([area]);
  assert.equal(chains.length, 1);
  assert.equal(chains[0].points.length, 1);
  const side = Math.hypot(L, h),
    inradius = (L * h) / (side + h);
  assert.ok(near(chains[0].points[0], P(Math.round(inradius / Math.sin((20 * Math.PI) / 180)), 0), 20));
  assert.ok(Math.abs(chains[0].radii[0] - inradius) <= 0.01 * inradius);
});

test('a 0.5 mm strip ending in a 40° point has no line into the point; with a 5° point the line runs to the tip', () => {
  const blunt = pointedStrip(40, 500, 8000);
  const b = medialAxis([blunt.area]);
  assert.equal(b.length, 1);
  // the point tapers from x = 0 to the tip at x = -687: the line stops where the strip starts narrowing
  assert.ok(b[0].points[0].x >= -0.25 * 500, `starts at x ${b[0].points[0].x}`);
  assert.ok(Math.min(...b[0].radii) >= 0.85 * 250);
  assertSound(b, [blunt.area]);

  const sharp = pointedStrip(5, 500, 8000);
  const s = medialAxis([sharp.area]);
  assert.equal(s.length, 1);
  assert.ok(near(s[0].points[0], sharp.tip, 100), `starts at ${s[0].points[0].x}, tip ${sharp.tip.x}`);
  s[0].points.forEach((p, i) => {
    if (p.x < -500) assert.ok(Math.abs(s[0].radii[i] - (p.x - sharp.tip.x) * Math.sin((2.5 * Math.PI) / 180)) <= 5);
  });
  assertSound(s, [sharp.area]);
});

test('a thin strip ending in a 14° point (no junction where it narrows) is trimmed back to where it narrows', () => {
  const { area } = pointedStrip(14, 100, 5000);
  const chains = medialAxis([area]);
  assert.equal(chains.length, 1);
  // the point runs from x = 0 to x = -407
  assert.ok(chains[0].points[0].x >= -0.25 * 100, `starts at x ${chains[0].points[0].x}`);
  assert.ok(Math.min(...chains[0].radii) >= 0.85 * 50);
  assertSound(chains, [area]);
});

test('pruneAngleDeg: at 50° the 40° point keeps its line to the tip', () => {
  const { area, tip } = pointedStrip(40, 500, 8000);
  const chains = medialAxis([area], { pruneAngleDeg: 50 });
  assert.equal(chains.length, 1);
  assert.ok(near(chains[0].points[0], tip, 100), `starts at ${chains[0].points[0].x}`);
});

test('a sharp 8° spike on a 0.6 mm strip keeps its branch to the tip; a 30° spike loses it', () => {
  const sharp: ExPolygon = {
    outer: [P(0, 0), P(10000, 0), P(10000, 600), P(5105, 600), P(5000, 2100), P(4895, 600), P(0, 600)],
    holes: [],
  };
  const s = medialAxis([sharp]);
  assert.equal(s.length, 3);
  assert.ok(
    s.some((c) => ends(c).some((e) => near(e, P(5000, 2100), 100))),
    'a chain reaches the spike tip',
  );
  assertSound(s, [sharp]);
  const blunt: ExPolygon = {
    outer: [P(0, 0), P(10000, 0), P(10000, 600), P(5402, 600), P(5000, 2100), P(4598, 600), P(0, 600)],
    holes: [],
  };
  const b = medialAxis([blunt]);
  assert.equal(b.length, 1);
  assert.ok(
    b[0].points.every((p) => p.y < 700),
    'nothing runs up the spike',
  );
  assertSound(b, [blunt]);
});

// ---------------------------------------------------------------------------------------------------------
// junctions and general shapes

test('T junction of two 0.5 mm strips: three chains sharing one junction point', () => {
  const chains = medialAxis([tee]);
  assert.equal(chains.length, 3);
  assert.ok(chains.every((c) => !c.closed));
  // the junction circle touches the bar's top and the two inner corners: centre (0, -62.5), radius 312.5
  const shared = ends(chains[0]).find((e) => chains.every((c) => ends(c).some((f) => same(e, f))));
  assert.ok(shared, 'one point is an end of all three chains');
  assert.ok(near(shared, P(0, -62.5), 5), `junction ${shared.x},${shared.y}`);
  for (const c of chains) {
    const i = same(c.points[0], shared) ? 0 : c.points.length - 1;
    assert.ok(Math.abs(c.radii[i] - 312.5) <= 0.02 * 312.5);
  }
  const far = chains.map((c) => ends(c).find((e) => !same(e, shared))!);
  for (const want of [P(-4750, 0), P(4750, 0), P(0, -4750)])
    assert.ok(
      far.some((e) => near(e, want, 20)),
      `an end at ${want.x},${want.y}`,
    );
  assertSound(chains, [tee]);
});

test('L shape: one chain round the bend, inside the area, radii within the true distance', () => {
  const chains = medialAxis([ell]);
  assert.equal(chains.length, 1);
  const e = ends(chains[0]);
  assert.ok(e.some((p) => near(p, P(250, 5750), 20)) && e.some((p) => near(p, P(7750, 250), 20)));
  assertSound(chains, [ell]);
});

test('star of five 0.6 mm arms: five chains meeting at the centre, inside, radii within the true distance', () => {
  const area = star(5, 300, 5000);
  const chains = medialAxis([area]);
  assert.equal(chains.length, 5);
  for (const c of chains)
    assert.ok(
      ends(c).some((p) => near(p, P(0, 0), 5)),
      'one end at the centre',
    );
  assertSound(chains, [area]);
});

test('a solid square (all its branches run into right-angled corners) leaves its centre as one point', () => {
  const chains = medialAxis([rect(0, 0, 1000, 1000)]);
  assert.equal(chains.length, 1);
  assert.deepEqual(chains[0].points, [P(500, 500)]);
  assert.ok(Math.abs(chains[0].radii[0] - 500) <= 1);
  assert.equal(chains[0].closed, false);
});

test('a frame with walls of 0.4 and 0.5 mm round a hole: one closed chain, radius half the local wall', () => {
  const area: ExPolygon = { outer: rect(0, 0, 6000, 3000).outer, holes: [rect(400, 500, 5500, 2500).outer.reverse()] };
  const chains = medialAxis([area]);
  assert.equal(chains.length, 1);
  assert.equal(chains[0].closed, true);
  chains[0].points.forEach((p, i) => {
    if (p.y > 1000 && p.y < 2000)
      assert.ok(
        Math.abs(p.x < 3000 ? p.x - 200 : p.x - 5750) <= 10 &&
          Math.abs(chains[0].radii[i] - (p.x < 3000 ? 200 : 250)) <= 10,
      );
  });
  assertSound(chains, [area]);
});

test('several separate areas at once give the chains of each, in an order independent of the input order', () => {
  const areas = [rect(-5000, 0, 5000, 450), squareRing, tee, star(5, 300, 5000)].map((a, k) => shift(a, 30000 * k, 0));
  const all = medialAxis(areas);
  const each = areas.map((a) => medialAxis([a]));
  assert.equal(
    all.length,
    each.reduce((n, c) => n + c.length, 0),
  );
  for (const c of each.flat())
    assert.ok(
      all.some((d) => isDeepEqual(c, d)),
      'each area’s chains are in the whole',
    );
  assert.deepEqual(medialAxis(areas.slice().reverse()), all);
  assertSound(all, areas);
});

test('deterministic: the same input twice gives the same output; ring orientation does not matter', () => {
  const areas = [squareRing, circleRing, star(5, 300, 5000), ell];
  assert.deepEqual(medialAxis(areas), medialAxis(areas));
  const flipped = areas.map((a) => ({
    outer: a.outer.slice().reverse(),
    holes: a.holes.map((h) => h.slice().reverse()),
  }));
  assert.deepEqual(medialAxis(flipped), medialAxis(areas));
});

test('working memory handed from call to call (one layer’s) gives what fresh memory gives, whatever came before', () => {
  // large areas first, so the smaller ones after them run in arrays longer than they need, holding the larger ones' data
  const areas = [circleRing, squareRing, star(5, 300, 5000), ell, tee];
  const scratch = medialScratch();
  for (const a of [...areas, ...areas.slice().reverse()])
    assert.deepEqual(medialAxis([a], { scratch }), medialAxis([a]));
});

test('nothing for no areas or areas of no extent', () => {
  assert.deepEqual(medialAxis([]), []);
  assert.deepEqual(medialAxis([{ outer: [P(0, 0), P(1000, 0)], holes: [] }]), []);
  assert.deepEqual(medialAxis([{ outer: [P(0, 0), P(1000, 0), P(2000, 0)], holes: [] }]), []);
});

test('options: finer sampling and tolerance give the same T junction, with more points', () => {
  const fine = medialAxis([tee], { sampleUm: 20, toleranceUm: 2 });
  const coarse = medialAxis([tee]);
  assert.equal(fine.length, 3);
  for (let k = 0; k < 3; k++)
    assert.deepEqual(
      ends(fine[k]).map((p) => near(p, ends(coarse[k])[0], 3) || near(p, ends(coarse[k])[1], 3)),
      [true, true],
    );
  assertSound(fine, [tee]);
});

// ---------------------------------------------------------------------------------------------------------

function shift(a: ExPolygon, dx: number, dy: number): ExPolygon {
  const m = (r: Polygon): Polygon => r.map((p) => P(p.x + dx, p.y + dy));
  return { outer: m(a.outer), holes: a.holes.map(m) };
}

function isDeepEqual(a: unknown, b: unknown): boolean {
  try {
    assert.deepEqual(a, b);
    return true;
  } catch {
    return false;
  }
}
