import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { encode } from 'fast-png';
import { StrataError } from '#strata/errors.js';
import type { InfillParams } from '#strata/infill/types.js';
import { findInfiller, listInfillers, loadInfillerFile, shippedInfillersDir } from '#strata/shader/node-folder.js';
import { customInfillGenerator } from '#strata/infill/patterns/custom.js';
import { loadInfillers } from '#strata/shader/infiller.js';
import { compileShader, parseInfillParams } from '#strata/shader/shader.js';

const SQUARE = [
  {
    outer: [
      { x: 0, y: 0 },
      { x: 20000, y: 0 },
      { x: 20000, y: 20000 },
      { x: 0, y: 20000 },
    ],
    holes: [],
  },
];

test('the shipped infillers folder lists every infiller with kind and parameters', async () => {
  const list = await listInfillers(shippedInfillersDir());
  assert.deepEqual(
    list.map((i) => [i.name, i.kind]),
    [
      ['checker', 'shader'],
      ['example-image', 'image'],
      ['hexagon-grid', 'shader'],
      ['tpms-gyroid', 'shader'],
      ['tpms-schwarz-d', 'shader'],
      ['tpms-schwarz-p', 'shader'],
      ['voronoi-foam', 'shader'],
    ],
  );
  for (const i of list) assert.equal(i.error, undefined, `${i.name}: ${i.error}`);
  assert.equal(list.find((i) => i.name === 'checker')?.numPasses, 2);
  const hex = list.find((i) => i.name === 'hexagon-grid');
  assert.deepEqual(
    hex?.params?.map((p) => p.name),
    ['ui_side', 'ui_angle', 'ui_alternate'],
  );
  assert.match(hex?.params?.[0].tooltip ?? '', /Hexagon side/);
});

test('a folder in IceSL layout: shaders, images, broken entries reported', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'strata-infillers-'));
  try {
    mkdirSync(join(dir, 'stripes'));
    writeFileSync(
      join(dir, 'stripes', 'shader.glsl'),
      'uniform float ui_w = 2.0; // stripe width\nvec4 cellular(vec3 p) { return vec4(floor(p.x / ui_w)); }\n',
    );
    mkdirSync(join(dir, 'broken'));
    writeFileSync(join(dir, 'broken', 'shader.glsl'), 'vec4 cellular(vec3 p) {\n  return vec4(oops);\n}\n');
    mkdirSync(join(dir, 'picture'));
    writeFileSync(
      join(dir, 'picture', 'cells.png'),
      encode({
        width: 2,
        height: 2,
        data: Uint8Array.from([255, 0, 0, 0, 0, 255, 0, 0, 255, 255, 0, 0]),
        channels: 3,
        depth: 8,
      }),
    );
    mkdirSync(join(dir, 'empty'));
    const list = await listInfillers(dir);
    assert.deepEqual(
      list.map((i) => i.name),
      ['broken', 'picture', 'stripes'],
    );
    assert.match(list[0].error ?? '', /^broken\/shader\.glsl line 2: unknown identifier 'oops'/);
    assert.deepEqual(list[2].params, [{ name: 'ui_w', type: 'float', default: 2, tooltip: 'stripe width' }]);
    const stripes = await findInfiller('stripes', [dir]);
    const paths = stripes.paths({ region: SQUARE, z: 0.2, params: { w: 5 } });
    assert.equal(paths.length, 3);
    await assert.rejects(
      findInfiller('nope', [dir]),
      (e: unknown) => e instanceof StrataError && /unknown infiller 'nope'/.test(e.message),
    );
    const fromFile = await loadInfillerFile(join(dir, 'picture', 'cells.png'));
    assert.equal(fromFile.kind, 'image');
    assert.equal(fromFile.name, 'picture');
    const shaderFile = await loadInfillerFile(join(dir, 'stripes', 'shader.glsl'));
    assert.equal(shaderFile.kind, 'shader');
    assert.deepEqual(await listInfillers(join(dir, 'missing')), []);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('pure loading from file contents', () => {
  const { infillers, errors } = loadInfillers([
    { name: 'b', shader: 'vec4 cellular(vec3 p) { return vec4(step(0.0, sin(p.x))); }' },
    { name: 'a', shader: 'not glsl' },
  ]);
  assert.deepEqual(
    infillers.map((i) => i.name),
    ['b'],
  );
  assert.equal(errors[0].name, 'a');
  assert.equal(errors[0].error.code, 'BAD_SHADER');
});

test('registry adapter: generate() signature, density from the settings, --infill-param parsing', async () => {
  const hex = await findInfiller('hexagon-grid');
  const params: InfillParams = {
    density: 0.2,
    lineWidthUm: 400,
    nozzleDiameterUm: 400,
    angle: 45,
    centering: 'object',
    origin: { x: 0, y: 0 },
    connect: false,
  };
  const layer = { layerIndex: 3, zMm: 0.8, layerHeightMm: 0.2, region: SQUARE };
  const gen = customInfillGenerator(hex, { params: parseInfillParams(hex.params, ['angle=30', 'ui_alternate=true']) });
  const res = gen(layer, params);
  assert.ok(res.lines.length > 10);
  assert.deepEqual(res.loops, []);
  const denser = customInfillGenerator(hex)(layer, { ...params, density: 0.4 });
  const len = (ls: typeof res.lines) =>
    ls.reduce((s, p) => s + p.slice(1).reduce((t, q, i) => t + Math.hypot(q.x - p[i].x, q.y - p[i].y), 0), 0);
  assert.ok(len(denser.lines) > 1.6 * len(res.lines));
  // Per-layer density list and a density shader.
  const perLayer = customInfillGenerator(hex, { density: [10, 10, 10, 40] })(layer, params);
  assert.ok(len(perLayer.lines) > 1.6 * len(res.lines));
  const field = compileShader('float density(vec3 p) { return p.x < 10.0 ? 10.0 : 40.0; }', { entry: 'density' });
  assert.ok(customInfillGenerator(hex, { density: field })(layer, params).lines.length > 0);
  assert.throws(() => parseInfillParams(hex.params, ['nope=1']), /unknown infill parameter 'nope'/);
  assert.throws(() => parseInfillParams(hex.params, ['ui_alternate=maybe']), /must be true or false/);
  assert.throws(() => parseInfillParams(hex.params, ['side']), /NAME=VALUE/);
  assert.throws(
    () => customInfillGenerator(hex, { params: { bogus: 1 } }),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING',
  );
});
