import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import { listPresets } from '#strata/settings/presets/index.js';
import { SCHEMA } from '#strata/settings/schema.js';
import { checkTemplatesForFlavor } from '#strata/gcode/custom-gcode.js';
import { templateForFlavor } from '#strata/gcode/flavor-templates.js';
import type { GcodeFlavor } from '#strata/gcode/flavor.js';

/** A 10 mm cube as raw arrays. */
const CUBE = {
  positions: new Float32Array([0, 0, 0, 10, 0, 0, 0, 10, 0, 10, 10, 0, 0, 0, 10, 10, 0, 10, 0, 10, 10, 10, 10, 10]),
  indices: new Uint32Array([
    0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5,
  ]),
};

const COMMON = [
  'G0',
  'G1',
  'G2',
  'G3',
  'G4',
  'G28',
  'G90',
  'G91',
  'G92',
  'M73',
  'M82',
  'M83',
  'M84',
  'M106',
  'M107',
  'M140',
  'M190',
  'M204',
];
/** The commands each firmware takes (Klipper also runs its macros: upper-case words). */
const KNOWN: Record<GcodeFlavor, ReadonlySet<string>> = {
  marlin: new Set([
    ...COMMON,
    'M104',
    'M109',
    'G10',
    'G11',
    'G29',
    'M420',
    'G80',
    'M862.1',
    'M862.3',
    'M486',
    'M900',
    'M201',
    'M203',
    'M205',
  ]),
  klipper: new Set([...COMMON, 'M104', 'M109', 'G10', 'G11']),
  reprap: new Set([...COMMON, 'G10', 'G11', 'T0', 'M116', 'G29', 'M486', 'M572', 'M201', 'M203', 'M566']),
};

function commands(gcode: string): string[] {
  const out: string[] = [];
  for (const line of gcode.split('\n')) {
    const word = line.split(';')[0].trim().split(/\s+/)[0];
    if (word) out.push(word);
  }
  return out;
}

const FLAVOURS = SCHEMA.gcodeFlavor.values;

test('every preset in every flavour: only commands its firmware takes, heated before the first extrusion, or a clear refusal', async () => {
  let refusedCount = 0;
  for (const { id } of listPresets().printers) {
    for (const flavor of FLAVOURS) {
      const slicer = new Slicer({ printer: id, gcodeFlavor: flavor, threads: 1 });
      const usesMacros = /^\s*[A-Z_]{4,}/m.test(slicer.config.startGcode + '\n' + slicer.config.endGcode);
      if (usesMacros && flavor !== 'klipper') {
        assert.equal(
          new Slicer({ printer: id }).config.gcodeFlavor,
          'klipper',
          `${id}: only Klipper printers' templates call macros`,
        );
        await assert.rejects(
          slicer.slice(CUBE),
          (e: unknown) =>
            e instanceof StrataError && /is a Klipper macro, which .* firmware does not run/.test(e.message),
          `${id} ${flavor}`,
        );
        refusedCount++;
        continue;
      }
      const { gcode } = await slicer.slice(CUBE);
      const words = commands(gcode);
      for (const w of words) {
        const ok = KNOWN[flavor].has(w.toUpperCase()) || (flavor === 'klipper' && /^[A-Z_]+$/.test(w));
        assert.ok(ok, `${id} in ${flavor}: ${w} is not a ${flavor} command`);
      }
      const firstExtrusion = gcode.search(/^G1 [^;\n]*X[^;\n]*E[\d.]/m);
      const heat = flavor === 'reprap' ? /^(G10 P0 S|M116)/m : /^M10[49] S/m;
      const heatAt = gcode.search(heat);
      // Klipper macro presets heat inside the macro (START_PRINT … EXTRUDER_TEMP=…)
      const macroHeat = gcode.search(/^(START_PRINT|PRINT_START)\b.*\d/m);
      assert.ok(
        (heatAt >= 0 && heatAt < firstExtrusion) || (macroHeat >= 0 && macroHeat < firstExtrusion),
        `${id} in ${flavor}: heated before extruding`,
      );
      if (flavor === 'reprap') assert.doesNotMatch(gcode, /^M10[49]\b/m, `${id}: RepRap gets no M104/M109`);
    }
  }
  assert.ok(refusedCount > 0, 'Klipper-macro presets are refused under Marlin and RepRap');
});

test('RepRap: nozzle heating becomes tool temperatures; mesh commands and Prusa checks are translated', () => {
  const lines = [
    'M104 S{t} ; warm',
    'M109 S215',
    'M109 T1 S200',
    'M420 S1 ; mesh on',
    'G80',
    'M862.3 P "MK4"',
    'G28',
    'M104 S0',
  ];
  assert.deepEqual(templateForFlavor(lines, 'reprap', 'startGcode'), [
    'G10 P0 S{t} R{t} ; warm',
    'G10 P0 S215 R215 ; nozzle temperature',
    'T0 ; select the tool',
    'M116 P0 ; wait for the nozzle',
    'G10 P1 S200 R200 ; nozzle temperature',
    'T1 ; select the tool',
    'M116 P1 ; wait for the nozzle',
    'G29 S1 ; mesh on',
    'G29 ; probe the bed',
    '; M862.3 P "MK4" (a Prusa printer check; RepRapFirmware has none)',
    'G28',
    'G10 P0 S0 R0 ; nozzle heat, no wait',
  ]);
  assert.deepEqual(templateForFlavor(['M420 S1', 'G29', 'M104 S200'], 'klipper', 'startGcode'), [
    'BED_MESH_PROFILE LOAD=default ; load the saved bed mesh',
    'BED_MESH_CALIBRATE ; probe the bed mesh',
    'M104 S200',
  ]);
  assert.deepEqual(templateForFlavor(['M104 S200', 'G29'], 'marlin', 'startGcode'), ['M104 S200', 'G29']);
});

test('a Klipper macro under Marlin or RepRap is refused before slicing, naming the line', () => {
  for (const flavor of ['marlin', 'reprap'] as const) {
    assert.throws(
      () => checkTemplatesForFlavor({ gcodeFlavor: flavor, startGcode: 'G28\nSTART_PRINT BED=60', endGcode: '' }),
      (e: unknown) =>
        e instanceof StrataError &&
        e.code === 'BAD_SETTING' &&
        /^startGcode line 2 "START_PRINT BED=60" is a Klipper macro/.test(e.message),
    );
  }
  assert.doesNotThrow(() =>
    checkTemplatesForFlavor({ gcodeFlavor: 'klipper', startGcode: 'START_PRINT', endGcode: 'END_PRINT' }),
  );
});
