import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { analyzePrint } from './checks.js';
import { parseGcode } from './gcode-parse.js';
import { GcodeWriter, writeBoxPrint } from './synthetic-print.js';
import { placeOnBed, readStl, toyGcode } from './toy-slicer.js';
import { skipWithoutModels } from '../../test/e2e/models-dir.js';

const OPTS = { layerHeight: 0.2, firstLayerHeight: 0.2, lineWidth: 0.4, filamentDiameter: 1.75 };

test('30 MB of G-code parses in about a second', () => {
  const writer = new GcodeWriter({ lineWidth: 0.4, filamentDiameter: 1.75, relativeE: true, markers: 'cura' });
  writeBoxPrint({
    size: [40, 40, 10],
    origin: [90, 90],
    layerHeight: 0.2,
    lineWidth: 0.4,
    walls: 2,
    skinLayers: 4,
    infillSpacing: 2,
    writer,
  });
  const one = writer.text();
  const text = one.repeat(Math.ceil(30e6 / one.length));
  const t0 = performance.now();
  const parsed = parseGcode(text);
  const ms = performance.now() - t0;
  console.log(`parsed ${(text.length / 1e6).toFixed(1)} MB in ${ms.toFixed(0)} ms`);
  assert.equal(parsed.layers.length, 50);
  // Generous bound for loaded CI machines; typically well under a second.
  assert.ok(ms < 5000, `${ms} ms`);
});

const CUBE = new URL('../../../../shared/models/CalibrationCube.stl', import.meta.url);

test('a real model against toy G-code from its own sections', { skip: skipWithoutModels() }, () => {
  const mesh = placeOnBed(readStl(readFileSync(CUBE)), 110, 110);
  const gcode = toyGcode(mesh, { ...OPTS, infillSpacing: 4, skinLayers: 4 });
  const report = analyzePrint(mesh, gcode, OPTS);
  const s = report.summary;
  assert.equal(s.layerCount, 100);
  assert.equal(s.expectedLayerCount, 100);
  assert.equal(s.missingLayerCount, 0);
  // The toy prints the outline itself as the wall: walled everywhere and within half a width of the model.
  assert.ok(s.walls.minCoverage! > 0.99, `walls ${s.walls.minCoverage}`);
  assert.ok(s.outside.maxMm < 1e-3, `outside ${s.outside.maxMm}`);
  assert.ok(s.shift.maxMm! < 0.02, `shift ${s.shift.maxMm}`);
  console.log(`analysed 100 layers in ${s.timingMs.analyse.toFixed(0)} ms`);
});
