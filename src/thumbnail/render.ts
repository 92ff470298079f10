/**
 * A small software renderer for plate previews: the mesh seen from the front, above and a little to
 * the side (orthographic), every triangle filled through a depth buffer and shaded by two lights and
 * an ambient term, so the model's shape reads at 16×16 as well as at 480×240. Pure JavaScript, no GPU:
 * it runs the same in Node and browsers and gives the same pixels every time.
 *
 * The image is drawn SUPERSAMPLE× larger and box-filtered down (premultiplied alpha), which smooths the
 * edges. The background is transparent; `background` composites onto a colour instead (for JPG).
 */
import type { Mesh } from '../mesh/types.js';
import type { RgbaImage } from './types.js';

/** View direction: azimuth from the front (−Y) towards +X, and elevation above the bed, degrees. */
const VIEW_AZIMUTH_DEG = -35;
const VIEW_ELEVATION_DEG = 32;
/** Share of the image left free around the model on each side. */
const MARGIN = 0.06;
/** Model colour (sRGB) and lighting. */
const BASE_RGB: readonly [number, number, number] = [236, 120, 40];
const AMBIENT = 0.28;
const KEY_LIGHT = 0.62;
const FILL_LIGHT = 0.22;
/** Faces seen from behind (open meshes) are drawn this much darker. */
const BACK_FACE = 0.6;

type Vec3 = [number, number, number];

function normalize(v: Vec3): Vec3 {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
}
function cross(a: Vec3, b: Vec3): Vec3 {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

/** The camera's right, up and forward (into the scene) unit vectors. */
function cameraBasis(): { right: Vec3; up: Vec3; forward: Vec3 } {
  const az = (VIEW_AZIMUTH_DEG * Math.PI) / 180;
  const el = (VIEW_ELEVATION_DEG * Math.PI) / 180;
  // where the camera sits, seen from the model
  const toCamera: Vec3 = [Math.sin(az) * Math.cos(el), -Math.cos(az) * Math.cos(el), Math.sin(el)];
  const forward: Vec3 = [-toCamera[0], -toCamera[1], -toCamera[2]];
  const right = normalize(cross(forward, [0, 0, 1]));
  const up = cross(right, forward);
  return { right, up, forward };
}

export interface RenderOptions {
  /** Composite onto this sRGB colour instead of leaving the background transparent. */
  background?: readonly [number, number, number];
}

/** One mesh of the meshes given, all of them placed on the bed together. */
function joined(meshes: Mesh | readonly Mesh[]): Mesh {
  if (!Array.isArray(meshes)) return meshes as Mesh;
  const list = meshes as readonly Mesh[];
  if (list.length === 1) return list[0]!;
  let nv = 0,
    ni = 0;
  for (const m of list) {
    nv += m.positions.length;
    ni += m.indices.length;
  }
  const positions = new Float32Array(nv);
  const indices = new Uint32Array(ni);
  let pv = 0,
    pi = 0;
  for (const m of list) {
    positions.set(m.positions, pv);
    for (let k = 0; k < m.indices.length; k++) indices[pi + k] = m.indices[k]! + pv / 3;
    pv += m.positions.length;
    pi += m.indices.length;
  }
  return { positions, indices };
}

/** Render the mesh or meshes (mm, Z up) into a width × height RGBA image. Nothing to draw gives a transparent image. */
export function renderMesh(
  meshes: Mesh | readonly Mesh[],
  width: number,
  height: number,
  opts: RenderOptions = {},
): RgbaImage {
  const mesh = joined(meshes);
  const ss = width * height < 4096 ? 4 : 2;
  const W = width * ss;
  const H = height * ss;
  const { right, up, forward } = cameraBasis();
  const pos = mesh.positions;
  const idx = mesh.indices;
  const nv = pos.length / 3;
  // project every vertex once: screen x, y (mm) and depth
  const sx = new Float64Array(nv);
  const sy = new Float64Array(nv);
  const sz = new Float64Array(nv);
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (let v = 0; v < nv; v++) {
    const x = pos[v * 3]!,
      y = pos[v * 3 + 1]!,
      z = pos[v * 3 + 2]!;
    const px = x * right[0] + y * right[1] + z * right[2];
    const py = x * up[0] + y * up[1] + z * up[2];
    sx[v] = px;
    sy[v] = py;
    sz[v] = x * forward[0] + y * forward[1] + z * forward[2];
    if (px < minX) minX = px;
    if (px > maxX) maxX = px;
    if (py < minY) minY = py;
    if (py > maxY) maxY = py;
  }
  const colour = new Float32Array(W * H * 3);
  const cover = new Uint8Array(W * H);
  if (idx.length > 0 && maxX > minX && maxY > minY) {
    const scale = Math.min((W * (1 - 2 * MARGIN)) / (maxX - minX), (H * (1 - 2 * MARGIN)) / (maxY - minY));
    const ox = W / 2 - ((minX + maxX) / 2) * scale;
    const oy = H / 2 + ((minY + maxY) / 2) * scale;
    for (let v = 0; v < nv; v++) {
      sx[v] = ox + sx[v]! * scale;
      sy[v] = oy - sy[v]! * scale;
    }
    rasterize(mesh, sx, sy, sz, W, H, forward, colour, cover);
  }
  return downsample(colour, cover, W, H, ss, width, height, opts.background);
}

/** Lights: a key light from the upper left front and a fill from the right, as unit vectors towards them. */
const KEY_DIR = normalize([-0.45, -0.7, 0.75]);
const FILL_DIR = normalize([0.8, -0.2, 0.25]);

function rasterize(
  mesh: Mesh,
  sx: Float64Array,
  sy: Float64Array,
  sz: Float64Array,
  W: number,
  H: number,
  forward: Vec3,
  colour: Float32Array,
  cover: Uint8Array,
): void {
  const depth = new Float64Array(W * H).fill(Infinity);
  const pos = mesh.positions;
  const idx = mesh.indices;
  for (let t = 0; t < idx.length; t += 3) {
    const a = idx[t]!,
      b = idx[t + 1]!,
      c = idx[t + 2]!;
    // face normal in world space, for the shading
    const ux = pos[b * 3]! - pos[a * 3]!,
      uy = pos[b * 3 + 1]! - pos[a * 3 + 1]!,
      uz = pos[b * 3 + 2]! - pos[a * 3 + 2]!;
    const vx = pos[c * 3]! - pos[a * 3]!,
      vy = pos[c * 3 + 1]! - pos[a * 3 + 1]!,
      vz = pos[c * 3 + 2]! - pos[a * 3 + 2]!;
    let nx = uy * vz - uz * vy,
      ny = uz * vx - ux * vz,
      nz = ux * vy - uy * vx;
    const nl = Math.hypot(nx, ny, nz);
    if (!(nl > 0)) continue;
    nx /= nl;
    ny /= nl;
    nz /= nl;
    let tint = 1;
    if (nx * forward[0] + ny * forward[1] + nz * forward[2] > 0) {
      // seen from behind: light it as if it faced us, a little darker
      nx = -nx;
      ny = -ny;
      nz = -nz;
      tint = BACK_FACE;
    }
    const key = Math.max(0, nx * KEY_DIR[0] + ny * KEY_DIR[1] + nz * KEY_DIR[2]);
    const fill = Math.max(0, nx * FILL_DIR[0] + ny * FILL_DIR[1] + nz * FILL_DIR[2]);
    const light = tint * (AMBIENT + KEY_LIGHT * key + FILL_LIGHT * fill);
    const r = Math.min(255, BASE_RGB[0] * light);
    const g = Math.min(255, BASE_RGB[1] * light);
    const bl = Math.min(255, BASE_RGB[2] * light);

    const x0 = sx[a]!,
      y0 = sy[a]!,
      x1 = sx[b]!,
      y1 = sy[b]!,
      x2 = sx[c]!,
      y2 = sy[c]!;
    const area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if (area === 0) continue;
    const minPx = Math.max(0, Math.floor(Math.min(x0, x1, x2)));
    const maxPx = Math.min(W - 1, Math.ceil(Math.max(x0, x1, x2)));
    const minPy = Math.max(0, Math.floor(Math.min(y0, y1, y2)));
    const maxPy = Math.min(H - 1, Math.ceil(Math.max(y0, y1, y2)));
    const z0 = sz[a]!,
      z1 = sz[b]!,
      z2 = sz[c]!;
    const inv = 1 / area;
    for (let py = minPy; py <= maxPy; py++) {
      const cy = py + 0.5;
      for (let px = minPx; px <= maxPx; px++) {
        const cx = px + 0.5;
        // barycentric weights of the pixel centre (same sign as the area inside the triangle)
        const w0 = ((x1 - cx) * (y2 - cy) - (x2 - cx) * (y1 - cy)) * inv;
        const w1 = ((x2 - cx) * (y0 - cy) - (x0 - cx) * (y2 - cy)) * inv;
        const w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const d = w0 * z0 + w1 * z1 + w2 * z2;
        const i = py * W + px;
        if (d >= depth[i]!) continue;
        depth[i] = d;
        cover[i] = 1;
        colour[i * 3] = r;
        colour[i * 3 + 1] = g;
        colour[i * 3 + 2] = bl;
      }
    }
  }
}

function downsample(
  colour: Float32Array,
  cover: Uint8Array,
  W: number,
  _H: number,
  ss: number,
  width: number,
  height: number,
  background?: readonly [number, number, number],
): RgbaImage {
  const data = new Uint8Array(width * height * 4);
  const samples = ss * ss;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      let r = 0,
        g = 0,
        b = 0,
        n = 0;
      for (let dy = 0; dy < ss; dy++) {
        for (let dx = 0; dx < ss; dx++) {
          const i = (y * ss + dy) * W + x * ss + dx;
          if (!cover[i]) continue;
          r += colour[i * 3]!;
          g += colour[i * 3 + 1]!;
          b += colour[i * 3 + 2]!;
          n++;
        }
      }
      const o = (y * width + x) * 4;
      if (background) {
        const bg = samples - n;
        data[o] = Math.round((r + background[0] * bg) / samples);
        data[o + 1] = Math.round((g + background[1] * bg) / samples);
        data[o + 2] = Math.round((b + background[2] * bg) / samples);
        data[o + 3] = 255;
      } else if (n > 0) {
        data[o] = Math.round(r / n);
        data[o + 1] = Math.round(g / n);
        data[o + 2] = Math.round(b / n);
        data[o + 3] = Math.round((255 * n) / samples);
      }
    }
  }
  return { width, height, data };
}
