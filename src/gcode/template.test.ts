import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '../errors.js';
import { SCHEMA, SETTING_KEYS, type Settings } from '../settings/schema.js';
import { expandTemplate, placeholders, settingValue } from './template.js';

function defaults(overrides: Partial<Settings> = {}): Settings {
  const values: Record<string, unknown> = {};
  for (const key of SETTING_KEYS) values[key] = SCHEMA[key].default;
  return { ...(values as Settings), ...overrides };
}

test('every setting key is a placeholder; numbers compact, booleans 1/0, enums as text', () => {
  const s = defaults({ nozzleDiameter: 0.4, filamentDiameter: 1.75, originAtCenter: false, gcodeFlavor: 'klipper' });
  assert.equal(expandTemplate('startGcode', '{nozzleDiameter} {filamentDiameter} {originAtCenter} {gcodeFlavor}', s), '0.4 1.75 0 klipper');
  for (const key of SETTING_KEYS) {
    if (settingValue(s, key) === null) continue;
    assert.doesNotThrow(() => expandTemplate('startGcode', `{${key}}`, s), key);
  }
});

test('empty derived settings fall back as the schema describes; extra values win', () => {
  const s = defaults({ nozzleTemperature: 205, firstLayerNozzleTemperature: null, lineWidth: null, nozzleDiameter: 0.6 });
  assert.equal(expandTemplate('endGcode', 'M109 S{firstLayerNozzleTemperature} W{firstLayerLineWidth}', s), 'M109 S205 W0.6');
  assert.equal(expandTemplate('endGcode', '{layerCount}/{nozzleTemperature}', s, { layerCount: 12, nozzleTemperature: 1 }), '12/1');
});

test('unknown placeholders are BAD_SETTING errors naming the template; other braces stay', () => {
  const s = defaults();
  assert.throws(
    () => expandTemplate('startGcode', 'G28\n{foo}', s),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING' && e.message === 'startGcode: unknown placeholder {foo}',
  );
  assert.throws(() => expandTemplate('startGcode', '{toString}', s), /unknown placeholder \{toString\}/);
  assert.equal(expandTemplate('startGcode', '{ 1 } {a-b} {}', s), '{ 1 } {a-b} {}');
  assert.deepEqual(placeholders('{a} {b} {a}'), ['a', 'b']);
});
