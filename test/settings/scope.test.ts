import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { SCHEMA, SETTING_KEYS, type SettingKey } from '#strata/settings/schema.js';
import { checkScope, SETTING_SCOPE } from '#strata/settings/scope.js';
import { ConfigTable } from '#strata/settings/scoped.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { StrataError } from '#strata/errors.js';

const SRC = fileURLToPath(new URL('../../../src/', import.meta.url));

/** The settings a folder's product code reads as `cfg.key` / `c.key`. */
function settingsReadIn(folder: string): Map<SettingKey, string> {
  const out = new Map<SettingKey, string>();
  for (const f of readdirSync(SRC + folder)) {
    if (!f.endsWith('.ts') || f.includes('.test.') || f.startsWith('test-')) continue;
    const text = readFileSync(`${SRC}${folder}/${f}`, 'utf8');
    for (const m of text.matchAll(/\b(?:cfg|c|s|config)\.([a-zA-Z]+)\b/g)) {
      if (Object.hasOwn(SCHEMA, m[1])) out.set(m[1] as SettingKey, f);
    }
  }
  return out;
}

test('every setting has a scope', () => {
  for (const k of SETTING_KEYS) assert.ok(['print', 'layer', 'object', 'region'].includes(SETTING_SCOPE[k]), k);
  // one Z plan for the plate: the layer height varies by height only (layer ranges), never per object
  assert.deepEqual(
    SETTING_KEYS.filter((k) => SETTING_SCOPE[k] === 'layer'),
    ['layerHeight'],
  );
  assert.equal(SETTING_SCOPE.nozzleTemperature, 'print');
  assert.equal(SETTING_SCOPE.infillDensity, 'region');
  assert.equal(SETTING_SCOPE.supportEnabled, 'object');
});

test('what the planner and the G-code writer read once per print is print-scoped', () => {
  // they see only the print's config: a setting read there that could vary per object would be ignored
  for (const folder of ['plan', 'gcode']) {
    const read = settingsReadIn(folder);
    assert.ok(read.size > 10, `${folder} reads settings`);
    for (const [key, file] of read)
      assert.equal(SETTING_SCOPE[key], 'print', `${key}, read in ${folder}/${file}, must be print-scoped`);
  }
});

test('scope misuse is refused naming the key and where it may be set', () => {
  assert.throws(
    () => checkScope('bedTemperature', 'object', 'object "a"'),
    (e: unknown) =>
      e instanceof StrataError && /object "a": bedTemperature is the same for the whole print/.test(e.message),
  );
  assert.throws(
    () => checkScope('supportType', 'modifier', 'modifier "m"'),
    /supportType may vary per object but not inside one/,
  );
  assert.doesNotThrow(() => checkScope('supportType', 'object', 'x'));
  assert.doesNotThrow(() => checkScope('infillPattern', 'layer range', 'x'));
  assert.doesNotThrow(() => checkScope('layerHeight', 'layer range', 'x'));
  assert.throws(
    () => checkScope('layerHeight', 'modifier', 'modifier "m"'),
    /modifier "m": layerHeight is the same for every object at one height, so it cannot be set for a modifier; set it for the print or a layer range instead/,
  );
  assert.throws(
    () => checkScope('firstLayerHeight', 'layer range', 'x'),
    /firstLayerHeight is the same for the whole print/,
  );
});

test('configs that resolve the same are one config; the print config is the first', () => {
  const base = { layerHeight: 0.2 };
  const table = new ConfigTable(base, resolveConfig(base));
  const none = table.resolve([{ settings: undefined, use: 'object', where: 'a' }]);
  const same = table.resolve([{ settings: { infillDensity: 20 }, use: 'object', where: 'b' }]);
  const dense = table.resolve([{ settings: { infillDensity: 60 }, use: 'object', where: 'c' }]);
  const dense2 = table.resolve([{ settings: { infillDensity: 60 }, use: 'modifier', where: 'd' }]);
  assert.equal(none, 0);
  assert.equal(same, 0, 'the default value again is the print config');
  assert.equal(dense, 1);
  assert.equal(dense2, 1);
  assert.equal(table.configs.length, 2);
  assert.equal(table.configs[1].infillDensity, 60);
  assert.equal(table.configs[1].layerHeight, 0.2);
  assert.throws(
    () => table.resolve([{ settings: { infillDensity: -3 }, use: 'object', where: 'object "e"' }]),
    /^StrataError: object "e" setting infillDensity|infillDensity = -3 is not allowed/,
  );
});
