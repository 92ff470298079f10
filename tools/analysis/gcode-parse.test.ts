import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Feature, FEATURE_NAMES, featureCodeOf } from './feature-names.js';
import { createGcodeParser, parseGcode } from './gcode-parse.js';
import { GcodeWriter } from './synthetic-print.js';

const near = (a: number, b: number, tol: number, what = '') =>
  assert.ok(Math.abs(a - b) <= tol, `${what} ${a} is not within ${tol} of ${b}`);

function squareLayers(relativeE: boolean): string {
  const g = new GcodeWriter({ lineWidth: 0.4, filamentDiameter: 1.75, relativeE, markers: 'cura' });
  for (let l = 0; l < 3; l++) {
    g.layer(l, 0.2 * (l + 1), 0.2)
      .type('WALL-OUTER')
      .rect(10, 10, 30, 30);
    g.retract(0.8).travel(12, 12).prime(0.8).type('FILL').line(28, 28);
  }
  g.retract(2);
  return g.text();
}

test('absolute and relative E give the same totals', () => {
  const abs = parseGcode(squareLayers(false));
  const rel = parseGcode(squareLayers(true));
  assert.equal(abs.e.mode, 'absolute');
  assert.equal(rel.e.mode, 'relative');
  near(abs.e.extruded, rel.e.extruded, 1e-3, 'extruded');
  near(abs.e.retracted, rel.e.retracted, 1e-3, 'retracted');
  near(abs.e.net, rel.e.net, 1e-3, 'net');
  near(abs.e.retracted, 3 * 0.8 + 2, 1e-4, 'retracted');
  // Filament for 3 layers of an 80 mm loop and a 22.6 mm diagonal, 0.4 × 0.2 per mm.
  const area = (Math.PI * 1.75 * 1.75) / 4;
  near(abs.e.extruded, (3 * (80 + 16 * Math.SQRT2) * 0.08) / area, 1e-3, 'extruded');
  // Read the other way round, the absolute file's numbers sum to something very different.
  assert.ok(abs.e.asIfRelative > 5 * abs.e.net);
  near(rel.e.asIfRelative, rel.e.net, 1e-6);
  assert.equal(abs.layers.length, 3);
  assert.equal(abs.balance.unbalanced, 0);
  near(abs.balance.trailingMm, 2, 1e-4, 'trailing');
});

test('unbalanced retraction is detected', () => {
  const g = new GcodeWriter({ lineWidth: 0.4, filamentDiameter: 1.75, relativeE: true, markers: 'cura' });
  g.layer(0, 0.2, 0.2).rect(0, 0, 10, 10).retract(1).travel(5, 5).line(6, 6); // never primed
  g.retract(1).travel(1, 1).prime(1.5).line(2, 2); // over-primed
  g.retract(1).travel(3, 3).prime(1).line(4, 4); // fine
  const p = parseGcode(g.text());
  assert.equal(p.balance.retractions, 3);
  assert.equal(p.balance.primes, 2);
  assert.equal(p.balance.unbalanced, 2);
  assert.equal(p.balance.unbalancedLines.length, 2);
});

test('firmware retraction G10/G11 and tool-offset G10 are told apart', () => {
  const text = [
    'G10 P0 S200 ; RRF tool temperature, not a retraction',
    ';LAYER:0',
    'G1 Z0.2',
    'G1 X10 Y0 E1',
    'G10',
    'G0 X20',
    'G11',
    'G1 X30 E2',
    'G10',
    'G0 X0',
    'G1 X5 E3',
  ].join('\n');
  const p = parseGcode(text);
  assert.equal(p.balance.firmwareRetractions, 2);
  assert.equal(p.balance.unbalanced, 1);
});

test('PrusaSlicer, Orca and Cura type names map to canonical features', () => {
  const cases: [string, number][] = [
    ['External perimeter', Feature.WallOuter],
    ['Overhang perimeter', Feature.WallOuter],
    ['Perimeter', Feature.WallInner],
    ['Gap fill', Feature.WallInner],
    ['Solid infill', Feature.Skin],
    ['Top solid infill', Feature.Skin],
    ['Bridge infill', Feature.Skin],
    ['Internal infill', Feature.Fill],
    ['Skirt/Brim', Feature.Skirt],
    ['Support material', Feature.Support],
    ['Support material interface', Feature.SupportInterface],
    ['Wipe tower', Feature.PrimeTower],
    ['Ironing', Feature.Ironing],
    ['Custom', Feature.Custom],
    ['WALL-OUTER', Feature.WallOuter],
    ['WALL-INNER', Feature.WallInner],
    ['SKIN', Feature.Skin],
    ['FILL', Feature.Fill],
    ['SUPPORT', Feature.Support],
    ['SUPPORT-INTERFACE', Feature.SupportInterface],
    ['RAFT', Feature.Raft],
    ['BRIDGE', Feature.Skin],
    ['SKIRT', Feature.Skirt],
    ['Support interface', Feature.SupportInterface],
    ['Support transition', Feature.Support],
    ['Outer wall', Feature.WallOuter],
    ['Sparse infill', Feature.Fill],
  ];
  for (const [name, code] of cases) assert.equal(featureCodeOf(name), code, name);
  assert.equal(featureCodeOf('Mystery'), -1);

  const text = [
    'M83',
    ';TYPE:Custom',
    'G1 Z0.2',
    'G1 X60 E9 ; intro line',
    ';LAYER_CHANGE',
    ';Z:0.2',
    ';TYPE:Skirt/Brim',
    'G1 X70 Y0 E1',
    ';TYPE:External perimeter',
    'G1 X70 Y10 E1',
    ';TYPE:Perimeter',
    'G1 X60 Y10 E1',
    ';TYPE:Solid infill',
    'G1 X60 Y5 E1',
    ';TYPE:Internal infill',
    'G1 X65 Y5 E1',
    ';TYPE:Mystery',
    'G1 X66 E1',
  ].join('\n');
  const p = parseGcode(text);
  assert.equal(p.layers.length, 1);
  assert.equal(p.preamble.extrusions.count, 1, 'the intro line before ;LAYER_CHANGE is preamble');
  const names = Array.from(p.layers[0]!.extrusions.feature, (f) => FEATURE_NAMES[f]);
  assert.deepEqual(names, ['SKIRT', 'WALL-OUTER', 'WALL-INNER', 'SKIN', 'FILL', 'UNKNOWN']);
  assert.deepEqual(p.unknownTypes, ['Mystery']);
  assert.equal(p.hasTypeMarkers, true);
});

test('layers without markers come from distinct extrusion Z, and z-hops do not make layers', () => {
  const text = [
    'G1 Z0.3 F600',
    'G1 X10 E1',
    'G1 Z0.9',
    'G0 X20',
    'G1 Z0.3',
    'G1 X30 E2', // hop between extrusions
    'G1 Z0.5',
    'G1 X0 E3',
    'G1 Z0.3',
    'G1 X5 E4', // back down (a second object at the first height)
  ].join('\n');
  const p = parseGcode(text);
  assert.equal(p.hasLayerMarkers, false);
  assert.deepEqual(
    p.layers.map((l) => l.z),
    [0.3, 0.5],
  );
  assert.equal(p.layers[0]!.extrusions.count, 3);
  near(p.layers[0]!.thickness, 0.3, 1e-9);
  near(p.layers[1]!.thickness, 0.2, 1e-9);
});

test('G2/G3 arcs become chords along the arc', () => {
  const text = ['G1 Z0.2', 'G1 X10 Y0 F1000', 'G3 X0 Y10 I-10 J0 E1', 'G2 X10 Y0 R10 E2'].join('\n');
  const p = parseGcode(text);
  const t = p.layers[0]!.extrusions;
  let len = 0;
  let maxR = 0;
  let minR = Infinity;
  for (let i = 0; i < t.count; i++) {
    len += Math.hypot(t.x1[i]! - t.x0[i]!, t.y1[i]! - t.y0[i]!);
    const r = Math.hypot(t.x1[i]!, t.y1[i]!);
    maxR = Math.max(maxR, r);
    minR = Math.min(minR, r);
  }
  // A counter-clockwise quarter round the origin, then (R form) the same quarter back clockwise.
  near(len, Math.PI * 10, 0.05, 'arc length');
  assert.ok(t.count > 20);
  near(p.e.extruded, 2, 1e-6);
  assert.ok(maxR <= 10 + 1e-3 && minR > 5, `first arc stays at radius 10: ${minR}..${maxR}`);
  const full = parseGcode(['G1 Z0.2', 'G1 X10 Y0', 'G2 X10 Y0 I-10 J0 E5'].join('\n'));
  let fullLen = 0;
  const f = full.layers[0]!.extrusions;
  for (let i = 0; i < f.count; i++) fullLen += Math.hypot(f.x1[i]! - f.x0[i]!, f.y1[i]! - f.y0[i]!);
  near(fullLen, 2 * Math.PI * 10, 0.05, 'full circle');
});

test('G91, G92, line numbers, checksums, inches and comments', () => {
  const text = [
    'N1 G21*12',
    'G1 Z0.2 ; first layer',
    'G92 X100 Y100 ; shift logical origin',
    'G1 X110 Y100 E1',
    'G91',
    'G1 X0 Y10 E1',
    'G90',
    'G20',
    'G1 (comment) Y4.72440945 E0.11811024',
    'G21',
    'g1 x105 y110 e4',
    'G1 X.5 Y-1.25 E5',
  ].join('\n');
  const p = parseGcode(text);
  const t = p.layers[0]!.extrusions;
  assert.equal(t.count, 5);
  near(t.x1[0]!, 10, 1e-4); // physical X: logical 110 with offset -100
  near(t.y1[1]!, 10, 1e-4);
  near(t.y1[2]!, 20, 1e-4); // 4.7244" = 120 mm logical
  near(t.x1[3]!, 5, 1e-4);
  near(t.x1[4]!, -99.5, 1e-4);
  near(t.y1[4]!, -101.25, 1e-4);
  // G91 makes E relative too: E1 after E1 adds 1, then G90 restores absolute E (3 mm after 2 mm).
  near(p.e.extruded, 5, 1e-3);
});

test('streaming in arbitrary chunks gives the same result as one string', () => {
  const text = squareLayers(false);
  const whole = parseGcode(text);
  const parser = createGcodeParser();
  let at = 0;
  let size = 1;
  while (at < text.length) {
    parser.write(text.slice(at, at + size));
    at += size;
    size = (size * 7 + 3) % 97;
  }
  const streamed = parser.end();
  assert.equal(streamed.layers.length, whole.layers.length);
  assert.deepEqual(streamed.e, whole.e);
  assert.deepEqual(Array.from(streamed.layers[2]!.extrusions.x1), Array.from(whole.layers[2]!.extrusions.x1));
  assert.equal(streamed.lineCount, whole.lineCount);
});
