import { test } from 'node:test';
import assert from 'node:assert/strict';
import { SCHEMA, type SettingDef, type Settings } from '#strata/settings/schema.js';
import {
  DEFAULT_FILAMENT_ID,
  DEFAULT_PRINTER_ID,
  FILAMENT_PRESETS,
  findFilament,
  findPrinter,
  listPresets,
  normalizePresetName,
  PRINTER_PRESETS,
} from '#strata/settings/presets/index.js';
import { FILAMENTS } from '#strata/settings/presets/filaments.js';
import { PRINTERS } from '#strata/settings/presets/printers.js';

const ALL = [
  ...PRINTERS.map((p) => ({ kind: 'printer', ...p })),
  ...FILAMENTS.map((p) => ({ kind: 'filament', ...p })),
];

/** Why a value does not fit its schema definition, or '' when it does. */
function misfit(def: SettingDef, value: unknown): string {
  switch (def.type) {
    case 'number':
    case 'integer':
      if (value === null) return def.nullable ? '' : 'null is not allowed';
      if (typeof value !== 'number' || !Number.isFinite(value))
        return `expected a number, got ${JSON.stringify(value)}`;
      if (def.type === 'integer' && !Number.isInteger(value)) return `expected an integer, got ${value}`;
      if (value < def.min || value > def.max) return `${value} is outside ${def.min}..${def.max}`;
      return '';
    case 'boolean':
      return typeof value === 'boolean' ? '' : `expected a boolean, got ${JSON.stringify(value)}`;
    case 'enum':
      return typeof value === 'string' && def.values.includes(value)
        ? ''
        : `${JSON.stringify(value)} is not one of ${def.values.join(', ')}`;
    case 'string':
      if (typeof value !== 'string') return `expected a string, got ${JSON.stringify(value)}`;
      return value.length <= def.maxLength ? '' : `longer than ${def.maxLength}`;
  }
}

test('every preset setting is a schema key with a value of its type and range', () => {
  for (const p of ALL) {
    for (const [key, value] of Object.entries(p.settings)) {
      assert.ok(Object.hasOwn(SCHEMA, key), `${p.kind} ${p.id}: unknown setting ${key}`);
      const why = misfit(SCHEMA[key as keyof typeof SCHEMA], value);
      assert.equal(why, '', `${p.kind} ${p.id}: ${key}: ${why}`);
    }
  }
});

test('every {placeholder} in start and end G-code is a schema key', () => {
  for (const p of PRINTERS) {
    for (const key of ['startGcode', 'endGcode'] as const) {
      const text = p.settings[key];
      assert.equal(typeof text, 'string', `${p.id}: ${key} is set`);
      const placeholders = [...text!.matchAll(/\{([^{}]*)\}/g)].map((m) => m[1]!);
      for (const name of placeholders)
        assert.ok(Object.hasOwn(SCHEMA, name), `${p.id} ${key}: {${name}} is not a setting`);
      assert.ok(!/[{}]/.test(text!.replace(/\{[A-Za-z]\w*\}/g, '')), `${p.id} ${key}: stray brace`);
    }
  }
});

test('start G-code heats and leaves absolute extrusion with E reset, like the schema default', () => {
  for (const p of PRINTERS) {
    const start = p.settings.startGcode!;
    assert.match(start, /\{firstLayerNozzleTemperature\}/, `${p.id}: start heats the nozzle`);
    assert.match(start, /\{firstLayerBedTemperature\}/, `${p.id}: start heats the bed`);
    assert.ok(!/^M83\b/m.test(start), `${p.id}: the writer, not the start code, chooses relative E`);
    const lines = start.split('\n');
    const lastG92 = lines.map((l) => l.trim()).lastIndexOf('G92 E0');
    assert.ok(lastG92 >= 0, `${p.id}: E reset`);
    assert.ok(
      !lines.slice(lastG92 + 1).some((l) => /\bE-?\d/.test(l)),
      `${p.id}: nothing extrudes after the last E reset`,
    );
  }
});

test('literal XY moves in start G-code stay on the bed (5 mm margin for purge strips off the sheet)', () => {
  for (const p of PRINTERS) {
    const s = effective(p.settings);
    const [minX, maxX] = s.originAtCenter ? [-s.buildPlateWidth / 2, s.buildPlateWidth / 2] : [0, s.buildPlateWidth];
    const [minY, maxY] = s.originAtCenter ? [-s.buildPlateLength / 2, s.buildPlateLength / 2] : [0, s.buildPlateLength];
    for (const line of s.startGcode.split('\n')) {
      const x = /^G[01]\b.*\bX(-?[\d.]+)/.exec(line)?.[1];
      const y = /^G[01]\b.*\bY(-?[\d.]+)/.exec(line)?.[1];
      if (x !== undefined) assert.ok(+x >= minX - 5 && +x <= maxX + 5, `${p.id}: X${x} off the bed in "${line}"`);
      if (y !== undefined) assert.ok(+y >= minY - 5 && +y <= maxY + 5, `${p.id}: Y${y} off the bed in "${line}"`);
      if (s.originAtCenter && x !== undefined && y !== undefined) {
        assert.ok(Math.hypot(+x, +y) <= s.buildPlateWidth / 2, `${p.id}: (${x}, ${y}) off the round bed`);
      }
    }
  }
});

/** A preset's settings over the schema defaults. */
function effective(settings: Readonly<Partial<Settings>>): Settings {
  const defaults = Object.fromEntries(Object.entries(SCHEMA).map(([k, d]) => [k, d.default]));
  return { ...defaults, ...settings } as Settings;
}

test('printers carry their machine facts', () => {
  const required = [
    'buildPlateWidth',
    'buildPlateLength',
    'buildVolumeHeight',
    'nozzleDiameter',
    'filamentDiameter',
    'originAtCenter',
    'gcodeFlavor',
    'heatedBed',
    'acceleration',
    'cornerVelocity',
    'maxSpeed',
    'retractionDistance',
    'retractionSpeed',
    'startGcode',
    'endGcode',
  ] as const;
  for (const p of PRINTERS) {
    for (const key of required) assert.ok(p.settings[key] !== undefined, `${p.id}: ${key} is set`);
    const s = effective(p.settings);
    for (const speed of [
      'perimeterSpeed',
      'innerWallSpeed',
      'skinSpeed',
      'infillSpeed',
      'firstLayerSpeed',
      'travelSpeed',
      'firstLayerTravelSpeed',
    ] as const) {
      assert.ok(s[speed] <= s.maxSpeed, `${p.id}: ${speed} ${s[speed]} exceeds maxSpeed ${s.maxSpeed}`);
    }
    const r = p.settings.retractionDistance!;
    if (p.extruder === 'bowden') assert.ok(r >= 2 && r <= 8, `${p.id}: bowden retraction ${r} mm`);
    else assert.ok(r > 0 && r <= 2, `${p.id}: direct-drive retraction ${r} mm`);
  }
});

test('flavours and origins of well-known printers', () => {
  for (const id of [
    'creality-k1',
    'creality-k1-max',
    'voron-2.4-350',
    'voron-trident-300',
    'sovol-sv07',
    'elegoo-neptune-4',
  ]) {
    assert.equal(PRINTER_PRESETS[id]?.settings.gcodeFlavor, 'klipper', id);
  }
  for (const id of [
    'bambu-lab-a1',
    'bambu-lab-a1-mini',
    'bambu-lab-p1s',
    'bambu-lab-x1c',
    'creality-ender-3',
    'prusa-mk4',
  ]) {
    assert.equal(PRINTER_PRESETS[id]?.settings.gcodeFlavor, 'marlin', id);
  }
  assert.equal(PRINTER_PRESETS['flsun-q5']?.settings.originAtCenter, true);
  assert.equal(PRINTER_PRESETS['creality-ender-3']?.settings.originAtCenter, false);
  assert.equal(PRINTER_PRESETS['creality-ender-3']?.extruder, 'bowden');
  assert.equal(PRINTER_PRESETS['prusa-i3-mk3s']?.settings.buildPlateWidth, 250);
  assert.equal(PRINTER_PRESETS['prusa-i3-mk3s']?.settings.buildPlateLength, 210);
});

test('the printers the brief names are all there', () => {
  const wanted = [
    'creality-ender-3',
    'creality-ender-3-v2',
    'creality-ender-3-s1',
    'creality-ender-3-v3-se',
    'creality-ender-5',
    'creality-cr-10',
    'creality-k1',
    'creality-k1-max',
    'prusa-i3-mk3s',
    'prusa-mk4',
    'prusa-mini',
    'prusa-xl',
    'bambu-lab-a1',
    'bambu-lab-a1-mini',
    'bambu-lab-p1s',
    'bambu-lab-x1c',
    'voron-2.4-350',
    'voron-trident-300',
    'anycubic-kobra-2',
    'anycubic-i3-mega',
    'elegoo-neptune-4',
    'elegoo-neptune-3-pro',
    'artillery-sidewinder-x2',
    'sovol-sv06',
    'flsun-q5',
  ];
  for (const id of wanted) assert.ok(PRINTER_PRESETS[id], id);
});

test('filaments carry temperatures, cooling and density; only flexible ones set retraction distance', () => {
  const required = [
    'nozzleTemperature',
    'firstLayerNozzleTemperature',
    'bedTemperature',
    'firstLayerBedTemperature',
    'fanSpeed',
    'firstLayerFanSpeed',
    'minLayerTime',
    'filamentDensity',
  ] as const;
  for (const f of FILAMENTS) {
    for (const key of required) assert.ok(f.settings[key] !== undefined, `${f.id}: ${key} is set`);
    if (f.material !== 'TPU')
      assert.equal(f.settings.retractionDistance, undefined, `${f.id}: retraction distance belongs to the printer`);
    for (const key of Object.keys(f.settings)) {
      assert.notEqual(SCHEMA[key as keyof typeof SCHEMA].stage, 'machine', `${f.id}: ${key} is a machine setting`);
    }
  }
  const tpu = findFilament('tpu')!;
  assert.ok(
    tpu.settings.retractionDistance! <= 2 && tpu.settings.retractionSpeed! <= 30,
    'TPU retracts short and slow',
  );
  assert.ok(
    findFilament('petg')!.settings.retractionSpeed! < (SCHEMA.retractionSpeed.default as number),
    'PETG retracts slower',
  );
  assert.ok(findFilament('abs')!.settings.bedTemperature! >= 90);
  for (const id of ['pla-cf', 'petg-cf', 'pa-cf', 'pet-cf', 'asa-cf', 'pc-cf', 'pa-gf', 'pla-glow'])
    assert.equal(FILAMENT_PRESETS[id]?.abrasive, true, id);
});

test('ids are unique, presets are frozen, and there are enough of them', () => {
  assert.ok(PRINTERS.length >= 40, `${PRINTERS.length} printers`);
  assert.ok(FILAMENTS.length >= 30, `${FILAMENTS.length} filaments`);
  assert.equal(new Set(PRINTERS.map((p) => p.id)).size, PRINTERS.length);
  assert.equal(new Set(FILAMENTS.map((p) => p.id)).size, FILAMENTS.length);
  for (const p of ALL) {
    assert.match(p.id, /^[a-z0-9][a-z0-9.-]*$/, `${p.id}: lower-case id`);
    assert.ok(
      p.aliases.every((a) => a === a.toLowerCase()),
      `${p.id}: aliases are lower-case`,
    );
  }
  assert.ok(Object.isFrozen(PRINTER_PRESETS) && Object.isFrozen(FILAMENT_PRESETS));
  for (const p of [...PRINTERS, ...FILAMENTS])
    assert.ok(Object.isFrozen(p) && Object.isFrozen(p.settings) && Object.isFrozen(p.aliases), p.id);
  assert.throws(() => {
    (PRINTER_PRESETS['creality-ender-3']!.settings as Record<string, unknown>).maxSpeed = 1;
  }, TypeError);
});

test('lookup by id, name and alias, case-insensitively', () => {
  assert.equal(findPrinter('creality-ender-3')?.id, 'creality-ender-3');
  assert.equal(findPrinter('Creality Ender-3')?.id, 'creality-ender-3');
  assert.equal(findPrinter('ender-3')?.id, 'creality-ender-3');
  assert.equal(findPrinter('ENDER3')?.id, 'creality-ender-3');
  assert.equal(findPrinter('  Ender 3 V2 ')?.id, 'creality-ender-3-v2');
  assert.equal(findPrinter('Prusa i3 MK3S')?.id, 'prusa-i3-mk3s');
  assert.equal(findPrinter('mk4')?.id, 'prusa-mk4');
  assert.equal(findPrinter('X1C')?.id, 'bambu-lab-x1c');
  assert.equal(findPrinter('Bambu Lab A1 mini')?.id, 'bambu-lab-a1-mini');
  assert.equal(findPrinter('voron 2.4')?.id, 'voron-2.4-350');
  assert.equal(findFilament('PLA')?.id, 'pla');
  assert.equal(findFilament('Generic PETG')?.id, 'petg');
  assert.equal(findFilament('nylon (pa)')?.id, 'nylon');
  assert.equal(findFilament('PA')?.id, 'nylon');
  assert.equal(findFilament('tpu')?.id, 'tpu-95a');
  assert.equal(normalizePresetName(' A_b  C '), 'a-b-c');
});

test('unknown lookups return undefined, also for Object.prototype names', () => {
  for (const name of ['', 'ender-99', 'constructor', '__proto__', 'toString', 'hasOwnProperty']) {
    assert.equal(findPrinter(name), undefined, name);
    assert.equal(findFilament(name), undefined, name);
  }
  assert.equal(findFilament('creality-ender-3'), undefined);
  assert.equal(findPrinter('pla'), undefined);
});

test('every id, name and alias finds its own preset', () => {
  for (const p of PRINTERS)
    for (const key of [p.id, p.name, ...p.aliases]) assert.equal(findPrinter(key)?.id, p.id, key);
  for (const f of FILAMENTS)
    for (const key of [f.id, f.name, ...f.aliases]) assert.equal(findFilament(key)?.id, f.id, key);
});

test('defaults and listPresets', () => {
  assert.equal(DEFAULT_PRINTER_ID, 'creality-ender-3');
  assert.equal(DEFAULT_FILAMENT_ID, 'pla');
  assert.ok(findPrinter(DEFAULT_PRINTER_ID) && findFilament(DEFAULT_FILAMENT_ID));
  const list = listPresets();
  assert.deepEqual(
    list.printers.map((p) => p.id),
    PRINTERS.map((p) => p.id),
  );
  assert.deepEqual(
    list.filaments.map((p) => p.id),
    FILAMENTS.map((p) => p.id),
  );
  assert.ok(list.printers.every((p) => typeof p.name === 'string' && Array.isArray(p.aliases)));
  // A fresh copy each call: callers may not change the tables through it.
  list.printers[0]!.aliases.push('x');
  assert.ok(!listPresets().printers[0]!.aliases.includes('x'));
});

test('host features: thumbnails the printers show, arcs where the firmware runs them, every table entry a printer', async () => {
  const { PRINTER_HOST_FEATURES } = await import('#strata/settings/presets/printer-host-features.js');
  const { parseThumbnailSpecs } = await import('#strata/thumbnail/spec.js');
  for (const id of Object.keys(PRINTER_HOST_FEATURES)) assert.ok(PRINTER_PRESETS[id], `${id} is a printer`);
  for (const p of PRINTERS)
    if (p.settings.thumbnails) assert.ok(parseThumbnailSpecs(p.settings.thumbnails).length > 0, p.id);
  assert.match(PRINTER_PRESETS['prusa-mk4']!.settings.thumbnails!, /16x16\/QOI/);
  assert.equal(PRINTER_PRESETS['prusa-mk4']!.settings.arcFitting, true);
  assert.equal(PRINTER_PRESETS['creality-k1']!.settings.thumbnails, '96x96/PNG,300x300/PNG');
  assert.equal(PRINTER_PRESETS['bambu-lab-x1c']!.settings.arcFitting, true);
  assert.notEqual(
    PRINTER_PRESETS['creality-ender-3']!.settings.arcFitting,
    true,
    'stock Ender-3 Marlin has no ARC_SUPPORT',
  );
  assert.equal(PRINTER_PRESETS['prusa-i3-mk3s']!.settings.machineLimits, 'write');
  assert.equal(PRINTER_PRESETS['creality-ender-3']!.settings.maxAccelerationX, 500);
  // the preset's own settings win over the table's
  assert.equal(PRINTER_PRESETS['prusa-mini']!.settings.retractionDistance, 3.2);
});

test('a slice with every printer preset resolves (limits, thumbnails and templates fit together)', async () => {
  const { resolveConfig } = await import('#strata/settings/resolve.js');
  for (const p of PRINTERS)
    for (const f of ['pla', 'petg'])
      assert.doesNotThrow(() => resolveConfig({ printer: p.id, filament: f }), `${p.id} + ${f}`);
  for (const f of FILAMENTS) assert.doesNotThrow(() => resolveConfig({ filament: f.id }), f.id);
});
