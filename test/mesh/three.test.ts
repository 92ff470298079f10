import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { prepareMesh } from '#strata/mesh/prepare.js';
import { fromThree } from '#strata/mesh/three.js';
import type { Mesh } from '#strata/mesh/types.js';

// Minimal three.js look-alikes: plain objects with the fields three.js has.

/** A unit cube BufferGeometry (indexed, 8 vertices, 12 outward triangles). */
function cubeGeometry(indexed = true): Record<string, unknown> {
  const v = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1];
  const f = [
    0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5,
  ];
  if (indexed) {
    return {
      isBufferGeometry: true,
      attributes: { position: { array: new Float32Array(v), itemSize: 3, count: 8 } },
      index: { array: new Uint16Array(f), itemSize: 1, count: f.length },
    };
  }
  const soup: number[] = [];
  for (const i of f) soup.push(v[i * 3], v[i * 3 + 1], v[i * 3 + 2]);
  return {
    isBufferGeometry: true,
    attributes: { position: { array: new Float32Array(soup), itemSize: 3, count: f.length } },
    index: null,
  };
}

/** Column-major translation/scale matrix as three.js stores it. */
function matrix(tx: number, ty: number, tz: number, s = 1): { elements: number[] } {
  return { elements: [s, 0, 0, 0, 0, s, 0, 0, 0, 0, s, 0, tx, ty, tz, 1] };
}

function mesh(name: string, m: { elements: number[] }, geometry = cubeGeometry()): Record<string, unknown> {
  return { isObject3D: true, isMesh: true, name, matrix: m, geometry, children: [] };
}

function bbox(mesh: Mesh): { min: number[]; max: number[] } {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < mesh.positions.length; i++) {
    min[i % 3] = Math.min(min[i % 3], mesh.positions[i]);
    max[i % 3] = Math.max(max[i % 3], mesh.positions[i]);
  }
  return { min, max };
}

test('a Group with two translated meshes gives two objects at the right places (matrix chain)', () => {
  const group = {
    isObject3D: true,
    isGroup: true,
    matrix: matrix(0, 0, 10),
    children: [mesh('a', matrix(5, 0, 0)), mesh('b', matrix(-20, 3, 0, 2))],
  };
  const objs = fromThree(group);
  assert.deepEqual(
    objs.map((o) => o.name),
    ['a', 'b'],
  );
  assert.deepEqual(bbox(objs[0].mesh), { min: [5, 0, 10], max: [6, 1, 11] });
  assert.deepEqual(bbox(objs[1].mesh), { min: [-20, 3, 10], max: [-18, 5, 12] });
});

test('with updateMatrixWorld, matrixWorld is used after calling it with force = true', () => {
  const a = { ...mesh('a', matrix(0, 0, 0)), matrixWorld: matrix(0, 0, 0) };
  const b = { ...mesh('b', matrix(0, 0, 0)), matrixWorld: matrix(0, 0, 0) };
  let forced: unknown;
  const scene = {
    isObject3D: true,
    isScene: true,
    children: [a, { isObject3D: true, children: [b] }],
    updateMatrixWorld(force?: boolean) {
      forced = force;
      a.matrixWorld = matrix(100, 0, 0);
      b.matrixWorld = matrix(0, 100, 0);
    },
  };
  const objs = fromThree(scene);
  assert.equal(forced, true);
  assert.equal(objs.length, 2);
  assert.deepEqual(bbox(objs[0].mesh).min, [100, 0, 0]);
  assert.deepEqual(bbox(objs[1].mesh).min, [0, 100, 0]);
});

test('position / quaternion / scale are used when there is no matrix', () => {
  const s = Math.SQRT1_2;
  const m = {
    isObject3D: true,
    isMesh: true,
    position: { x: 1, y: 2, z: 3 },
    quaternion: { x: 0, y: 0, z: s, w: s }, // 90° about Z
    scale: { x: 2, y: 1, z: 1 },
    geometry: cubeGeometry(),
  };
  const [o] = fromThree(m);
  const b = bbox(o.mesh);
  // x in 0..2 after scale, rotated to y 0..2; y 0..1 rotated to x -1..0; then translated.
  b.min.forEach((v, i) => assert.ok(Math.abs(v - [0, 2, 3][i]) < 1e-6, `${b.min}`));
  b.max.forEach((v, i) => assert.ok(Math.abs(v - [1, 4, 4][i]) < 1e-6, `${b.max}`));
  assert.ok(prepareMesh(o.mesh).report.volume > 0);
});

test('every mesh in a deep tree is taken; lines and points are skipped', () => {
  const line = { isObject3D: true, isLine: true, geometry: cubeGeometry(), children: [] };
  const points = { isObject3D: true, isPoints: true, isMesh: false, geometry: cubeGeometry(), children: [] };
  const tree = {
    isObject3D: true,
    children: [
      line,
      { isObject3D: true, children: [mesh('deep', matrix(1, 1, 1), cubeGeometry(false)), points] },
      mesh('top', matrix(0, 0, 0)),
    ],
  };
  const objs = fromThree(tree);
  assert.deepEqual(
    objs.map((o) => o.name),
    ['deep', 'top'],
  );
  assert.equal(objs[0].mesh.positions.length / 3, 8, 'unindexed geometry is welded');
  assert.equal(prepareMesh(objs[0].mesh).report.openEdges, 0);
});

test('a bare BufferGeometry, an interleaved attribute, and a mirrored mesh', () => {
  const [g] = fromThree(cubeGeometry());
  assert.equal(g.mesh.indices.length / 3, 12);

  const base = cubeGeometry() as { attributes: { position: { array: Float32Array } }; index: unknown };
  const src = base.attributes.position.array;
  const inter = new Float32Array(8 * 5);
  for (let i = 0; i < 8; i++) inter.set([9, src[i * 3], src[i * 3 + 1], src[i * 3 + 2], 7], i * 5);
  const geometry = {
    isBufferGeometry: true,
    attributes: {
      position: {
        isInterleavedBufferAttribute: true,
        data: { array: inter, stride: 5 },
        offset: 1,
        itemSize: 3,
        count: 8,
      },
    },
    index: base.index,
  };
  const [i] = fromThree(geometry);
  assert.deepEqual(bbox(i.mesh), { min: [0, 0, 0], max: [1, 1, 1] });

  const mirrored = mesh('m', { elements: [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1] });
  const [m] = fromThree(mirrored);
  assert.deepEqual(bbox(m.mesh).min, [-1, 0, 0]);
  assert.ok(Math.abs(prepareMesh(m.mesh).report.volume - 1) < 1e-9, 'winding flipped with the mirror');
});

test('an InstancedMesh gives one object per instance', () => {
  const inst = new Float32Array(32);
  inst.set(matrix(0, 0, 0).elements, 0);
  inst.set(matrix(10, 0, 0).elements, 16);
  const im = { ...mesh('bolt', matrix(0, 0, 5)), isInstancedMesh: true, instanceMatrix: { array: inst }, count: 2 };
  const objs = fromThree(im);
  assert.deepEqual(
    objs.map((o) => o.name),
    ['bolt #1', 'bolt #2'],
  );
  assert.deepEqual(bbox(objs[1].mesh).min, [10, 0, 5]);
});

test('bad three.js input throws StrataError', () => {
  const check = (v: unknown, code: string): void =>
    assert.throws(
      () => fromThree(v),
      (e: unknown) => e instanceof StrataError && e.code === code,
    );
  check(null, 'UNSUPPORTED_FORMAT');
  check({ foo: 1 }, 'UNSUPPORTED_FORMAT');
  check({ isObject3D: true, children: [] }, 'EMPTY_MODEL');
  check({ isBufferGeometry: true, attributes: {} }, 'BAD_MESH');
  check({ isBufferGeometry: true, attributes: { position: { array: [0, 0, 0, 1, 0, 0], itemSize: 2 } } }, 'BAD_MESH');
  check({ isBufferGeometry: true, attributes: { position: { array: [0, 0, 0, 1, 0, 0], itemSize: 3 } } }, 'BAD_MESH');
  check(
    { isBufferGeometry: true, attributes: { position: { array: [0, 0, 0, 1, 0, 0, 0, 1, 0], itemSize: 3, count: 9 } } },
    'BAD_MESH',
  );
  check(
    {
      isBufferGeometry: true,
      attributes: { position: { array: [0, 0, 0, 1, 0, 0, 0, 1, 0] } },
      index: { array: [0, 1, 3] },
    },
    'BAD_MESH',
  );
  check({ isBufferGeometry: true, attributes: { position: { array: [0, 0, NaN, 1, 0, 0, 0, 1, 0] } } }, 'BAD_MESH');
  const cyclic: Record<string, unknown> = { isObject3D: true, children: [] };
  (cyclic.children as unknown[]).push(cyclic);
  check(cyclic, 'EMPTY_MODEL');
});
