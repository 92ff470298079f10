import { test } from 'node:test';
import assert from 'node:assert/strict';
import { resolveConfig } from '#strata/settings/resolve.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { sphere } from '../e2e/curved-shapes.js';
import type { Mesh } from '#strata/mesh/types.js';
import { planLayers, planVaryingLayers } from '#strata/slice/layers.js';
import { box, merge } from './test-helpers.js';
import type { LayerZ } from '#strata/slice/types.js';
import { planPlateLayers, type HeightRange } from '#strata/slice/z-plan.js';

const um = (mm: number) => Math.round(mm * 1000);

function plan(mesh: Mesh, options: SliceOptions, ranges: HeightRange[] = []): LayerZ[] {
  let top = 0;
  for (let i = 2; i < mesh.positions.length; i += 3) top = Math.max(top, mesh.positions[i]);
  return planPlateLayers(top, resolveConfig(options), [mesh], ranges);
}

/** Z strictly rising, each layer's z the sum of the heights up to it in whole µm, cut inside itself. */
function assertExact(layers: readonly LayerZ[]): void {
  let sum = 0;
  layers.forEach((l, i) => {
    assert.equal(l.index, i);
    assert.ok(
      Number.isInteger(um(l.height)) && Math.abs(l.height * 1000 - um(l.height)) < 1e-6,
      `layer ${i} height ${l.height} on the µm grid`,
    );
    sum += um(l.height);
    assert.equal(um(l.z), sum, `layer ${i}: z ${l.z} is the sum of the heights`);
    assert.ok(Math.abs(l.z * 1000 - sum) < 1e-6);
    if (i > 0) assert.ok(l.z > layers[i - 1].z);
    assert.ok(l.sliceZ > l.z - l.height && l.sliceZ < l.z, `layer ${i} is cut inside itself`);
  });
}

test('a sphere gets thin layers near its poles, thick ones at its equator, within the limits and changing gradually', () => {
  const r = 10;
  const opts = {
    adaptiveLayerHeight: true,
    minLayerHeight: 0.07,
    maxLayerHeight: 0.3,
    layerHeight: 0.2,
    adaptiveLayerStep: 0.05,
  };
  const layers = plan(sphere(r, 96, 64), opts);
  assertExact(layers);
  const rest = layers.slice(1);
  for (const l of rest)
    assert.ok(l.height >= 0.07 - 1e-9 && l.height <= 0.3 + 1e-9, `layer at ${l.z}: ${l.height} within [0.07, 0.3]`);
  for (let i = 2; i < layers.length; i++)
    assert.ok(
      Math.abs(layers[i].height - layers[i - 1].height) <= 0.05 + 1e-9,
      `layers ${i - 1}, ${i}: ${layers[i - 1].height} → ${layers[i].height}`,
    );
  const near = (z: number) => rest.reduce((a, b) => (Math.abs(b.sliceZ - z) < Math.abs(a.sliceZ - z) ? b : a));
  const equator = near(r).height,
    bottom = near(0.6).height,
    top = near(2 * r - 0.3).height;
  assert.equal(equator, 0.3, 'vertical at the equator: the thickest');
  assert.ok(bottom < 0.15 && top < 0.15, `thin near the poles (bottom ${bottom}, top ${top})`);
  const heights = new Set(rest.map((l) => l.height));
  assert.ok(heights.size > 10, `heights vary (${heights.size} of them)`);
  // finer quality, more layers; none, every layer as thick as allowed
  const fine = plan(sphere(r, 96, 64), { ...opts, adaptiveLayerQuality: 0.9 });
  const coarse = plan(sphere(r, 96, 64), { ...opts, adaptiveLayerQuality: 0 });
  assert.ok(
    fine.length > layers.length && layers.length > coarse.length,
    `${fine.length} > ${layers.length} > ${coarse.length}`,
  );
  assert.ok(
    coarse.slice(2).every((l) => l.height === 0.3),
    'at 0: 0.3 mm after a step up from the first layer',
  );
  // the same every time
  assert.deepEqual(plan(sphere(r, 96, 64), opts), layers);
});

test('layers change gradually where the surface does not: a sphere resting on a tall box', () => {
  const ball = sphere(8, 64, 32);
  for (let i = 2; i < ball.positions.length; i += 3) ball.positions[i] += 10;
  const mesh = merge(box(-5, -5, 0, 5, 5, 10.5), ball);
  const layers = plan(mesh, {
    adaptiveLayerHeight: true,
    minLayerHeight: 0.07,
    maxLayerHeight: 0.3,
    layerHeight: 0.2,
    adaptiveLayerStep: 0.04,
  });
  assertExact(layers);
  for (let i = 2; i < layers.length; i++)
    assert.ok(
      Math.abs(layers[i].height - layers[i - 1].height) <= 0.04 + 1e-9,
      `layers ${i - 1}, ${i} at ${layers[i].z}: ${layers[i - 1].height} → ${layers[i].height}`,
    );
  // the box's walls thick, the ball's underside where it leaves the box thin
  assert.equal(layers.find((l) => l.z > 5)!.height, 0.3);
  assert.ok(layers.find((l) => l.z > 10.6)!.height < 0.15);
});

test('a box with vertical walls prints its layers as thick as allowed, the last one ending on its top', () => {
  const layers = plan(box(0, 0, 0, 20, 20, 20.23), {
    adaptiveLayerHeight: true,
    maxLayerHeight: 0.3,
    layerHeight: 0.2,
    adaptiveLayerStep: 0.05,
  });
  assertExact(layers);
  // a step up from the first layer, 0.3 mm to 19.95, and a layer of 0.28 ending on the flat top
  const heights = layers.map((l) => l.height);
  assert.deepEqual(heights, [0.2, 0.25, ...new Array(65).fill(0.3), 0.28]);
  assert.equal(layers.at(-1)!.z, 20.23);
});

test('with nothing uneven the plan is planLayers, and constant heights give planLayers exactly', () => {
  for (const [top, first, h] of [
    [20, 0.2, 0.2],
    [20, 0.3, 0.2],
    [7.33, 0.25, 0.12],
    [0.19, 0.2, 0.2],
    [0.1, 0.2, 0.2],
  ] as const) {
    const even = planLayers(top, first, h);
    assert.deepEqual(
      planVaryingLayers(top, first, () => um(h)),
      even,
      `${top}/${first}/${h}`,
    );
    assert.deepEqual(planPlateLayers(top, resolveConfig({ firstLayerHeight: first, layerHeight: h }), []), even);
  }
});

test("a range's layer height sets the plate's layers in it, starting and ending on its bounds", () => {
  const layers = plan(box(0, 0, 0, 10, 10, 10), { layerHeight: 0.2 }, [{ fromZ: 3.05, toZ: 5.05, layerHeight: 0.1 }]);
  assertExact(layers);
  const zs = layers.map((l) => um(l.z));
  // 0.2 mm layers to 3.0, one of 0.05 to the range's start, 20 of 0.1 through it, then 0.2 mm again
  const start = zs.indexOf(3050);
  assert.equal(layers[start].height, 0.05);
  assert.equal(layers[start - 1].z, 3);
  assert.ok(layers.slice(1, start).every((l) => l.height === 0.2));
  assert.ok(layers.slice(start + 1, start + 21).every((l) => l.height === 0.1));
  assert.equal(layers[start + 20].z, 5.05);
  assert.ok(layers.slice(start + 21).every((l) => l.height === 0.2));
  // the last layer's plane (9.95) is below the top: it is planned, as planLayers would
  assert.deepEqual(layers.at(-1), { index: layers.length - 1, z: 10.05, height: 0.2, sliceZ: 9.95 });
});
