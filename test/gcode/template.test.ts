import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { SCHEMA, SETTING_KEYS, type Settings } from '#strata/settings/schema.js';
import { compileTemplate, expandTemplate, placeholders, settingValue } from '#strata/gcode/template.js';

function defaults(overrides: Partial<Settings> = {}): Settings {
  const values: Record<string, unknown> = {};
  for (const key of SETTING_KEYS) values[key] = SCHEMA[key].default;
  return { ...(values as Settings), ...overrides };
}

/** The error message of `fn`, which must throw a StrataError BAD_SETTING. */
function failure(fn: () => unknown): string {
  try {
    fn();
  } catch (e) {
    assert.ok(e instanceof StrataError && e.code === 'BAD_SETTING', String(e));
    assert.doesNotMatch(e.message, /\n/, 'one line');
    return e.message;
  }
  assert.fail('no error');
}

test('every setting key is a placeholder; numbers compact, booleans 1/0, enums as text', () => {
  const s = defaults({ nozzleDiameter: 0.4, filamentDiameter: 1.75, originAtCenter: false, gcodeFlavor: 'klipper' });
  assert.equal(
    expandTemplate('startGcode', '{nozzleDiameter} {filamentDiameter} {originAtCenter} {gcodeFlavor}', s),
    '0.4 1.75 0 klipper',
  );
  for (const key of SETTING_KEYS) {
    const value = settingValue(s, key);
    if (key === 'threads' || value === null) continue;
    // a template's own text has braces, which are never passed on
    if (typeof value === 'string' && /[{}]/.test(value))
      assert.throws(() => expandTemplate('startGcode', `{${key}}`, s), /still has a brace/);
    else assert.doesNotThrow(() => expandTemplate('startGcode', `{${key}}`, s), key);
  }
});

test('empty derived settings fall back as the schema describes; extra values win', () => {
  const s = defaults({
    nozzleTemperature: 205,
    firstLayerNozzleTemperature: null,
    lineWidth: null,
    nozzleDiameter: 0.6,
  });
  assert.equal(
    expandTemplate('endGcode', 'M109 S{firstLayerNozzleTemperature} W{firstLayerLineWidth}', s),
    'M109 S205 W0.6',
  );
  assert.equal(
    expandTemplate('endGcode', '{layerCount}/{nozzleTemperature}', s, { layerCount: 12, nozzleTemperature: 1 }),
    '12/1',
  );
});

test('unknown placeholders and syntax errors are one BAD_SETTING line naming the template, the line and the problem', () => {
  const s = defaults();
  assert.equal(
    failure(() => expandTemplate('startGcode', 'G28\n{foo}', s)),
    'startGcode line 2: unknown placeholder {foo}',
  );
  assert.match(
    failure(() => expandTemplate('startGcode', '{toString}', s)),
    /^startGcode line 1: unknown placeholder \{toString\}$/,
  );
  assert.equal(
    failure(() => expandTemplate('endGcode', 'G1\nG1\nM104 S{foo + 1}', s)),
    'endGcode line 3: unknown placeholder foo in {foo + 1}',
  );
  assert.equal(
    failure(() => expandTemplate('startGcode', 'G1\nM140 S[bed_temp]', s)),
    'startGcode line 2: unknown placeholder [bed_temp]',
  );
  assert.match(
    failure(() => expandTemplate('startGcode', 'G28\n\nM104 S{nozzleTemperature +}', s)),
    /^startGcode line 3: the expression ends where a value was expected in \{nozzleTemperature \+\}$/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', 'G28\n{if layerHeight > 0.1}\nG1 Z1', s)),
    /^startGcode line 2: \{if layerHeight > 0.1\} has no \{endif\}$/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', 'G28\n{endif}', s)),
    /^startGcode line 2: \{endif\} with no \{if\} before it/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', 'M117 }', s)),
    /^startGcode line 1: a "\}" with no "\{" before it$/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', '{ }', s)),
    /line 1: an empty \{\}/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', '{layerHeight = 1}', s)),
    /line 1: a single "=" \(compare with "=="\)/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', '{nozzleTemperature / 0}', s)),
    /line 1: division by zero in \{nozzleTemperature \/ 0\}/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', 'M117 {"a" - 1}', s)),
    /"-" needs a number, not text/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', '{nozzleTemperature[0]}', s)),
    /nozzleTemperature is a single value: it takes no \[0\]/,
  );
  assert.match(
    failure(() => expandTemplate('startGcode', '{frobnicate(1)}', s)),
    /unknown function frobnicate\(\)/,
  );
  // a placeholder with no value, and a brace a value brings in, are errors too, never text for the printer
  assert.equal(
    failure(() => expandTemplate('startGcode', 'M203 X{maxSpeedX}', defaults({ maxSpeedX: null }))),
    'startGcode line 1: placeholder {maxSpeedX} has no value (the setting is empty)',
  );
  assert.match(
    failure(() => expandTemplate('startGcode', 'G28\nM117 {"{"}done', s)),
    /^startGcode line 2: "M117 \{done" still has a brace after its placeholders were filled in$/,
  );
  // unknown names are found in every branch, taken or not, before anything runs
  assert.match(
    failure(() => compileTemplate('startGcode', '{if false}\nM104 S{bogus}\n{endif}')),
    /^startGcode line 2: unknown placeholder \{bogus\}$/,
  );
});

test("PrusaSlicer's forms: [key], {key[0]}, [key_0], [key[initial_extruder]], arithmetic, min/max, ternary, regex, digits", () => {
  const s = defaults({
    nozzleTemperature: 210,
    firstLayerNozzleTemperature: 215,
    bedTemperature: 60,
    firstLayerBedTemperature: 65,
    filamentType: 'PETG',
    layerHeight: 0.15,
  });
  const x = (t: string, extra = {}) => expandTemplate('startGcode', t, s, extra);
  assert.equal(x('M104 S[first_layer_temperature] ; then [temperature]'), 'M104 S215 ; then 210');
  assert.equal(
    x('M190 S{first_layer_bed_temperature[0]} M109 S{first_layer_temperature[initial_extruder]}'),
    'M190 S65 M109 S215',
  );
  assert.equal(
    x('[first_layer_temperature_0] [first_layer_temperature[initial_tool]] {temperature[1]}'),
    '215 215 210',
    'one extruder: any index is its value',
  );
  assert.equal(x('G1 Z{min(max_layer_z + 1, max_print_height)}', { maxLayerZ: 12.3 }), 'G1 Z13.3');
  assert.equal(
    x(
      '{(first_layer_temperature[0] - 10) * 2 / 4} {7 % 4} {-layer_height} {int(2.7)} {round(2.5)} {round(1.23456, 2)} {max(1, 5, 3)}',
    ),
    '102.5 3 -0.15 2 3 1.23 5',
  );
  assert.equal(
    x(
      '{filament_type[0] == "PETG" ? 230 : 210} {(filament_type[0]=~/.*PET.*/) ? 175 : 170} {filament_type[0] !~ /PLA/}',
    ),
    '230 175 1',
  );
  assert.equal(x('{digits(layer_height, 0, 3)}|{zdigits(7, 3)}|{digits(7, 3)}|{"a" + 1.5}'), '0.150|007|  7|a1.5');
  assert.equal(x('{one_of(filament_type[0], "PLA", /PET.?/)} {is_nil(temperature[0])} {size(print_bed_min)}'), '1 0 2');
  assert.equal(
    x('{interpolate_table(layer_z, (0,7000), (150,7000), (200,4000))} {interpolate_table(300, (0,1), (10,2))}', {
      layerZ: 175,
    }),
    '5500 2',
  );
  assert.equal(
    x('{is_extruder_used[0]} {is_extruder_used[1]} {num_extruders} {not has_wipe_tower && true} {1 < 2 or false}'),
    '1 0 1 1 1',
  );
  assert.equal(
    x('M862.1 P[nozzle_diameter] ; [Nozzle] and [not a placeholder] stay'),
    'M862.1 P0.4 ; [Nozzle] and [not a placeholder] stay',
  );
  assert.match(
    failure(() => x('{print_bed_min}')),
    /print_bed_min is a point: write print_bed_min\[0\] for X/,
  );
});

test("{if}{elsif}{else}{endif}: inline and on lines of their own (which leave no line), nested; Cura's {elif}", () => {
  const s = defaults({ layerHeight: 0.15, filamentType: 'FLEX', bedTemperature: 70 });
  const x = (t: string) => expandTemplate('startGcode', t, s);
  assert.equal(x('M221 S{if layer_height<0.075}100{else}95{endif}'), 'M221 S95');
  assert.equal(
    x('G28\n{if filament_type[0]=="FLEX"}\nG1 E-4 F2400\n{else}\nG1 E-2 F2400\n{endif}\nG92 E0'),
    'G28\nG1 E-4 F2400\nG92 E0',
  );
  assert.equal(
    x('{if layer_height > 0.2}A{elsif layer_height > 0.1}B{if bed_temperature >= 70}C{endif}{else}D{endif}'),
    'BC',
  );
  assert.equal(
    x(
      ';cura\n{if material_bed_temperature > 60}\nM190 S{material_bed_temperature}\n{elif material_bed_temperature > 0}\nM140 S1\n{else}\n{endif}\nG28',
    ),
    ';cura\nM190 S70\nG28',
  );
  assert.equal(x('{if false}nothing{endif}'), '');
  assert.equal(x("{'x' if bed_temperature > 60 else 'y'}{True and not False}"), 'x1');
});

test("Cura's {key} and {key, extruder}; its names and Strata's for the same quantities", () => {
  const s = defaults({
    nozzleTemperature: 200,
    firstLayerNozzleTemperature: 205,
    bedTemperature: 55,
    firstLayerBedTemperature: 60,
    buildPlateWidth: 235,
  });
  assert.equal(
    expandTemplate(
      'startGcode',
      'M104 S{material_print_temperature_layer_0} M109 S{material_print_temperature, 0} M140 S{material_bed_temperature_layer_0} M190 S{print_bed_temperature} X{machine_width}',
      s,
    ),
    'M104 S205 M109 S200 M140 S60 M190 S55 X235',
  );
  assert.equal(
    expandTemplate('endGcode', ';{print_time} {filament_amount}m {filament_weight}g', s, {
      printTimeSeconds: 3725,
      filamentMm: 1234.5,
      filamentGrams: 3.7,
    }),
    ';01:02:05 1.23m 3.7g',
  );
});

test('placeholders: the quantities a template uses, by their Strata names, in any of the forms', () => {
  assert.deepEqual(placeholders('{a} {b} {a}'), ['a', 'b']);
  assert.deepEqual(
    placeholders('M104 S[first_layer_temperature]\n{if x}M190 S{material_bed_temperature, 0}{endif}\n[temperature_0]'),
    ['firstLayerNozzleTemperature', 'x', 'bedTemperature', 'nozzleTemperature'],
  );
  assert.deepEqual(placeholders('{broken'), []);
});
