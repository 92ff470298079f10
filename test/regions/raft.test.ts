import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area, difference, offset } from '#strata/geometry/clip.js';
import { rect, square } from '../geometry/test-shapes.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { raftUnder } from '#strata/regions/raft.js';
import { layersOf } from '../support/test-layers.js';

test('a raft: base, interface and surface layers under the first layer and its support, grown by the margin, holes filled', () => {
  const cfg = resolveConfig({
    adhesionType: 'raft',
    raftMargin: 3,
    raftBaseThickness: 0.3,
    raftInterfaceLayers: 1,
    raftSurfaceLayers: 2,
    raftAirGap: 0.2,
  });
  const ring = { outer: square(0, 0, 20_000).outer, holes: [square(5_000, 5_000, 10_000).outer.slice().reverse()] };
  const [first] = layersOf(1, () => [ring], cfg);
  first.support = { body: [rect(30_000, 0, 35_000, 5_000)], roof: [], floor: [] };
  const raft = raftUnder(first, cfg);
  assert.deepEqual(
    raft.layers.map((l) => l.raft!.kind),
    ['base', 'interface', 'surface', 'surface'],
  );
  assert.deepEqual(
    raft.layers.map((l) => l.z),
    [0.3, 0.5, 0.7, 0.9],
  );
  assert.deepEqual(
    raft.layers.map((l) => l.height),
    [0.3, 0.2, 0.2, 0.2],
  );
  assert.equal(raft.zOffset, 1.1, 'raft top 0.9 mm plus the 0.2 mm air gap');
  const a = raft.layers[0].raft!.area;
  assert.equal(
    area(difference(offset([square(0, 0, 20_000)], 2_990, 'round'), a)),
    0,
    'covers the part (hole filled) and its margin',
  );
  assert.equal(area(difference([rect(30_000, 0, 35_000, 5_000)], a)), 0, 'covers the support');
  assert.ok(area(a) < area(offset([square(0, 0, 35_000)], 3_000)));
});

test('no raft unless asked for', () => {
  const cfg = resolveConfig({});
  const [first] = layersOf(1, () => [square(0, 0, 20_000)], cfg);
  assert.deepEqual(raftUnder(first, cfg), { layers: [], zOffset: 0 });
});
