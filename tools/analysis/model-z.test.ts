import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseGcode } from './gcode-parse.js';
import { modelZFrames } from './model-z.js';

const O = { layerHeight: 0.2, firstLayerHeight: 0.2, zTolerance: 0.005, modelZOffset: null };

/** One layer: a marker, a Z move and a line of each named type. */
function layers(spec: [number, string[]][]): string {
  const out = ['G21', 'G90', 'M83'];
  spec.forEach(([z, types], k) => {
    out.push(`;LAYER:${k}`, `G0 Z${z}`);
    types.forEach((t, n) => out.push(`;TYPE:${t}`, `G0 X${10 + n} Y10`, `G1 X${10 + n} Y20 E0.5`));
  });
  return out.join('\n');
}

test('a raft with a raised first model layer: the offset comes from the second part layer', () => {
  // CuraEngine: raft 0.24 / 0.54 / 0.74, first model layer 0.5 mm above, the next pressed down by 0.15 mm.
  const p = parseGcode(
    layers([
      [0.24, ['SUPPORT']],
      [0.54, ['SUPPORT-INTERFACE']],
      [0.74, ['SUPPORT-INTERFACE']],
      [1.24, ['WALL-OUTER']],
      [1.29, ['WALL-OUTER', 'SKIN']],
      [1.49, ['WALL-OUTER']],
    ]),
  );
  const z = modelZFrames(p.layers, O);
  assert.equal(z.source, 'detected');
  assert.ok(Math.abs(z.offsetMm - 0.89) < 1e-6, `offset ${z.offsetMm}`);
  assert.equal(z.firstModelLayer, 3);
  assert.equal(z.raftLayerCount, 3);
  assert.ok(Math.abs(z.raftGapMm! - 0.3) < 1e-6, `gap ${z.raftGapMm}`);
  assert.deepEqual(
    z.frames.map((f) => f.raft),
    [true, true, true, false, false, false],
  );
  assert.deepEqual(
    z.frames.map((f) => f.firstOverRaft),
    [false, false, false, true, false, false],
  );
  assert.deepEqual(
    z.frames.slice(3).map((f) => Math.round(f.modelZ * 1e6) / 1e6),
    [0.2, 0.4, 0.6],
  );
  assert.deepEqual(
    z.frames.slice(3).map((f) => Math.round(f.partThickness * 1e6) / 1e6),
    [0.2, 0.2, 0.2],
  );
  // Given, the offset is used as it is.
  const given = modelZFrames(p.layers, { ...O, modelZOffset: 0.89 });
  assert.equal(given.source, 'option');
  assert.equal(given.raftLayerCount, 3);
});

test('support on a grid of its own between part layers: no raft, thickness per material', () => {
  // PrusaSlicer: part every 0.2 mm, support layers at 0.467 and 0.733 between them.
  const p = parseGcode(
    layers([
      [0.2, ['External perimeter', 'Support material']],
      [0.4, ['External perimeter']],
      [0.467, ['Support material']],
      [0.6, ['External perimeter']],
      [0.733, ['Support material interface']],
      [0.8, ['External perimeter']],
    ]),
  );
  const z = modelZFrames(p.layers, O);
  assert.equal(z.source, 'none');
  assert.equal(z.offsetMm, 0);
  assert.equal(z.raftLayerCount, 0);
  assert.deepEqual(
    z.frames.map((f) => f.hasPart),
    [true, true, false, true, false, true],
  );
  const t = (v: number) => Math.round(v * 1000) / 1000;
  assert.deepEqual(
    z.frames.filter((f) => f.hasPart).map((f) => t(f.partThickness)),
    [0.2, 0.2, 0.2, 0.2],
  );
  assert.deepEqual(
    z.frames.filter((f) => f.hasSupport).map((f) => t(f.supportThickness)),
    [0.2, 0.267, 0.266],
  );
});

test('a declared layer height (;HEIGHT:) is the thickness of support, also after a layer without support', () => {
  // support on layers 1 and 3, none on layer 2 (a floor starting above the part's top)
  const spec: [number, string[]][] = [
    [0.2, ['WALL-OUTER']],
    [0.4, ['WALL-OUTER', 'SUPPORT']],
    [0.6, ['WALL-OUTER']],
    [0.8, ['WALL-OUTER', 'SUPPORT']],
  ];
  const t = (v: number) => Math.round(v * 1000) / 1000;
  const supportThickness = (gcode: string) =>
    modelZFrames(parseGcode(gcode).layers, O)
      .frames.filter((f) => f.hasSupport)
      .map((f) => t(f.supportThickness));
  // without ;HEIGHT: the support is taken to reach down to the last layer with support (a grid of its own)
  assert.deepEqual(supportThickness(layers(spec)), [0.4, 0.4]);
  const declared = layers(spec).replace(/(;LAYER:\d+\n)/g, '$1;HEIGHT:0.2\n');
  assert.deepEqual(supportThickness(declared), [0.2, 0.2]);
  assert.deepEqual(
    parseGcode(declared).layers.map((l) => l.declaredHeight),
    [0.2, 0.2, 0.2, 0.2],
  );
});

test('without layers before the part there is no raft, typed or not', () => {
  const typed = parseGcode(
    layers([
      [0.2, ['WALL-OUTER', 'SUPPORT']],
      [0.4, ['WALL-OUTER']],
    ]),
  );
  assert.equal(modelZFrames(typed.layers, O).source, 'none');
  const untyped = parseGcode('M83\nG0 Z0.3\nG1 X10 E1\nG0 Z0.5\nG1 X20 E1\nG0 Z0.7\nG1 X0 E1\n');
  const z = modelZFrames(untyped.layers, O);
  assert.equal(z.offsetMm, 0);
  assert.equal(z.firstModelLayer, 0);
});
