/**
 * Test meshes made in code for the end-to-end tests: axis-aligned boxes, and several closed meshes as one.
 * Plain typed arrays, as the library's Slicer takes them.
 */

export type Arrays = { positions: Float32Array; indices: Uint32Array };

/** An axis-aligned box, mm. */
export function box(x0: number, y0: number, z0: number, x1: number, y1: number, z1: number): Arrays {
  const v: number[] = [];
  for (const [x, y, z] of [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [1, 1, 1],
    [0, 1, 1],
  ]) {
    v.push(x ? x1 : x0, y ? y1 : y0, z ? z1 : z0);
  }
  const f = [
    0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
  ];
  return { positions: new Float32Array(v), indices: new Uint32Array(f) };
}

/** Several closed meshes as one (they may overlap: the slicer unions a mesh's shells). */
export function join(...meshes: Arrays[]): Arrays {
  const positions: number[] = [],
    indices: number[] = [];
  for (const m of meshes) {
    const base = positions.length / 3;
    positions.push(...m.positions);
    for (const i of m.indices) indices.push(i + base);
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}
