/**
 * Test-only helpers for the slice tests: a tiny STL reader (binary and ASCII, welded by exact
 * float bits) and synthetic meshes. Not exported from the package; src/mesh is the real loader.
 */
import { existsSync, readFileSync } from 'node:fs';
import { gunzipSync } from 'node:zlib';
import type { Mesh } from '#strata/mesh/types.js';
import { inCi, modelPath } from '../e2e/models-dir.js';

export { MODELS_DIR } from '../e2e/models-dir.js';

/** Weld a triangle soup (9 floats per triangle) by exact float32 bit patterns. */
export function weldSoup(soup: Float32Array): Mesh {
  const bits = new Uint32Array(soup.buffer, soup.byteOffset, soup.length);
  const corners = soup.length / 3;
  let cap = 16;
  while (cap < corners * 2) cap *= 2;
  const mask = cap - 1;
  const table = new Int32Array(cap).fill(-1);
  const positions = new Float32Array(soup.length);
  const posBits = new Uint32Array(positions.buffer);
  const indices = new Uint32Array(corners);
  let count = 0;
  for (let c = 0; c < corners; c++) {
    const a = bits[3 * c],
      b = bits[3 * c + 1],
      d = bits[3 * c + 2];
    let h = (Math.imul(a, 0x9e3779b1) ^ Math.imul(b, 0x85ebca77) ^ Math.imul(d, 0xc2b2ae3d)) >>> 0;
    h = (h ^ (h >>> 16)) & mask;
    for (;;) {
      const v = table[h];
      if (v === -1) {
        table[h] = count;
        posBits[3 * count] = a;
        posBits[3 * count + 1] = b;
        posBits[3 * count + 2] = d;
        indices[c] = count++;
        break;
      }
      if (posBits[3 * v] === a && posBits[3 * v + 1] === b && posBits[3 * v + 2] === d) {
        indices[c] = v;
        break;
      }
      h = (h + 1) & mask;
    }
  }
  return { positions: positions.slice(0, 3 * count), indices };
}

/** Parse a binary or ASCII STL into a welded mesh. */
export function parseStl(data: Uint8Array): Mesh {
  const view = new DataView(data.buffer, data.byteOffset, data.byteLength);
  const binaryCount = data.byteLength >= 84 ? view.getUint32(80, true) : -1;
  if (binaryCount >= 0 && 84 + 50 * binaryCount === data.byteLength) {
    const soup = new Float32Array(binaryCount * 9);
    for (let t = 0; t < binaryCount; t++) {
      const o = 84 + 50 * t + 12;
      for (let k = 0; k < 9; k++) soup[9 * t + k] = view.getFloat32(o + 4 * k, true);
    }
    return weldSoup(soup);
  }
  const text = new TextDecoder().decode(data);
  const values: number[] = [];
  const re = /vertex\s+(\S+)\s+(\S+)\s+(\S+)/g;
  for (let m = re.exec(text); m; m = re.exec(text)) values.push(Number(m[1]), Number(m[2]), Number(m[3]));
  return weldSoup(Float32Array.from(values.slice(0, values.length - (values.length % 9))));
}

/** Load a model from the shared models folder (`.gz` is unpacked); null when it is not there (an error under CI). */
export function loadModel(name: string): Mesh | null {
  const path = modelPath(name);
  if (!existsSync(path)) {
    if (inCi()) throw new Error(`shared model ${path} is missing: under CI the tests fail rather than skip`);
    return null;
  }
  let data: Uint8Array = readFileSync(path);
  if (name.endsWith('.gz')) data = gunzipSync(data);
  return parseStl(data);
}

/** Highest z of a mesh (mm). */
export function meshTop(mesh: Mesh): number {
  let top = -Infinity;
  for (let i = 2; i < mesh.positions.length; i += 3) if (mesh.positions[i] > top) top = mesh.positions[i];
  return top;
}

type Tri = [number, number, number, number, number, number, number, number, number];

function soupOf(tris: Tri[]): Mesh {
  return weldSoup(Float32Array.from(tris.flat()));
}

/** Outward-facing wall triangles under edge p→q (outside on the right of p→q seen from above). */
function wall(px: number, py: number, qx: number, qy: number, z0: number, z1: number): Tri[] {
  return [
    [px, py, z0, qx, qy, z0, qx, qy, z1],
    [px, py, z0, qx, qy, z1, px, py, z1],
  ];
}

/** A closed box, outward-facing. */
export function box(x0: number, y0: number, z0: number, x1: number, y1: number, z1: number): Mesh {
  return frame([x0, y0, x1, y1], null, z0, z1);
}

/**
 * A square frame (outer rectangle minus an inner one) extruded from z0 to z1, closed and
 * outward-facing; with `inner` null it is a plain box.
 */
export function frame(
  outer: [number, number, number, number],
  inner: [number, number, number, number] | null,
  z0: number,
  z1: number,
): Mesh {
  const ring = (r: [number, number, number, number]): [number, number][] => [
    [r[0], r[1]],
    [r[2], r[1]],
    [r[2], r[3]],
    [r[0], r[3]],
  ];
  const o = ring(outer);
  const tris: Tri[] = [];
  for (let k = 0; k < 4; k++) {
    const p = o[k],
      q = o[(k + 1) % 4];
    tris.push(...wall(p[0], p[1], q[0], q[1], z0, z1));
  }
  if (!inner) {
    tris.push([o[0][0], o[0][1], z1, o[1][0], o[1][1], z1, o[2][0], o[2][1], z1]);
    tris.push([o[0][0], o[0][1], z1, o[2][0], o[2][1], z1, o[3][0], o[3][1], z1]);
    tris.push([o[0][0], o[0][1], z0, o[2][0], o[2][1], z0, o[1][0], o[1][1], z0]);
    tris.push([o[0][0], o[0][1], z0, o[3][0], o[3][1], z0, o[2][0], o[2][1], z0]);
    return soupOf(tris);
  }
  const h = ring(inner);
  for (let k = 0; k < 4; k++) {
    // The hole's wall faces into the hole: walk the inner ring clockwise.
    const p = h[(k + 1) % 4],
      q = h[k];
    tris.push(...wall(p[0], p[1], q[0], q[1], z0, z1));
    // Caps: trapezoid O_k, O_k+1, I_k+1, I_k (counter-clockwise seen from above).
    const a = o[k],
      b = o[(k + 1) % 4],
      c = h[(k + 1) % 4],
      d = h[k];
    tris.push([a[0], a[1], z1, b[0], b[1], z1, c[0], c[1], z1]);
    tris.push([a[0], a[1], z1, c[0], c[1], z1, d[0], d[1], z1]);
    tris.push([a[0], a[1], z0, c[0], c[1], z0, b[0], b[1], z0]);
    tris.push([a[0], a[1], z0, d[0], d[1], z0, c[0], c[1], z0]);
  }
  return soupOf(tris);
}

/** Several meshes as one (shells stay separate). */
export function merge(...meshes: Mesh[]): Mesh {
  let nv = 0,
    ni = 0;
  for (const m of meshes) {
    nv += m.positions.length;
    ni += m.indices.length;
  }
  const positions = new Float32Array(nv);
  const indices = new Uint32Array(ni);
  let pv = 0,
    pi = 0;
  for (const m of meshes) {
    positions.set(m.positions, pv);
    for (let i = 0; i < m.indices.length; i++) indices[pi + i] = m.indices[i] + pv / 3;
    pv += m.positions.length;
    pi += m.indices.length;
  }
  return { positions, indices };
}

/** The same mesh with every triangle's winding reversed (normals pointing inwards). */
export function inverted(mesh: Mesh): Mesh {
  const indices = mesh.indices.slice();
  for (let t = 0; t + 2 < indices.length; t += 3) {
    const tmp = indices[t + 1];
    indices[t + 1] = indices[t + 2];
    indices[t + 2] = tmp;
  }
  return { positions: mesh.positions, indices };
}
