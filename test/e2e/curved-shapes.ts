/**
 * Test-only meshes with curved and sloping overhangs, made here rather than read from ../shared/models: a sphere
 * on the bed, a torus lying flat, a mushroom (a thin stem under a wide, conical cap), fins leaning at several
 * angles and an arch. Closed, outward-facing, indexed, mm. The sphere's, torus's and arch's undersides slope
 * through every angle, the mushroom's and each fin's at one; the shared models' overhangs are mostly flat or
 * stepped.
 */
import type { Mesh } from '#strata/mesh/types.js';

/** An indexed mesh built vertex by vertex and face by face. */
class MeshBuilder {
  readonly positions: number[] = [];
  readonly indices: number[] = [];

  vertex(x: number, y: number, z: number): number {
    this.positions.push(x, y, z);
    return this.positions.length / 3 - 1;
  }

  tri(a: number, b: number, c: number): void {
    this.indices.push(a, b, c);
  }

  /** Two triangles a b c, a c d (counter-clockwise seen from outside). */
  quad(a: number, b: number, c: number, d: number): void {
    this.tri(a, b, c);
    this.tri(a, c, d);
  }

  mesh(): Mesh {
    return { positions: new Float32Array(this.positions), indices: new Uint32Array(this.indices) };
  }
}

/** A UV sphere of radius r resting on the bed (its centre at height r), `around` × `rings` faces. */
export function sphere(r: number, around = 64, rings = 32): Mesh {
  const g = new MeshBuilder();
  const bottom = g.vertex(0, 0, 0);
  const ring: number[][] = [];
  for (let k = 1; k < rings; k++) {
    const polar = (Math.PI * k) / rings;
    const row: number[] = [];
    for (let i = 0; i < around; i++) {
      const a = (2 * Math.PI * i) / around;
      row.push(g.vertex(r * Math.sin(polar) * Math.cos(a), r * Math.sin(polar) * Math.sin(a), r - r * Math.cos(polar)));
    }
    ring.push(row);
  }
  const top = g.vertex(0, 0, 2 * r);
  for (let i = 0; i < around; i++) {
    const n = (i + 1) % around;
    g.tri(bottom, ring[0][n], ring[0][i]);
    for (let k = 0; k + 1 < ring.length; k++) g.quad(ring[k][i], ring[k][n], ring[k + 1][n], ring[k + 1][i]);
    g.tri(top, ring[ring.length - 1][i], ring[ring.length - 1][n]);
  }
  return g.mesh();
}

/** A torus lying flat on the bed: the tube's centre circle of radius R at height r, the tube's radius r. */
export function torus(R: number, r: number, around = 72, tube = 36): Mesh {
  const g = new MeshBuilder();
  const grid: number[][] = [];
  for (let i = 0; i < around; i++) {
    const a = (2 * Math.PI * i) / around;
    const row: number[] = [];
    for (let k = 0; k < tube; k++) {
      const b = (2 * Math.PI * k) / tube;
      const d = R + r * Math.cos(b);
      row.push(g.vertex(d * Math.cos(a), d * Math.sin(a), r + r * Math.sin(b)));
    }
    grid.push(row);
  }
  for (let i = 0; i < around; i++) {
    const n = (i + 1) % around;
    for (let k = 0; k < tube; k++) {
      const m = (k + 1) % tube;
      g.quad(grid[i][k], grid[n][k], grid[n][m], grid[i][m]);
    }
  }
  return g.mesh();
}

/**
 * A closed solid of revolution about the z axis from its profile, (radius, height) pairs from the bottom up
 * (every radius above 0): a flat disc closes each end.
 */
function revolved(profile: readonly [number, number][], sides = 64): Mesh {
  const g = new MeshBuilder();
  const rows = profile.map(([r, z]) => {
    const row: number[] = [];
    for (let i = 0; i < sides; i++) {
      const a = (2 * Math.PI * i) / sides;
      row.push(g.vertex(r * Math.cos(a), r * Math.sin(a), z));
    }
    return row;
  });
  const c0 = g.vertex(0, 0, profile[0][1]),
    c1 = g.vertex(0, 0, profile[profile.length - 1][1]);
  const last = rows[rows.length - 1];
  for (let i = 0; i < sides; i++) {
    const n = (i + 1) % sides;
    g.tri(c0, rows[0][n], rows[0][i]);
    for (let k = 0; k + 1 < rows.length; k++) g.quad(rows[k][i], rows[k][n], rows[k + 1][n], rows[k + 1][i]);
    g.tri(c1, last[i], last[n]);
  }
  return g.mesh();
}

/**
 * A mushroom: a stem of radius 4 mm, 12 mm high, under a cap widening to 15 mm at 75° from vertical, 17 mm
 * high in all.
 */
export function mushroom(): Mesh {
  return revolved([
    [4, 0],
    [4, 12],
    [15, 15],
    [15, 17],
  ]);
}

/**
 * Four fins, 4 mm thick, 8 mm deep and 8 mm high, leaning over at 55°, 60°, 65° and 70° from vertical (their
 * undersides flat slopes past the support threshold), 30 mm apart.
 */
export function leaningFins(): Mesh {
  const g = new MeshBuilder();
  [55, 60, 65, 70].forEach((deg, k) => {
    const x = 30 * k,
      h = 8,
      s = h * Math.tan((deg * Math.PI) / 180);
    const b = [g.vertex(x, 0, 0), g.vertex(x + 4, 0, 0), g.vertex(x + 4, 8, 0), g.vertex(x, 8, 0)];
    const t = [g.vertex(x + s, 0, h), g.vertex(x + 4 + s, 0, h), g.vertex(x + 4 + s, 8, h), g.vertex(x + s, 8, h)];
    g.quad(b[0], b[3], b[2], b[1]); // bottom
    g.quad(t[0], t[1], t[2], t[3]); // top
    g.quad(b[0], b[1], t[1], t[0]); // front
    g.quad(b[3], t[3], t[2], b[2]); // back
    g.quad(b[0], t[0], t[3], b[3]); // the side leaning over the bed
    g.quad(b[1], b[2], t[2], t[1]); // the underside
  });
  return g.mesh();
}

/**
 * An arch standing on the bed: a block 2·halfWidth wide (along x), `height` high and `depth` deep (along y),
 * with a half-cylinder of radius `radius` taken out of its underside, so the opening's roof slopes through
 * every angle from the vertical feet to the flat crown. Each face between the opening and the outside is cut
 * along rays from the opening's centre (the block's corners among them), so the end faces are made of convex
 * quads.
 */
export function arch(halfWidth = 12, height = 14, radius = 10, depth = 10, steps = 48): Mesh {
  const g = new MeshBuilder();
  const corner = Math.atan2(height, halfWidth);
  const angles = [
    ...new Set([...Array.from({ length: steps + 1 }, (_, i) => (Math.PI * i) / steps), corner, Math.PI - corner]),
  ].sort((p, q) => p - q);
  // where the ray at angle t from the opening's centre leaves the block (its sides x = ±halfWidth, its top z = height)
  const exit = (t: number): [number, number] => {
    const c = Math.cos(t),
      s = Math.sin(t);
    const k = Math.min(Math.abs(c) > 1e-12 ? halfWidth / Math.abs(c) : Infinity, s > 1e-12 ? height / s : Infinity);
    return [c * k, s * k];
  };
  // per ray, the opening's point and the outside's, at the front (y = 0) and the back (y = depth)
  const inner: [number, number][] = [],
    outer: [number, number][] = [];
  for (const t of angles) {
    const [ox, oz] = exit(t);
    const ix = radius * Math.cos(t),
      iz = radius * Math.sin(t);
    inner.push([g.vertex(ix, 0, iz), g.vertex(ix, depth, iz)]);
    outer.push([g.vertex(ox, 0, oz), g.vertex(ox, depth, oz)]);
  }
  const n = angles.length;
  for (let k = 0; k + 1 < n; k++) {
    g.quad(inner[k][0], outer[k][0], outer[k + 1][0], inner[k + 1][0]); // front
    g.quad(inner[k][1], inner[k + 1][1], outer[k + 1][1], outer[k][1]); // back
    g.quad(inner[k][0], inner[k + 1][0], inner[k + 1][1], inner[k][1]); // the opening's roof
    g.quad(outer[k][0], outer[k][1], outer[k + 1][1], outer[k + 1][0]); // the outside
  }
  g.quad(inner[0][0], inner[0][1], outer[0][1], outer[0][0]); // the feet on the bed
  g.quad(inner[n - 1][0], outer[n - 1][0], outer[n - 1][1], inner[n - 1][1]);
  return g.mesh();
}
