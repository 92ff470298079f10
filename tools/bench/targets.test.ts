import { test } from 'node:test';
import assert from 'node:assert/strict';
import { notRun, relativeToGrid, summarize, supportRow, wallsRow, type ModelRow, type SlicerStats } from './report.js';
import { checkTargets, TARGETS, type TargetRow } from './targets.js';

const stats = (wallSeconds: number, peakMiB = 100): SlicerStats =>
  summarize([
    {
      exitCode: 0,
      signal: null,
      timedOut: false,
      spawnError: null,
      wallSeconds,
      cpuSeconds: wallSeconds,
      peakMiB,
      stderrTail: '',
    },
  ]);
const row = (
  model: string,
  wallRatio: number | null,
  cpuRatio: number | null,
  strata = stats(1),
  cura: SlicerStats = stats(1),
): ModelRow => ({ model, triangles: 1000, strata, cura, prusa: notRun('missing'), wallRatio, cpuRatio });

type Figures = Parameters<typeof checkTargets>[0];

/** Figures that meet every target, each right at its limit. */
function atLimits(): Figures {
  return {
    models: [
      row('3DBenchy.stl', 0.75, 1.0, stats(1, 120)),
      row('stanford-bunny.stl', 0.75, 0.9),
      row('3DBenchy-x4.stl', 0.75, 0.9),
      row('spot.stl', 1.0, 1.2),
      row('CalibrationCube.stl', 3, 3, stats(0.2)),
    ],
    threadScaling: {
      model: '3DBenchy.stl',
      one: stats(1.3),
      two: stats(1),
      speedup: 1.3,
      cpuRatio: 1.1,
      gcodeIdentical: true,
    },
    patternModel: '3DBenchy.stl',
    patterns: relativeToGrid([
      { pattern: 'grid', strata: stats(2) },
      { pattern: 'gyroid', strata: stats(3) },
      { pattern: 'lines', strata: stats(1.8) },
    ]),
    support: [supportRow('spot.stl', stats(2), stats(3), stats(2.5))],
    walls: [
      wallsRow('3DBenchy.stl', stats(1.25), stats(1), stats(1.25)),
      wallsRow('HollowCalibrationCube.stl', stats(1.1), stats(1), stats(2)),
    ],
    triangleScaling: {
      small: { model: '3DBenchy.stl', triangles: 225154, wallSeconds: 1, microsPerTriangle: 4.4 },
      big: { model: '3DBenchy-x4.stl', triangles: 900616, wallSeconds: 4, microsPerTriangle: 4.4 },
      wallRatio: 4,
      triangleRatio: 4,
    },
  };
}

const verdicts = (rows: TargetRow[]) => rows.map((r) => r.verdict);
const find = (rows: TargetRow[], re: RegExp) => rows.find((r) => re.test(r.figure))!;

test('every target at its limit holds, and the table names the figures the issue names', () => {
  const rows = checkTargets(atLimits());
  assert.deepEqual(
    verdicts(rows),
    rows.map(() => 'pass'),
    JSON.stringify(rows, null, 1),
  );
  assert.deepEqual(
    rows.map((r) => `${r.figure}: ${r.target}`),
    [
      'wall, Strata / CuraEngine, 3DBenchy.stl: ≤ 0.75×',
      'wall, Strata / CuraEngine, stanford-bunny.stl: ≤ 0.75×',
      'wall, Strata / CuraEngine, 3DBenchy-x4.stl: ≤ 0.75×',
      'wall, Strata / CuraEngine, spot.stl: ≤ 1.00×',
      "wall, Strata, CalibrationCube.stl (node's start included): ≤ 0.20 s",
      'CPU, Strata / CuraEngine, 3DBenchy.stl: ≤ 1.00×',
      'peak memory, Strata, 3DBenchy.stl: ≤ 120 MiB',
      'speed-up, 2 threads over 1, 3DBenchy.stl: ≥ 1.30×',
      'G-code, 1 thread = 2 threads = default: byte-identical',
      'every infill pattern / grid, 3DBenchy.stl: ≤ 1.50×',
      'support (normal, tree) / none, spot.stl: ≤ 1.50×',
      'wall, variable walls / classic, 3DBenchy.stl, HollowCalibrationCube.stl: ≤ 1.25×',
      'wall, variable walls / CuraEngine, 3DBenchy.stl, HollowCalibrationCube.stl: ≤ 1.00×',
      'wall, 3DBenchy-x4.stl / 3DBenchy.stl (4× the triangles): ≤ 4.00× (linear)',
    ],
  );
  assert.equal(find(rows, /every infill/).measured, 'worst 1.50× (gyroid)');
  assert.equal(find(rows, /support/).measured, 'worst 1.50× (normal, spot.stl)');
  assert.equal(find(rows, /variable walls \/ classic/).measured, 'worst 1.25× (3DBenchy.stl)');
  assert.equal(find(rows, /variable walls \/ CuraEngine/).measured, 'worst 1.00× (3DBenchy.stl)');
});

test('each target fails just past its limit', () => {
  const f = atLimits();
  f.models = [
    row('3DBenchy.stl', 0.76, 1.01, stats(1, 121)),
    row('stanford-bunny.stl', 0.751, 0.9),
    row('3DBenchy-x4.stl', 1.2, 0.9),
    row('spot.stl', 1.01, 1.2),
    row('CalibrationCube.stl', 3, 3, stats(0.201)),
  ];
  f.threadScaling = { ...f.threadScaling!, speedup: 1.29, gcodeIdentical: false };
  f.patterns = relativeToGrid([
    { pattern: 'grid', strata: stats(2) },
    { pattern: 'lightning', strata: stats(3.1) },
  ]);
  f.support = [supportRow('SupportTest.stl', stats(2), stats(2.2), stats(3.2))];
  f.walls = [
    wallsRow('HollowCalibrationCube.stl', stats(1.1), stats(1), stats(2)),
    wallsRow('BridgeTest.stl', stats(1.26), stats(1), stats(1.2)),
  ];
  f.triangleScaling = { ...f.triangleScaling!, wallRatio: 4.2 };
  const rows = checkTargets(f);
  assert.deepEqual(
    verdicts(rows),
    rows.map(() => 'fail'),
    JSON.stringify(rows, null, 1),
  );
  assert.equal(find(rows, /every infill/).measured, 'worst 1.55× (lightning)');
  assert.equal(find(rows, /support/).measured, 'worst 1.60× (tree, SupportTest.stl)');
  assert.equal(find(rows, /G-code/).measured, 'different');
  assert.equal(find(rows, /variable walls \/ classic/).measured, 'worst 1.26× (BridgeTest.stl)');
  assert.equal(find(rows, /variable walls \/ CuraEngine/).measured, 'worst 1.05× (BridgeTest.stl)');
  assert.equal(find(rows, /CalibrationCube/).measured, '0.20 s', 'shown rounded, judged exactly');
});

test('figures a run did not produce are "missing", with the reason', () => {
  const empty: Figures = {
    models: [],
    threadScaling: null,
    patternModel: null,
    patterns: [],
    support: [],
    walls: [],
    triangleScaling: null,
  };
  const rows = checkTargets(empty);
  assert.ok(rows.every((r) => r.verdict === 'missing'));
  assert.ok(
    rows.every((r) => /not (run|compared)/.test(r.measured)),
    JSON.stringify(rows.map((r) => r.measured)),
  );
  // Strata ran but CuraEngine is not installed (CI): the ratio rows say so, Strata's own figures are judged
  const noPeer = checkTargets({
    ...empty,
    models: [
      row('3DBenchy.stl', null, null, stats(1, 100), notRun('missing')),
      row('CalibrationCube.stl', null, null, stats(0.1), notRun('missing')),
    ],
  });
  assert.equal(find(noPeer, /wall, Strata \/ CuraEngine, 3DBenchy/).measured, 'no CuraEngine');
  assert.equal(find(noPeer, /peak memory/).verdict, 'pass');
  assert.equal(find(noPeer, /CalibrationCube/).verdict, 'pass');
  // a pattern without a figure leaves the pattern verdict open rather than judging the others
  const partial = checkTargets({
    ...empty,
    patternModel: '3DBenchy.stl',
    patterns: relativeToGrid([
      { pattern: 'grid', strata: stats(1) },
      { pattern: 'gyroid', strata: notRun('skipped') },
    ]),
  });
  assert.equal(find(partial, /every infill/).verdict, 'missing');
  assert.match(find(partial, /every infill/).measured, /no figure for gyroid/);
  // the walls section without CuraEngine: variable against classic judged, against CuraEngine says why not
  const noCura = checkTargets({
    ...empty,
    walls: [
      wallsRow('3DBenchy.stl', stats(1.2), stats(1), notRun('missing')),
      wallsRow('BridgeTest.stl', stats(1), stats(1), notRun('missing')),
    ],
  });
  assert.equal(find(noCura, /variable walls \/ classic/).verdict, 'pass');
  assert.equal(find(noCura, /variable walls \/ CuraEngine/).verdict, 'missing');
  assert.equal(find(noCura, /variable walls \/ CuraEngine/).measured, 'no CuraEngine');
  // CuraEngine on one model only (it reads no 3MF), a failed classic run: open verdicts naming the model and why
  const mixed = checkTargets({
    ...empty,
    walls: [
      wallsRow('3DBenchy.3mf', stats(1), stats(1), notRun('unsupported')),
      wallsRow(
        'BridgeTest.stl',
        stats(1),
        summarize([
          {
            exitCode: 1,
            signal: null,
            timedOut: false,
            spawnError: null,
            wallSeconds: 1,
            cpuSeconds: 1,
            peakMiB: 1,
            stderrTail: 'x',
          },
        ]),
        stats(2),
      ),
    ],
  });
  assert.equal(find(mixed, /variable walls \/ classic/).verdict, 'missing');
  assert.equal(find(mixed, /variable walls \/ classic/).measured, 'no figure for BridgeTest.stl (classic failed)');
  assert.equal(find(mixed, /variable walls \/ CuraEngine/).verdict, 'missing');
  assert.equal(
    find(mixed, /variable walls \/ CuraEngine/).measured,
    'no figure for 3DBenchy.3mf (CuraEngine unsupported)',
  );
  assert.equal(
    checkTargets({ ...empty, walls: [wallsRow('3DBenchy.stl', stats(1), stats(1), null)] }).find(
      (r) => /CuraEngine, 3DBenchy/.test(r.figure) && /walls/.test(r.figure),
    )!.measured,
    'CuraEngine not run',
  );
});

test("the limits are the issue's", () => {
  assert.deepEqual(
    { ...TARGETS },
    {
      wallRatioVsCura: 0.75,
      wallRatioVsCuraSpot: 1,
      cubeWallSeconds: 0.2,
      cpuRatioVsCuraBenchy: 1,
      benchyPeakMiB: 120,
      twoThreadSpeedup: 1.3,
      patternRatioVsGrid: 1.5,
      supportRatioVsNone: 1.5,
      variableWallsRatioVsClassic: 1.25,
      variableWallsRatioVsCura: 1,
    },
  );
});
