import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area, intersection } from '#strata/geometry/clip.js';
import { rect } from '../geometry/test-shapes.js';
import { supportArea, supported, type Box } from './test-models.js';

/**
 * A 20 mm block with a recess in its +x face: 1 mm deep, 4 mm wide, from z = `floor` up to 10 mm (the top of
 * an engraved letter's stroke). The recess's top overhangs; a tip and its XY gaps do not fit in 1 mm.
 */
function recessed(floor: number): Box[] {
  return [
    { x: [-10, 10], y: [-10, 10], z: [0, floor] },
    { x: [-10, 9], y: [-10, 10], z: [floor, 10] },
    { x: [9, 10], y: [-10, -2], z: [floor, 10] },
    { x: [9, 10], y: [2, 10], z: [floor, 10] },
    { x: [-10, 10], y: [-10, 10], z: [10, 20] },
  ];
}

/** The recess, µm, and a margin of half a line out of the face (where the column's edge may reach). */
const RECESS = rect(8_000, -2_000, 10_200, 2_000);

for (const floor of [8, 6.5]) {
  test(`tree support under the top of a recess ${10 - floor} mm tall stays in the recess, as normal support's column does, and holds its top`, () => {
    const tree = supported(recessed(floor), { supportType: 'tree' });
    const normal = supported(recessed(floor), { supportType: 'normal' });
    const { layers, cfg } = tree;
    let inRecess = 0;
    let tops = 0;
    for (let j = 0; j < layers.length; j++) {
      const s = supportArea(layers[j]);
      const total = area(s);
      const inside = area(intersection(s, [RECESS]));
      // before pockets, tips at the recess's mouth went down outside the face to the bed
      assert.ok(
        total - inside < 0.01e6,
        `layer ${j}: ${((total - inside) / 1e6).toFixed(2)} mm² of support outside the recess`,
      );
      inRecess += inside;
      const z = layers[j].z;
      if (z > 10 - (cfg.supportTopGapLayers + cfg.supportInterfaceLayers + 1) * cfg.layerHeight && z < 10)
        tops += inside;
    }
    assert.ok(inRecess > 0, 'no support in the recess');
    assert.ok(tops > 0, 'nothing right under the top of the recess');
    // the same as normal support there, layer by layer
    for (let j = 0; j < layers.length; j++) {
      const a = area(supportArea(layers[j])),
        b = area(supportArea(normal.layers[j]));
      assert.ok(
        Math.abs(a - b) < 0.01e6,
        `layer ${j}: tree ${(a / 1e6).toFixed(2)} mm², normal ${(b / 1e6).toFixed(2)} mm²`,
      );
    }
  });
}

for (const [why, options] of [
  ['with build-plate placement (none may stand on the part)', { supportPlacement: 'buildPlate' }],
  ['with no roof (the tips hold the part themselves)', { supportInterfaceLayers: 0 }],
] as const) {
  test(`${why}, a recess gets no column`, () => {
    const { layers } = supported(recessed(8), { supportType: 'tree', ...options });
    for (let j = 0; j < layers.length; j++)
      assert.equal(layers[j].support?.columnBody?.length ?? 0, 0, `a column on layer ${j}`);
    assert.ok(
      layers.some((l) => l.support),
      'no support at all',
    );
  });
}
