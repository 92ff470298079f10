import { test } from 'node:test';
import assert from 'node:assert/strict';
import { plateSetup, type PlacedObject } from '#strata/pipeline/print-setup.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { StrataError } from '#strata/errors.js';
import type { Mesh } from '#strata/mesh/types.js';

function box(x0: number, y0: number, x1: number, y1: number, z1 = 10): Mesh {
  const p: number[] = [];
  for (const [x, y, z] of [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [1, 1, 1],
    [0, 1, 1],
  ])
    p.push(x ? x1 : x0, y ? y1 : y0, z ? z1 : 0);
  return {
    positions: new Float32Array(p),
    indices: new Uint32Array([
      0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
    ]),
  };
}
const cfg = resolveConfig({});
const plate = (objects: PlacedObject[]) => plateSetup(objects, {}, cfg);

test('objects without settings of their own read the print config, one mesh each', () => {
  const { setup, meshes, objects } = plate([
    { name: 'a', mesh: box(0, 0, 10, 10) },
    { name: 'b', mesh: box(20, 0, 30, 10) },
  ]);
  assert.equal(setup.configs.length, 1);
  assert.deepEqual(
    setup.objects.map((o) => [o.parts, o.config, o.regions]),
    [
      [0, 0, [[0]]],
      [1, 0, [[0]]],
    ],
  );
  assert.equal(meshes.length, 2);
  assert.equal(objects.length, 2);
});

test('overlapping twins become one object; overlapping objects with different settings are checked layer by layer', () => {
  const twins = plate([
    { name: 'a', mesh: box(0, 0, 10, 10) },
    { name: 'b', mesh: box(5, 0, 15, 10) },
    { name: 'c', mesh: box(40, 0, 50, 10) },
  ]);
  assert.deepEqual(
    twins.objects.map((o) => o.name),
    ['a + b', 'c'],
  );
  assert.equal(twins.meshes[0].indices.length, 72);
  assert.match(twins.warnings.join('\n'), /a, b overlap .* print as one object/);
  const different = plate([
    { name: 'a', mesh: box(0, 0, 10, 10) },
    { name: 'b', mesh: box(5, 0, 15, 10), settings: { infillDensity: 50 } },
  ]);
  assert.equal(different.objects.length, 2);
  assert.deepEqual(different.setup.overlapPairs, [[0, 1]]);
});

test('each layer range and modifier resolves once over the object, alike configs shared', () => {
  const { setup, meshes } = plate([
    {
      name: 'a',
      mesh: box(0, 0, 10, 10),
      settings: { infillDensity: 30 },
      volumes: [
        { kind: 'modifier', name: 'm1', mesh: box(0, 0, 5, 5), settings: { infillDensity: 80 } },
        { kind: 'negative', name: 'hole', mesh: box(4, 4, 6, 6) },
        { kind: 'modifier', name: 'm2', mesh: box(5, 5, 10, 10), settings: { infillDensity: 30 } },
        { kind: 'support-blocker', name: 'b', mesh: box(0, 0, 2, 2) },
      ],
      layerRanges: [{ fromZ: 2, toZ: 4, settings: { infillDensity: 80 } }],
    },
  ]);
  const o = setup.objects[0];
  assert.deepEqual([o.parts, o.negatives, o.modifiers, o.blockers, o.enforcers], [0, [1], [2, 3], [4], []]);
  assert.equal(meshes.length, 5);
  const density = (r: number, m: number) => setup.configs[o.regions[r][m]].infillDensity;
  assert.deepEqual(
    [density(0, 0), density(0, 1), density(0, 2), density(1, 0), density(1, 1), density(1, 2)],
    [30, 80, 30, 80, 80, 30],
  );
  // the object's 30 % and m2's are one config, the modifier's and the range's 80 % another
  assert.equal(o.regions[0][2], o.config);
  assert.equal(o.regions[1][0], o.regions[0][1]);
  assert.equal(setup.configs.length, 3);
});

test('settings that cannot vary there are refused, naming the object', () => {
  assert.throws(
    () => plate([{ name: 'cup', mesh: box(0, 0, 1, 1), settings: { nozzleTemperature: 190 } }]),
    (e: unknown) =>
      e instanceof StrataError && /object "cup": nozzleTemperature is the same for the whole print/.test(e.message),
  );
  // the layer height may vary between layer ranges (the plate's Z plan), not between objects
  assert.throws(
    () => plate([{ name: 'cup', mesh: box(0, 0, 1, 1), settings: { layerHeight: 0.1 } }]),
    (e: unknown) =>
      e instanceof StrataError &&
      /object "cup": layerHeight is the same for every object at one height, so it cannot be set for an object; set it for the print or a layer range instead/.test(
        e.message,
      ),
  );
  assert.doesNotThrow(() =>
    plate([
      { name: 'cup', mesh: box(0, 0, 1, 1), layerRanges: [{ fromZ: 0.4, toZ: 0.8, settings: { layerHeight: 0.1 } }] },
    ]),
  );
  assert.throws(
    () =>
      plate([
        {
          name: 'cup',
          mesh: box(0, 0, 1, 1),
          volumes: [{ kind: 'modifier', name: 'm', mesh: box(0, 0, 1, 1), settings: { supportEnabled: true } }],
        },
      ]),
    /modifier "m" of "cup": supportEnabled may vary per object but not inside one/,
  );
});
