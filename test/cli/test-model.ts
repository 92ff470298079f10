/**
 * A small test part for CLI tests: a square block with a round hole through it, as binary STL. It has
 * walls, top and bottom skin, sparse infill, a curved wall (for mesh tolerance), a hole to travel
 * around (combing) and sharp corners (seams), and slices in a fraction of a second.
 */

/**
 * A `side` × `side` × `height` mm block centred on `at` with a round hole of `radius` mm (`segments`
 * sides), or with `squareHole` a square hole `2 · radius` wide (a square tube).
 */
export function blockWithHole(
  side = 14,
  height = 11,
  radius = 3.5,
  segments = 64,
  at: readonly [number, number] = [0, 0],
  squareHole = false,
): Uint8Array {
  const inner: Array<[number, number]> = [];
  const outer: Array<[number, number]> = [];
  for (let i = 0; i < segments; i++) {
    const a = (2 * Math.PI * i) / segments;
    const c = Math.cos(a),
      s = Math.sin(a);
    // the same direction on a square: corners fall on multiples of 45° when segments is a multiple of 8
    const k = side / 2 / Math.max(Math.abs(c), Math.abs(s));
    const r = squareHole ? (k * radius * 2) / side : radius;
    inner.push([at[0] + r * c, at[1] + r * s]);
    outer.push([at[0] + k * c, at[1] + k * s]);
  }
  const tris: number[][] = [];
  const quad = (a: number[], b: number[], c: number[], d: number[]) =>
    tris.push([...a, ...b, ...c], [...a, ...c, ...d]);
  for (let i = 0; i < segments; i++) {
    const j = (i + 1) % segments;
    const [ix, iy] = inner[i],
      [jx, jy] = inner[j];
    const [ox, oy] = outer[i],
      [px, py] = outer[j];
    quad([ox, oy, 0], [ix, iy, 0], [jx, jy, 0], [px, py, 0]); // bottom, facing down
    quad([ox, oy, height], [px, py, height], [jx, jy, height], [ix, iy, height]); // top
    quad([ox, oy, 0], [px, py, 0], [px, py, height], [ox, oy, height]); // outside
    quad([ix, iy, 0], [ix, iy, height], [jx, jy, height], [jx, jy, 0]); // hole, facing in
  }
  const out = new Uint8Array(84 + 50 * tris.length);
  const dv = new DataView(out.buffer);
  dv.setUint32(80, tris.length, true);
  tris.forEach((t, n) => t.forEach((v, k) => dv.setFloat32(84 + 50 * n + 12 + 4 * k, v, true)));
  return out;
}

type Tri = number[];

function boxTris(x0: number, y0: number, z0: number, x1: number, y1: number, z1: number): Tri[] {
  const v = [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [1, 1, 1],
    [0, 1, 1],
  ].map(([a, b, c]) => [a ? x1 : x0, b ? y1 : y0, c ? z1 : z0]);
  const f = [
    0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
  ];
  const out: Tri[] = [];
  for (let t = 0; t < f.length; t += 3) out.push([...v[f[t]], ...v[f[t + 1]], ...v[f[t + 2]]]);
  return out;
}

/** A prism under a ledge: its underside slopes at 45° from (x, z0) out to (x − (z1 − z0), z1). */
function slopeTris(x: number, y0: number, y1: number, z0: number, z1: number): Tri[] {
  const d = z1 - z0;
  const A = [x, y0, z0],
    B = [x, y0, z1],
    C = [x - d, y0, z1];
  const A2 = [x, y1, z0],
    B2 = [x, y1, z1],
    C2 = [x - d, y1, z1];
  return [
    [...A, ...B, ...C],
    [...A2, ...C2, ...B2],
    [...A, ...A2, ...B2],
    [...A, ...B2, ...B],
    [...B, ...B2, ...C2],
    [...B, ...C2, ...C],
    [...A, ...C, ...C2],
    [...A, ...C2, ...A2],
  ];
}

function binaryStl(tris: Tri[]): Uint8Array {
  const out = new Uint8Array(84 + 50 * tris.length);
  const dv = new DataView(out.buffer);
  dv.setUint32(80, tris.length, true);
  tris.forEach((t, n) => t.forEach((v, k) => dv.setFloat32(84 + 50 * n + 12 + 4 * k, v, true)));
  return out;
}

/**
 * A part with every kind of overhang, as binary STL: two pillars under a slab (a bridge between them),
 * the slab running on past the second pillar (a cantilever) over a low ledge (support standing on the
 * part), and a 45° slope on the first pillar's side (for the support angle).
 */
export function overhangPart(): Uint8Array {
  return binaryStl([
    ...boxTris(0, 0, 0, 6, 6, 12), // pillar
    ...boxTris(14, 0, 0, 18, 6, 12), // pillar
    ...boxTris(0, 0, 12, 24, 6, 14), // slab: 12 mm up, high enough for tree branches to grow to their full width
    ...boxTris(20, 0, 0, 24, 6, 3), // ledge under the cantilever
    ...slopeTris(0, 0, 6, 2, 6), // slope
  ]);
}

/**
 * Thin features, as binary STL: standing fins 8 mm long and 3 mm tall, 0.25 to 1.8 mm thick, 3 mm apart; a
 * 1 mm wall with a 1.4 mm bulge 2 mm long in its middle; and a wedge tapering from 2 mm to nothing over 10 mm
 * (for the variable-width wall settings).
 */
export function thinFeatures(): Uint8Array {
  const tris: Tri[] = [];
  let x = 0;
  for (const t of [0.25, 0.35, 0.5, 0.7, 1.0, 1.4, 1.8]) {
    tris.push(...boxTris(x, 0, 0, x + t, 8, 3));
    x += t + 3;
  }
  const bulge: [number, number][] = [
    [x, 0],
    [x + 1, 0],
    [x + 1, 3],
    [x + 1.2, 3],
    [x + 1.2, 5],
    [x + 1, 5],
    [x + 1, 8],
    [x, 8],
    [x, 5],
    [x - 0.2, 5],
    [x - 0.2, 3],
    [x, 3],
  ];
  tris.push(...starPrism(bulge, [x + 0.5, 4], 3));
  x += 4;
  tris.push(
    ...starPrism(
      [
        [x, 0],
        [x + 2, 0],
        [x + 1, 10],
      ],
      [x + 1, 3],
      3,
    ),
  );
  return binaryStl(tris);
}

/** A prism `height` tall over a counter-clockwise polygon that every vertex of sees `centre` (a fan from it covers the polygon). */
function starPrism(ring: readonly [number, number][], centre: [number, number], height: number): Tri[] {
  const out: Tri[] = [];
  const n = ring.length;
  for (let i = 0; i < n; i++) {
    const [ax, ay] = ring[i],
      [bx, by] = ring[(i + 1) % n];
    out.push([centre[0], centre[1], 0, bx, by, 0, ax, ay, 0]); // bottom, facing down
    out.push([centre[0], centre[1], height, ax, ay, height, bx, by, height]); // top
    out.push([ax, ay, 0, bx, by, 0, bx, by, height], [ax, ay, 0, bx, by, height, ax, ay, height]); // side
  }
  return out;
}
