/** Same input and settings give byte-identical G-code, whatever the thread count; E modes agree. */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { analyzePrint } from '../../tools/analysis/checks.js';
import { prepareModel } from '#strata/api/slicer.js';
import { skipWithoutModels, readModel } from './models.js';

const skip = skipWithoutModels();

for (const name of ['CalibrationCube.stl', 'HoleTest.stl']) {
  test(`${name}: identical G-code on 1 and 2 threads, and on a second run`, { skip, timeout: 300_000 }, async () => {
    const bytes = readModel(name);
    const one = await new Slicer({ threads: 1 }).slice(bytes);
    const two = await new Slicer({ threads: 2 }).slice(bytes);
    const again = await new Slicer({ threads: 2 }).slice(bytes);
    assert.ok(one.gcode.length > 1000);
    assert.ok(one.gcode === two.gcode, 'threads 1 vs 2');
    assert.ok(two.gcode === again.gcode, 'run to run');
  });
}

for (const [name, options] of [
  ['SupportTest.stl', { supportEnabled: true }],
  ['SupportTest.stl', { supportEnabled: true, supportType: 'tree', adhesionType: 'raft' }],
  ['spot.stl', { supportEnabled: true, supportPlacement: 'buildPlate', infillPattern: 'lightning' }],
] as const) {
  test(`${name} ${JSON.stringify(options)}: identical G-code on 1, 2 and 3 threads`, {
    skip,
    timeout: 300_000,
  }, async () => {
    const bytes = readModel(name);
    const one = await new Slicer({ threads: 1, ...options }).slice(bytes);
    const two = await new Slicer({ threads: 2, ...options }).slice(bytes);
    const three = await new Slicer({ threads: 3, ...options }).slice(bytes);
    assert.match(one.gcode, /;TYPE:SUPPORT/);
    assert.ok(one.gcode === two.gcode, 'threads 1 vs 2');
    assert.ok(one.gcode === three.gcode, 'threads 1 vs 3');
  });
}

// Slices in one process share its modules: nothing one slice leaves in them (a cache, a working buffer) may reach
// another. Two slices at once take turns at every await; each must write what it writes alone.
test('two slices at once in one process each give the G-code they give alone', { skip, timeout: 300_000 }, async () => {
  const hole = readModel('HoleTest.stl');
  const cube = readModel('CalibrationCube.stl');
  const cubeOptions = { infillPattern: 'gyroid', infillDensity: 30, wallCount: 3 } as const;
  for (const threads of [1, 2]) {
    const aloneHole = (await new Slicer({ threads }).slice(hole)).gcode;
    const aloneCube = (await new Slicer({ threads, ...cubeOptions }).slice(cube)).gcode;
    const [withHole, withCube] = await Promise.all([
      new Slicer({ threads }).slice(hole),
      new Slicer({ threads, ...cubeOptions }).slice(cube),
    ]);
    assert.ok(aloneHole !== aloneCube);
    assert.ok(withHole.gcode === aloneHole, `HoleTest beside the cube, ${threads} thread(s)`);
    assert.ok(withCube.gcode === aloneCube, `the cube beside HoleTest, ${threads} thread(s)`);
  }
});

test('absolute and relative E give the same filament total', { skip, timeout: 120_000 }, async () => {
  const bytes = readModel('CalibrationCube.stl');
  // start and end G-code without extrusion, so the file's E is exactly the print's
  const plain = { threads: 1, startGcode: 'G28', endGcode: 'M84' };
  const abs = new Slicer({ ...plain, extruderMode: 'absolute' });
  const rel = new Slicer({ ...plain, extruderMode: 'relative' });
  const a = await abs.slice(bytes);
  const r = await rel.slice(bytes);
  const mesh = prepareModel(bytes, abs.config).mesh;
  const opts = { layerHeight: 0.2, firstLayerHeight: 0.2, lineWidth: 0.4, filamentDiameter: 1.75 };
  const ea = analyzePrint(mesh, a.gcode, opts).summary.e;
  const er = analyzePrint(mesh, r.gcode, opts).summary.e;
  assert.equal(ea.mode, 'absolute');
  assert.equal(er.mode, 'relative');
  assert.ok(Math.abs(ea.net - er.net) < 1e-3 * ea.net, `net E ${ea.net} vs ${er.net}`);
  const printed = ea.net + ea.balance.trailingMm;
  assert.ok(
    Math.abs(printed - a.stats.filamentMm) < 0.005 * printed,
    `stats filament ${a.stats.filamentMm} vs parsed ${printed}`,
  );
});
