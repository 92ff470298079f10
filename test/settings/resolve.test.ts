import { test } from 'node:test';
import assert from 'node:assert/strict';
import { resolveConfig, parseSettingText } from '#strata/settings/resolve.js';
import { StrataError } from '#strata/errors.js';

test('defaults resolve to Ender-3, PLA, 0.2 mm layers, 20 % grid, 2 walls, 4 skin layers', () => {
  const c = resolveConfig();
  assert.equal(c.printerId, 'creality-ender-3');
  assert.equal(c.filamentId, 'pla');
  assert.equal(c.layerHeight, 0.2);
  assert.equal(c.infillDensity, 20);
  assert.equal(c.infillPattern, 'grid');
  assert.equal(c.wallCount, 2);
  assert.equal(c.topLayers, 4);
  assert.equal(c.bottomLayers, 4);
  assert.equal(c.lineWidthMm, c.nozzleDiameter);
  assert.ok(Object.isFrozen(c));
});

test('unknown settings, presets and out-of-range values are errors naming what is allowed', () => {
  assert.throws(
    () => resolveConfig({ layerHieght: 0.2 } as never),
    (e: unknown) => e instanceof StrataError && /layerHeight/.test(e.message),
  );
  assert.throws(
    () => resolveConfig({ infillPattern: 'zigzag' } as never),
    (e: unknown) => e instanceof StrataError && /grid/.test(e.message),
  );
  assert.throws(
    () => resolveConfig({ infillDensity: 150 }),
    (e: unknown) => e instanceof StrataError && /0 to 100/.test(e.message),
  );
  assert.throws(() => resolveConfig({ layerHeight: Number.NaN }), StrataError);
  assert.throws(
    () => resolveConfig({ printer: 'no-such-printer' }),
    (e: unknown) => e instanceof StrataError && e.code === 'UNKNOWN_PRESET',
  );
  assert.throws(
    () => resolveConfig({ layerHeight: 0.39 }),
    (e: unknown) => e instanceof StrataError && /too thick/.test(e.message),
  );
});

test('the caller options object is never mutated', () => {
  const opts = Object.freeze({ layerHeight: 0.16, infillDensity: 30 });
  const c = resolveConfig(opts);
  assert.equal(c.layerHeight, 0.16);
  assert.deepEqual(opts, { layerHeight: 0.16, infillDensity: 30 });
  assert.equal(c.topLayers, 5);
});

test('wallCount overrides shellWallThickness; text values parse by type', () => {
  assert.equal(resolveConfig({ wallCount: 3 }).wallCount, 3);
  assert.equal(resolveConfig({ shellWallThickness: 1.2 }).wallCount, 3);
  assert.equal(parseSettingText('infillDensity', '20%'), 20);
  assert.equal(parseSettingText('combing', 'off'), false);
  assert.equal(parseSettingText('lineWidth', 'auto'), null);
});

test('the config holds each derived setting once, resolved; the settings as given keep it empty', () => {
  const c = resolveConfig({ nozzleDiameter: 0.6, shellWallThickness: 1.8 });
  assert.equal(c.lineWidthMm, 0.6);
  assert.equal(c.wallCount, 3);
  assert.equal(c.firstLayerNozzleTemperature, c.settings.firstLayerNozzleTemperature);
  for (const key of ['lineWidth', 'firstLayerLineWidth', 'supportLineWidth', 'minLayerHeight', 'topSkinThickness'])
    assert.ok(!(key in c), `${key} is only in its resolved form`);
  assert.equal(c.settings.lineWidth, null, 'an empty setting stays empty where settings are written back out');
  assert.equal(c.settings.wallCount, null);
  assert.equal(resolveConfig({ wallCount: 4 }).settings.wallCount, 4);
});

test('setting the nozzle or bed temperature moves the first-layer one with it, keeping the preset offset', () => {
  const base = resolveConfig();
  const c = resolveConfig({ nozzleTemperature: 230, bedTemperature: 70 });
  assert.equal(c.firstLayerNozzleTemperature - 230, base.firstLayerNozzleTemperature - base.nozzleTemperature);
  assert.equal(c.firstLayerBedTemperature - 70, base.firstLayerBedTemperature - base.bedTemperature);
  assert.equal(
    resolveConfig({ nozzleTemperature: 230, firstLayerNozzleTemperature: 240 }).firstLayerNozzleTemperature,
    240,
  );
});
