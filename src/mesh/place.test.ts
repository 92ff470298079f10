import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '../errors.js';
import { mergeObjects, placeOnBed, type PlaceOptions } from './place.js';
import type { Mesh, MeshObject } from './types.js';

/** An axis-aligned box from (x0,y0,z0) to (x1,y1,z1) as 8 vertices / 12 triangles. */
function box(x0: number, y0: number, z0: number, x1: number, y1: number, z1: number): Mesh {
  const p: number[] = [];
  for (let i = 0; i < 8; i++) p.push(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  const f = [0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5];
  return { positions: new Float32Array(p), indices: new Uint32Array(f) };
}

function bounds(m: Mesh): number[][] {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < m.positions.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], m.positions[i]);
    hi[i % 3] = Math.max(hi[i % 3], m.positions[i]);
  }
  return [lo, hi];
}

const BED: PlaceOptions = { center: true, bedWidth: 220, bedLength: 220, bedHeight: 250, originAtCenter: false };

test('mergeObjects concatenates meshes and offsets indices', () => {
  const objs: MeshObject[] = [
    { name: 'a', mesh: box(0, 0, 0, 1, 1, 1) },
    { name: 'b', mesh: box(10, 0, 0, 12, 1, 1) },
  ];
  const m = mergeObjects(objs);
  assert.equal(m.positions.length, 48);
  assert.equal(m.indices.length, 72);
  assert.equal(m.indices[36], 8);
  assert.deepEqual(bounds(m), [[0, 0, 0], [12, 1, 1]]);
  assert.equal(mergeObjects([]).indices.length, 0);
});

test('placeOnBed centres on the bed and drops to z = 0', () => {
  const { mesh, offset } = placeOnBed(box(-10, -5, 3, 10, 5, 13), BED);
  assert.deepEqual(bounds(mesh), [[100, 105, 0], [120, 115, 10]]);
  assert.deepEqual(offset, [110, 110, -3]);
});

test('placeOnBed with originAtCenter centres on (0, 0)', () => {
  const { mesh } = placeOnBed(box(50, 60, -2, 70, 80, 8), { ...BED, originAtCenter: true });
  assert.deepEqual(bounds(mesh), [[-10, -10, 0], [10, 10, 10]]);
});

test('placeOnBed without center keeps XY and still drops to z = 0', () => {
  const { mesh, offset } = placeOnBed(box(30, 40, 5, 50, 60, 25), { ...BED, center: false });
  assert.deepEqual(bounds(mesh), [[30, 40, 0], [50, 60, 20]]);
  assert.deepEqual(offset, [0, 0, -5]);
});

function doesNotFit(fn: () => unknown, re: RegExp): void {
  assert.throws(fn, (e: unknown) => {
    assert.ok(e instanceof StrataError);
    assert.equal(e.code, 'DOES_NOT_FIT');
    assert.match(e.message, re);
    return true;
  });
}

test('too wide, too deep or too tall: DOES_NOT_FIT naming the size, the volume and the axis', () => {
  doesNotFit(
    () => placeOnBed(box(0, 0, 0, 250, 30, 48), BED),
    /^the model is 250\.0 × 30\.0 × 48\.0 mm and does not fit the 220 × 220 × 250 mm build volume \(250\.0 mm wide in X/,
  );
  doesNotFit(() => placeOnBed(box(0, 0, 0, 10, 221, 10), BED), /221\.0 mm deep in Y/);
  doesNotFit(() => placeOnBed(box(0, 0, 0, 10, 10, 300), BED), /300\.0 mm tall in Z, the volume 250 mm/);
});

test('without centring, a model off the plate does not fit (axis and span named)', () => {
  doesNotFit(() => placeOnBed(box(-30, 10, 0, 10, 20, 5), { ...BED, center: false }), /X spans -30\.0 to 10\.0 mm, outside the bed's 0 to 220 mm/);
  doesNotFit(() => placeOnBed(box(10, 200, 0, 20, 240, 5), { ...BED, center: false }), /Y spans 200\.0 to 240\.0 mm/);
  // With an origin at the centre, (-30..10) is on a 220 mm plate.
  assert.doesNotThrow(() => placeOnBed(box(-30, 10, 0, 10, 20, 5), { ...BED, center: false, originAtCenter: true }));
});

test('a model exactly the bed size fits', () => {
  assert.doesNotThrow(() => placeOnBed(box(0, 0, 0, 220, 220, 250), BED));
});

test('empty model and nonsense bed sizes are refused', () => {
  assert.throws(
    () => placeOnBed({ positions: new Float32Array(0), indices: new Uint32Array(0) }, BED),
    (e: unknown) => e instanceof StrataError && e.code === 'EMPTY_MODEL',
  );
  assert.throws(() => placeOnBed(box(0, 0, 0, 1, 1, 1), { ...BED, bedWidth: -1 }), (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING');
  assert.throws(() => placeOnBed(box(0, 0, 0, 1, 1, 1), { ...BED, bedHeight: NaN }), (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING');
});
