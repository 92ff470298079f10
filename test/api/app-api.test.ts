/**
 * The public API an app (the web page) builds on besides `Slicer`: both entries export the same names, by the
 * package's name; a worker listens first; settings are checked one at a time in the slicer's words; a volume
 * moves with its object; a project saves the print settings given; a custom infiller describes itself.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import * as node from 'strata-slicer';
import { listenFirst } from 'strata-slicer/worker';
import * as browser from '#strata/browser.js';

const ROOT = fileURLToPath(new URL('../../../', import.meta.url));

/** What the web page takes from the library, besides what the API had before it used the library alone. */
const APP_NAMES = [
  'checkSettingKey',
  'validateSetting',
  'checkSettingScope',
  'resolveScopedConfig',
  'settingsFromSource',
  'loadModelFile',
  'mergeObjects',
  'IDENTITY_LINEAR',
  'axisRotation',
  'linearBounds',
  'multiplyLinear',
  'placeObjects',
  'placementAffine',
  'rotationBetween',
  'transformMesh',
  'ARRANGE_GAP_MM',
  'arrange',
  'findSpot',
  'footprintsOverlap',
  'estimatePlan',
  'describeCustomInfill',
  'previewTransferList',
  'FEATURE_COLOURS',
  'sendToPrinter',
  'HOST_KINDS',
];

test('the Node and browser entries export the same names, the page’s among them', () => {
  assert.deepEqual(Object.keys(browser).sort(), Object.keys(node).sort());
  for (const name of APP_NAMES) assert.ok(name in node, `${name} is exported`);
  // the Node entry sends over node:http, the browser's over XMLHttpRequest
  assert.notEqual(node.sendToPrinter, browser.sendToPrinter);
});

test('listenFirst keeps what arrives before its handler, in order', async () => {
  const scope: { onmessage: ((e: { data: number }) => void) | null } = { onmessage: null };
  const got: number[] = [];
  let ready!: () => void;
  const loaded = new Promise<void>((r) => (ready = r));
  listenFirst(scope, async () => {
    await loaded;
    return (n: number) => got.push(n);
  });
  scope.onmessage!({ data: 1 });
  scope.onmessage!({ data: 2 });
  ready();
  await new Promise((r) => setTimeout(r, 0));
  scope.onmessage!({ data: 3 });
  assert.deepEqual(got, [1, 2, 3]);
});

test("settings one at a time: a name, a value, where it may be given, and a part's config, in the slicer's words", () => {
  assert.equal(node.checkSettingKey('infillDensity'), 'infillDensity');
  assert.throws(() => node.checkSettingKey('infilDensity', 'setting'), {
    name: 'StrataError',
    code: 'UNKNOWN_SETTING',
    message: /unknown setting "infilDensity" \(did you mean "infillDensity"\?\)/,
  });
  assert.equal(node.validateSetting('infillDensity', 30), 30);
  assert.throws(() => node.validateSetting('infillDensity', 300, 'setting'), {
    code: 'BAD_SETTING',
    message: /^setting infillDensity = 300 is not allowed: expected a number from 0 to 100/,
  });
  // the same words as the slicer's for the same mistake
  const slicerSays = (() => {
    try {
      new node.Slicer({ infillDensity: 300 });
    } catch (e) {
      return (e as Error).message;
    }
  })();
  assert.throws(() => node.validateSetting('infillDensity', 300), { message: slicerSays });

  node.checkSettingScope('infillDensity', 'modifier', 'modifier "m"');
  assert.throws(() => node.checkSettingScope('nozzleTemperature', 'object', 'object "cube"'), {
    code: 'BAD_SETTING',
    message: /^object "cube": nozzleTemperature is the same for the whole print/,
  });

  const options = { printer: 'prusa-mk4', infillDensity: 15 } as const;
  const layers = [
    { settings: { infillDensity: 40 }, use: 'object' as const, where: 'object "cube"' },
    { settings: { infillDensity: 90 }, use: 'modifier' as const, where: 'modifier "m" of "cube"' },
  ];
  assert.equal(node.resolveScopedConfig(options, layers).infillDensity, 90);
  assert.equal(node.resolveScopedConfig(options, layers.slice(0, 1)).infillDensity, 40);
  assert.deepEqual(node.resolveScopedConfig(options, []), node.resolveConfig(options));
  assert.throws(
    () =>
      node.resolveScopedConfig(options, [
        { settings: { topSkinThickness: 2 }, use: 'modifier', where: 'modifier "m" of "cube"' },
      ]),
    { code: 'BAD_SETTING', message: /modifier "m" of "cube"/ },
  );
});

test('a volume moves with its object: transformMesh, mirrored triangles turned to face outwards', () => {
  const tri = { positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]), indices: new Uint32Array([0, 1, 2]) };
  const placement = {
    linear: node.multiplyLinear(node.axisRotation('z', 90), [2, 0, 0, 0, 2, 0, 0, 0, 2]),
    center: [50, 60] as const,
  };
  const affine = node.placementAffine(placement, node.linearBounds(tri.positions, placement.linear));
  const moved = node.transformMesh(tri, affine);
  assert.deepEqual([...moved.positions], [51, 59, 0, 51, 61, 0, 49, 59, 0]);
  assert.deepEqual([...moved.indices], [0, 1, 2]);
  assert.notEqual(moved.indices, tri.indices, 'new arrays');
  const mirror = Float64Array.of(-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0);
  assert.deepEqual([...node.transformMesh(tri, mirror).indices], [0, 2, 1]);
});

test('saveProject keeps the print settings given (placement ones as done), and loadModelFile reads them back', async () => {
  const stl = new Uint8Array(readFileSync(`${ROOT}examples/calibration-cube.stl`));
  const slicer = new node.Slicer({ wallCount: 3, rotateZ: 90 });
  const printSettings = { printer: 'creality-ender-3', filament: 'pla', wallCount: 3, rotateZ: 90 };
  const project = await slicer.saveProject(stl, { printSettings });
  const file = node.loadModelFile(project, 'cube.3mf');
  assert.equal(file.objects.length, 1);
  assert.equal(file.projectSettings?.format, 'strata');
  const saved = file.projectSettings!.values;
  assert.deepEqual(
    Object.keys(saved).sort(),
    [...Object.keys(printSettings), 'upAxis', 'rotateX', 'rotateY', 'scale', 'scaleX', 'scaleY', 'scaleZ'].sort(),
  );
  assert.equal(saved.wallCount, 3);
  assert.equal(saved.rotateZ, 0, 'the object is saved turned already');
  const mapped = node.settingsFromSource(file.projectSettings!);
  assert.equal(mapped.settings.wallCount, 3);
  // by default every setting as resolved
  const every = node.loadModelFile(await slicer.saveProject(stl), 'cube.3mf').projectSettings!.values;
  assert.ok(Object.keys(every).length > 100);
});

test('describeCustomInfill: a shipped shader with its ui_ parameters; a broken one refused in words', async () => {
  const shader = readFileSync(`${ROOT}infillers/hexagon-grid/shader.glsl`, 'utf8');
  const info = await node.describeCustomInfill({ name: 'hexagon-grid', shader });
  assert.equal(info.kind, 'shader');
  assert.equal(info.name, 'hexagon-grid');
  assert.ok(info.params.length > 0);
  for (const p of info.params) assert.ok(['bool', 'int', 'float'].includes(p.type), p.name);
  await assert.rejects(node.describeCustomInfill({ name: 'bad', shader: 'float cellular(vec3 p) { return nope; }' }), {
    name: 'StrataError',
  });
});
