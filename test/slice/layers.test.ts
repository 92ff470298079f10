import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { planLayers } from '#strata/slice/layers.js';
import { sliceMesh } from '#strata/slice/slice-mesh.js';
import { box } from './test-helpers.js';

test('a 20 mm cube at 0.2/0.2 has 100 layers, cut at mid-height', () => {
  const layers = planLayers(20, 0.2, 0.2);
  assert.equal(layers.length, 100);
  assert.deepEqual(layers[0], { index: 0, z: 0.2, height: 0.2, sliceZ: 0.1 });
  assert.deepEqual(layers[99], { index: 99, z: 20, height: 0.2, sliceZ: 19.9 });
  layers.forEach((l, i) => assert.equal(l.index, i));
});

test('a 0.3 mm first layer: first z 0.3, then 0.2 steps', () => {
  const layers = planLayers(20, 0.3, 0.2);
  assert.deepEqual(layers[0], { index: 0, z: 0.3, height: 0.3, sliceZ: 0.15 });
  assert.deepEqual(layers[1], { index: 1, z: 0.5, height: 0.2, sliceZ: 0.4 });
  assert.equal(layers[10].z, 2.3);
  // The last plane (20.0) is at the top: it is kept (it cuts the top outline); 20.2 is not.
  assert.equal(layers.length, 100);
  assert.equal(layers[99].sliceZ, 19.9995);
});

test('heights come from integer µm: no float drift after thousands of layers', () => {
  const layers = planLayers(300, 0.1, 0.1);
  assert.equal(layers.length, 3000);
  for (const l of layers) {
    assert.equal(l.z, Number(((l.index + 1) / 10).toFixed(1)));
    assert.equal(l.sliceZ, Number(((l.index + 0.5) / 10).toFixed(2)));
  }
});

test('a thin top feature reaching a slice plane gets exactly one layer, even with float noise', () => {
  // Planes at 0.1, 0.3, …, 20.1. A top at 20.1 (or a float hair below) keeps the 20.1 layer.
  for (const top of [20.1, 20.1 + 1e-7, 20.1 - 1e-7, Math.fround(20.1)]) {
    const layers = planLayers(top, 0.2, 0.2);
    assert.equal(layers.length, 101, `top ${top}`);
    const sections = sliceMesh(box(0, 0, 0, 10, 10, Math.fround(top)), layers, 10);
    assert.equal(sections[100].islands.length, 1, `top ${top}: the last layer is not empty`);
  }
  // Well below the plane (less than half a layer above 20.0): rounds away, no empty layer.
  assert.equal(planLayers(20.09, 0.2, 0.2).length, 100);
});

test('no height gives no layers; nonsense heights throw StrataError', () => {
  assert.deepEqual(planLayers(0, 0.2, 0.2), []);
  assert.deepEqual(planLayers(0.05, 0.2, 0.2), []);
  assert.equal(planLayers(0.1, 0.2, 0.2).length, 1);
  assert.throws(() => planLayers(10, 0, 0.2), StrataError);
  assert.throws(() => planLayers(10, 0.2, -1), StrataError);
  assert.throws(() => planLayers(10, 0.2, NaN), StrataError);
  assert.throws(() => planLayers(Infinity, 0.2, 0.2), StrataError);
});
