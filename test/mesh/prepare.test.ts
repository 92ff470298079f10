import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gunzipSync } from 'node:zlib';
import { StrataError } from '#strata/errors.js';
import { prepareMesh } from '#strata/mesh/prepare.js';
import { parseStl } from '#strata/mesh/stl.js';
import type { Mesh } from '#strata/mesh/types.js';
import { weld } from '#strata/mesh/weld.js';
import { MODELS_DIR } from '../e2e/models-dir.js';

const MODELS = MODELS_DIR;
const load = (f: string): Mesh => parseStl(new Uint8Array(readFileSync(join(MODELS, f))), f)[0].mesh;

test('stanford-bunny.stl: 223 open edges, warned about', () => {
  const { report } = prepareMesh(load('stanford-bunny.stl'));
  assert.equal(report.triangles, 69451);
  assert.equal(report.openEdges, 223);
  assert.equal(report.nonManifoldEdges, 0);
  assert.ok(report.warnings.some((w) => w.startsWith('223 open edges: the mesh has holes')));
});

test('BridgeTest.stl: 28 non-manifold edges', () => {
  const { report } = prepareMesh(load('BridgeTest.stl'));
  assert.equal(report.nonManifoldEdges, 28);
  assert.equal(report.openEdges, 0);
  assert.ok(report.warnings.some((w) => w.startsWith('28 non-manifold edges')));
});

test('3DBenchy: 8 degenerate triangles removed, then closed (0 open, 0 non-manifold)', () => {
  const mesh = parseStl(new Uint8Array(gunzipSync(readFileSync(join(MODELS, '3DBenchy.stl.gz')))))[0].mesh;
  const { mesh: clean, report } = prepareMesh(mesh);
  assert.equal(report.degenerateRemoved, 8);
  assert.equal(report.triangles, 225154 - 8);
  assert.equal(clean.indices.length / 3, report.triangles);
  assert.equal(report.vertices, 112565);
  assert.equal(report.openEdges, 0);
  assert.equal(report.nonManifoldEdges, 0);
  assert.ok(report.volume > 14000 && report.volume < 17000, `volume ${report.volume}`);
  assert.deepEqual(
    [report.max[0] - report.min[0], report.max[1] - report.min[1], report.max[2]].map((v) => Math.round(v)),
    [60, 31, 48],
  );
  assert.deepEqual(report.warnings, ['removed 8 degenerate triangles (two corners at the same point)']);
});

test('CalibrationCube.stl: closed, volume a bit under 8000 mm³ (engraved letters), bounds ±10 / 0..20', () => {
  const { report } = prepareMesh(load('CalibrationCube.stl'));
  assert.equal(report.openEdges, 0);
  assert.equal(report.nonManifoldEdges, 0);
  assert.ok(report.volume > 7700 && report.volume < 8000, `volume ${report.volume}`);
  assert.deepEqual(report.min, [-10, -10, 0]);
  assert.deepEqual(report.max, [10, 10, 20]);
  assert.deepEqual(report.warnings, []);
});

test('every closed shared model reports a positive volume and no edge problems', () => {
  for (const f of ['HollowCalibrationCube.stl', 'HoleTest.stl', 'Overhang.stl', 'SupportTest.stl', 'spot.stl']) {
    const { report } = prepareMesh(load(f));
    assert.equal(report.openEdges + report.nonManifoldEdges, 0, f);
    assert.ok(report.volume > 0, f);
  }
  const hollow = prepareMesh(load('HollowCalibrationCube.stl')).report;
  assert.ok(hollow.volume > 1000 && hollow.volume < 8000 - 1000, `hollow cube volume ${hollow.volume}`);
});

const TET_P = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]);
const TET_I = new Uint32Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);

test('a tetrahedron: volume 1/6, closed, welded', () => {
  const { report } = prepareMesh({ positions: TET_P, indices: TET_I });
  assert.ok(Math.abs(report.volume - 1 / 6) < 1e-12);
  assert.equal(report.vertices, 4);
  assert.equal(report.openEdges, 0);
});

test('welding merges equal float32 positions, including -0 and +0, and drops unused vertices', () => {
  const p = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, -0, 0, -0, 5, 5, 5]);
  const m = weld(p, new Uint32Array([0, 1, 2, 3, 2, 1]));
  assert.equal(m.positions.length / 3, 3);
  assert.deepEqual(Array.from(m.indices), [0, 1, 2, 0, 2, 1]);
  assert.throws(() => weld(p, new Uint32Array([0, 1, 9])), StrataError);
  assert.throws(() => weld(new Float32Array([0, 0, NaN, 1, 0, 0, 0, 1, 0]), null), StrataError);
});

test('degenerate triangles (a repeated corner) are removed; collinear slivers are kept', () => {
  const positions = new Float32Array([...TET_P, 0.5, 0, 0]);
  const indices = new Uint32Array([...TET_I, 0, 0, 1, 2, 2, 2, 0, 4, 1]);
  const { mesh, report } = prepareMesh({ positions, indices });
  assert.equal(report.degenerateRemoved, 2);
  assert.equal(report.triangles, 5); // the collinear 0-4-1 sliver stays
  assert.equal(mesh.indices.length, 15);
  assert.equal(report.vertices, 5);
});

test('open edges, non-manifold edges, flipped triangles and inside-out meshes are reported', () => {
  const open = prepareMesh({ positions: TET_P, indices: TET_I.subarray(0, 9) }).report;
  assert.equal(open.openEdges, 3);
  const fin = new Float32Array([...TET_P, 1, 1, 1]);
  const nm = prepareMesh({ positions: fin, indices: new Uint32Array([...TET_I, 1, 2, 4]) }).report;
  assert.equal(nm.nonManifoldEdges, 1);
  assert.equal(nm.openEdges, 2);
  const flippedIdx = TET_I.slice();
  [flippedIdx[1], flippedIdx[2]] = [flippedIdx[2], flippedIdx[1]];
  const fl = prepareMesh({ positions: TET_P, indices: flippedIdx }).report;
  assert.ok(
    fl.warnings.some((w) => /3 edges join triangles that face opposite ways/.test(w)),
    fl.warnings.join('|'),
  );
  const inverted = TET_I.slice();
  for (let i = 0; i < inverted.length; i += 3) [inverted[i + 1], inverted[i + 2]] = [inverted[i + 2], inverted[i + 1]];
  const inv = prepareMesh({ positions: TET_P, indices: inverted }).report;
  assert.ok(inv.volume < 0);
  assert.ok(inv.warnings.some((w) => w.includes('inside out')));
});

test('a vertex shared by many triangles (large edge bucket) is counted correctly', () => {
  // A closed cone: apex 0, base centre 1, n rim vertices.
  const n = 200;
  const p: number[] = [0, 0, 1, 0, 0, 0];
  for (let i = 0; i < n; i++) p.push(Math.cos((2 * Math.PI * i) / n), Math.sin((2 * Math.PI * i) / n), 0);
  const idx: number[] = [];
  for (let i = 0; i < n; i++) {
    const a = 2 + i,
      b = 2 + ((i + 1) % n);
    idx.push(0, a, b, 1, b, a);
  }
  const { report } = prepareMesh({ positions: new Float32Array(p), indices: new Uint32Array(idx) });
  assert.equal(report.openEdges, 0);
  assert.equal(report.nonManifoldEdges, 0);
  assert.ok(report.volume > 0);
  assert.deepEqual(report.warnings, []);
});

test('an empty mesh gives an empty report with a warning', () => {
  const { report } = prepareMesh({ positions: new Float32Array(0), indices: new Uint32Array(0) });
  assert.equal(report.triangles, 0);
  assert.deepEqual(report.warnings, ['the mesh has no triangles']);
});
