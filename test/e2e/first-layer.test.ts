/**
 * The first layer on the bed under an open bottom: the Stanford bunny's mesh is open where it meets the bed and
 * its sections halfway up the first layer hold almost nothing (0.2 mm² at Z 0.1, 122 mm² at Z 0.3), so the first
 * layer takes the section above as well and the print starts on the bed, with a warning; a box's bottom is
 * whole, and is not touched.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { Slicer } from '#strata/api/slicer.js';
import { MODELS_DIR, modelsAvailable } from './models-dir.js';
import { box } from './test-meshes.js';

/** Length (mm) of the extrusion of model features (not skirt, brim, support) printed at Z `z`. */
function modelExtrusionAt(gcode: string, z: number): number {
  let x = 0,
    y = 0,
    cz = 0,
    e = 0,
    type = '',
    length = 0;
  for (const line of gcode.split('\n')) {
    if (line.startsWith(';TYPE:')) type = line.slice(6);
    const code = line.split(';')[0];
    if (!/^G[01] /.test(code)) continue;
    const get = (k: string) => {
      const m = new RegExp(` ${k}([-\\d.]+)`).exec(code);
      return m ? Number(m[1]) : null;
    };
    const nx = get('X') ?? x,
      ny = get('Y') ?? y,
      nz = get('Z') ?? cz,
      ne = get('E');
    const model = !/SKIRT|BRIM|SUPPORT|RAFT/.test(type);
    if (ne !== null && ne > e && (nx !== x || ny !== y) && model && Math.abs(nz - z) < 1e-3)
      length += Math.hypot(nx - x, ny - y);
    if (ne !== null) e = ne;
    x = nx;
    y = ny;
    cz = nz;
  }
  return length;
}

test('the open-bottomed bunny: its first layer is printed on the bed, with a warning', {
  skip: !modelsAvailable(),
  timeout: 300_000,
}, async () => {
  const { gcode, warnings } = await new Slicer({ threads: 1, extruderMode: 'absolute' }).slice(
    readFileSync(join(MODELS_DIR, 'stanford-bunny.stl')),
  );
  const first = modelExtrusionAt(gcode, 0.2);
  assert.ok(first >= 250, `${first.toFixed(0)} mm of model extrusion at Z 0.2`);
  assert.ok(
    warnings.some((w) => /bottom is open or too thin/.test(w)),
    warnings.join('\n'),
  );
});

test('a whole bottom is left as it is: no warning, the first layer as the box is', { timeout: 60_000 }, async () => {
  const { gcode, warnings } = await new Slicer({ threads: 1, center: false, extruderMode: 'absolute' }).slice(
    box(40, 40, 0, 60, 60, 2),
  );
  assert.ok(!warnings.some((w) => /bottom is open/.test(w)), warnings.join('\n'));
  assert.ok(modelExtrusionAt(gcode, 0.2) > 500);
});
