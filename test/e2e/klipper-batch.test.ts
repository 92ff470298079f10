/**
 * Strata's Klipper-flavour G-code through Klipper itself (klippy's batch mode, see klipper.ts): every
 * command accepted (none unknown, no move refused), and Strata's time estimate (the `;TIME_ELAPSED:` of its
 * last layer, what M73 and `; estimated printing time` come from) within 2 % of the print time of Klipper's
 * own planner for the same limits (klipper/printer.cfg, KLIPPER_CONFIG_SETTINGS). Skips without klippy,
 * except under CI (.ci/klipper.sh installs it).
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { Slicer } from '#strata/api/slicer.js';
import { assertKlipperAgrees, KLIPPER_CONFIG_SETTINGS, skipWithoutKlipper } from './klipper.js';
import { MODELS_DIR, skipWithoutModels } from './models-dir.js';

const skip = skipWithoutKlipper() || skipWithoutModels();

/** The settings that describe klipper/printer.cfg's printer to Strata. */
const PRINTER = { ...KLIPPER_CONFIG_SETTINGS, maxSpeedE: null, maxAccelerationE: null, threads: 1 };

function lastElapsed(gcode: string): number {
  const all = [...gcode.matchAll(/^;TIME_ELAPSED:([\d.]+)$/gm)];
  assert.ok(all.length > 0, 'no ;TIME_ELAPSED: line');
  return Number(all[all.length - 1]![1]);
}

async function check(model: string, options: Record<string, unknown> = {}): Promise<void> {
  const { gcode, stats } = new Slicer({ ...PRINTER, ...options }).sliceSync(readFileSync(join(MODELS_DIR, model)));
  const strata = lastElapsed(gcode);
  assert.ok(
    Math.abs(strata - stats.printTimeSeconds) < 1,
    `${model}: the G-code's time ${strata} s is the estimate's ${stats.printTimeSeconds} s`,
  );
  await assertKlipperAgrees(model, gcode, strata);
}

test('Klipper batch mode: the calibration cube is accepted and its estimate within 2 % of Klipper', {
  skip,
  timeout: 120_000,
}, async () => {
  await check('CalibrationCube.stl');
});

test('Klipper batch mode: the overhang test with arcs (G2/G3) and firmware retraction (G10/G11) is accepted and its estimate within 2 %', {
  skip,
  timeout: 120_000,
}, async () => {
  // printer.cfg's [firmware_retraction]: 0.8 mm at 35 mm/s
  await check('Overhang.stl', {
    arcFitting: true,
    firmwareRetraction: true,
    retractionDistance: 0.8,
    retractionSpeed: 35,
  });
});

test('Klipper batch mode: a print with its limits written (SET_VELOCITY_LIMIT) is accepted and its estimate within 2 %', {
  skip,
  timeout: 120_000,
}, async () => {
  // klippy 0.12.0.dev283 keeps printer.cfg's max_accel_to_decel (1500) under a lower ACCEL: 2000 × (1 − 0.25)
  await check('HollowCalibrationCube.stl', {
    machineLimits: 'write',
    maxSpeedX: 200,
    maxSpeedY: 200,
    acceleration: 2000,
    cornerVelocity: 8,
    minimumCruiseRatio: 0.25,
  });
});
