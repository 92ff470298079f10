/**
 * The G-code of the shared models, held by its SHA-256: a restructuring that means to change nothing
 * must leave every hash as it is. A change that means to change the G-code updates the hashes in the
 * same commit, on purpose:
 *
 *   STRATA_UPDATE_HASHES=1 node --test dist-dev/test/e2e/gcode-hashes.test.js
 *
 * rewrites test/e2e/gcode-hashes.json (the commit's diff then shows which prints changed).
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Slicer } from '#strata/api/slicer.js';
import type { CustomInfillSpec, SliceOptions } from '#strata/index.js';
import { readModel, skipWithoutModels } from './models.js';

const skip = skipWithoutModels();
const INFILLERS = fileURLToPath(new URL('../../../infillers/', import.meta.url));
const HASH_FILE = fileURLToPath(new URL('../../../test/e2e/gcode-hashes.json', import.meta.url));
const update = process.env.STRATA_UPDATE_HASHES === '1';

/** Each case: a name, the models on the plate, the settings. */
const CASES: Array<[string, string[], SliceOptions & { customInfill?: CustomInfillSpec }]> = [
  ['CalibrationCube', ['CalibrationCube.stl'], {}],
  ['HollowCalibrationCube', ['HollowCalibrationCube.stl'], {}],
  ['HoleTest', ['HoleTest.stl'], {}],
  ['Overhang', ['Overhang.stl'], {}],
  ['SupportTest support', ['SupportTest.stl'], { supportEnabled: true }],
  ['SupportTest tree raft', ['SupportTest.stl'], { supportEnabled: true, supportType: 'tree', adhesionType: 'raft' }],
  ['BridgeTest', ['BridgeTest.stl'], {}],
  [
    'spot lightning support',
    ['spot.stl'],
    { supportEnabled: true, supportPlacement: 'buildPlate', infillPattern: 'lightning' },
  ],
  ['stanford-bunny klipper arcs', ['stanford-bunny.stl'], { gcodeFlavor: 'klipper', arcFitting: true }],
  ['3DBenchy', ['3DBenchy.stl.gz'], {}],
  [
    '3DBenchy gyroid brim classic walls',
    ['3DBenchy.stl.gz'],
    { infillPattern: 'gyroid', adhesionType: 'brim', wallGenerator: 'classic' },
  ],
  ['two objects', ['BridgeTest.stl', 'CalibrationCube.stl'], { supportEnabled: true, labelObjects: 'firmware' }],
  [
    'CalibrationCube voronoi-foam shader',
    ['CalibrationCube.stl'],
    {
      infillDensity: 15,
      customInfill: { name: 'voronoi-foam', shader: readFileSync(`${INFILLERS}voronoi-foam/shader.glsl`, 'utf8') },
    },
  ],
  [
    'CalibrationCube image cells',
    ['CalibrationCube.stl'],
    {
      customInfill: {
        name: 'example-image',
        image: new Uint8Array(readFileSync(`${INFILLERS}example-image/cells.png`)),
      },
    },
  ],
];

function sha256(text: string): string {
  return createHash('sha256').update(text).digest('hex');
}

test('the G-code of the shared models is what the hashes hold', { skip, timeout: 600_000 }, async () => {
  const held = JSON.parse(readFileSync(HASH_FILE, 'utf8')) as Record<string, string>;
  const now: Record<string, string> = {};
  for (const [name, models, options] of CASES) {
    const input = models.length === 1 ? readModel(models[0]) : models.map((m) => readModel(m));
    const { gcode } = await new Slicer({ threads: 1, ...options }).slice(input);
    assert.ok(gcode.length > 10_000, `${name}: a print`);
    now[name] = sha256(gcode);
  }
  if (update) {
    writeFileSync(HASH_FILE, JSON.stringify(now, null, 2) + '\n');
    return;
  }
  const changed = CASES.map(([name]) => name).filter((name) => held[name] !== now[name]);
  assert.deepEqual(
    changed,
    [],
    `G-code changed for: ${changed.join(', ')} (if on purpose: STRATA_UPDATE_HASHES=1 node --test dist-dev/test/e2e/gcode-hashes.test.js)`,
  );
});
