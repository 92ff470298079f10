/**
 * The printing modes through Klipper's own host software (klippy's batch mode, klipper.ts): a spiral vase, a
 * colour change and a pause (PAUSE, printer.cfg's [pause_resume]), and a plate printed one object at a time
 * are each accepted with no command unknown and no move refused, and Strata's estimate stays within 2 % of
 * Klipper's planner on them. Skips without klippy, except under CI (.ci/klipper.sh installs it).
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { assertKlipperAgrees, KLIPPER_CONFIG_SETTINGS, skipWithoutKlipper } from './klipper.js';
import { box } from './test-meshes.js';

const skip = skipWithoutKlipper();
const PRINTER: SliceOptions = { ...KLIPPER_CONFIG_SETTINGS, maxSpeedE: null, maxAccelerationE: null, threads: 1 };

async function accepted(name: string, input: unknown, options: SliceOptions): Promise<string> {
  const { gcode, stats } = new Slicer({ ...PRINTER, ...options }).sliceSync(input);
  await assertKlipperAgrees(name, gcode, stats.printTimeSeconds);
  return gcode;
}

test('Klipper batch mode accepts a spiral vase (Z rising along every turn)', { skip, timeout: 120_000 }, async () => {
  const gcode = await accepted('vase', box(0, 0, 0, 20, 20, 8), { spiralVase: true });
  // extrusions that move Z too: the spiral's turns, four sides each, over some 35 layers
  assert.ok((gcode.match(/^G1 [^;\n]*Z[\d.]+ E/gm) ?? []).length > 100, 'the turns rise as they go');
});

test('Klipper batch mode accepts a colour change and a pause (PAUSE)', { skip, timeout: 120_000 }, async () => {
  const gcode = await accepted('colour change', box(0, 0, 0, 15, 15, 6), { colorChangeAt: '2', pauseAt: '4' });
  assert.equal((gcode.match(/^PAUSE\b/gm) ?? []).length, 2, 'one PAUSE for the colour change, one for the pause');
});

test('Klipper batch mode accepts a plate printed one object at a time', { skip, timeout: 120_000 }, async () => {
  const objects = [
    { name: 'a', mesh: box(0, 0, 0, 10, 10, 5) },
    { name: 'b', mesh: box(0, 0, 0, 8, 8, 4) },
  ];
  const gcode = await accepted('sequential', objects, { sequentialPrinting: true });
  // Z goes back down once, to the second object's first layer
  const zs = [...gcode.matchAll(/^;Z:([\d.]+)$/gm)].map((m) => Number(m[1]));
  assert.equal(zs.filter((z, i) => i > 0 && z < zs[i - 1]).length, 1);
});
