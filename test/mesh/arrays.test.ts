import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { fromArrays } from '#strata/mesh/arrays.js';
import { weld } from '#strata/mesh/weld.js';
import type { RawMeshArrays } from '#strata/mesh/types.js';

const TET_P = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1];
const TET_I = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3];

test('fromArrays accepts number[], Float64Array and typed indices', () => {
  const a = fromArrays({ positions: TET_P, indices: TET_I }, 'tet');
  assert.equal(a.name, 'tet');
  assert.ok(a.mesh.positions instanceof Float32Array && a.mesh.indices instanceof Uint32Array);
  assert.equal(a.mesh.indices.length, 12);
  const b = fromArrays({ positions: new Float64Array(TET_P), indices: new Uint16Array(TET_I) });
  assert.deepEqual(Array.from(b.mesh.indices), Array.from(a.mesh.indices));
  assert.equal(b.name, 'mesh');
});

test('fromArrays: unindexed positions are welded into an indexed mesh', () => {
  const soup: number[] = [];
  for (const i of TET_I) soup.push(TET_P[i * 3], TET_P[i * 3 + 1], TET_P[i * 3 + 2]);
  const m = fromArrays({ positions: soup }).mesh;
  assert.equal(m.positions.length, 12);
  assert.equal(m.indices.length, 12);
});

test('fromArrays rejects bad arrays with BAD_MESH and a precise message', () => {
  const bad = (raw: unknown, re: RegExp): void =>
    assert.throws(
      () => fromArrays(raw as RawMeshArrays),
      (e: unknown) => e instanceof StrataError && e.code === 'BAD_MESH' && re.test(e.message),
    );
  bad({ positions: [0, 0, 0, 1] }, /4 numbers, not a multiple of 3/);
  bad({ positions: [0, 0, 0, 1, 0, 0] }, /whole triangles/);
  bad({ positions: [0, 0, NaN, 1, 0, 0, 0, 1, 0] }, /positions\[2\] is NaN/);
  bad({ positions: [0, 0, Infinity, 1, 0, 0, 0, 1, 0] }, /positions\[2\]/);
  bad({ positions: [0, 0, 1e300, 1, 0, 0, 0, 1, 0] }, /too large for float32/);
  bad({ positions: ['0', 0, 0, 1, 0, 0, 0, 1, 0] }, /positions\[0\]/);
  bad({ positions: TET_P, indices: [0, 1] }, /not a multiple of 3/);
  bad({ positions: TET_P, indices: [0, 1, 4] }, /indices\[2\] = 4 is out of range; the mesh has 4 vertices/);
  bad({ positions: TET_P, indices: [0, 1.5, 2] }, /indices\[1\] is 1.5/);
  bad({ positions: TET_P, indices: [0, -1, 2] }, /indices\[1\] is -1/);
  bad({ positions: 'abc' }, /positions must be/);
  bad({ positions: TET_P, indices: {} }, /indices must be/);
  bad(null, /expected/);
});

test('a mesh a loader welded passes through as it is (welding it again would change nothing), its coordinates still checked', () => {
  // two triangles sharing an edge, as a triangle soup: welded to four vertices
  const soup = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]);
  const welded = fromArrays({ positions: soup }).mesh;
  assert.equal(welded.positions.length, 12);
  const again = fromArrays(welded);
  assert.equal(again.mesh, welded, 'taken as it is');
  const rewelded = weld(welded.positions, welded.indices);
  assert.deepEqual(
    [...rewelded.positions, ...rewelded.indices],
    [...welded.positions, ...welded.indices],
    'welding again changes nothing',
  );
  welded.positions[4] = NaN;
  assert.throws(
    () => fromArrays(welded),
    (e: Error) => e instanceof StrataError && /positions\[4\] is NaN/.test(e.message),
  );
});
