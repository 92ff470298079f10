import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area, difference, intersection, offset, union } from '#strata/geometry/clip.js';
import { disc, rect, square } from '../geometry/test-shapes.js';
import type { ExPolygon } from '#strata/geometry/types.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { supportPass } from '#strata/support/index.js';
import { drain, layersOf } from './test-layers.js';

const all = (l: { support: { body: ExPolygon[]; roof: ExPolygon[]; floor: ExPolygon[] } | null }) =>
  l.support ? union([...l.support.body, ...l.support.roof, ...l.support.floor]) : [];

// a 20 mm table top (layers 40..49) on a 4 mm post in its middle
const post = square(8_000, 8_000, 4_000);
const top = square(0, 0, 20_000);
const table = (j: number) => (j < 40 ? [post] : j < 50 ? [top] : []);

test('normal support: columns under the overhang, the XY gap from the post, the top Z gap, roof layers under the part', () => {
  const cfg = resolveConfig({ supportEnabled: true, supportZGap: 0.2, supportInterfaceLayers: 2, supportXYGap: 0.6 });
  const layers = layersOf(50, table, cfg);
  drain(supportPass(layers, cfg));
  // the layer right under the table top is the Z gap: empty; the two below have roof only, the rest body
  assert.equal(layers[39].support, null, 'top Z gap');
  for (const j of [37, 38]) {
    const s = layers[j].support!;
    assert.ok(area(s.roof) > 0.9 * (area([top]) - area(offset([post], 600))), `roof on layer ${j}`);
    assert.equal(area(intersection(s.body, [top])), 0, `no body under the part on roof layer ${j}`);
  }
  for (const j of [0, 10, 36]) {
    const s = all(layers[j]);
    // holds up the table top all round the post (and half a line beyond its edge), keeps 0.6 mm from it
    const expected = area(offset([top], 200)) - area(offset([post], 600));
    assert.ok(
      Math.abs(area(s) - expected) / expected < 0.03,
      `layer ${j}: support ${area(s) / 1e6} mm², expected ${expected / 1e6}`,
    );
    assert.equal(area(intersection(s, offset([post], 590))), 0, `layer ${j}: XY gap`);
    assert.ok(layers[j].support!.body.length > 0, `layer ${j}: body`);
  }
  // nothing above the part or beside the table top
  for (let j = 40; j < 50; j++) assert.equal(layers[j].support, null);
});

test('support stands on the part in everywhere placement (bottom gap and floor), not at all in buildPlate placement', () => {
  // a ledge at layers 30..39 over a lower step (layers 0..9) that sticks out under it
  const column = rect(0, 0, 5_000, 10_000);
  const step = rect(0, 0, 15_000, 10_000);
  const ledge = rect(0, 0, 15_000, 10_000);
  const at = (j: number) => (j < 10 ? [step] : j < 30 ? [column] : j < 40 ? [ledge] : []);
  const everywhere = resolveConfig({ supportEnabled: true, supportFloorLayers: 2, supportBottomZGap: 0.2 });
  const a = layersOf(40, at, everywhere);
  drain(supportPass(a, everywhere));
  assert.equal(a[10].support, null, 'bottom Z gap above the step');
  assert.ok(a[11].support && area(a[11].support.floor) > 0, 'floor on the step');
  assert.ok(a[20].support && area(a[20].support.body) > 40e6, 'body between step and ledge');
  for (let j = 0; j < 10; j++) assert.equal(a[j].support, null, `no support inside the step (layer ${j})`);
  const plate = resolveConfig({ supportEnabled: true, supportPlacement: 'buildPlate' });
  const b = layersOf(40, at, plate);
  drain(supportPass(b, plate));
  assert.ok(
    b.every((l) => l.support === null),
    'buildPlate: the ledge stands over the step, so nothing reaches the bed',
  );
});

test('support reaches under a sloping surface (a cone standing on its tip), close to it but never inside', () => {
  // radius grows 0.4 mm per 0.2 mm layer: ~63° from vertical, beyond the 50° threshold
  const cone = (j: number) => (j < 40 ? [disc(20_000, 20_000, 1_000 + 400 * j)] : []);
  const cfg = resolveConfig({ supportEnabled: true });
  const layers = layersOf(40, cone, cfg);
  drain(supportPass(layers, cfg));
  let over = 0,
    held = 0;
  for (let j = 2; j < 40; j++) {
    const o = layers[j].overhang;
    over += area(o);
    const under = [...all(layers[j - 2]), ...cone(j - 2)];
    held += area(intersection(o, union(under)));
    assert.equal(area(intersection(all(layers[j]), cone(j))), 0, `layer ${j}: support inside the cone`);
  }
  assert.ok(held / over > 0.9, `overhang held ${((100 * held) / over).toFixed(1)} %`);
});

test('short bridges are left unsupported when supportSkipBridges allows their span', () => {
  // two pillars 6 mm apart joined by a bridge at layer 20
  const pillars = [rect(0, 0, 4_000, 10_000), rect(10_000, 0, 14_000, 10_000)];
  const at = (j: number) => (j < 20 ? pillars : j < 25 ? [rect(0, 0, 14_000, 10_000)] : []);
  const on = resolveConfig({ supportEnabled: true });
  const a = layersOf(25, at, on);
  drain(supportPass(a, on));
  assert.ok(a[10].support && area(difference(all(a[10]), pillars)) > 30e6, 'the bridge is supported by default');
  const skip = resolveConfig({ supportEnabled: true, supportSkipBridges: 8 });
  const b = layersOf(25, at, skip);
  drain(supportPass(b, skip));
  assert.ok(
    b.every((l) => l.support === null),
    'a 6 mm bridge is left to bridge at supportSkipBridges 8',
  );
  const short = resolveConfig({ supportEnabled: true, supportSkipBridges: 4 });
  const c = layersOf(25, at, short);
  drain(supportPass(c, short));
  assert.ok(c[10].support !== null, 'but supported when the setting is shorter than the span');
});

test('the overhang of the second layer (a part whose first layer is smaller) gets support on the first, for both kinds, off the part', () => {
  // a block whose first layer is a 10 mm square and whose next layers are 14 mm: a 2 mm ledge one layer up
  const small = square(3_000, 3_000, 10_000);
  const big = square(1_000, 1_000, 14_000);
  const at = (j: number) => (j === 0 ? [small] : j < 20 ? [big] : []);
  for (const supportType of ['normal', 'tree'] as const) {
    const cfg = resolveConfig({ supportEnabled: true, supportType });
    const layers = layersOf(20, at, cfg);
    assert.ok(area(layers[1].overhang) > 60e6, 'the ledge is overhang');
    drain(supportPass(layers, cfg));
    const s = all(layers[0]);
    // under the ledge, from half a line off the first layer out to its edge: the zero Z gap the first layer allows
    const ledge = difference([big], offset([small], 200));
    assert.ok(
      area(intersection(s, ledge)) > 0.95 * area(ledge),
      `${supportType}: ledge held ${(area(intersection(s, ledge)) / 1e6).toFixed(1)} of ${(area(ledge) / 1e6).toFixed(1)} mm²`,
    );
    assert.equal(area(intersection(s, offset([small], 190))), 0, `${supportType}: support keeps off the first layer`);
    for (let j = 1; j < 20; j++)
      assert.equal(layers[j].support, null, `${supportType}: nothing above the first layer (layer ${j})`);
  }
});

test('with uneven layers the Z gaps are in mm: 0.3 mm over 0.1 mm layers is three layers, under 0.3 mm ones one', () => {
  // layers of 0.3 mm up to layer 29, then 0.1 mm ones; the table top from layer 40 (a gap of 0.2 mm would round to 2 layers of 0.2)
  const heightOf = (j: number) => (j === 0 ? 0.2 : j < 30 ? 0.3 : 0.1);
  for (const supportType of ['normal', 'tree'] as const) {
    const cfg = resolveConfig({
      supportEnabled: true,
      supportType,
      supportZGap: 0.3,
      supportBottomZGap: 0.3,
      supportInterfaceLayers: 2,
    });
    assert.equal(cfg.supportTopGapLayers, 2, 'the config counts layers of layerHeight');
    const layers = layersOf(50, table, cfg, heightOf);
    drain(supportPass(layers, cfg));
    for (const j of [37, 38, 39])
      assert.equal(layers[j].support, null, `${supportType}: layer ${j} in the 0.3 mm top gap`);
    assert.ok(area(all(layers[36])) > 0, `${supportType}: support right under the gap`);
    assert.ok(area(layers[36].support!.roof) > 0, `${supportType}: roof`);
  }
  // a ledge on a post over 0.3 mm layers: a 0.3 mm gap is one layer
  const ledge = (j: number) => (j < 10 ? [post] : j < 14 ? [top] : []);
  const cfg = resolveConfig({ supportEnabled: true, supportZGap: 0.3 });
  const layers = layersOf(14, ledge, cfg, (j) => (j === 0 ? 0.2 : 0.3));
  drain(supportPass(layers, cfg));
  assert.equal(layers[9].support, null);
  assert.ok(area(all(layers[8])) > 0);
});
