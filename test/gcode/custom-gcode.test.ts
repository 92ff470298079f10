import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import { FILAMENTS } from '#strata/settings/presets/filaments.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { parseHeights } from '#strata/gcode/custom-gcode.js';

/** A 10 mm cube as raw arrays: layers at Z 0.2, 0.4, … 10. */
const CUBE = {
  positions: new Float32Array([0, 0, 0, 10, 0, 0, 0, 10, 0, 10, 10, 0, 0, 0, 10, 10, 0, 10, 0, 10, 10, 10, 10, 10]),
  indices: new Uint32Array([
    0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5,
  ]),
};

async function slice(options: SliceOptions) {
  return new Slicer({ threads: 1, ...options }).slice(CUBE);
}

interface Layer {
  index: number;
  z: number;
  /** The layer's lines, from its ;LAYER marker to the next. */
  lines: string[];
}

/** The G-code's layers by their ;LAYER:n / ;Z: markers. */
function layers(gcode: string): Layer[] {
  const out: Layer[] = [];
  for (const line of gcode.split('\n')) {
    const m = /^;LAYER:(\d+)$/.exec(line);
    if (m) out.push({ index: Number(m[1]), z: NaN, lines: [] });
    const current = out[out.length - 1];
    if (!current) continue;
    const z = /^;Z:([\d.]+)$/.exec(line);
    if (z) current.z = Number(z[1]);
    current.lines.push(line);
  }
  return out;
}

/** Where in its layer a command is: the line index, and whether any extrusion comes before it there. */
function occurrences(gcode: string, command: RegExp): Array<{ layer: Layer; at: number; afterExtrusion: boolean }> {
  const found: Array<{ layer: Layer; at: number; afterExtrusion: boolean }> = [];
  for (const layer of layers(gcode)) {
    layer.lines.forEach((line, at) => {
      if (command.test(line)) {
        const afterExtrusion = layer.lines.slice(0, at).some((l) => /^G[123] [^;]*E\d/.test(l));
        found.push({ layer, at, afterExtrusion });
      }
    });
  }
  return found;
}

test('heights are read in any order, each once; the schema refuses negative numbers and words', () => {
  assert.deepEqual(parseHeights('10, 5 2.5;5'), [2.5, 5, 10]);
  assert.deepEqual(parseHeights(''), []);
  for (const bad of ['-5', 'five', '5,,x', '1e3'])
    assert.throws(() => new Slicer({ colorChangeAt: bad }), /colorChangeAt/, bad);
  assert.throws(
    () => new Slicer({ pauseAt: Array.from({ length: 101 }, (_, i) => i).join(',') }),
    /pauseAt/,
    'at most 100 heights',
  );
  assert.equal(new Slicer({ colorChangeAt: '10,5' }).config.colorChangeAt, '10,5');
});

test('colorChangeAt: exactly one M600 before the first layer at or above each height, before anything is printed there', async () => {
  const heights = [5, 2.1, 7.3];
  const { gcode } = await slice({ colorChangeAt: '5, 2.1,7.3,50' });
  const all = layers(gcode);
  const changes = occurrences(gcode, /^M600$/);
  assert.equal(changes.length, heights.length, 'one per height in the print; none for 50 mm, above its top');
  for (const h of heights.sort((a, b) => a - b)) {
    const first = all.find((l) => l.z >= h - 1e-4)!;
    const at = changes.filter((c) => c.layer.index === first.index);
    assert.equal(at.length, 1, `one M600 at the layer at ${first.z} mm for ${h} mm`);
    assert.ok(all[first.index - 1]!.z < h, 'the layer below is under the height');
    assert.equal(at[0]!.afterExtrusion, false, 'before the layer prints');
    assert.equal(first.lines[at[0]!.at - 1], ';COLOR_CHANGE,T0');
  }
  assert.deepEqual(
    changes.map((c) => c.layer.z),
    [2.2, 5, 7.4],
  );
  // two heights on one layer give one change
  const merged = await slice({ colorChangeAt: '5.01,5.1' });
  assert.deepEqual(
    occurrences(merged.gcode, /^M600$/).map((c) => c.layer.z),
    [5.2],
  );
});

test('pauses and colour changes in each flavour: Marlin M601 / M600, Klipper PAUSE, RepRapFirmware M226 / M600; a template replaces them', async () => {
  const expected = { marlin: ['M600', 'M601'], klipper: ['PAUSE', 'PAUSE'], reprap: ['M600', 'M226'] } as const;
  for (const [flavor, [change, pause]] of Object.entries(expected)) {
    const { gcode } = await slice({ gcodeFlavor: flavor as keyof typeof expected, colorChangeAt: '3', pauseAt: '6' });
    const c = occurrences(gcode, new RegExp(`^${change}$`));
    const p = occurrences(gcode, new RegExp(`^${pause}$`));
    const layerOf = (list: typeof c) => list.map((o) => o.layer.z);
    if (change === pause) assert.deepEqual(layerOf(c), [3, 6], flavor);
    else {
      assert.deepEqual(layerOf(c), [3], `${flavor}: colour change`);
      assert.deepEqual(layerOf(p), [6], `${flavor}: pause`);
    }
    assert.equal(occurrences(gcode, /^;PAUSE_PRINT$/).length, 1);
  }
  const custom = await slice({
    gcodeFlavor: 'klipper',
    pauseAt: '4',
    pauseGcode: 'M117 Insert the nut at {layer_z} mm\nPAUSE_PARK Z={max_layer_z + 10}',
    colorChangeAt: '8',
    colorChangeGcode: 'M600 ; layer [layer_num]',
  });
  assert.deepEqual(
    occurrences(custom.gcode, /^M117 Insert the nut at 4 mm$/).map((o) => o.layer.index),
    [19],
  );
  assert.equal(occurrences(custom.gcode, /^PAUSE_PARK Z=14$/).length, 1);
  assert.deepEqual(
    occurrences(custom.gcode, /^M600 ; layer 39$/).map((o) => o.layer.z),
    [8],
  );
});

test('no heights, or none within the print: the G-code is exactly as without; a pause adds no time', async () => {
  const plain = await slice({});
  const above = await slice({ colorChangeAt: '11', pauseAt: '', colorChangeGcode: 'M600 X0' });
  assert.equal(above.gcode, plain.gcode);
  const paused = await slice({ pauseAt: '2,4,6' });
  assert.equal(paused.stats.printTimeSeconds, plain.stats.printTimeSeconds);
  assert.equal(/^;TIME:(\d+)/m.exec(paused.gcode)![1], /^;TIME:(\d+)/m.exec(plain.gcode)![1]);
  assert.equal(
    paused.gcode.split('\n').length,
    plain.gcode.split('\n').length + 6,
    'a marker and M601 per pause, nothing else',
  );
});

test('layer templates run at every layer with layer_num and layer_z: before the layer change, and after its first Z move', async () => {
  const { gcode } = await slice({
    beforeLayerChangeGcode: ';BEFORE [layer_num] [layer_z]',
    layerChangeGcode: ';AFTER {layer_num} {layer_z} {layer_num == total_layer_count - 1 ? "last" : "more"}',
  });
  const all = layers(gcode);
  assert.equal(all.length, 50);
  for (const l of all) {
    const before = l.lines.filter((x) => x.startsWith(';BEFORE '));
    const after = l.lines.filter((x) => x.startsWith(';AFTER'));
    assert.deepEqual(before, [`;BEFORE ${l.index} ${l.z}`]);
    assert.deepEqual(after, [`;AFTER ${l.index} ${l.z} ${l.index === 49 ? 'last' : 'more'}`]);
    const firstZ = l.lines.findIndex((x) => /^G0 .*Z[\d.]+$/.test(x));
    assert.ok(l.lines.indexOf(before[0]!) < firstZ, 'before: ahead of the move to the layer');
    assert.equal(l.lines[firstZ + 1], after[0], 'after: right after it');
  }
});

test('a G92 E in a layer template resets the E the writer counts from: absolute E stays consistent', async () => {
  const plain = parseGcode((await slice({ extruderMode: 'absolute' })).gcode);
  const reset = parseGcode(
    (
      await slice({
        extruderMode: 'absolute',
        layerChangeGcode: 'G92 E0 ; reset',
        beforeLayerChangeGcode: ';[layer_z]\nG92 E0',
      })
    ).gcode,
  );
  assert.equal(reset.balance.unbalanced, 0);
  assert.ok(Math.abs(reset.e.extruded - plain.e.extruded) < 1e-3, `${reset.e.extruded} vs ${plain.e.extruded}`);
});

test('template problems are one error naming the template and the line, before anything is sliced', async () => {
  const refused = async (options: SliceOptions, message: RegExp) => {
    await assert.rejects(
      slice(options),
      (e: unknown) =>
        e instanceof StrataError && e.code === 'BAD_SETTING' && message.test(e.message) && !e.message.includes('\n'),
    );
  };
  await refused({ pauseAt: '2', pauseGcode: 'M400\n{bogus}' }, /^pauseGcode line 2: unknown placeholder \{bogus\}$/);
  await refused(
    { layerChangeGcode: ';x\n{if layer_z > 2}G1 Z5' },
    /^layerChangeGcode line 2: \{if layer_z > 2\} has no \{endif\}/,
  );
  await refused(
    { layerChangeGcode: 'G4\nTIMELAPSE_TAKE_FRAME' },
    /^layerChangeGcode line 2 "TIMELAPSE_TAKE_FRAME" is a Klipper macro, which Marlin firmware does not run/,
  );
  await refused(
    { colorChangeAt: '3', gcodeFlavor: 'marlin', colorChangeGcode: 'PAUSE' },
    /^colorChangeGcode line 1 "PAUSE" is a Klipper macro/,
  );
  await refused(
    { startGcode: 'G28\nM104 S{first_layer_temperature[0] / (layer_z - layer_z)}' },
    /^startGcode line 2: division by zero in \{first_layer_temperature\[0\] \/ \(layer_z - layer_z\)\}$/,
  );
  // a colour change template with no heights is not run, but must still read
  await refused({ colorChangeGcode: 'M600 {' }, /^colorChangeGcode line 1: /);
});

test("filament presets give their material as filamentType, which templates read as PrusaSlicer's filament_type", async () => {
  for (const f of FILAMENTS) assert.equal(f.settings.filamentType, f.material, f.id);
  const { gcode } = await slice({
    filament: 'petg',
    startGcode:
      'G28\n{if filament_type[0] == "PETG"}M104 S{first_layer_temperature[0] - 10}{else}M104 S0{endif} ; [filament_type]',
  });
  const petg = new Slicer({ filament: 'petg' }).config;
  assert.match(
    gcode,
    new RegExp(`^M104 S${(petg.firstLayerNozzleTemperature ?? petg.nozzleTemperature) - 10} ; PETG$`, 'm'),
  );
});

test("start and end templates see the plan: the first layer's extent, the layer count, the print's top and the filament used", async () => {
  const { gcode, stats } = await slice({
    startGcode:
      'G28\nM555 X{first_layer_print_min[0]} Y{first_layer_print_min[1]} W{first_layer_print_size[0]} H{first_layer_print_size[1]}\n;layers [total_layer_count], first at {layer_z}',
    endGcode: ';top {max_layer_z} of {max_print_height}, {extruded_weight_total} g, layer {layer_num}',
  });
  const m = /^M555 X([\d.]+) Y([\d.]+) W([\d.]+) H([\d.]+)$/m.exec(gcode)!;
  const [x, y, w, h] = m.slice(1).map(Number);
  // the skirt, 3 mm out around the 10 mm cube
  assert.ok(w! > 15 && w! < 18 && h! > 15 && h! < 18 && x! > 0 && y! > 0, m[0]);
  assert.match(gcode, /^;layers 50, first at 0\.2$/m);
  const end = /^;top 10 of 250, ([\d.]+) g, layer 49$/m.exec(gcode);
  assert.ok(end && Math.abs(Number(end[1]) - stats.filamentGrams) < 0.01 * stats.filamentGrams, end?.[0]);
});
