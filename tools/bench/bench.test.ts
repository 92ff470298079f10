import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { PATTERN_IDS } from '#strata/infill/types.js';
import { parseBenchArgs } from './args.js';
import { availableModels, runBench, wallsModels, WALLS_MODELS } from './bench.js';
import { BIG_MODEL, countTriangles, listModelFiles, prepareModels, type BenchModel } from './models.js';
import { renderReport } from './report.js';

/** A binary STL of `n` triangles with distinct corners. */
function binaryStl(n: number): Uint8Array {
  const bytes = new Uint8Array(84 + 50 * n);
  const dv = new DataView(bytes.buffer);
  dv.setUint32(80, n, true);
  for (let t = 0; t < n; t++) for (let k = 0; k < 9; k++) dv.setFloat32(84 + 50 * t + 12 + 4 * k, t + k, true);
  return bytes;
}

/**
 * A stub of Strata's CLI: checks the arguments, writes an output that depends on everything but -o and --threads
 * (as Strata's G-code does), fails on models named "broken"; STUB_THREADS_MATTER=1 makes the threads show.
 */
const STUB_CLI = `
const args = process.argv.slice(2);
const o = args.indexOf('-o');
const out = args[o + 1];
if (args[0] !== 'slice' || !out) { console.error('stub: bad arguments ' + args.join(' ')); process.exit(2); }
if (args[1].includes('broken')) { console.error('stub: cannot slice ' + args[1]); process.exit(1); }
const t = args.indexOf('--threads');
const kept = args.filter((_, i) => i !== o && i !== o + 1 && (process.env.STUB_THREADS_MATTER || t < 0 || (i !== t && i !== t + 1)));
require('node:fs').writeFileSync(out, ';stub ' + kept.join(' ') + '\\n');
`;

function fixture() {
  const root = mkdtempSync(join(tmpdir(), 'strata-bench-test-'));
  const models = join(root, 'models');
  const work = join(root, 'work');
  mkdirSync(models);
  mkdirSync(work);
  writeFileSync(join(models, 'cube.stl'), binaryStl(12));
  writeFileSync(join(models, 'broken.stl'), binaryStl(3));
  writeFileSync(join(models, 'spot.stl'), binaryStl(4));
  writeFileSync(join(models, 'BridgeTest.stl'), binaryStl(6));
  writeFileSync(join(models, '3DBenchy.stl.gz'), gzipSync(binaryStl(5)));
  writeFileSync(
    join(models, 'ascii.stl'),
    'solid a\nfacet normal 0 0 1\nouter loop\nendloop\nendfacet\nfacet normal 0 0 1\nendfacet\nendsolid a\n',
  );
  writeFileSync(join(models, 'SOURCES.md'), '# not a model\n');
  const cli = join(root, 'stub-cli.cjs');
  writeFileSync(cli, STUB_CLI);
  return { root, models, work, cli };
}

async function withFixture(fn: (f: ReturnType<typeof fixture>) => Promise<void> | void) {
  const f = fixture();
  try {
    await fn(f);
  } finally {
    rmSync(f.root, { recursive: true, force: true });
  }
}

test('models: listing, triangle counts, gzip unpacked once, the big mesh made from 3DBenchy', () =>
  withFixture((f) => {
    const files = listModelFiles(f.models);
    assert.deepEqual(files, ['3DBenchy.stl.gz', 'ascii.stl', 'BridgeTest.stl', 'broken.stl', 'cube.stl', 'spot.stl']);
    assert.deepEqual(availableModels(files, true), [...files, BIG_MODEL]);
    assert.deepEqual(availableModels(files, false), files);
    assert.deepEqual(availableModels(['cube.stl'], true), ['cube.stl'], 'no 3DBenchy, no big mesh');
    assert.equal(countTriangles('x.stl', binaryStl(7)), 7);
    const prepared = prepareModels(f.models, ['3DBenchy.stl.gz', 'ascii.stl', BIG_MODEL], f.work);
    assert.deepEqual(
      prepared.map((m) => [m.name, m.triangles]),
      [
        ['3DBenchy.stl', 5],
        ['ascii.stl', 2],
        [BIG_MODEL, 20],
      ],
    );
    assert.equal(prepared[0]!.path, join(f.work, '3DBenchy.stl'));
    assert.equal(prepared[2]!.path, join(f.work, BIG_MODEL));
    assert.match(prepared[2]!.madeFrom!, /3DBenchy\.stl, each triangle split into 4/);
    assert.equal(readFileSync(prepared[2]!.path).length, 84 + 50 * 20);
  }));

test("wallsModels: 3DBenchy as the 3DBenchy sections pick it, the hollow cube and BridgeTest, in the models' order", () => {
  const m = (name: string): BenchModel => ({ name, path: `/m/${name}`, triangles: 1 });
  const picked = (names: string[]) => wallsModels(names.map(m)).map((x) => x.name);
  assert.deepEqual([...WALLS_MODELS], ['3DBenchy.stl', 'HollowCalibrationCube.stl', 'BridgeTest.stl']);
  assert.deepEqual(
    picked([
      '3DBenchy.3mf',
      '3DBenchy.stl',
      '3DBenchy-x4.stl',
      'BridgeTest.stl',
      'CalibrationCube.stl',
      'HollowCalibrationCube.stl',
      'spot.stl',
    ]),
    ['3DBenchy.stl', 'BridgeTest.stl', 'HollowCalibrationCube.stl'],
  );
  assert.deepEqual(picked(['3DBenchy.3mf', 'spot.stl']), ['3DBenchy.3mf'], 'the 3MF when the STL is not selected');
  assert.deepEqual(picked(['HollowCalibrationCube.stl']), ['HollowCalibrationCube.stl']);
  assert.deepEqual(picked(['CalibrationCube.stl', 'spot.stl', '3DBenchy-x4.stl']), []);
});

test('runBench with a stub CLI: every model, failures, threads, every pattern, support, walls, targets', () =>
  withFixture(async (f) => {
    const options = parseBenchArgs([
      '--models-dir',
      f.models,
      '--strata-cli',
      f.cli,
      '--no-peers',
      '--repeat',
      '1',
      '--warmup',
      '0',
      '--timeout',
      '60',
    ]);
    const log: string[] = [];
    const report = await runBench(options, { workDir: f.work, log: (l) => log.push(l) });
    assert.equal(report.strataCli.built, true);
    assert.equal(report.peers.cura, null);
    const byName = Object.fromEntries(report.models.map((r) => [r.model, r]));
    assert.deepEqual(Object.keys(byName), [
      '3DBenchy.stl',
      'ascii.stl',
      'BridgeTest.stl',
      'broken.stl',
      'cube.stl',
      'spot.stl',
      BIG_MODEL,
    ]);
    assert.equal(byName['cube.stl']!.strata.status, 'ok');
    assert.ok(byName['cube.stl']!.strata.wallSeconds! > 0);
    assert.equal(byName['cube.stl']!.triangles, 12);
    assert.equal(byName[BIG_MODEL]!.triangles, 20);
    assert.equal(byName['broken.stl']!.strata.status, 'failed');
    assert.match(byName['broken.stl']!.strata.message!, /cannot slice/);
    assert.equal(byName['cube.stl']!.cura.status, 'missing');
    assert.equal(byName['cube.stl']!.wallRatio, null);
    // 3DBenchy sections
    assert.equal(report.threadScaling!.model, '3DBenchy.stl');
    assert.equal(report.threadScaling!.one.status, 'ok');
    assert.equal(report.threadScaling!.gcodeIdentical, true);
    assert.ok(report.threadScaling!.speedup! > 0);
    assert.equal(report.patternModel, '3DBenchy.stl');
    assert.deepEqual(
      report.patterns.map((p) => p.pattern),
      [...PATTERN_IDS],
    );
    assert.ok(report.patterns.every((p) => p.strata.status === 'ok' && p.relativeToGrid !== null));
    assert.equal(report.patterns[0]!.relativeToGrid, 1);
    // support on the selected support models, BridgeTest also scaled
    assert.deepEqual(
      report.support.map((s) => s.model),
      ['3DBenchy.stl', 'BridgeTest.stl', 'BridgeTest.stl --scale 2,2,1', 'spot.stl'],
    );
    assert.ok(
      report.support.every((s) => s.normal.status === 'ok' && s.tree.status === 'ok' && s.wallRatio.tree !== null),
    );
    // walls on the selected walls models, variable and classic; no CuraEngine to compare with (--no-peers)
    assert.deepEqual(
      report.walls.map((w) => w.model),
      ['3DBenchy.stl', 'BridgeTest.stl'],
    );
    assert.ok(
      report.walls.every(
        (w) => w.variable.status === 'ok' && w.classic.status === 'ok' && w.wallRatio !== null && w.cpuRatio !== null,
      ),
    );
    assert.ok(report.walls.every((w) => w.cura?.status === 'missing' && w.curaWallRatio === null));
    for (const g of ['variable', 'classic']) {
      assert.match(
        readFileSync(join(f.work, 'out', `BridgeTest.stl.walls-${g}.gcode`), 'utf8'),
        new RegExp(`BridgeTest\\.stl --wall-generator ${g}\\n`),
        g,
      );
    }
    assert.ok(report.triangleScaling && report.triangleScaling.triangleRatio === 4);
    // what ran, with which flags
    const outputs = readdirSync(join(f.work, 'out'));
    for (const o of [
      '3DBenchy.stl.infill-gyroid.gcode',
      '3DBenchy.stl.threads-1.gcode',
      '3DBenchy.stl.threads-2.gcode',
      'spot.stl.support-tree.gcode',
      `${BIG_MODEL}.strata.gcode`,
    ])
      assert.ok(outputs.includes(o), o);
    assert.match(
      readFileSync(join(f.work, 'out', 'spot.stl.support-tree.gcode'), 'utf8'),
      /--support-enabled --support-type tree/,
    );
    for (const kind of ['none', 'normal', 'tree']) {
      assert.match(
        readFileSync(join(f.work, 'out', `BridgeTest.stl.support-${kind}-scaled.gcode`), 'utf8'),
        /BridgeTest\.stl --scale 2,2,1/,
        kind,
      );
    }
    assert.ok(
      log.some((l) => /Strata --threads 2 run 1\/1: [\d.]+ s wall/.test(l)),
      log.join('\n'),
    );
    // the targets table: Strata's own figures judged, ratios to CuraEngine not measured here
    assert.equal(report.targets.find((t) => /CuraEngine, 3DBenchy\.stl/.test(t.figure))!.measured, 'no CuraEngine');
    assert.notEqual(report.targets.find((t) => /G-code/.test(t.figure))!.verdict, 'missing');
    const text = renderReport(report);
    assert.match(text, /### Infill patterns on 3DBenchy\.stl/);
    assert.match(text, /### Support/);
    assert.match(text, /### Walls \(--wall-generator variable against classic; wall \/ CPU\)/);
    assert.match(
      text,
      /\| wall, variable walls \/ classic, 3DBenchy\.stl, BridgeTest\.stl +\| ≤ 1\.25× +\| worst [\d.]+× \(/,
    );
    assert.match(
      text,
      /\| wall, variable walls \/ CuraEngine, 3DBenchy\.stl, BridgeTest\.stl +\| ≤ 1\.00× +\| no CuraEngine +\| – +\|/,
    );
    assert.match(text, /Strata on broken\.stl: exit code 1: stub: cannot slice/);
    assert.match(text, new RegExp(`${BIG_MODEL.replace('.', '\\.')}: made by the bench from 3DBenchy\\.stl`));
    assert.doesNotThrow(() => JSON.parse(JSON.stringify(report)));
  }));

test('runBench: warm-up plus counted rounds, interleaved; G-code that differs by thread count is caught', () =>
  withFixture(async (f) => {
    const options = parseBenchArgs([
      '--models-dir',
      f.models,
      '--strata-cli',
      f.cli,
      '--no-peers',
      '--models',
      '3DBenchy',
      '--repeat',
      '2',
      '--no-big',
      '--no-support',
      '--no-patterns',
      '--no-walls',
    ]);
    const log: string[] = [];
    const report = await runBench(options, {
      workDir: f.work,
      log: (l) => log.push(l.trim()),
      env: { ...process.env, STUB_THREADS_MATTER: '1' },
    });
    assert.equal(report.models[0]!.strata.runs.length, 2);
    assert.equal(report.threadScaling!.one.runs.length, 2);
    assert.equal(report.threadScaling!.gcodeIdentical, false);
    const threadRuns = log.filter((l) => l.startsWith('Strata --threads'));
    assert.deepEqual(
      threadRuns.map((l) => l.replace(/: .*/, '')),
      [
        'Strata --threads 1 warm-up 1/1',
        'Strata --threads 2 warm-up 1/1',
        'Strata --threads 1 run 1/2',
        'Strata --threads 2 run 1/2',
        'Strata --threads 1 run 2/2',
        'Strata --threads 2 run 2/2',
      ],
    );
    assert.equal(report.patterns.length, 0);
    assert.equal(report.support.length, 0);
    assert.equal(report.walls.length, 0, '--no-walls');
    assert.equal(report.load.blocks.length, 2, 'one block for the model, one for the threads');
  }));

test('runBench walls section: variable and classic interleaved round by round, one block per model', () =>
  withFixture(async (f) => {
    const options = parseBenchArgs([
      '--models-dir',
      f.models,
      '--strata-cli',
      f.cli,
      '--no-peers',
      '--models',
      'BridgeTest',
      '--repeat',
      '2',
      '--no-big',
      '--no-support',
      '--no-patterns',
      '--no-thread-scaling',
    ]);
    const log: string[] = [];
    const report = await runBench(options, { workDir: f.work, log: (l) => log.push(l.trim()) });
    assert.equal(report.walls.length, 1);
    assert.equal(report.walls[0]!.variable.runs.length, 2);
    assert.equal(report.walls[0]!.classic.runs.length, 2);
    assert.deepEqual(
      log.filter((l) => l.startsWith('Strata --wall-generator')).map((l) => l.replace(/: .*/, '')),
      [
        'Strata --wall-generator variable warm-up 1/1',
        'Strata --wall-generator classic warm-up 1/1',
        'Strata --wall-generator variable run 1/2',
        'Strata --wall-generator classic run 1/2',
        'Strata --wall-generator variable run 2/2',
        'Strata --wall-generator classic run 2/2',
      ],
    );
    assert.deepEqual(
      report.load.blocks.map((b) => b.label),
      ['BridgeTest.stl', 'BridgeTest.stl walls'],
    );
  }));

test('runBench walls section: a note when none of its models is selected', () =>
  withFixture(async (f) => {
    const options = parseBenchArgs([
      '--models-dir',
      f.models,
      '--strata-cli',
      f.cli,
      '--no-peers',
      '--models',
      'cube',
      '--repeat',
      '1',
      '--warmup',
      '0',
      '--no-big',
      '--no-support',
      '--no-patterns',
      '--no-thread-scaling',
    ]);
    const report = await runBench(options, { workDir: f.work, log: () => {} });
    assert.equal(report.walls.length, 0);
    assert.ok(
      report.notes.some((n) =>
        /^walls section skipped: none of 3DBenchy\.stl, HollowCalibrationCube\.stl, BridgeTest\.stl/.test(n),
      ),
      report.notes.join('\n'),
    );
  }));

test('runBench without a built CLI reports it instead of crashing', () =>
  withFixture(async (f) => {
    const options = parseBenchArgs([
      '--models-dir',
      f.models,
      '--strata-cli',
      join(f.root, 'missing.js'),
      '--no-peers',
      '--models',
      'cube',
      '--repeat',
      '1',
    ]);
    const report = await runBench(options, { workDir: f.work, log: () => {} });
    assert.equal(report.strataCli.built, false);
    assert.equal(report.models.length, 1);
    assert.equal(report.models[0]!.strata.status, 'missing');
    assert.equal(report.patterns.length, 0);
    assert.equal(report.threadScaling, null);
    assert.match(renderReport(report), /Strata: not built/);
  }));

test('runBench rejects a filter that matches nothing, naming the models', () =>
  withFixture(async (f) => {
    const options = parseBenchArgs(['--models-dir', f.models, '--no-peers', '--models', 'nope']);
    await assert.rejects(
      runBench(options, { workDir: f.work, log: () => {} }),
      /no model matches --models nope; models in .*cube\.stl/,
    );
  }));
