import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area, ringArea } from '#strata/geometry/clip.js';
import type { Mesh } from '#strata/mesh/types.js';
import { planLayers } from '#strata/slice/layers.js';
import { sliceMesh } from '#strata/slice/slice-mesh.js';
import { box, frame, inverted, merge } from './test-helpers.js';
import type { LayerSection } from '#strata/slice/types.js';

const MM2 = 1e6; // µm² per mm²

function slice(mesh: Mesh, height: number): LayerSection[] {
  return sliceMesh(mesh, planLayers(height, 0.2, 0.2), 10);
}

function assertEveryLayer(sections: LayerSection[], islands: number, holes: number, areaMm2: number): void {
  assert.ok(sections.length > 0);
  for (const s of sections) {
    assert.equal(s.islands.length, islands, `layer ${s.index}: islands`);
    assert.equal(
      s.islands.reduce((n, i) => n + i.holes.length, 0),
      holes,
      `layer ${s.index}: holes`,
    );
    assert.ok(Math.abs(area(s.islands) / MM2 - areaMm2) < 1e-3, `layer ${s.index}: area ${area(s.islands) / MM2}`);
    for (const i of s.islands) {
      assert.ok(ringArea(i.outer) > 0, 'outer rings are counter-clockwise');
      for (const h of i.holes) assert.ok(ringArea(h) < 0, 'holes are clockwise');
      for (const p of i.outer) assert.ok(Number.isInteger(p.x) && Number.isInteger(p.y), 'integer µm');
    }
  }
}

test('a cube gives one square island per layer with the right area', () => {
  const sections = slice(box(0, 0, 0, 10, 10, 10), 10);
  assert.equal(sections.length, 50);
  assertEveryLayer(sections, 1, 0, 100);
  assert.equal(sections[7].islands[0].outer.length, 4);
  assert.equal(sections[7].sliceZ, 1.5);
  assertEveryLayer(slice(box(-0.5, -0.5, 0, 0.5, 0.5, 1), 1), 1, 0, 1);
});

test('a cube with a through-hole gives one island with one hole', () => {
  assertEveryLayer(slice(frame([0, 0, 20, 20], [5, 5, 15, 15], 0, 10), 10), 1, 1, 400 - 100);
});

test('two disjoint cubes give two islands', () => {
  assertEveryLayer(slice(merge(box(0, 0, 0, 10, 10, 10), box(20, 0, 0, 30, 10, 10)), 10), 2, 0, 200);
});

test('two overlapping cubes union to one island', () => {
  assertEveryLayer(slice(merge(box(0, 0, 0, 10, 10, 10), box(5, 5, 0, 15, 15, 10)), 10), 1, 0, 175);
});

test('a cube with inverted winding still slices solid', () => {
  assertEveryLayer(slice(inverted(box(0, 0, 0, 10, 10, 10)), 10), 1, 0, 100);
  assertEveryLayer(slice(inverted(frame([0, 0, 20, 20], [5, 5, 15, 15], 0, 10)), 10), 1, 1, 300);
});

test('an inverted shell overlapping a correct one still unions', () => {
  assertEveryLayer(slice(merge(box(0, 0, 0, 10, 10, 10), inverted(box(5, 5, 0, 15, 15, 10))), 10), 1, 0, 175);
});

test('a cavity shell (facing inwards) stays a hole, also when the whole model is inverted', () => {
  const outer = box(0, 0, 0, 20, 20, 10);
  const cavity = inverted(box(5, 5, 2, 15, 15, 8));
  const sections = slice(merge(outer, cavity), 10);
  assertEveryLayer(
    sections.filter((s) => s.sliceZ > 2 && s.sliceZ < 8),
    1,
    1,
    300,
  );
  assertEveryLayer(
    sections.filter((s) => s.sliceZ < 2 || s.sliceZ > 8),
    1,
    0,
    400,
  );
  const flipped = slice(inverted(merge(outer, cavity)), 10);
  assertEveryLayer(
    flipped.filter((s) => s.sliceZ > 2 && s.sliceZ < 8),
    1,
    1,
    300,
  );
});

test('a body embedded in another (separate positive shells) unions', () => {
  assertEveryLayer(slice(merge(box(0, 0, 0, 20, 20, 10), box(5, 5, 0, 15, 15, 10)), 10), 1, 0, 400);
});

test('a few flipped triangles do not break a loop', () => {
  const mesh = frame([0, 0, 20, 20], [5, 5, 15, 15], 0, 10);
  const indices = mesh.indices.slice();
  for (const t of [0, 5, 9]) {
    const tmp = indices[3 * t + 1];
    indices[3 * t + 1] = indices[3 * t + 2];
    indices[3 * t + 2] = tmp;
  }
  assertEveryLayer(slice({ positions: mesh.positions, indices }, 10), 1, 1, 300);
});

test('open meshes: missing triangles are bridged or closed, nothing throws', () => {
  const mesh = box(0, 0, 0, 10, 10, 10);
  // Drop one wall triangle: chains open across a 10 mm gap and are closed on themselves.
  const holed = { positions: mesh.positions, indices: mesh.indices.slice(3) };
  assertEveryLayer(slice(holed, 10), 1, 0, 100);
  // A triangle soup (nothing welded): every segment is its own open chain, joined end to end.
  const soup = new Float32Array(mesh.indices.length * 3);
  mesh.indices.forEach((v, i) => soup.set(mesh.positions.subarray(3 * v, 3 * v + 3), 3 * i));
  assertEveryLayer(
    slice({ positions: soup, indices: Uint32Array.from(soup.subarray(0, soup.length / 3), (_, i) => i) }, 10),
    1,
    0,
    100,
  );
});

test('degenerate input does not throw', () => {
  const mesh = box(0, 0, 0, 10, 10, 10);
  const n = mesh.positions.length / 3;
  const positions = new Float32Array([...mesh.positions, NaN, 0, 5, 1, 1, 1]);
  const extra = [0, 0, 1, n, 1, 2, 0, 1, 999, 0, 1, 0xffffffff, n + 1, 2, 3];
  const sections = slice({ positions, indices: Uint32Array.from([...mesh.indices, ...extra]) }, 10);
  assertEveryLayer(sections, 1, 0, 100);
  const odd = sliceMesh(
    mesh,
    [
      { index: 0, z: 5, height: 0.2, sliceZ: NaN },
      { index: 1, z: 5, height: 0.2, sliceZ: 4.9 },
    ],
    10,
  );
  assert.deepEqual(
    odd.map((s) => s.islands.length),
    [0, 1],
  );
  assert.deepEqual(
    sliceMesh({ positions: new Float32Array(0), indices: new Uint32Array(0) }, planLayers(1, 0.2, 0.2), 10).map(
      (s) => s.islands.length,
    ),
    [0, 0, 0, 0, 0],
  );
});

test('vertices exactly on a slice plane: z ≥ plane counts as above', () => {
  // An octahedron with its equator at z = 5 cut exactly there, and a cube cut exactly at its top.
  const r = 4,
    c = 5;
  const v = [
    [r, 0, c],
    [0, r, c],
    [-r, 0, c],
    [0, -r, c],
    [0, 0, c + r],
    [0, 0, c - r],
  ];
  const tris: number[] = [];
  for (let k = 0; k < 4; k++) {
    const a = v[k],
      b = v[(k + 1) % 4];
    tris.push(...a, ...b, ...v[4], ...b, ...a, ...v[5]);
  }
  const octa = { positions: Float32Array.from(v.flat()), indices: new Uint32Array(0) };
  const index = (x: number, y: number, z: number): number => v.findIndex((p) => p[0] === x && p[1] === y && p[2] === z);
  octa.indices = Uint32Array.from({ length: tris.length / 3 }, (_, i) =>
    index(tris[3 * i], tris[3 * i + 1], tris[3 * i + 2]),
  );
  const at = (z: number) => [{ index: 0, z: z + 0.1, height: 0.2, sliceZ: z }];
  const [mid] = sliceMesh(octa, at(5), 0);
  assert.equal(mid.islands.length, 1);
  assert.equal(area(mid.islands) / MM2, 2 * r * r);
  const [top] = sliceMesh(box(0, 0, 0, 10, 10, 10), at(10), 0);
  assert.equal(area(top.islands) / MM2, 100);
  const [bottom] = sliceMesh(box(0, 0, 0, 10, 10, 10), at(0), 0);
  assert.equal(bottom.islands.length, 0);
});

test('layers are returned in the order given, with their own fields', () => {
  const layers = planLayers(10, 0.2, 0.2).reverse();
  const sections = sliceMesh(merge(box(0, 0, 0, 10, 10, 5), box(0, 0, 5, 5, 5, 10)), layers, 10);
  assert.deepEqual(
    sections.map((s) => s.index),
    layers.map((l) => l.index),
  );
  for (const s of sections) assert.equal(area(s.islands) / MM2, s.sliceZ < 5 ? 100 : 25);
});

test('simplification stays within tolerance and drops slivers', () => {
  // A 160-gon cylinder of radius 10, as an unwelded soup (320 open chains per layer): at 10 µm tolerance it keeps its outline within 10 µm.
  const n = 160,
    R = 10,
    tris: number[] = [];
  for (let k = 0; k < n; k++) {
    const a0 = (2 * Math.PI * k) / n,
      a1 = (2 * Math.PI * (k + 1)) / n;
    const p = [R * Math.cos(a0), R * Math.sin(a0)],
      q = [R * Math.cos(a1), R * Math.sin(a1)];
    tris.push(p[0], p[1], 0, q[0], q[1], 0, q[0], q[1], 5, p[0], p[1], 0, q[0], q[1], 5, p[0], p[1], 5);
    tris.push(0, 0, 5, p[0], p[1], 5, q[0], q[1], 5, 0, 0, 0, q[0], q[1], 0, p[0], p[1], 0);
  }
  const soup = Float32Array.from(tris);
  const cyl = sliceMesh(
    { positions: soup, indices: Uint32Array.from({ length: soup.length / 3 }, (_, i) => i) },
    planLayers(5, 0.2, 0.2),
    10,
  );
  const expected = (n / 2) * R * R * Math.sin((2 * Math.PI) / n);
  for (const s of cyl) {
    assert.equal(s.islands.length, 1);
    // Chords cut at most 10 µm inside the outline: the lost area is under perimeter × 10 µm.
    const a = area(s.islands) / MM2;
    assert.ok(a <= expected + 1e-3 && a > expected - 2 * Math.PI * R * 0.01, `area ${a} vs ${expected}`);
    assert.ok(s.islands[0].outer.length < n, 'simplified');
  }
  // A 0.02 mm wide sliver box (area 0.02 × 1 = 0.02 mm² > 0.0025) survives, a 0.02 × 0.02 speck does not.
  const sections = slice(merge(box(0, 0, 0, 10, 10, 1), box(20, 0, 0, 20.02, 1, 1), box(30, 0, 0, 30.02, 0.02, 1)), 1);
  for (const s of sections) assert.equal(s.islands.length, 2);
});
