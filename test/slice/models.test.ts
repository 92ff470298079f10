/** Slicing the shared real models (skipped when ../shared/models is not there, failing under CI). */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area } from '#strata/geometry/clip.js';
import type { Mesh } from '#strata/mesh/types.js';
import { planLayers } from '#strata/slice/layers.js';
import { sliceMesh } from '#strata/slice/slice-mesh.js';
import { loadModel, meshTop } from './test-helpers.js';
import type { LayerSection } from '#strata/slice/types.js';

const MM2 = 1e6;

function meshVolume(mesh: Mesh): number {
  const p = mesh.positions,
    ix = mesh.indices;
  let v = 0;
  for (let t = 0; t < ix.length; t += 3) {
    const a = 3 * ix[t],
      b = 3 * ix[t + 1],
      c = 3 * ix[t + 2];
    v +=
      p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) +
      p[a + 1] * (p[b + 2] * p[c] - p[b] * p[c + 2]) +
      p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return v / 6;
}

function slicedVolume(sections: LayerSection[]): number {
  return sections.reduce((v, s) => v + (area(s.islands) / MM2) * s.height, 0);
}

function sliceModel(name: string): { mesh: Mesh; sections: LayerSection[] } | null {
  const mesh = loadModel(name);
  if (!mesh) return null;
  return { mesh, sections: sliceMesh(mesh, planLayers(meshTop(mesh), 0.2, 0.2), 10) };
}

function assertEveryLayerSolid(sections: LayerSection[]): void {
  for (const s of sections) {
    assert.ok(s.islands.length >= 1, `layer ${s.index} has an island`);
    assert.ok(area(s.islands) > 0, `layer ${s.index} has positive area`);
  }
}

test('CalibrationCube: every layer non-empty, ~400 mm² minus the engraving, volume matches', (t) => {
  const r = sliceModel('CalibrationCube.stl');
  if (!r) return t.skip('model not found');
  assert.equal(r.sections.length, 100);
  for (const s of r.sections) {
    const a = area(s.islands) / MM2;
    assert.ok(a > 340 && a <= 400.001, `layer ${s.index}: ${a} mm²`);
  }
  assert.ok(Math.abs(area(r.sections[0].islands) / MM2 - 400) < 0.01);
  assert.ok(Math.abs(slicedVolume(r.sections) / meshVolume(r.mesh) - 1) < 0.002);
});

test('HollowCalibrationCube (ASCII STL): holes show, volume matches', (t) => {
  const r = sliceModel('HollowCalibrationCube.stl');
  if (!r) return t.skip('model not found');
  assert.equal(r.mesh.indices.length / 3, 160);
  assertEveryLayerSolid(r.sections);
  const withHoles = r.sections.filter((s) => s.islands.some((i) => i.holes.length > 0));
  assert.ok(withHoles.length > 20, `${withHoles.length} layers with holes`);
  // Just above the floor the walls ring an 18 × 18 mm hollow.
  const s = r.sections[25];
  assert.equal(s.islands.length, 1);
  assert.equal(s.islands[0].holes.length, 1);
  assert.ok(Math.abs(area(s.islands) / MM2 - (400 - 324)) < 0.01);
  assert.ok(Math.abs(slicedVolume(r.sections) / meshVolume(r.mesh) - 1) < 0.002);
});

test('stanford-bunny (open scan) slices without throwing, every layer solid', (t) => {
  const r = sliceModel('stanford-bunny.stl');
  if (!r) return t.skip('model not found');
  assertEveryLayerSolid(r.sections);
  assert.ok(Math.abs(slicedVolume(r.sections) / meshVolume(r.mesh) - 1) < 0.01);
});

test('BridgeTest (non-manifold) slices without throwing, every layer solid', (t) => {
  const r = sliceModel('BridgeTest.stl');
  if (!r) return t.skip('model not found');
  assertEveryLayerSolid(r.sections);
  assert.ok(Math.abs(slicedVolume(r.sections) / meshVolume(r.mesh) - 1) < 0.005);
});

test('3DBenchy: sensible island counts, volume matches, fast', (t) => {
  const mesh = loadModel('3DBenchy.stl.gz');
  if (!mesh) return t.skip('model not found');
  const layers = planLayers(meshTop(mesh), 0.2, 0.2);
  assert.equal(layers.length, 240);
  let best = Infinity;
  let sections: LayerSection[] = [];
  for (let run = 0; run < 3; run++) {
    const t0 = performance.now();
    sections = sliceMesh(mesh, layers, 10);
    best = Math.min(best, performance.now() - t0);
  }
  t.diagnostic(`3DBenchy: ${mesh.indices.length / 3} triangles, 240 layers, best of 3: ${best.toFixed(0)} ms`);
  assertEveryLayerSolid(sections);
  // Hull (z 12): hull + chimney/cabin pieces; cabin (z 24): roof pillars and walls; top (z 46): the chimney.
  for (const [k, lo, hi] of [
    [60, 1, 4],
    [120, 3, 8],
    [230, 1, 1],
  ]) {
    const n = sections[k].islands.length;
    assert.ok(n >= lo && n <= hi, `layer ${k} (z ${sections[k].sliceZ}): ${n} islands`);
  }
  assert.ok(Math.abs(slicedVolume(sections) / meshVolume(mesh) - 1) < 0.01);
  assert.ok(best < 2000, `slicing took ${best} ms`);
});

test('other shared models: every layer solid and sliced volume matches the mesh', (t) => {
  for (const name of ['HoleTest.stl', 'Overhang.stl', 'SupportTest.stl', 'spot.stl']) {
    const r = sliceModel(name);
    if (!r) {
      t.diagnostic(`${name} not found`);
      continue;
    }
    assertEveryLayerSolid(r.sections);
    const ratio = slicedVolume(r.sections) / meshVolume(r.mesh);
    assert.ok(Math.abs(ratio - 1) < 0.002, `${name}: volume ratio ${ratio}`);
  }
  const holes = sliceModel('HoleTest.stl');
  if (holes) for (const s of holes.sections) assert.equal(s.islands[0].holes.length, 16);
});
