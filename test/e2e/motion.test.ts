/**
 * Wipe, coasting, z-hop speed, z-hop only over printed parts and the retraction count limit on a shared
 * model (HoleTest): the G-code parses back with E balanced, in Marlin and Klipper flavours and with
 * firmware retraction, and the estimate moves by a sane amount.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { readModel, skipWithoutModels } from './models.js';

const skip = skipWithoutModels();

async function slice(options: SliceOptions) {
  const r = await new Slicer({ threads: 1, ...options }).slice(readModel('HoleTest.stl'));
  return {
    gcode: r.gcode,
    parsed: parseGcode(r.gcode),
    seconds: r.stats.printTimeSeconds,
    filament: r.stats.filamentMm,
  };
}

const hops = (gcode: string, z: string) =>
  gcode.split('\n').filter((l) => l.startsWith('G0') && l.endsWith(' Z' + z)).length;

test('HoleTest with wipe, coasting and z-hop: balanced E, the time a little longer, less filament', {
  skip,
  timeout: 300_000,
}, async () => {
  const base = await slice({ zHop: 0.4 });
  const motion = { zHop: 0.4, zHopSpeed: 10, wipeDistance: 2, retractBeforeWipe: 20, coastingVolume: 0.064 };
  for (const extra of [
    { gcodeFlavor: 'marlin' },
    { gcodeFlavor: 'klipper' },
    { firmwareRetraction: true },
    { extruderMode: 'relative' },
  ] as const) {
    const r = await slice({ ...motion, ...extra });
    const what = JSON.stringify(extra);
    assert.equal(r.parsed.balance.unbalanced, 0, `${what}: balanced`);
    if (!('firmwareRetraction' in extra)) {
      assert.ok(
        /^G1 F\d+ X[\d.]+ Y[\d.]+ E/m.test(r.gcode) || /^G1 X[\d.]+ Y[\d.]+ E-/m.test(r.gcode),
        `${what}: wipe moves`,
      );
      // same retractions as without the wipe: each spread over its wipe counts once
      assert.equal(r.parsed.balance.retractions, base.parsed.balance.retractions, `${what}: retractions`);
    }
    if (extra.gcodeFlavor !== 'klipper') {
      assert.ok(
        r.seconds > base.seconds * 0.9 && r.seconds < base.seconds * 1.25,
        `${what}: ${r.seconds} s against ${base.seconds} s`,
      );
    }
    if (!('firmwareRetraction' in extra)) assert.ok(r.filament < base.filament, `${what}: coasting saves filament`);
  }
});

test('HoleTest: zHopOnlyOverParts lifts less; retractionCountMax skips retractions inside the part only', {
  skip,
  timeout: 300_000,
}, async () => {
  const always = await slice({ zHop: 0.4 });
  const over = await slice({ zHop: 0.4, zHopOnlyOverParts: true });
  assert.ok(
    hops(over.gcode, '0.6') < hops(always.gcode, '0.6'),
    `${hops(over.gcode, '0.6')} lifts against ${hops(always.gcode, '0.6')}`,
  );
  assert.equal(over.parsed.balance.retractions, always.parsed.balance.retractions);
  assert.equal(over.parsed.balance.unbalanced, 0);
  const limited = await slice({ retractionCountMax: 1, retractionExtrusionWindow: 20 });
  const plain = await slice({});
  assert.ok(limited.parsed.balance.retractions < plain.parsed.balance.retractions);
  assert.equal(limited.parsed.balance.unbalanced, 0);
  // every layer change still retracts (retractOnLayerChange)
  const layers = plain.parsed.layers.length;
  assert.ok(
    limited.parsed.balance.retractions >= layers - 1,
    `${limited.parsed.balance.retractions} retractions, ${layers} layers`,
  );
});
