import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  IDENTITY_LINEAR,
  axisRotation,
  isIdentityLinear,
  linearBounds,
  mul3,
  placeObjects,
  rotationBetween,
} from '#strata/mesh/placement.js';
import { placeModels } from '#strata/mesh/place.js';
import { prepareMesh } from '#strata/mesh/prepare.js';
import type { MeshObject } from '#strata/mesh/types.js';

/** A closed box 10 × 20 × 5 mm with its corner at (3, 4, 7). */
function box(): MeshObject {
  const [x0, y0, z0, x1, y1, z1] = [3, 4, 7, 13, 24, 12];
  const positions = Float32Array.of(
    x0,
    y0,
    z0,
    x1,
    y0,
    z0,
    x1,
    y1,
    z0,
    x0,
    y1,
    z0,
    x0,
    y0,
    z1,
    x1,
    y0,
    z1,
    x1,
    y1,
    z1,
    x0,
    y1,
    z1,
  );
  const indices = Uint32Array.of(
    0,
    2,
    1,
    0,
    3,
    2,
    4,
    5,
    6,
    4,
    6,
    7,
    0,
    1,
    5,
    0,
    5,
    4,
    1,
    2,
    6,
    1,
    6,
    5,
    2,
    3,
    7,
    2,
    7,
    6,
    3,
    0,
    4,
    3,
    4,
    7,
  );
  return { name: 'box', mesh: { positions, indices } };
}

test('identity placement at the bed centre gives the same vertices as placeModels centring', () => {
  const o = box();
  const [placed] = placeObjects([o], { linear: IDENTITY_LINEAR, center: [110, 110] });
  const ref = placeModels([{ name: 'box', objects: [o] }], {
    center: true,
    bedWidth: 220,
    bedLength: 220,
    bedHeight: 250,
    originAtCenter: false,
  }).objects[0].mesh;
  assert.deepEqual(Array.from(placed.mesh.positions), Array.from(ref.positions));
  assert.ok(isIdentityLinear(IDENTITY_LINEAR) && !isIdentityLinear([0, -1, 0, 1, 0, 0, 0, 0, 1]));
});

test('a rotation and scale: bounds centred where asked, bottom on the bed, volume scaled, still outward', () => {
  const o = box();
  const s = 2,
    c = 0,
    q = 1; // 90° about Z, doubled
  const linear = [s * c, -s * q, 0, s * q, s * c, 0, 0, 0, s];
  const [placed] = placeObjects([o], { linear, center: [50, 60] });
  const b = linearBounds([placed]);
  assert.deepEqual(
    b.min.map((v) => Math.round(v * 1e4) / 1e4),
    [30, 50, 0],
  );
  assert.deepEqual(
    b.max.map((v) => Math.round(v * 1e4) / 1e4),
    [70, 70, 10],
  );
  const before = prepareMesh(o.mesh).report.volume,
    after = prepareMesh(placed.mesh).report.volume;
  assert.ok(Math.abs(after - 8 * before) < 1e-3, `volume ${before} → ${after}`);
  // a mirror keeps the triangles facing outwards (positive volume)
  const [mirrored] = placeObjects([o], { linear: [-1, 0, 0, 0, 1, 0, 0, 0, 1], center: [50, 60] });
  assert.ok(prepareMesh(mirrored.mesh).report.volume > 0);
});

function apply(m: readonly number[], v: readonly number[]): number[] {
  return [0, 1, 2].map((r) => m[r * 3] * v[0] + m[r * 3 + 1] * v[1] + m[r * 3 + 2] * v[2]);
}

test('quarter turns are exact; rotationBetween takes a face normal down onto the bed', () => {
  assert.deepEqual(apply(axisRotation('x', 90), [0, 1, 0]), [0, 0, 1]);
  assert.deepEqual(apply(axisRotation('y', -90), [0, 0, 1]), [-1, 0, 0]);
  assert.deepEqual(apply(axisRotation('z', 270), [1, 0, 0]), [0, -1, 0]);
  assert.deepEqual(
    mul3(axisRotation('z', 90), axisRotation('z', -90)).map((v) => v + 0),
    [...IDENTITY_LINEAR],
  );
  const down = [0, 0, -1];
  for (const n of [
    [1, 0, 0],
    [0.6, 0, 0.8],
    [0, 0, -1],
    [0, 0, 1],
    [-0.36, 0.48, 0.8],
  ]) {
    const r = rotationBetween(n, down);
    const got = apply(r, n);
    assert.ok(
      got.every((v, k) => Math.abs(v - down[k]) < 1e-12),
      `${n} → ${got}`,
    );
    // a rotation: orthonormal, determinant 1
    const rt = [r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]];
    assert.ok(
      mul3(r, rt).every((v, k) => Math.abs(v - IDENTITY_LINEAR[k]) < 1e-12),
      `orthonormal for ${n}`,
    );
  }
});

test('laying a box on its side face: the placed box is as tall as that side was wide', () => {
  const o = box();
  // the +X face (normal (1, 0, 0)) goes down: the 10 mm X extent becomes the height
  const [placed] = placeObjects([o], { linear: rotationBetween([1, 0, 0], [0, 0, -1]), center: [110, 110] });
  const b = linearBounds([placed]);
  assert.ok(Math.abs(b.max[2] - b.min[2] - 10) < 1e-4 && Math.abs(b.min[2]) < 1e-6, `height ${b.max[2] - b.min[2]}`);
});
