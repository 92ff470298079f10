import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Measurement } from './measure.js';
import {
  figuresCell,
  notRun,
  pairedRatio,
  ratioOfMedians,
  relativeToGrid,
  renderReport,
  summarize,
  supportRow,
  triangleScaling,
  wallsRow,
  type BenchReport,
  type ModelRow,
  type SlicerStats,
} from './report.js';
import { checkTargets } from './targets.js';

const run = (wallSeconds: number, cpuSeconds: number | null, peakMiB: number | null, exitCode = 0): Measurement => ({
  exitCode,
  signal: null,
  timedOut: false,
  spawnError: null,
  wallSeconds,
  cpuSeconds,
  peakMiB,
  stderrTail: exitCode === 0 ? '' : 'error: broken mesh\n',
});
/** ok stats from per-round walls (CPU = 1.5 × wall, peak fixed). */
const ok = (walls: number[], peakMiB = 100, cpuFactor = 1.5): SlicerStats =>
  summarize(walls.map((w) => run(w, w * cpuFactor, peakMiB)));

test('summarize takes medians of wall, CPU and peak; a failure wins', () => {
  const s = summarize([run(3, 5, 100), run(1, 2, 90), run(2, 4, 120)]);
  assert.equal(s.status, 'ok');
  assert.equal(s.wallSeconds, 2);
  assert.equal(s.cpuSeconds, 4);
  assert.equal(s.peakMiB, 100);
  assert.deepEqual(
    s.runs.map((r) => r.wallSeconds),
    [3, 1, 2],
  );
  const f = summarize([run(1, 1, 10), run(1, 1, 10, 2)]);
  assert.equal(f.status, 'failed');
  assert.equal(f.wallSeconds, null);
  assert.match(f.message!, /exit code 2: error: broken mesh/);
  assert.equal(
    summarize([{ ...run(600, null, null), exitCode: null, signal: 'SIGKILL', timedOut: true }]).status,
    'timeout',
  );
  assert.equal(summarize([run(1, null, null)]).peakMiB, null);
  assert.equal(summarize([run(1, 1, 5), run(1, null, 5)]).cpuSeconds, null, 'a figure some run lacks is no median');
});

test('pairedRatio: median of per-round ratios, null unless both ran', () => {
  const strata = ok([1.0, 2.0, 2.2, 1.1, 1.05]);
  const cura = ok([2.0, 3.0, 3.3, 2.0, 2.1], 60, 1.8);
  assert.equal(pairedRatio(strata, cura, 'wallSeconds'), 0.55);
  assert.ok(Math.abs(pairedRatio(strata, cura, 'cpuSeconds')! - (0.55 * 1.5) / 1.8) < 1e-12);
  assert.equal(pairedRatio(strata, notRun('missing'), 'wallSeconds'), null);
  assert.equal(pairedRatio(summarize([run(1, 1, 1, 1)]), cura, 'wallSeconds'), null);
});

test('relativeToGrid and supportRow divide round by round', () => {
  const rows = relativeToGrid([
    { pattern: 'grid', strata: ok([2, 4]) },
    { pattern: 'gyroid', strata: ok([3, 6]) },
    { pattern: 'lightning', strata: notRun('skipped') },
  ]);
  assert.deepEqual(
    rows.map((r) => r.relativeToGrid),
    [1, 1.5, null],
  );
  assert.deepEqual(
    rows.map((r) => r.cpuRelativeToGrid),
    [1, 1.5, null],
  );
  const s = supportRow('spot.stl', ok([1, 1]), ok([1.2, 1.4]), ok([2, 2]));
  assert.ok(Math.abs(s.wallRatio.normal! - 1.3) < 1e-12);
  assert.equal(s.wallRatio.tree, 2);
});

test('wallsRow: variable over classic round by round, over CuraEngine median over median', () => {
  const cura = ok([2, 2.5, 10], 60, 2); // median 2.5 s wall, 5 s CPU; its rounds are of another block
  const w = wallsRow('3DBenchy.stl', ok([1.2, 2.2, 1.1]), ok([1, 2, 1]), cura);
  assert.equal(w.model, '3DBenchy.stl');
  assert.ok(Math.abs(w.wallRatio! - 1.1) < 1e-12, 'median of 1.2, 1.1, 1.1');
  assert.ok(Math.abs(w.cpuRatio! - 1.1) < 1e-12);
  assert.ok(Math.abs(w.curaWallRatio! - 1.2 / 2.5) < 1e-12, 'median 1.2 s over median 2.5 s');
  assert.ok(Math.abs(w.curaCpuRatio! - (1.2 * 1.5) / 5) < 1e-12);
  assert.equal(w.cura, cura);
  // no CuraEngine (not installed, or no row for the model), or a failed run: no ratio to it
  const none = wallsRow('BridgeTest.stl', ok([1]), ok([1]), null);
  assert.equal(none.cura, null);
  assert.equal(none.curaWallRatio, null);
  assert.equal(none.wallRatio, 1);
  assert.equal(wallsRow('BridgeTest.stl', ok([1]), ok([1]), notRun('missing')).curaCpuRatio, null);
  const failed = wallsRow('BridgeTest.stl', ok([1]), summarize([run(1, 1, 1, 1)]), cura);
  assert.equal(failed.wallRatio, null);
  assert.equal(failed.cpuRatio, null);
  assert.equal(failed.curaWallRatio, 0.4, 'variable ran, so its ratio to CuraEngine stands');
  assert.equal(wallsRow('x', summarize([run(1, 1, 1, 1)]), ok([1]), cura).curaWallRatio, null);
});

test('ratioOfMedians: null unless both ran fine and both have the figure', () => {
  assert.equal(ratioOfMedians(ok([1, 3, 2]), ok([4, 4]), 'wallSeconds'), 0.5);
  assert.equal(ratioOfMedians(summarize([run(1, null, null)]), ok([1]), 'cpuSeconds'), null);
  assert.equal(ratioOfMedians(ok([1]), notRun('skipped'), 'wallSeconds'), null);
});

test('triangleScaling: time per triangle of a model and of its subdivided copy', () => {
  const row = (model: string, triangles: number, wall: number): ModelRow => ({
    model,
    triangles,
    strata: ok([wall]),
    cura: notRun('missing'),
    prusa: notRun('missing'),
    wallRatio: null,
    cpuRatio: null,
  });
  const ts = triangleScaling(
    [row('3DBenchy.stl', 200_000, 2), row('3DBenchy-x4.stl', 800_000, 3)],
    '3DBenchy.stl',
    '3DBenchy-x4.stl',
  )!;
  assert.equal(ts.small.microsPerTriangle, 10);
  assert.equal(ts.big.microsPerTriangle, 3.75);
  assert.equal(ts.wallRatio, 1.5);
  assert.equal(ts.triangleRatio, 4);
  assert.equal(triangleScaling([row('3DBenchy.stl', 200_000, 2)], '3DBenchy.stl', '3DBenchy-x4.stl'), null);
});

function sampleReport(over: Partial<BenchReport> = {}): BenchReport {
  const benchyStrata = ok([1.6, 1.7, 1.67], 159);
  const benchyCura = ok([1.3, 1.31, 1.35], 59);
  const report: BenchReport = {
    startedAt: '2026-01-01T00:00:00.000Z',
    machine: { cpus: 2, cpuModel: 'Test CPU', node: 'v20', platform: 'linux x64' },
    load: {
      cpus: 2,
      busyAbove: 0.7,
      before: 0.1,
      blocks: [{ label: '3DBenchy.stl', seconds: 30, loadAverage: 1.8, foreignShare: 0.01 }],
    },
    warnings: [],
    repeat: 3,
    warmup: 1,
    threads: null,
    curaThreads: 2,
    memoryMethod: 'gnu-time',
    cpuMeasured: true,
    strataCli: { path: '/repo/dist/cli/main.js', built: true },
    peers: {
      cura: {
        path: '/usr/bin/CuraEngine',
        version: 'Cura_SteamEngine version 4.13.0',
        definitions: '/defs/fdmprinter.def.json',
      },
      prusa: null,
    },
    models: [
      {
        model: '3DBenchy.stl',
        triangles: 225154,
        strata: benchyStrata,
        cura: benchyCura,
        prusa: notRun('missing'),
        wallRatio: pairedRatio(benchyStrata, benchyCura, 'wallSeconds'),
        cpuRatio: pairedRatio(benchyStrata, benchyCura, 'cpuSeconds'),
      },
      {
        model: '3DBenchy.3mf',
        triangles: 225154,
        strata: { ...notRun('skipped'), status: 'failed', message: 'exit code 1: no 3MF' },
        cura: notRun('unsupported'),
        prusa: notRun('missing'),
        wallRatio: null,
        cpuRatio: null,
      },
    ],
    threadScaling: {
      model: '3DBenchy.stl',
      one: ok([2, 2]),
      two: ok([1.5, 1.6]),
      speedup: 1.29,
      cpuRatio: 1.1,
      gcodeIdentical: true,
    },
    patternModel: '3DBenchy.stl',
    patterns: relativeToGrid([
      { pattern: 'grid', strata: ok([1.5]) },
      { pattern: 'gyroid', strata: ok([3]) },
    ]),
    support: [supportRow('spot.stl', ok([1]), ok([1.2]), ok([1.4]))],
    walls: [wallsRow('3DBenchy.stl', ok([1.2, 1.4], 100, 2), ok([1, 1]), benchyCura)],
    triangleScaling: null,
    targets: [],
    notes: [],
    ...over,
  };
  report.targets = checkTargets(report);
  return report;
}

test('renderReport: the README table (wall / CPU / peak, ratios), statuses, sections, targets, failure notes', () => {
  const text = renderReport(sampleReport());
  const lines = text.split('\n');
  assert.match(text, /3 counted runs per slicer after 1 warm-up round, interleaved/);
  const cells = (line: string) =>
    line
      .split('|')
      .map((c) => c.trim())
      .filter((c) => c !== '');
  assert.deepEqual(cells(lines.find((l) => l.startsWith('| model'))!), [
    'model',
    'Strata wall / CPU / peak',
    'CuraEngine wall / CPU / peak',
    'wall ratio',
    'CPU ratio',
    'PrusaSlicer wall',
  ]);
  assert.match(lines[lines.findIndex((l) => l.startsWith('| model')) + 1]!, /^\|:-+\|(-+:\|){5}$/);
  const benchy = lines.find((l) => l.startsWith('| 3DBenchy.stl'))!;
  assert.deepEqual(cells(benchy), [
    '3DBenchy.stl (225 k)',
    '1.67 s / 2.50 s / 159 MiB',
    '1.31 s / 1.97 s / 59 MiB',
    '1.24×',
    '1.24×',
    '–',
  ]);
  const threeMf = lines.find((l) => l.startsWith('| 3DBenchy.3mf'))!;
  assert.match(threeMf, /failed/);
  assert.match(threeMf, /n\/a/);
  assert.match(text, /### Threads on 3DBenchy\.stl/);
  assert.match(text, /\| 2 +\| 1\.55 s \/ 2\.33 s \/ 100 MiB \| +1\.29× \| 1\.10× \|/);
  assert.match(text, /byte-identical/);
  assert.match(text, /### Infill patterns on 3DBenchy\.stl/);
  assert.match(text, /\| gyroid +\| 3\.00 s \/ 4\.50 s \/ 100 MiB \| +2\.00× \| +2\.00× \|/);
  assert.match(
    text,
    /\| spot\.stl \| 1\.00 s \/ 1\.50 s \| 1\.20 s \/ 1\.80 s \| +1\.20× \/ 1\.20× \| 1\.40 s \/ 2\.10 s \| +1\.40× \/ 1\.40× \|/,
  );
  assert.match(text, /### Walls \(--wall-generator variable against classic, and against CuraEngine; wall \/ CPU\)/);
  assert.deepEqual(cells(lines.find((l) => l.startsWith('| model') && l.includes('variable vs classic'))!), [
    'model',
    'variable',
    'classic',
    'variable vs classic',
    'CuraEngine',
    'variable vs CuraEngine',
  ]);
  const wallsLine = lines.filter((l) => l.startsWith('| 3DBenchy.stl'))[1]!;
  assert.deepEqual(cells(wallsLine), [
    '3DBenchy.stl',
    '1.30 s / 2.60 s',
    '1.00 s / 1.50 s',
    '1.30× / 1.73×',
    '1.31 s / 1.97 s',
    '0.99× / 1.32×',
  ]);
  assert.match(text, /against CuraEngine: variable's median over CuraEngine's from the models table/);
  assert.match(text, /### Targets/);
  assert.match(
    text,
    /\| wall, variable walls \/ classic, 3DBenchy\.stl +\| ≤ 1\.25× +\| worst 1\.30× \(3DBenchy\.stl\) +\| ✗ +\|/,
  );
  assert.match(
    text,
    /\| wall, variable walls \/ CuraEngine, 3DBenchy\.stl +\| ≤ 1\.00× +\| worst 0\.99× \(3DBenchy\.stl\) +\| ✓ +\|/,
  );
  assert.match(text, /\| wall, Strata \/ CuraEngine, 3DBenchy\.stl +\| ≤ 0\.75× +\| 1\.24× +\| ✗ +\|/);
  assert.match(text, /\| peak memory, Strata, 3DBenchy\.stl +\| ≤ 120 MiB +\| 159 MiB +\| ✗ +\|/);
  assert.match(
    text,
    /\| every infill pattern \/ grid, 3DBenchy\.stl +\| ≤ 1\.50× +\| worst 2\.00× \(gyroid\) +\| ✗ +\|/,
  );
  assert.match(
    text,
    /\| support \(normal, tree\) \/ none, spot\.stl +\| ≤ 1\.50× +\| worst 1\.40× \(tree, spot\.stl\) +\| ✓ +\|/,
  );
  assert.match(text, /targets met/);
  assert.match(text, /Strata on 3DBenchy\.3mf: exit code 1: no 3MF/);
  assert.match(text, /PrusaSlicer: not run/);
  assert.match(text, /1-minute load average 0\.10 before the start \(idle/);
  assert.doesNotMatch(text, /Warning/);
});

test('renderReport puts load warnings at the top', () => {
  const text = renderReport(
    sampleReport({ warnings: ['the machine is busy: 1-minute load average 2.50 before the start'] }),
  );
  assert.match(text.split('\n')[0]!, /^> \*\*Warning:\*\* the machine is busy: 1-minute load average 2\.50/);
  assert.match(text, /on a busy machine: see the warning above/);
});

test('renderReport says clearly when the Strata CLI is not built', () => {
  const text = renderReport(
    sampleReport({
      strataCli: { path: '/repo/dist/cli/main.js', built: false },
      models: [
        {
          model: 'cube.stl',
          triangles: 12,
          strata: notRun('missing', 'strata CLI not built'),
          cura: ok([0.1]),
          prusa: notRun('missing'),
          wallRatio: null,
          cpuRatio: null,
        },
      ],
      threadScaling: null,
      patternModel: null,
      patterns: [],
      support: [],
      walls: [],
    }),
  );
  assert.match(text, /Strata: not built: \/repo\/dist\/cli\/main\.js is missing/);
  assert.match(text.split('\n').find((l) => l.startsWith('| cube.stl'))!, /not built/);
  assert.doesNotMatch(text, /Infill patterns|### Threads|### Support|### Walls/);
});

test('renderReport: the walls section without CuraEngine has no CuraEngine columns; failed runs become notes', () => {
  const text = renderReport(
    sampleReport({
      peers: { cura: null, prusa: null },
      walls: [
        wallsRow('3DBenchy.stl', ok([1.1]), ok([1]), notRun('missing')),
        wallsRow('HollowCalibrationCube.stl', ok([0.5]), summarize([run(0.2, 0.2, 50, 1)]), notRun('missing')),
      ],
    }),
  );
  const lines = text.split('\n');
  const cells = (line: string) =>
    line
      .split('|')
      .map((c) => c.trim())
      .filter((c) => c !== '');
  assert.match(text, /### Walls \(--wall-generator variable against classic; wall \/ CPU\)/);
  assert.deepEqual(cells(lines.find((l) => l.startsWith('| model') && l.includes('variable vs classic'))!), [
    'model',
    'variable',
    'classic',
    'variable vs classic',
  ]);
  assert.deepEqual(cells(lines.find((l) => l.startsWith('| HollowCalibrationCube.stl'))!), [
    'HollowCalibrationCube.stl',
    '0.50 s / 0.75 s',
    'failed',
    '– / –',
  ]);
  assert.doesNotMatch(text, /variable's median over CuraEngine's/);
  assert.match(text, /Strata --wall-generator classic on HollowCalibrationCube\.stl: exit code 1: error: broken mesh/);
  assert.match(
    text,
    /\| wall, variable walls \/ classic, 3DBenchy\.stl, HollowCalibrationCube\.stl +\| ≤ 1\.25× +\| no figure for HollowCalibrationCube\.stl \(classic failed\) +\| – +\|/,
  );
  assert.match(
    text,
    /\| wall, variable walls \/ CuraEngine, 3DBenchy\.stl, HollowCalibrationCube\.stl +\| ≤ 1\.00× +\| no CuraEngine +\| – +\|/,
  );
});

test('figuresCell: wall / CPU / peak, with placeholders for what was not measurable', () => {
  assert.equal(figuresCell(ok([1.666], 159.4)), '1.67 s / 2.50 s / 159 MiB');
  assert.equal(figuresCell(summarize([run(0.5, null, null)])), '0.50 s / – / –');
  assert.equal(figuresCell(notRun('unsupported')), 'n/a');
});
