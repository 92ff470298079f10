import { test } from 'node:test';
import assert from 'node:assert/strict';
import { resolveConfig } from '#strata/settings/resolve.js';
import { applyLayerFans, layerFan } from '#strata/plan/cooling.js';
import type { LayerPlan, PrintPlan } from '#strata/plan/types.js';

test('fan by layer: off for fanOffLayers, then rising evenly to full at fanFullLayer', () => {
  const cfg = resolveConfig({ fanSpeed: 80, firstLayerFanSpeed: 0, fanOffLayers: 3, fanFullLayer: 6 });
  const fans = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => layerFan(cfg, k, 60));
  // layers 3, 4, 5 at 1/4, 2/4, 3/4 of the way; 6 on at 80 %
  assert.deepEqual(fans, [0, 0, 0, 0.2, 0.4, 0.6, 0.8, 0.8]);
  // no ramp: full from the first layer after the off ones
  assert.deepEqual(
    [0, 1, 2].map((k) => layerFan(resolveConfig({ fanSpeed: 80, fanOffLayers: 1 }), k, 60)),
    [0, 0.8, 0.8],
  );
  // none off: the first layer runs the fan too
  assert.equal(layerFan(resolveConfig({ fanSpeed: 80, fanOffLayers: 0 }), 0, 60), 0.8);
});

test('fan by layer time: above fanSpeed below fanBelowLayerTime, up to maxFanSpeed at minLayerTime', () => {
  const cfg = resolveConfig({
    fanSpeed: 40,
    maxFanSpeed: 100,
    fanBelowLayerTime: 60,
    minLayerTime: 10,
    fanOffLayers: 1,
  });
  assert.equal(layerFan(cfg, 5, 120), 0.4, 'a long layer: fanSpeed');
  assert.equal(layerFan(cfg, 5, 60), 0.4);
  assert.equal(layerFan(cfg, 5, 35), 0.7, 'half way from 60 s to 10 s: half way from 40 % to 100 %');
  assert.equal(layerFan(cfg, 5, 10), 1);
  assert.equal(layerFan(cfg, 5, 2), 1);
  assert.equal(layerFan(resolveConfig({ fanSpeed: 40, maxFanSpeed: 100, fanBelowLayerTime: 0 }), 5, 2), 0.4, 'off');
});

test('the fan pass counts layers from each object: where Z goes down (sequential printing) the count starts again', () => {
  const layer = (index: number, z: number): LayerPlan => ({ index, z, height: 0.2, fan: 0, steps: [] });
  const plan: PrintPlan = {
    layers: [layer(0, 0.2), layer(1, 0.4), layer(2, 0.6), layer(3, 0.2), layer(4, 0.4)],
    objects: [],
    bounds: { minX: 0, minY: 0, minZ: 0, maxX: 0, maxY: 0, maxZ: 0 },
  };
  applyLayerFans(plan, resolveConfig({ fanSpeed: 100, firstLayerFanSpeed: 0, fanOffLayers: 1, fanFullLayer: 2 }));
  assert.deepEqual(
    plan.layers.map((l) => l.fan),
    [0, 0.5, 1, 0, 0.5],
  );
});
