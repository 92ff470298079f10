/**
 * Putting models on the build plate. A model is what the caller gave as one input (a file, a
 * three.js scene, a mesh): its objects keep their places relative to each other. Each model is
 * turned and scaled (model-transform.ts), dropped to z = 0, and then either arranged with the
 * others around the bed centre (arrange.ts) or kept at its own XY coordinates. A model that does
 * not fit the build volume is refused, naming it, the axis and by how much.
 */
import { StrataError } from '../errors.js';
import { arrangeAll } from './arrange.js';
import { isIdentity, modelMatrix, NO_TRANSFORM, type ModelTransform } from './model-transform.js';
import { usedVertexBounds } from './prepare.js';
import { transformPoints } from './transform.js';
import type { Mesh, MeshObject, SettingsSource } from './types.js';

/** One model: what the caller gave as one input. */
export interface ModelInput {
  /** For messages: the file name, or the object's name. */
  name: string;
  objects: MeshObject[];
  /** A project file's print settings, and what its reader noted (carried to the slicer with the objects). */
  projectSettings?: SettingsSource;
  warnings?: string[];
}

/** Concatenate the objects' meshes (no welding across objects). */
export function mergeObjects(objects: readonly MeshObject[]): Mesh {
  let nPos = 0;
  let nIdx = 0;
  for (const o of objects) {
    nPos += o.mesh.positions.length;
    nIdx += o.mesh.indices.length;
  }
  const positions = new Float32Array(nPos);
  const indices = new Uint32Array(nIdx);
  let p = 0;
  let k = 0;
  for (const o of objects) {
    const base = p / 3;
    positions.set(o.mesh.positions, p);
    const src = o.mesh.indices;
    for (let i = 0; i < src.length; i++) indices[k + i] = src[i] + base;
    p += o.mesh.positions.length;
    k += src.length;
  }
  return { positions, indices };
}

export interface PlaceOptions {
  /** Arrange the models around the bed centre; false keeps their XY coordinates. */
  center: boolean;
  bedWidth: number;
  bedLength: number;
  bedHeight: number;
  /** The bed origin (0, 0) is its centre (delta printers) rather than its front-left corner. */
  originAtCenter: boolean;
  /** Gap between arranged models, mm (default 6). */
  spacing?: number;
  /** The setting the gap comes from, for the message when the models do not fit (default objectSpacing). */
  spacingSetting?: string;
  /** What the first layer adds around the models (a skirt or brim), mm, kept on the bed too. */
  margin?: { mm: number; what: string };
  /** Turned and scaled before placing (default none). */
  transform?: ModelTransform;
}

export interface PlacedModels {
  /** Every object of every model, in bed coordinates, in input order. */
  objects: MeshObject[];
  /** Translation given to each model after its transform, mm. */
  offsets: Array<[number, number, number]>;
  /** Notes for the caller. */
  warnings: string[];
}

/** Tolerance for "fits" comparisons, in mm (float32 rounding of coordinates near 200 mm is ~1e-5). */
const FIT_EPS = 1e-3;

interface Box {
  min: [number, number, number];
  max: [number, number, number];
}

/** Bounds of the vertices the triangles use, checking indices and finiteness. */
function usedBounds(mesh: Mesh, what: string, box: Box): void {
  const { positions, indices } = mesh;
  const nVerts = positions.length / 3;
  for (let i = 0; i < indices.length; i++) {
    const v = indices[i];
    if (v >= nVerts)
      throw new StrataError(
        'BAD_MESH',
        `${what}: triangle ${Math.floor(i / 3)} uses vertex ${v} but there are only ${nVerts} vertices`,
      );
  }
  const { min, max } = usedVertexBounds(positions, indices);
  for (let k = 0; k < 3; k++) {
    if (min[k] < box.min[k]) box.min[k] = min[k];
    if (max[k] > box.max[k]) box.max[k] = max[k];
  }
  if (![...box.min, ...box.max].every(Number.isFinite)) {
    throw new StrataError('BAD_MESH', `${what}: the model has coordinates that are not finite numbers`);
  }
}

function emptyBox(): Box {
  return { min: [Infinity, Infinity, Infinity], max: [-Infinity, -Infinity, -Infinity] };
}

function checkBed(opts: PlaceOptions): void {
  for (const key of ['bedWidth', 'bedLength', 'bedHeight'] as const) {
    const v = opts[key];
    if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0) {
      throw new StrataError('BAD_SETTING', `${key} must be a positive number of mm, got ${String(v)}`);
    }
  }
}

/** Place the models on the bed; throws DOES_NOT_FIT naming the model that does not fit. */
export function placeModels(models: readonly ModelInput[], opts: PlaceOptions): PlacedModels {
  checkBed(opts);
  const transform = opts.transform ?? NO_TRANSFORM;
  const linear = isIdentity(transform) ? null : modelMatrix(transform);
  // turn and scale each model, and find its bounds
  const turned = models.map((m) => {
    if (m.objects.every((o) => o.mesh.indices.length === 0)) {
      throw new StrataError('EMPTY_MODEL', `${m.name}: the model has no triangles: there is nothing to print`);
    }
    const box = emptyBox();
    const objects = m.objects.map((o): MeshObject => {
      const mesh = linear ? transformMesh(o.mesh, linear) : o.mesh;
      usedBounds(mesh, m.name, box);
      // the object's other volumes turn with it; only its parts are printed, so only they are placed
      const volumes = o.volumes?.map((v) => (linear ? { ...v, mesh: transformMesh(v.mesh, linear) } : v));
      return volumes ? { ...o, mesh, volumes } : { ...o, mesh };
    });
    return { name: m.name, objects, box };
  });

  const { bedWidth: w, bedLength: l } = opts;
  const bedX0 = opts.originAtCenter ? -w / 2 : 0;
  const bedY0 = opts.originAtCenter ? -l / 2 : 0;
  const margin = opts.margin && opts.margin.mm > 0 ? opts.margin : { mm: 0, what: '' };
  const around = margin.mm;
  const withMargin = around > 0 ? ` with its ${mm(around)} mm ${margin.what}` : '';
  for (const m of turned) checkSize(m.name, m.box, opts, margin);

  const offsets: Array<[number, number, number]> = [];
  const warnings: string[] = [];
  if (opts.center) {
    const cx = opts.originAtCenter ? 0 : w / 2;
    const cy = opts.originAtCenter ? 0 : l / 2;
    if (turned.length === 1) {
      const { min, max } = turned[0].box;
      offsets.push([cx - (min[0] + max[0]) / 2, cy - (min[1] + max[1]) / 2, -min[2]]);
    } else {
      const gap = opts.spacing ?? 6;
      const sizes = turned.map((m) => ({ width: m.box.max[0] - m.box.min[0], depth: m.box.max[1] - m.box.min[1] }));
      // packed around the centre of a bed twice the size, so the first model in the middle does not
      // pin the group; then the group has to fit the real bed, and is centred on it
      const bedW = w - 2 * around;
      const bedL = l - 2 * around;
      const spots = arrangeAll(sizes, { center: [0, 0], width: 2 * bedW, depth: 2 * bedL }, gap);
      let gx0 = Infinity,
        gy0 = Infinity,
        gx1 = -Infinity,
        gy1 = -Infinity;
      spots?.forEach(([x, y], i) => {
        gx0 = Math.min(gx0, x - sizes[i].width / 2);
        gx1 = Math.max(gx1, x + sizes[i].width / 2);
        gy0 = Math.min(gy0, y - sizes[i].depth / 2);
        gy1 = Math.max(gy1, y + sizes[i].depth / 2);
      });
      if (spots === null || gx1 - gx0 > bedW + FIT_EPS || gy1 - gy0 > bedL + FIT_EPS) {
        throw new StrataError(
          'DOES_NOT_FIT',
          `the ${turned.length} models do not fit on the ${fmt(w)} × ${fmt(l)} mm bed together, ${fmt(gap)} mm apart${withMargin.replace(' its', ' their')}: slice fewer at once, make them smaller or lower ${opts.spacingSetting ?? 'objectSpacing'}`,
        );
      }
      const sx = cx - (gx0 + gx1) / 2,
        sy = cy - (gy0 + gy1) / 2;
      turned.forEach((m, i) => {
        const { min, max } = m.box;
        offsets.push([sx + spots[i][0] - (min[0] + max[0]) / 2, sy + spots[i][1] - (min[1] + max[1]) / 2, -min[2]]);
      });
    }
  } else {
    for (const m of turned) offsets.push([0, 0, -m.box.min[2]]);
    const off: string[] = [];
    for (const m of turned) {
      const { min, max } = m.box;
      const past: string[] = [];
      const side = (by: number, where: string, axis: string, lo: number, hi: number, b0: number, b1: number): void => {
        if (by > FIT_EPS)
          past.push(
            `${mm(by)} mm past the ${where} edge (${axis} ${mm(lo)} to ${mm(hi)} mm${withMargin}, the bed ${fmt(b0)} to ${fmt(b1)} mm)`,
          );
      };
      side(bedX0 - (min[0] - around), 'left', 'X', min[0], max[0], bedX0, bedX0 + w);
      side(max[0] + around - (bedX0 + w), 'right', 'X', min[0], max[0], bedX0, bedX0 + w);
      side(bedY0 - (min[1] - around), 'front', 'Y', min[1], max[1], bedY0, bedY0 + l);
      side(max[1] + around - (bedY0 + l), 'back', 'Y', min[1], max[1], bedY0, bedY0 + l);
      if (past.length) off.push(`${m.name} leaves the bed by ${past.join(' and ')}`);
    }
    if (off.length) {
      throw new StrataError(
        'DOES_NOT_FIT',
        `${off.join('; ')}; without --no-center (center: true) it would be placed on the bed`,
      );
    }
  }

  const objects: MeshObject[] = [];
  turned.forEach((m, i) => {
    const [dx, dy, dz] = offsets[i];
    for (const o of m.objects) {
      const placed: MeshObject = { ...o, mesh: translate(o.mesh, dx, dy, dz) };
      if (o.volumes) placed.volumes = o.volumes.map((v) => ({ ...v, mesh: translate(v.mesh, dx, dy, dz) }));
      if (o.layerRanges) placed.layerRanges = o.layerRanges;
      objects.push(placed);
    }
  });
  return { objects, offsets, warnings };
}

/** Refuse a model larger than the build volume (only the size matters here, not the position). */
function checkSize(name: string, box: Box, opts: PlaceOptions, margin: { mm: number; what: string }): void {
  const { bedWidth: w, bedLength: l, bedHeight: h } = opts;
  const sx = box.max[0] - box.min[0],
    sy = box.max[1] - box.min[1],
    sz = box.max[2] - box.min[2];
  const m = 2 * margin.mm;
  const plus = (size: number, bed: number) =>
    m > 0 && size <= bed + FIT_EPS ? ` (${mm(size + m)} mm with its ${margin.what})` : '';
  const problems: string[] = [];
  if (sx + m > w + FIT_EPS) problems.push(`${mm(sx)} mm wide in X${plus(sx, w)}, the bed ${fmt(w)} mm`);
  if (sy + m > l + FIT_EPS) problems.push(`${mm(sy)} mm deep in Y${plus(sy, l)}, the bed ${fmt(l)} mm`);
  if (sz > h + FIT_EPS) problems.push(`${mm(sz)} mm tall in Z, the volume ${fmt(h)} mm`);
  if (problems.length > 0) {
    throw new StrataError(
      'DOES_NOT_FIT',
      `${name} is ${mm(sx)} × ${mm(sy)} × ${mm(sz)} mm and does not fit the ${fmt(w)} × ${fmt(l)} × ${fmt(h)} mm build volume (${problems.join('; ')})`,
    );
  }
}

function transformMesh(mesh: Mesh, m: Float64Array): Mesh {
  const out = new Float32Array(mesh.positions.length);
  transformPoints(m, mesh.positions, mesh.positions.length / 3, out, 0);
  return { positions: out, indices: mesh.indices };
}

function translate(mesh: Mesh, dx: number, dy: number, dz: number): Mesh {
  const { positions } = mesh;
  const out = new Float32Array(positions.length);
  for (let i = 0; i < positions.length; i += 3) {
    out[i] = positions[i] + dx;
    out[i + 1] = positions[i + 1] + dy;
    out[i + 2] = positions[i + 2] + dz;
  }
  return { positions: out, indices: mesh.indices };
}

/** One decimal, as model sizes are shown. */
function mm(v: number): string {
  const s = v.toFixed(1);
  return s === '-0.0' ? '0.0' : s;
}

/** A setting as the user wrote it: 220 → "220", 220.5 → "220.5". */
function fmt(v: number): string {
  return String(Math.round(v * 1000) / 1000);
}
