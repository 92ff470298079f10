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
    const c = Math.cos(a), s = Math.sin(a);
    // the same direction on a square: corners fall on multiples of 45° when segments is a multiple of 8
    const k = side / 2 / Math.max(Math.abs(c), Math.abs(s));
    const r = squareHole ? (k * radius * 2) / side : radius;
    inner.push([at[0] + r * c, at[1] + r * s]);
    outer.push([at[0] + k * c, at[1] + k * s]);
  }
  const tris: number[][] = [];
  const quad = (a: number[], b: number[], c: number[], d: number[]) => tris.push([...a, ...b, ...c], [...a, ...c, ...d]);
  for (let i = 0; i < segments; i++) {
    const j = (i + 1) % segments;
    const [ix, iy] = inner[i], [jx, jy] = inner[j];
    const [ox, oy] = outer[i], [px, py] = outer[j];
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
