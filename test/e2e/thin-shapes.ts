/**
 * Test-only parts with features thinner than a few lines, as binary STL: standing fins from a fraction of a
 * line up to four lines thick, a wall tapering from half a line to five, and a comb (fins standing off a spine,
 * where walls meet in T-junctions). Each comes with the outlines of its thin features in the part's own XY (mm)
 * so a test can measure what was printed there: slice with `center: false` and they are where the G-code is.
 *
 * The meshes are closed and manifold: every part is one or more prisms over a counter-clockwise outline, with
 * outward normals (counter-clockwise winding seen from outside) and caps triangulated without T-junctions.
 * Parts stand around (110, 110), the centre of the default 220 mm bed.
 */

/** A point in the XY plane, mm. */
export type Point = readonly [number, number];
/** A simple polygon, counter-clockwise, mm. */
export type Polygon = readonly Point[];

/** An axis-aligned rectangle, mm. */
export interface Rect {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

/** One thin feature of a test part: its nominal thickness and where it stands. */
export interface Fin {
  /** Thickness, mm. */
  thickness: number;
  rect: Rect;
  /** `rect` as a counter-clockwise polygon. */
  polygon: Polygon;
}

/** Centre of the default 220 × 220 mm bed: the parts stand around it. */
export const BED_CENTRE: Point = [110, 110];

/** Height of every thin test part, mm. */
export const THIN_PART_HEIGHT = 4;

/** Fin thicknesses of `finsPart`, mm: from below a line (0.4 mm nozzle) to four lines. */
export const FIN_THICKNESSES = [0.25, 0.35, 0.45, 0.6, 0.8, 1.0, 1.2, 1.6] as const;
/** Length (Y) of each of `finsPart`'s fins, mm. */
export const FIN_LENGTH = 10;
/** Clear gap between neighbouring fins of `finsPart`, mm. */
export const FIN_GAP = 4;

/** Fin thicknesses of `combPart`, mm. */
export const COMB_FIN_THICKNESSES = [0.3, 0.5, 0.7, 1.0] as const;

/** A rectangle as a counter-clockwise polygon. */
export function rectPolygon(r: Rect): Polygon {
  return [
    [r.x0, r.y0],
    [r.x1, r.y0],
    [r.x1, r.y1],
    [r.x0, r.y1],
  ];
}

/** Area of a polygon (positive when counter-clockwise), mm². */
export function polygonArea(poly: Polygon): number {
  let a = 0;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) a += poly[j][0] * poly[i][1] - poly[i][0] * poly[j][1];
  return a / 2;
}

type Vec3 = readonly [number, number, number];
type Triangle = readonly [Vec3, Vec3, Vec3];

/** Triangles as binary STL, with each facet's unit normal. */
export function binaryStl(tris: readonly Triangle[]): Uint8Array {
  const out = new Uint8Array(84 + 50 * tris.length);
  const dv = new DataView(out.buffer);
  dv.setUint32(80, tris.length, true);
  tris.forEach((t, n) => {
    const [a, b, c] = t;
    const ux = b[0] - a[0],
      uy = b[1] - a[1],
      uz = b[2] - a[2];
    const vx = c[0] - a[0],
      vy = c[1] - a[1],
      vz = c[2] - a[2];
    let nx = uy * vz - uz * vy,
      ny = uz * vx - ux * vz,
      nz = ux * vy - uy * vx;
    const len = Math.hypot(nx, ny, nz) || 1;
    nx /= len;
    ny /= len;
    nz /= len;
    const base = 84 + 50 * n;
    dv.setFloat32(base, nx, true);
    dv.setFloat32(base + 4, ny, true);
    dv.setFloat32(base + 8, nz, true);
    t.forEach((v, k) => v.forEach((q, m) => dv.setFloat32(base + 12 + 12 * k + 4 * m, q, true)));
  });
  return out;
}

/**
 * A closed prism from z0 to z1 over a counter-clockwise outline. Its caps are the union of convex `pieces`, each a
 * counter-clockwise list of indices into `outline` fanned from its first index (which must not lie on the line of
 * any other edge of the piece); together they must tile the outline, sharing whole edges. Without pieces the
 * outline itself must be convex.
 */
export function prismTris(
  outline: Polygon,
  z0: number,
  z1: number,
  pieces?: readonly (readonly number[])[],
): Triangle[] {
  const n = outline.length;
  const lo = outline.map(([x, y]): Vec3 => [x, y, z0]);
  const hi = outline.map(([x, y]): Vec3 => [x, y, z1]);
  const tris: Triangle[] = [];
  for (const piece of pieces ?? [outline.map((_, i) => i)]) {
    for (let k = 1; k + 1 < piece.length; k++) {
      const a = piece[0],
        b = piece[k],
        c = piece[k + 1];
      tris.push([hi[a], hi[b], hi[c]]); // top, facing up
      tris.push([lo[a], lo[c], lo[b]]); // bottom, facing down
    }
  }
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    // the outside of a counter-clockwise outline is on each edge's right
    tris.push([lo[i], lo[j], hi[j]], [lo[i], hi[j], hi[i]]);
  }
  return tris;
}

function boxFin(thickness: number, rect: Rect): Fin {
  return { thickness, rect, polygon: rectPolygon(rect) };
}

export interface FinsPart {
  stl: Uint8Array;
  height: number;
  /** The fins, thinnest first, left to right (increasing X). */
  fins: Fin[];
}

/**
 * Separate standing fins, no base: each its own island, `FIN_LENGTH` (10) mm along Y, `THIN_PART_HEIGHT` (4) mm
 * tall, `FIN_THICKNESSES` thick along X, with a clear `FIN_GAP` (4) mm between neighbours; the row is centred
 * on `at`.
 */
export function finsPart(at: Point = BED_CENTRE): FinsPart {
  const total = FIN_THICKNESSES.reduce((s, t) => s + t, 0) + FIN_GAP * (FIN_THICKNESSES.length - 1);
  let x = at[0] - total / 2;
  const y0 = at[1] - FIN_LENGTH / 2,
    y1 = at[1] + FIN_LENGTH / 2;
  const fins: Fin[] = [];
  const tris: Triangle[] = [];
  for (const t of FIN_THICKNESSES) {
    const fin = boxFin(t, { x0: x, y0, x1: x + t, y1 });
    fins.push(fin);
    tris.push(...prismTris(fin.polygon, 0, THIN_PART_HEIGHT));
    x += t + FIN_GAP;
  }
  return { stl: binaryStl(tris), height: THIN_PART_HEIGHT, fins };
}

export interface TaperPart {
  stl: Uint8Array;
  height: number;
  /** The wall's outline: a trapezoid, thin end at the left (smaller X). */
  outline: Polygon;
  /** Length along X, mm. */
  length: number;
  /** Thickness (Y) at the left and right ends, mm. */
  thinEnd: number;
  thickEnd: number;
  /** The wall's centre line runs along this Y from x0 to x0 + length. */
  x0: number;
  yCentre: number;
}

/**
 * One wall `length` (20) mm long along X, its thickness (Y) growing linearly from `thinEnd` (0.2) to `thickEnd`
 * (2) mm, `THIN_PART_HEIGHT` tall: a trapezoid prism, symmetric about its centre line, centred on `at`.
 */
export function taperPart(at: Point = BED_CENTRE, length = 20, thinEnd = 0.2, thickEnd = 2): TaperPart {
  const x0 = at[0] - length / 2,
    x1 = at[0] + length / 2,
    yc = at[1];
  const outline: Polygon = [
    [x0, yc - thinEnd / 2],
    [x1, yc - thickEnd / 2],
    [x1, yc + thickEnd / 2],
    [x0, yc + thinEnd / 2],
  ];
  return {
    stl: binaryStl(prismTris(outline, 0, THIN_PART_HEIGHT)),
    height: THIN_PART_HEIGHT,
    outline,
    length,
    thinEnd,
    thickEnd,
    x0,
    yCentre: yc,
  };
}

/**
 * The taper's outline cut across its length into `count` equal pieces (thinnest first), to judge it along its
 * length rather than on average.
 */
export function taperSections(taper: TaperPart, count: number): Polygon[] {
  const half = (x: number) => (taper.thinEnd + ((taper.thickEnd - taper.thinEnd) * (x - taper.x0)) / taper.length) / 2;
  const out: Polygon[] = [];
  for (let k = 0; k < count; k++) {
    const a = taper.x0 + (taper.length * k) / count,
      b = taper.x0 + (taper.length * (k + 1)) / count;
    const yc = taper.yCentre;
    out.push([
      [a, yc - half(a)],
      [b, yc - half(b)],
      [b, yc + half(b)],
      [a, yc + half(a)],
    ]);
  }
  return out;
}

export interface CombPart {
  stl: Uint8Array;
  height: number;
  /** The spine, `spineWidth` along X by `spineLength` along Y. */
  spine: Rect;
  /** The fins standing off the spine's right side (+X), thinnest first (increasing Y). */
  fins: Fin[];
  /** The whole part's outline (spine and fins), counter-clockwise. */
  outline: Polygon;
}

/**
 * A spine 4 mm (X) × 20 mm (Y) with fins `COMB_FIN_THICKNESSES` thick (along Y) and 6 mm long (along X) standing
 * off its right side, one per 5 mm of spine: T-junctions where each fin's walls meet the spine's. One closed
 * mesh, `THIN_PART_HEIGHT` tall, centred on `at` (the spine and fins together).
 */
export function combPart(at: Point = BED_CENTRE, spineWidth = 4, spineLength = 20, finLength = 6): CombPart {
  const sx0 = at[0] - (spineWidth + finLength) / 2,
    sx1 = sx0 + spineWidth;
  const sy0 = at[1] - spineLength / 2,
    sy1 = sy0 + spineLength;
  const fx1 = sx1 + finLength;
  const pitch = spineLength / COMB_FIN_THICKNESSES.length;
  const fins = COMB_FIN_THICKNESSES.map((t, k) => {
    const yc = sy0 + pitch * (k + 0.5);
    return boxFin(t, { x0: sx1, y0: yc - t / 2, x1: fx1, y1: yc + t / 2 });
  });
  // outline, counter-clockwise: along the spine's bottom, up its right side out and back along each fin, then
  // back along its top and down its left side
  const outline: Point[] = [
    [sx0, sy0],
    [sx1, sy0],
  ];
  const spinePiece: number[] = [0, 1];
  const finPieces: number[][] = [];
  for (const f of fins) {
    const i = outline.length;
    outline.push([sx1, f.rect.y0], [fx1, f.rect.y0], [fx1, f.rect.y1], [sx1, f.rect.y1]);
    spinePiece.push(i, i + 3);
    finPieces.push([i, i + 1, i + 2, i + 3]);
  }
  const tr = outline.length;
  outline.push([sx1, sy1], [sx0, sy1]);
  spinePiece.push(tr, tr + 1);
  // the spine's cap is fanned from its bottom-left corner, which lies on neither its right nor its top side
  const stl = binaryStl(prismTris(outline, 0, THIN_PART_HEIGHT, [spinePiece, ...finPieces]));
  return { stl, height: THIN_PART_HEIGHT, spine: { x0: sx0, y0: sy0, x1: sx1, y1: sy1 }, fins, outline };
}
