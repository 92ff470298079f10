/** Custom IceSL-style infill through the whole pipeline: API and CLI, on one and two threads. */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { Slicer } from '#strata/index.js';
import { StrataError } from '#strata/errors.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { featureLengths } from '../../tools/analysis/layer-report.js';

const root = fileURLToPath(new URL('../../../', import.meta.url));
const cube = readFileSync(root + 'examples/calibration-cube.stl');
const STRIPES = `
uniform float ui_spacing = 3.0; // stripe spacing in mm
vec4 cellular(vec3 world) {
  float k = floor(world.x / ui_spacing);
  return vec4(mod(k, 2.0), 0.0, 0.0, 1.0);
}`;

/** Length of FILL extrusion (mm), from the independent analyser's G-code parser. */
function fillLength(gcode: string): number {
  return parseGcode(gcode).layers.reduce((sum, layer) => sum + (featureLengths(layer).FILL ?? 0), 0);
}

test('a shader infiller replaces the pattern, its ui_ parameter changes the paths, threads agree', async () => {
  const base = { infillDensity: 20, adhesionType: 'none' as const };
  const a = await new Slicer({ ...base, threads: 1, customInfill: { name: 'stripes', shader: STRIPES } }).slice(cube);
  const b = await new Slicer({ ...base, threads: 2, customInfill: { name: 'stripes', shader: STRIPES } }).slice(cube);
  const c = await new Slicer({
    ...base,
    threads: 1,
    customInfill: { name: 'stripes', shader: STRIPES, params: { spacing: 1.5 } },
  }).slice(cube);
  assert.ok(a.gcode === b.gcode, 'identical for 1 and 2 threads');
  const la = fillLength(a.gcode),
    lc = fillLength(c.gcode);
  assert.ok(la > 100, `fill printed: ${la} mm`);
  assert.ok(lc > 1.6 * la, `half the spacing, about twice the lines: ${la} → ${lc}`);
});

test('a broken shader is a clear error at construction', () => {
  assert.throws(
    () =>
      new Slicer({ customInfill: { name: 'bad', shader: 'vec4 cellular(vec3 w) { return vec4(undefinedThing); }' } }),
    (e: unknown) => e instanceof StrataError && /bad|line/.test(e.message),
  );
});

test('CLI: a shipped infiller by name, with a parameter', () => {
  const out = root + 'dist-dev/test/e2e/hexagon.gcode';
  const r = spawnSync(
    process.execPath,
    [
      root + 'dist/cli/main.js',
      'slice',
      root + 'examples/calibration-cube.stl',
      '--infill-pattern',
      'hexagon-grid',
      '--infill-param',
      'side=3',
      '-o',
      out,
      '--threads',
      '1',
    ],
    { encoding: 'utf8' },
  );
  assert.equal(r.status, 0, r.stderr);
  assert.ok(fillLength(readFileSync(out, 'utf8')) > 100);
});

test('density() from a JS field, a per-layer list and a density shader changes the paths', async () => {
  const VORONOI = readFileSync(root + 'infillers/voronoi-foam/shader.glsl', 'utf8');
  const run = async (density: unknown, threads = 2) =>
    fillLength(
      (
        await new Slicer({
          threads,
          adhesionType: 'none',
          customInfill: { name: 'foam', shader: VORONOI, density: density as never },
        }).slice(cube)
      ).gcode,
    );
  const sparse = await run(10),
    dense = await run(40);
  assert.ok(dense > 1.5 * sparse, `40 % prints more than 10 %: ${sparse} → ${dense}`);
  // a JS field runs on the calling thread (functions cannot travel to workers) and still works
  const field = await run((x: number) => (x < 110 ? 10 : 40));
  assert.ok(field > sparse * 1.2 && field < dense * 0.9, `graded field between the two: ${field}`);
  const shader = await run({ shader: 'float density(vec3 w) { return w.x < 110.0 ? 10.0 : 40.0; }' });
  assert.ok(Math.abs(shader - field) < 0.1 * field, `shader field ${shader} ≈ JS field ${field}`);
  const layers = await run(Array.from({ length: 100 }, (_, i) => (i < 50 ? 10 : 40)));
  assert.ok(layers > sparse * 1.2 && layers < dense * 0.9, `per-layer list between the two: ${layers}`);
});
