/**
 * Test and benchmark regions, integer µm: a 30 mm square, a 30 mm disc with an off-centre 10 mm hole, a
 * 30 mm square with a quarter cut away (an L with 15 mm arms), and a Benchy-sized hull (60 × 30 mm) with two holes whose outline changes with height.
 */
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import type { InfillParams } from '#strata/infill/types.js';

function circle(cx: number, cy: number, r: number, n: number, cw = false): Pt[] {
  const pts: Pt[] = [];
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * (cw ? n - i : i)) / n;
    pts.push({ x: Math.round(cx + r * Math.cos(a)), y: Math.round(cy + r * Math.sin(a)) });
  }
  return pts;
}

/** Centre of the test shapes on the bed, µm. */
export const SHAPE_CENTRE: Pt = { x: 110_000, y: 105_000 };

export function square(side = 30_000, c: Pt = SHAPE_CENTRE): ExPolygon[] {
  const h = side / 2;
  return [
    {
      outer: [
        { x: c.x - h, y: c.y - h },
        { x: c.x + h, y: c.y - h },
        { x: c.x + h, y: c.y + h },
        { x: c.x - h, y: c.y + h },
      ],
      holes: [],
    },
  ];
}

export function discWithHole(c: Pt = SHAPE_CENTRE): ExPolygon[] {
  return [{ outer: circle(c.x, c.y, 15_000, 240), holes: [circle(c.x + 4_000, c.y + 2_000, 5_000, 96, true)] }];
}

export function lShape(c: Pt = SHAPE_CENTRE): ExPolygon[] {
  const x0 = c.x - 15_000,
    y0 = c.y - 15_000;
  return [
    {
      outer: [
        { x: x0, y: y0 },
        { x: x0 + 30_000, y: y0 },
        { x: x0 + 30_000, y: y0 + 15_000 },
        { x: x0 + 15_000, y: y0 + 15_000 },
        { x: x0 + 15_000, y: y0 + 30_000 },
        { x: x0, y: y0 + 30_000 },
      ],
      holes: [],
    },
  ];
}

/** A boat-like hull about 60 × 30 mm with a round hole and a slot; shrinks a little with z (mm). */
export function hull(z = 0, c: Pt = SHAPE_CENTRE): ExPolygon[] {
  const s = 1 - 0.15 * Math.min(1, z / 48);
  const outer: Pt[] = [];
  const n = 400;
  for (let i = 0; i < n; i++) {
    const t = (2 * Math.PI * i) / n;
    // rounded stern on the left, pointed bow on the right
    const x = 30_000 * s * Math.cos(t) * (Math.cos(t) > 0 ? 1 : 0.9);
    const y = 15_000 * s * Math.sin(t) * (Math.cos(t) > 0 ? ((1 - Math.cos(t)) ** 0.35 / 2 ** 0.35) * 1.3 : 1);
    outer.push({ x: Math.round(c.x + x), y: Math.round(c.y + Math.max(-15_000, Math.min(15_000, y))) });
  }
  const slot: Pt[] = [
    { x: c.x - 14_000, y: c.y - 2_500 },
    { x: c.x - 14_000, y: c.y + 2_500 },
    { x: c.x - 6_000, y: c.y + 2_500 },
    { x: c.x - 6_000, y: c.y - 2_500 },
  ];
  return [{ outer, holes: [circle(c.x + 8_000, c.y, 4_000, 80, true), slot] }];
}

export const TEST_SHAPES: Record<string, () => ExPolygon[]> = {
  square: () => square(),
  'disc with hole': () => discWithHole(),
  'L-shape': () => lShape(),
};

export function testParams(density: number, over: Partial<InfillParams> = {}): InfillParams {
  return {
    density,
    lineWidthUm: 450,
    nozzleDiameterUm: 400,
    angle: 45,
    centering: 'object',
    origin: SHAPE_CENTRE,
    connect: true,
    ...over,
  };
}
