/**
 * Uneven layers end to end (adaptive layer height, a layer range's own layerHeight): the G-code's Z steps,
 * skin thickness in mm counted over the layers' real heights, extrusion per layer height, the estimate, and
 * the G-code read back by the analyser's parser.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { analyzePrint } from '../../tools/analysis/checks.js';
import { analysisProfile } from '../e2e/models.js';
import { prepareModel } from '#strata/api/prepare-model.js';
import { estimatePlan } from '#strata/plan/estimate.js';
import { planToArrays, SEGMENT_STRIDE } from '#strata/preview/plan-arrays.js';
import { sphere } from '../e2e/curved-shapes.js';
import { box } from '../slice/test-helpers.js';

interface GLayer {
  z: number;
  height: number;
  types: Set<string>;
  /** Outer wall: filament per mm of line. */
  wallEPerMm: number;
}

/** The layers of Strata's G-code: Z (from the layer's first G1 Z), declared height, features, outer-wall flow. */
function layersOf(gcode: string): GLayer[] {
  const out: GLayer[] = [];
  let cur: GLayer | null = null;
  let type = '',
    x = 0,
    y = 0,
    e = 0,
    len = 0,
    ew = 0;
  const finish = () => {
    if (cur) cur.wallEPerMm = len > 0 ? ew / len : NaN;
  };
  for (const line of gcode.split('\n')) {
    if (line.startsWith(';LAYER:')) {
      finish();
      cur = { z: NaN, height: NaN, types: new Set(), wallEPerMm: NaN };
      out.push(cur);
      len = ew = 0;
    } else if (line.startsWith(';HEIGHT:') && cur && Number.isNaN(cur.height)) cur.height = Number(line.slice(8));
    else if (line.startsWith(';TYPE:')) {
      type = line.slice(6);
      cur?.types.add(type);
    } else if (/^G[01] /.test(line)) {
      const v = (k: string) => {
        const m = new RegExp(`\\b${k}(-?[\\d.]+)`).exec(line.split(';')[0]);
        return m ? Number(m[1]) : null;
      };
      const nx = v('X') ?? x,
        ny = v('Y') ?? y,
        ne = v('E'),
        nz = v('Z');
      if (cur && nz !== null && Number.isNaN(cur.z)) cur.z = nz;
      if (ne !== null) {
        if (cur && type === 'WALL-OUTER' && ne > e && (nx !== x || ny !== y)) {
          len += Math.hypot(nx - x, ny - y);
          ew += ne - e;
        }
        e = ne;
      }
      x = nx;
      y = ny;
    } else if (line.startsWith('G92 E0')) e = 0;
  }
  finish();
  return out;
}

test('a layer range with its own layerHeight: Z steps of that height in the range, skin as thick in mm as asked, flow by height', () => {
  const slicer = new Slicer({
    threads: 1,
    layerHeight: 0.2,
    topSkinThickness: 0.8,
    bottomSkinThickness: 0.8,
    infillDensity: 20,
  });
  slicer.addObject(box(0, 0, 0, 20, 20, 10), { layerRanges: [{ fromZ: 4, toZ: 10, settings: { layerHeight: 0.1 } }] });
  const { gcode, stats } = slicer.sliceSync();
  const layers = layersOf(gcode);
  assert.equal(layers.length, stats.layers);
  // 20 layers of 0.2 to 4 mm, 60 of 0.1 to 10 mm
  assert.equal(layers.length, 80);
  layers.forEach((l, i) => {
    assert.equal(l.height, i < 20 ? 0.2 : 0.1, `layer ${i}`);
    assert.equal(Math.round(l.z * 1000), i < 20 ? 200 * (i + 1) : 4000 + 100 * (i - 19), `layer ${i} Z`);
  });
  // top skin: the top 0.8 mm, 8 layers of 0.1 (not 0.8 / layerHeight = 4); bottom: 4 layers of 0.2
  const solid = layers.map((l) => l.types.has('SKIN') && !l.types.has('FILL'));
  assert.deepEqual(
    solid.map((s, i) => (s ? i : -1)).filter((i) => i >= 0),
    [0, 1, 2, 3, 72, 73, 74, 75, 76, 77, 78, 79],
  );
  const skinMm = (from: number, to: number) => layers.slice(from, to).reduce((a, l) => a + l.height, 0);
  assert.ok(Math.abs(skinMm(72, 80) - 0.8) < 1e-9 && Math.abs(skinMm(0, 4) - 0.8) < 1e-9);
  // each layer extrudes for its own height: a 0.1 mm layer's outer wall half the filament per mm of a 0.2 one's
  const ratio = layers[50].wallEPerMm / layers[10].wallEPerMm;
  assert.ok(Math.abs(ratio - 0.5) < 0.02, `flow ratio ${ratio}`);
  // the analyser's parser reads the layers back at the same heights
  const parsed = parseGcode(gcode);
  assert.deepEqual(
    parsed.layers.map((l) => Math.round(l.thickness * 1000)),
    layers.map((l) => Math.round(l.height * 1000)),
  );
  assert.deepEqual(
    parsed.layers.map((l) => l.declaredHeight),
    layers.map((l) => l.height),
  );
});

test('adaptive layer height on a sphere: thin near the poles, thick at the equator, read back by the parser; the estimate grows with the layers', () => {
  const ball = sphere(10, 96, 48);
  const even = new Slicer({ threads: 1 }).sliceSync(ball);
  const adaptive = new Slicer({
    threads: 1,
    adaptiveLayerHeight: true,
    minLayerHeight: 0.08,
    maxLayerHeight: 0.3,
  }).sliceSync(ball);
  const layers = layersOf(adaptive.gcode);
  assert.equal(layers.length, adaptive.stats.layers);
  for (const l of layers.slice(1)) assert.ok(l.height >= 0.08 && l.height <= 0.3, `${l.height}`);
  const at = (z: number) => layers.reduce((a, b) => (Math.abs(b.z - z) < Math.abs(a.z - z) ? b : a));
  assert.equal(at(10).height, 0.3);
  assert.ok(at(1).height < 0.15 && at(19.8).height < 0.15, `${at(1).height} ${at(19.8).height}`);
  const parsed = parseGcode(adaptive.gcode);
  assert.equal(parsed.layers.length, layers.length);
  parsed.layers.forEach((l, i) => {
    assert.ok(Math.abs(l.z - layers[i].z) < 1e-6);
    assert.ok(
      Math.abs(l.thickness - layers[i].height) < 1e-6,
      `layer ${i}: parsed ${l.thickness}, declared ${layers[i].height}`,
    );
  });
  // the filament is about the same (the same solid), the time differs with the layer count
  assert.ok(
    Math.abs(adaptive.stats.filamentMm / even.stats.filamentMm - 1) < 0.1,
    `${adaptive.stats.filamentMm} vs ${even.stats.filamentMm}`,
  );
  assert.notEqual(adaptive.stats.layers, even.stats.layers);
});

test('adaptive off and no range heights: the G-code is what it was (a range repeating the print height changes nothing)', () => {
  const ball = sphere(6, 48, 24);
  const plain = new Slicer({ threads: 1 }).sliceSync(ball).gcode;
  assert.equal(
    new Slicer({ threads: 1, adaptiveLayerHeight: false, minLayerHeight: 0.1, maxLayerHeight: 0.25 }).sliceSync(ball)
      .gcode,
    plain,
  );
  const ranged = new Slicer({ threads: 1 })
    .addObject(ball, { layerRanges: [{ fromZ: 3.1, toZ: 5, settings: { layerHeight: 0.2 } }] })
    .sliceSync().gcode;
  assert.equal(ranged.replace(/^;.*\n/gm, ''), plain.replace(/^;.*\n/gm, ''));
});

test('adaptive layer height settings that make no sense are one clear error', () => {
  const bad = (options: Record<string, unknown>, message: RegExp) =>
    assert.throws(
      () => new Slicer({ adaptiveLayerHeight: true, ...options }),
      (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING' && message.test(e.message),
      JSON.stringify(options),
    );
  bad(
    { minLayerHeight: 0.25, layerHeight: 0.2 },
    /^adaptiveLayerHeight: layerHeight 0.2 mm must lie between minLayerHeight 0.25 mm and maxLayerHeight 0.3 mm$/,
  );
  bad(
    { maxLayerHeight: 0.15, layerHeight: 0.2 },
    /layerHeight 0.2 mm must lie between minLayerHeight 0.07 mm and maxLayerHeight 0.15 mm/,
  );
  bad({ minLayerHeight: 0.3, maxLayerHeight: 0.1 }, /minLayerHeight 0.3 mm is above maxLayerHeight 0.1 mm/);
  bad(
    { maxLayerHeight: 0.38 },
    /maxLayerHeight 0.38 mm is too thick for a 0.4 mm nozzle \(at most 85% of it: 0.34 mm\)/,
  );
  assert.throws(
    () => new Slicer({ adaptiveLayerQuality: 2 }),
    /adaptiveLayerQuality = 2 is not allowed: expected a number from 0 to 1/,
  );
  // a layer range's height obeys the layer height's rules, naming the range
  assert.throws(
    () =>
      new Slicer().addObject(box(0, 0, 0, 5, 5, 5), {
        name: 'b',
        layerRanges: [{ fromZ: 1, toZ: 2, settings: { layerHeight: 0.39 } }],
      }),
    /object "b" layers 1–2 mm: layerHeight 0.39 mm is too thick for a 0.4 mm nozzle/,
  );
  assert.throws(
    () => new Slicer().addObject(box(0, 0, 0, 5, 5, 5), { name: 'b', settings: { layerHeight: 0.1 } }),
    /layerHeight is the same for every object at one height/,
  );
  // off, the limits are not checked (they do nothing)
  assert.doesNotThrow(() => new Slicer({ minLayerHeight: 0.25, layerHeight: 0.2 }));
});

test("the analyser judges adaptive G-code by its layers' thickness: none off the range or missing; a layer taken out is found", () => {
  const ball = sphere(8, 64, 32);
  const slicer = new Slicer({ threads: 1, adaptiveLayerHeight: true, minLayerHeight: 0.08, maxLayerHeight: 0.3 });
  const { gcode } = slicer.sliceSync(ball);
  const cfg = slicer.config;
  const placed = prepareModel(ball, cfg).mesh;
  const options = {
    ...analysisProfile(cfg),
    sampleEvery: 8,
    supportChecks: false,
    layerHeightRange: [0.08, 0.3] as [number, number],
  };
  const report = analyzePrint(placed, gcode, options);
  assert.equal(report.summary.zMismatchCount, 0);
  assert.equal(report.summary.missingLayerCount, 0);
  assert.equal(report.summary.expectedLayerCount, report.summary.layerCount);
  assert.ok(report.summary.walls.coverage! > 0.97, `walls ${report.summary.walls.coverage}`);
  assert.ok(report.summary.skin.top.coverage! > 0.9 && report.summary.skin.bottom.coverage! > 0.9);
  // judged against the even grid it is all off-grid
  assert.ok(analyzePrint(placed, gcode, { ...options, layerHeightRange: undefined }).summary.zMismatchCount > 10);
  // two neighbouring 0.3 mm layers at the equator taken out: a gap of 0.9 mm, two layers missing, the one above too thick
  const parts = gcode.split(/(?=^;LAYER:)/m);
  const equator = parts.findIndex((p) => /^;Z:8\.\d+$/m.test(p) && /^;HEIGHT:0\.3$/m.test(p));
  assert.ok(equator > 0);
  const broken = [...parts.slice(0, equator), ...parts.slice(equator + 2)].join('');
  const bad = analyzePrint(placed, broken, options).summary;
  assert.equal(bad.missingLayerCount, 2);
  assert.equal(bad.zMismatchCount, 1);
});

test("a layer height profile (PrusaSlicer's variable layer height) sets the layers' heights, from the library and a PrusaSlicer 3MF", async () => {
  // 0.2 mm to 4 mm, down to 0.1 at 6 mm, 0.1 to 8 mm, up to 0.3 at 9 mm
  const profile = [0, 0.2, 4, 0.2, 6, 0.1, 8, 0.1, 9, 0.3, 12, 0.3];
  const heights = (gcode: string) => layersOf(gcode).map((l) => [Math.round(l.z * 1000), Math.round(l.height * 1000)]);
  const check = (hz: number[][]) => {
    for (const [z, h] of hz) {
      const bottom = z - h;
      if (bottom < 4000 && z <= 4000) assert.equal(h, 200, `${z}`);
      else if (bottom >= 6000 && bottom < 8000) assert.equal(h, 100, `${z}`);
      else if (bottom >= 9000) assert.equal(h, 300, `${z}`);
      else assert.ok(h >= 100 && h <= 300);
    }
    let sum = 0;
    for (const [z, h] of hz) assert.equal(z, (sum += h));
  };
  const lib = new Slicer({ threads: 1 })
    .addObject(box(0, 0, 0, 10, 10, 12), { layerHeightProfile: profile })
    .sliceSync().gcode;
  check(heights(lib));
  // the same in a PrusaSlicer project
  const { strToU8, zipSync } = await import('fflate');
  const v = [
    [0, 0, 0],
    [10, 0, 0],
    [0, 10, 0],
    [10, 10, 0],
    [0, 0, 12],
    [10, 0, 12],
    [0, 10, 12],
    [10, 10, 12],
  ];
  const faces = [
    [0, 2, 3],
    [0, 3, 1],
    [4, 5, 7],
    [4, 7, 6],
    [0, 1, 5],
    [0, 5, 4],
    [2, 6, 7],
    [2, 7, 3],
    [0, 4, 6],
    [0, 6, 2],
    [1, 3, 7],
    [1, 7, 5],
  ];
  const files: Record<string, string> = {
    '_rels/.rels':
      '<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>',
    '3D/3dmodel.model': `<?xml version="1.0" encoding="UTF-8"?><model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources><object id="1" type="model"><mesh><vertices>${v.map(([x, y, z]) => `<vertex x="${x}" y="${y}" z="${z}"/>`).join('')}</vertices><triangles>${faces.map(([a, b, c]) => `<triangle v1="${a}" v2="${b}" v3="${c}"/>`).join('')}</triangles></mesh></object></resources><build><item objectid="1" transform="1 0 0 0 1 0 0 0 1 100 100 0"/></build></model>`,
    'Metadata/Slic3r_PE_model.config':
      '<?xml version="1.0" encoding="UTF-8"?><config><object id="1" instances_count="1"><metadata type="object" key="name" value="box"/><volume firstid="0" lastid="11"><metadata type="volume" key="volume_type" value="ModelPart"/></volume></object></config>',
    'Metadata/Slic3r_PE_layer_heights_profile.txt': `object_id=1|${profile.map((x) => x.toFixed(6)).join(';')}\n`,
  };
  const bytes = zipSync(Object.fromEntries(Object.entries(files).map(([k, s]) => [k, strToU8(s)])));
  const project = await new Slicer({ threads: 1 }).slice(bytes);
  assert.deepEqual(heights(project.gcode), heights(lib));
});

test("uneven layers downstream: the plan, the preview arrays and the estimate per layer carry each layer's own height; minimum layer time holds per layer", async () => {
  const slicer = new Slicer({ threads: 1, minLayerTime: 8, minPrintSpeed: 1 });
  slicer.addObject(box(0, 0, 0, 6, 6, 3), { layerRanges: [{ fromZ: 1, toZ: 2, settings: { layerHeight: 0.1 } }] });
  const { plan } = await slicer.slicePlan();
  const heights = plan.layers.map((l) => Math.round(l.height * 1000));
  assert.deepEqual(heights, [...new Array(5).fill(200), ...new Array(10).fill(100), ...new Array(5).fill(200)]);
  let sum = 0;
  plan.layers.forEach((l) => assert.equal(Math.round(l.z * 1000), (sum += Math.round(l.height * 1000))));
  const estimate = estimatePlan(plan, slicer.config);
  assert.equal(estimate.layerSeconds.length, plan.layers.length);
  // small layers are slowed to the minimum layer time, thin ones as thick ones
  for (const [i, t] of estimate.layerSeconds.entries()) assert.ok(t >= 8 - 0.5, `layer ${i}: ${t} s`);
  const arrays = planToArrays(plan, estimate.layerSeconds);
  for (let li = 0; li < plan.layers.length; li++) {
    assert.ok(Math.abs(arrays.layerZ[li] - plan.layers[li].z) < 1e-6);
    for (let s = arrays.layerSegments[li]; s < arrays.layerSegments[li + 1]; s++) {
      assert.ok(
        Math.abs(arrays.segments[s * SEGMENT_STRIDE + 6] - plan.layers[li].height) < 1e-6,
        `layer ${li}: segment height`,
      );
    }
  }
});
