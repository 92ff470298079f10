import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { positionBounds } from '#strata/mesh/index.js';
import type { Mesh } from '#strata/mesh/types.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { prepareModel } from '#strata/api/prepare-model.js';
import { Slicer } from '#strata/api/slicer.js';

/** A closed axis-aligned box (outward-facing triangles). */
function box(x0: number, y0: number, z0: number, sx: number, sy: number, sz: number): Mesh {
  const v: number[] = [];
  for (const [x, y, z] of [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [1, 1, 1],
    [0, 1, 1],
  ])
    v.push(x0 + x * sx, y0 + y * sy, z0 + z * sz);
  const f = [
    0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
  ];
  return { positions: new Float32Array(v), indices: new Uint32Array(f) };
}

const prep = (input: unknown, opts: SliceOptions = {}) => prepareModel(input, resolveConfig(opts));

function empty(input: unknown, re: RegExp): void {
  assert.throws(
    () => prep(input),
    (e: unknown) =>
      e instanceof StrataError && e.code === 'EMPTY_MODEL' && re.test(e.message) && !e.message.includes('\n'),
  );
}

test('several models: separate placed objects with unique names, and the merged mesh of them all', () => {
  const cube = { name: 'cube', mesh: box(0, 0, 0, 20, 20, 20) };
  const p = prep([cube, cube, { name: 'cube (2)', mesh: box(0, 0, 0, 5, 5, 5) }]);
  assert.deepEqual(
    p.objects.map((o) => o.name),
    ['cube', 'cube (2)', 'cube (2) (2)'],
  );
  assert.equal(p.mesh.indices.length, 3 * 36);
  const boxes = p.objects.map((o) => positionBounds(o.mesh.positions));
  // no two overlap, all on the bed, all on z = 0
  for (let i = 0; i < boxes.length; i++) {
    assert.equal(boxes[i].min[2], 0);
    for (let j = i + 1; j < boxes.length; j++) {
      const a = boxes[i],
        b = boxes[j];
      const apart =
        a.max[0] + 6 - 1e-3 <= b.min[0] ||
        b.max[0] + 6 - 1e-3 <= a.min[0] ||
        a.max[1] + 6 - 1e-3 <= b.min[1] ||
        b.max[1] + 6 - 1e-3 <= a.min[1];
      assert.ok(apart, `objects ${i} and ${j} are 6 mm apart`);
    }
  }
  assert.match(p.warnings[0], /^3 models arranged around the bed centre, 6 mm apart$/);
  // a brim widens the gap by its width on each side
  const brim = prep([cube, cube], { adhesionType: 'brim', brimWidth: 5 }).objects.map((o) =>
    positionBounds(o.mesh.positions),
  );
  const gap = Math.max(
    brim[1].min[0] - brim[0].max[0],
    brim[0].min[0] - brim[1].max[0],
    brim[1].min[1] - brim[0].max[1],
    brim[0].min[1] - brim[1].max[1],
  );
  assert.ok(Math.abs(gap - 16) < 1e-3, `gap ${gap}`);
});

test('one model of several objects keeps them where they are relative to each other', () => {
  const p = prep({
    name: 'pair',
    objects: [
      { name: 'a', mesh: box(0, 0, 0, 10, 10, 10) },
      { name: 'b', mesh: box(12, 0, 0, 10, 10, 10) },
    ],
  });
  const [a, b] = p.objects.map((o) => positionBounds(o.mesh.positions));
  assert.equal(b.min[0] - a.min[0], 12);
  assert.equal(p.warnings.length, 0);
});

test('scale, per-axis scale and rotation reach the placed objects', () => {
  const size = (opts: SliceOptions) => {
    const { min, max } = positionBounds(prep(box(0, 0, 0, 40, 10, 5), opts).mesh.positions);
    return [max[0] - min[0], max[1] - min[1], max[2] - min[2]].map((v) => Math.round(v * 1000) / 1000);
  };
  assert.deepEqual(size({}), [40, 10, 5]);
  assert.deepEqual(size({ scale: 2 }), [80, 20, 10]);
  assert.deepEqual(size({ scale: 2, scaleZ: 1 }), [80, 20, 5]);
  assert.deepEqual(size({ rotateZ: 90 }), [10, 40, 5]);
  assert.deepEqual(size({ rotateX: 90 }), [40, 5, 10]);
  assert.deepEqual(size({ upAxis: 'y' }), [40, 5, 10]);
});

test('nothing to print is an error naming the cause', () => {
  const flat = {
    positions: new Float32Array([0, 0, 0, 20, 0, 0, 20, 0, 10, 0, 0, 10]),
    indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
  };
  empty(flat, /^nothing to print: the model is flat: its 2 triangles lie in one plane/);
  const line = {
    positions: new Float32Array([0, 0, 0, 5, 0, 0, 10, 0, 0, 0, 0, 3, 0, 0, 6, 0, 0, 9]),
    indices: new Uint32Array([0, 1, 2, 3, 4, 5]),
  };
  empty(line, /^nothing to print: the model has only triangles of zero area/);
  // a closed surface with both sides out: a tetrahedron's faces, each also reversed
  const t = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3];
  const both = {
    positions: new Float32Array([0, 0, 0, 10, 0, 0, 0, 10, 0, 0, 0, 10]),
    indices: new Uint32Array([...t, 0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2]),
  };
  empty(both, /^nothing to print: the model encloses no volume/);
  // with several models, the one at fault is named
  assert.throws(
    () => prep([box(0, 0, 0, 10, 10, 10), { name: 'wall', mesh: flat }]),
    /: nothing to print: wall is flat/,
  );
  assert.doesNotThrow(() => prep(box(0, 0, 0, 10, 10, 10)));
});

test('a closed model thinner than a line slices to an error, not to G-code that prints nothing', async () => {
  await assert.rejects(
    new Slicer({ threads: 1 }).slice(box(0, 0, 0, 20, 0.01, 10)),
    (e: unknown) =>
      e instanceof StrataError &&
      e.code === 'EMPTY_MODEL' &&
      /^nothing to print: .*thinner than the line width/.test(e.message),
  );
});

/** A duck-typed three.js mesh of a box. */
function threeMesh(name: string, b: Mesh, extra: Record<string, unknown> = {}) {
  return {
    isObject3D: true,
    isMesh: true,
    name,
    geometry: {
      isBufferGeometry: true,
      attributes: { position: { array: b.positions, itemSize: 3, count: b.positions.length / 3 } },
      index: { array: b.indices },
    },
    children: [],
    ...extra,
  };
}

test('three.js: invisible meshes are skipped; a Y-up scene is warned about, and upAxis y stands it up', () => {
  const scene = {
    isObject3D: true,
    isScene: true,
    up: { x: 0, y: 1, z: 0 },
    children: [
      threeMesh('tower', box(0, 0, 0, 10, 30, 10)),
      threeMesh('hidden', box(50, 0, 0, 10, 10, 10), { visible: false }),
    ],
  };
  const p = prep(scene);
  assert.deepEqual(
    p.objects.map((o) => o.name),
    ['tower'],
  );
  assert.match(p.warnings.join('\n'), /up axis is \+Y .* pass upAxis: 'y'/);
  const { min, max } = positionBounds(p.mesh.positions);
  assert.equal(Math.round(max[2] - min[2]), 10, 'sliced Z-up: lying on its side');
  const up = prep(scene, { upAxis: 'y' });
  assert.doesNotMatch(up.warnings.join('\n'), /up axis/);
  const b = positionBounds(up.mesh.positions);
  assert.equal(Math.round(b.max[2] - b.min[2]), 30, 'standing');
  // a scene that says it is Z-up gets no warning
  assert.doesNotMatch(prep({ ...scene, up: { x: 0, y: 0, z: 1 } }).warnings.join('\n'), /up axis/);
  // only hidden meshes: an error that says so
  empty(
    { isObject3D: true, children: [threeMesh('h', box(0, 0, 0, 1, 1, 1), { visible: false })] },
    /no visible meshes .*1 hidden object is skipped/,
  );
});
