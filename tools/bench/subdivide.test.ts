import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { binaryStlTriangles, subdivideBinaryStl } from './subdivide.js';

const MODELS = new URL('../../../../shared/models/', import.meta.url);

/** A binary STL from triangles given as 9 numbers each. */
function stl(triangles: readonly (readonly number[])[]): Uint8Array {
  const bytes = new Uint8Array(84 + 50 * triangles.length);
  const dv = new DataView(bytes.buffer);
  dv.setUint32(80, triangles.length, true);
  triangles.forEach((t, i) => t.forEach((v, k) => dv.setFloat32(84 + 50 * i + 12 + 4 * k, v, true)));
  return bytes;
}

/** The corner coordinates of every triangle (as stored: float32). */
function corners(bytes: Uint8Array): Float32Array {
  const n = binaryStlTriangles(bytes)!;
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = new Float32Array(9 * n);
  for (let t = 0; t < n; t++)
    for (let k = 0; k < 9; k++) out[9 * t + k] = dv.getFloat32(84 + 50 * t + 12 + 4 * k, true);
  return out;
}

function bounds(p: Float32Array): number[] {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < p.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3]!, p[i]!);
    hi[i % 3] = Math.max(hi[i % 3]!, p[i]!);
  }
  return [...lo, ...hi];
}

/** Signed volume (divergence theorem), float64 from the float32 corners. */
function volume(p: Float32Array): number {
  let v = 0;
  for (let i = 0; i < p.length; i += 9) {
    const [ax, ay, az, bx, by, bz, cx, cy, cz] = p.subarray(i, i + 9);
    v += ax! * (by! * cz! - bz! * cy!) - ay! * (bx! * cz! - bz! * cx!) + az! * (bx! * cy! - by! * cx!);
  }
  return v / 6;
}

/**
 * Edges that are not closed: on exact float32 positions, every directed edge a→b must meet exactly one b→a
 * (closed and consistently oriented). Returns how many directed edges lack their partner or repeat.
 */
function openEdges(p: Float32Array): number {
  const key = (i: number) => `${p[i]},${p[i + 1]},${p[i + 2]}`;
  const count = new Map<string, number>();
  for (let t = 0; t < p.length; t += 9) {
    for (let e = 0; e < 3; e++) {
      const a = key(t + 3 * e);
      const b = key(t + 3 * ((e + 1) % 3));
      if (a === b) continue; // a degenerate triangle's collapsed edge
      count.set(`${a}>${b}`, (count.get(`${a}>${b}`) ?? 0) + 1);
    }
  }
  let bad = 0;
  for (const [k, n] of count) {
    const [a, b] = k.split('>');
    if (n !== 1 || count.get(`${b}>${a}`) !== 1) bad++;
  }
  return bad;
}

// A closed tetrahedron with awkward float32 coordinates (midpoints need rounding).
const TETRA = stl(
  [
    [0.1, 0.2, 0.3, 10.7, 0.1, 0.3, 0.3, 9.9, 0.2],
    [0.1, 0.2, 0.3, 0.3, 9.9, 0.2, 3.3, 3.1, 7.77],
    [0.1, 0.2, 0.3, 3.3, 3.1, 7.77, 10.7, 0.1, 0.3],
    [10.7, 0.1, 0.3, 3.3, 3.1, 7.77, 0.3, 9.9, 0.2],
  ].map(([ax, ay, az, bx, by, bz, cx, cy, cz]) => [ax!, ay!, az!, cx!, cy!, cz!, bx!, by!, bz!]),
);

test('subdivision: 4× the triangles, same bounds and volume, watertight stays watertight (tetrahedron)', () => {
  const src = corners(TETRA);
  assert.equal(openEdges(src), 0, 'fixture is closed');
  assert.ok(volume(src) > 0, 'fixture faces outward');
  const out = subdivideBinaryStl(TETRA);
  assert.equal(binaryStlTriangles(out), 16);
  assert.equal(out.length, 84 + 50 * 16);
  const sub = corners(out);
  assert.deepEqual(bounds(sub), bounds(src));
  assert.ok(Math.abs(volume(sub) - volume(src)) <= 1e-5 * volume(src), `${volume(sub)} vs ${volume(src)}`);
  assert.equal(openEdges(sub), 0);
  // the first child is (a, ab, ca) with ab the float32 of the exact mean
  assert.equal(sub[0], src[0]);
  assert.equal(sub[3], Math.fround((src[0]! + src[3]!) / 2));
});

test('subdivision of a real watertight model (SupportTest.stl) and the shared models are binary', () => {
  const bytes: Uint8Array = readFileSync(new URL('SupportTest.stl', MODELS));
  const n = binaryStlTriangles(bytes)!;
  assert.equal(n, 3242);
  const src = corners(bytes);
  assert.equal(openEdges(src), 0);
  const sub = corners(subdivideBinaryStl(bytes));
  assert.equal(sub.length / 9, 4 * n);
  assert.deepEqual(bounds(sub), bounds(src));
  assert.ok(Math.abs(volume(sub) - volume(src)) <= 1e-6 * Math.abs(volume(src)));
  assert.equal(openEdges(sub), 0);
});

test('subdivision keeps every facet normal and rejects what is not a binary STL', () => {
  const withNormal = new Uint8Array(TETRA);
  new DataView(withNormal.buffer).setFloat32(84, 0.5, true);
  const out = new DataView(subdivideBinaryStl(withNormal).buffer);
  for (let c = 0; c < 4; c++) assert.equal(out.getFloat32(84 + 50 * c, true), 0.5);
  assert.throws(() => subdivideBinaryStl(new TextEncoder().encode('solid x\nendsolid x\n')), /needs a binary STL/);
  assert.throws(() => subdivideBinaryStl(TETRA.subarray(0, TETRA.length - 1)), /needs a binary STL/);
});
