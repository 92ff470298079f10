/**
 * Closed triangle meshes for volumes the user adds to an object: a box and an upright (elliptic)
 * cylinder, each given by the centre and size of its bounding box, mm, and any mesh fitted to a box.
 * Triangles face outwards (counter-clockwise seen from outside), as the slicer expects. No imports:
 * the browser test loads this file on its own to build the same meshes.
 */

export interface ShapeMesh {
  positions: Float32Array;
  indices: Uint32Array;
}

export type Vec3 = readonly [number, number, number];

/** Sides of a cylinder: round enough to print as a circle at modifier sizes. */
export const CYLINDER_SIDES = 48;

/** A box: 8 corners, 12 triangles. Corner i is at min or max in X (bit 0), Y (bit 1), Z (bit 2). */
export function boxMesh(centre: Vec3, size: Vec3): ShapeMesh {
  const positions = new Float32Array(24);
  for (let i = 0; i < 8; i++) {
    for (let k = 0; k < 3; k++) positions[i * 3 + k] = centre[k] + (i & (1 << k) ? size[k] / 2 : -size[k] / 2);
  }
  // two triangles per face: bottom, top, front (−Y), back (+Y), left (−X), right (+X)
  const indices = Uint32Array.of(
    0,
    2,
    1,
    1,
    2,
    3,
    4,
    5,
    6,
    5,
    7,
    6,
    0,
    1,
    4,
    1,
    5,
    4,
    2,
    6,
    3,
    3,
    6,
    7,
    0,
    4,
    2,
    2,
    4,
    6,
    1,
    3,
    5,
    3,
    7,
    5,
  );
  return { positions, indices };
}

/**
 * An upright cylinder filling the box's X and Y (an ellipse when they differ) and its height: `sides`
 * corners on each rim and a centre vertex on each cap; 4 × sides triangles.
 */
export function cylinderMesh(centre: Vec3, size: Vec3, sides = CYLINDER_SIDES): ShapeMesh {
  const n = Math.max(3, Math.floor(sides));
  const positions = new Float32Array((2 * n + 2) * 3);
  const z0 = centre[2] - size[2] / 2,
    z1 = centre[2] + size[2] / 2;
  for (let k = 0; k < n; k++) {
    const a = (2 * Math.PI * k) / n;
    const x = centre[0] + (Math.cos(a) * size[0]) / 2,
      y = centre[1] + (Math.sin(a) * size[1]) / 2;
    positions.set([x, y, z0], k * 3);
    positions.set([x, y, z1], (n + k) * 3);
  }
  positions.set([centre[0], centre[1], z0], 2 * n * 3);
  positions.set([centre[0], centre[1], z1], (2 * n + 1) * 3);
  const indices = new Uint32Array(n * 12);
  for (let k = 0, t = 0; k < n; k++) {
    const k1 = (k + 1) % n;
    indices.set([k, k1, n + k1, k, n + k1, n + k, 2 * n, k1, k, 2 * n + 1, n + k, n + k1], t);
    t += 12;
  }
  return { positions, indices };
}

/** Bounds of the vertices a mesh's triangles use. */
export function meshBox(m: ShapeMesh): { min: [number, number, number]; max: [number, number, number] } {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < m.indices.length; i++) {
    const v = m.indices[i] * 3;
    for (let k = 0; k < 3; k++) {
      const c = m.positions[v + k];
      if (c < min[k]) min[k] = c;
      if (c > max[k]) max[k] = c;
    }
  }
  return { min, max };
}

/**
 * A mesh moved and stretched so its bounding box has this centre and size (each axis on its own); the
 * mesh itself when they are its own already.
 */
export function fitMesh(m: ShapeMesh, centre: Vec3, size: Vec3): ShapeMesh {
  const { min, max } = meshBox(m);
  const c0 = [0, 1, 2].map((k) => (min[k] + max[k]) / 2);
  const s0 = [0, 1, 2].map((k) => max[k] - min[k]);
  if ([0, 1, 2].every((k) => c0[k] === centre[k] && s0[k] === size[k])) return m;
  const f = [0, 1, 2].map((k) => (s0[k] > 0 ? size[k] / s0[k] : 1));
  const positions = new Float32Array(m.positions.length);
  for (let i = 0; i < positions.length; i += 3) {
    for (let k = 0; k < 3; k++) positions[i + k] = centre[k] + (m.positions[i + k] - c0[k]) * f[k];
  }
  return { positions, indices: m.indices };
}

/** Triangle corners and flat normals, for drawing. */
export function drawArrays(m: ShapeMesh): { positions: Float32Array; normals: Float32Array } {
  const tris = m.indices.length / 3;
  const positions = new Float32Array(tris * 9);
  const normals = new Float32Array(tris * 9);
  const p = m.positions,
    ix = m.indices;
  for (let t = 0; t < tris; t++) {
    const a = ix[t * 3] * 3,
      b = ix[t * 3 + 1] * 3,
      c = ix[t * 3 + 2] * 3;
    const ux = p[b] - p[a],
      uy = p[b + 1] - p[a + 1],
      uz = p[b + 2] - p[a + 2];
    const vx = p[c] - p[a],
      vy = p[c + 1] - p[a + 1],
      vz = p[c + 2] - p[a + 2];
    const nx = uy * vz - uz * vy,
      ny = uz * vx - ux * vz,
      nz = ux * vy - uy * vx;
    const len = Math.hypot(nx, ny, nz) || 1;
    for (let k = 0; k < 3; k++) {
      const src = ix[t * 3 + k] * 3,
        o = t * 9 + k * 3;
      positions[o] = p[src];
      positions[o + 1] = p[src + 1];
      positions[o + 2] = p[src + 2];
      normals[o] = nx / len;
      normals[o + 1] = ny / len;
      normals[o + 2] = nz / len;
    }
  }
  return { positions, normals };
}
