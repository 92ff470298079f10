/**
 * The speed targets of issue 11 ("Faster than CuraEngine on every model, from a cold start, on both cores"), and
 * those of the variable-width walls (against classic walls and CuraEngine), with their verdicts from a benchmark's
 * figures. Pure: the report's data in, table rows out.
 */
import type { BenchReport, ModelRow, SlicerStats, WallsRow } from './report.js';
import { formatMiB, formatRatio, formatSeconds } from './stats.js';

/** The limits, each with its unit in the name. */
export const TARGETS = Object.freeze({
  /** Strata wall / CuraEngine wall on 3DBenchy, the bunny and the ~1 M-triangle mesh. */
  wallRatioVsCura: 0.75,
  /** … and on spot. */
  wallRatioVsCuraSpot: 1.0,
  /** Strata's wall time on the calibration cube, node's start included. */
  cubeWallSeconds: 0.2,
  /** Strata CPU / CuraEngine CPU on 3DBenchy. */
  cpuRatioVsCuraBenchy: 1.0,
  /** Strata's peak resident memory on 3DBenchy at the default thread count. */
  benchyPeakMiB: 120,
  /** 1-thread wall / 2-thread wall on 3DBenchy. */
  twoThreadSpeedup: 1.3,
  /** Any infill pattern's wall / grid's on 3DBenchy. */
  patternRatioVsGrid: 1.5,
  /** Wall with support (normal or tree) / without. */
  supportRatioVsNone: 1.5,
  /** Wall with variable walls / with classic walls (--wall-generator), on every model of the walls section. */
  variableWallsRatioVsClassic: 1.25,
  /** Wall with variable walls / CuraEngine's, on every model of the walls section CuraEngine ran on. */
  variableWallsRatioVsCura: 1.0,
});

/** The models the targets name (file names as the bench reports them). */
export const TARGET_MODELS = Object.freeze({
  benchy: '3DBenchy.stl',
  bunny: 'stanford-bunny.stl',
  spot: 'spot.stl',
  cube: 'CalibrationCube.stl',
  big: '3DBenchy-x4.stl',
});

export type Verdict = 'pass' | 'fail' | 'missing';

export interface TargetRow {
  figure: string;
  target: string;
  /** What was measured, or why nothing was ("not run"). */
  measured: string;
  verdict: Verdict;
}

type Figures = Pick<
  BenchReport,
  'models' | 'threadScaling' | 'patterns' | 'patternModel' | 'support' | 'walls' | 'triangleScaling'
>;

const verdict = (ok: boolean): Verdict => (ok ? 'pass' : 'fail');

function row(
  figure: string,
  target: string,
  value: number | null,
  holds: (v: number) => boolean,
  show: (v: number) => string,
  why = 'not run',
): TargetRow {
  return value === null
    ? { figure, target, measured: why, verdict: 'missing' }
    : { figure, target, measured: show(value), verdict: verdict(holds(value)) };
}

/**
 * A target on the largest of one ratio per walls row: judged only when every row has it, else "missing" with
 * the rows lacking it (and why, when `why` says).
 */
function worstWallsRow(
  figure: string,
  limit: number,
  walls: readonly WallsRow[],
  ratio: (r: WallsRow) => number | null,
  why: (r: WallsRow) => string,
): TargetRow {
  const target = `≤ ${formatRatio(limit)}`;
  const models = walls.map((r) => r.model).join(', ');
  if (walls.length === 0) return { figure, target, measured: 'not run', verdict: 'missing' };
  const unmeasured = walls.filter((r) => ratio(r) === null);
  if (unmeasured.length > 0) {
    const reasons = unmeasured.map(why);
    const measured =
      unmeasured.length === walls.length && reasons.every((w) => w === reasons[0])
        ? reasons[0]!
        : `no figure for ${unmeasured.map((r, i) => `${r.model} (${reasons[i]})`).join(', ')}`;
    return { figure: `${figure}, ${models}`, target, measured, verdict: 'missing' };
  }
  const worst = walls.reduce((a, r) => (ratio(r)! > ratio(a)! ? r : a));
  return row(
    `${figure}, ${models}`,
    target,
    ratio(worst),
    (v) => v <= limit,
    (v) => `worst ${formatRatio(v)} (${worst.model})`,
  );
}

const notOk = (who: string, s: SlicerStats) =>
  s.status === 'missing' && who === 'CuraEngine' ? 'no CuraEngine' : `${who} ${s.status}`;

/** Each target with its verdict. A figure the run did not produce (model not selected, peer missing) is "missing". */
export function checkTargets(report: Figures): TargetRow[] {
  const model = (name: string): ModelRow | undefined => report.models.find((m) => m.model === name);
  const rows: TargetRow[] = [];
  const T = TARGETS;
  const M = TARGET_MODELS;

  const whyNoRatio = (name: string) => {
    const m = model(name);
    if (!m) return 'not run';
    if (m.strata.status !== 'ok') return `Strata ${m.strata.status}`;
    if (m.cura.status !== 'ok') return m.cura.status === 'missing' ? 'no CuraEngine' : `CuraEngine ${m.cura.status}`;
    return 'not measured';
  };
  for (const [name, limit] of [
    [M.benchy, T.wallRatioVsCura],
    [M.bunny, T.wallRatioVsCura],
    [M.big, T.wallRatioVsCura],
    [M.spot, T.wallRatioVsCuraSpot],
  ] as const) {
    rows.push(
      row(
        `wall, Strata / CuraEngine, ${name}`,
        `≤ ${formatRatio(limit)}`,
        model(name)?.wallRatio ?? null,
        (v) => v <= limit,
        formatRatio,
        whyNoRatio(name),
      ),
    );
  }

  const cube = model(M.cube)?.strata;
  rows.push(
    row(
      `wall, Strata, ${M.cube} (node's start included)`,
      `≤ ${formatSeconds(T.cubeWallSeconds)}`,
      cube?.status === 'ok' ? cube.wallSeconds : null,
      (v) => v <= T.cubeWallSeconds,
      (v) => formatSeconds(v),
    ),
  );

  rows.push(
    row(
      `CPU, Strata / CuraEngine, ${M.benchy}`,
      `≤ ${formatRatio(T.cpuRatioVsCuraBenchy)}`,
      model(M.benchy)?.cpuRatio ?? null,
      (v) => v <= T.cpuRatioVsCuraBenchy,
      formatRatio,
      whyNoRatio(M.benchy),
    ),
  );

  const benchy = model(M.benchy)?.strata;
  rows.push(
    row(
      `peak memory, Strata, ${M.benchy}`,
      `≤ ${formatMiB(T.benchyPeakMiB)}`,
      benchy?.status === 'ok' ? benchy.peakMiB : null,
      (v) => v <= T.benchyPeakMiB,
      (v) => formatMiB(v),
    ),
  );

  const threads = report.threadScaling;
  rows.push(
    row(
      `speed-up, 2 threads over 1, ${threads?.model ?? M.benchy}`,
      `≥ ${formatRatio(T.twoThreadSpeedup)}`,
      threads?.speedup ?? null,
      (v) => v >= T.twoThreadSpeedup,
      formatRatio,
    ),
  );
  rows.push({
    figure: 'G-code, 1 thread = 2 threads = default',
    target: 'byte-identical',
    measured:
      threads?.gcodeIdentical === true ? 'identical' : threads?.gcodeIdentical === false ? 'different' : 'not compared',
    verdict: threads?.gcodeIdentical === true ? 'pass' : threads?.gcodeIdentical === false ? 'fail' : 'missing',
  });

  const patterns = report.patterns.filter((p) => p.pattern !== 'grid');
  const worstPattern = patterns.reduce<(typeof patterns)[number] | null>(
    (a, p) =>
      p.relativeToGrid === null
        ? a
        : a === null || a.relativeToGrid === null || p.relativeToGrid > a.relativeToGrid
          ? p
          : a,
    null,
  );
  const unmeasuredPatterns = patterns.filter((p) => p.relativeToGrid === null).map((p) => p.pattern);
  rows.push(
    unmeasuredPatterns.length > 0 || !worstPattern
      ? {
          figure: `every infill pattern / grid, ${report.patternModel ?? M.benchy}`,
          target: `≤ ${formatRatio(T.patternRatioVsGrid)}`,
          measured: patterns.length === 0 ? 'not run' : `no figure for ${unmeasuredPatterns.join(', ')}`,
          verdict: 'missing',
        }
      : row(
          `every infill pattern / grid, ${report.patternModel ?? M.benchy}`,
          `≤ ${formatRatio(T.patternRatioVsGrid)}`,
          worstPattern.relativeToGrid,
          (v) => v <= T.patternRatioVsGrid,
          (v) => `worst ${formatRatio(v)} (${worstPattern.pattern})`,
        ),
  );

  const supportRatios = report.support.flatMap((s) =>
    (['normal', 'tree'] as const).map((kind) => ({ model: s.model, kind, ratio: s.wallRatio[kind] })),
  );
  const worstSupport = supportRatios.reduce<(typeof supportRatios)[number] | null>(
    (a, s) => (s.ratio === null ? a : a === null || a.ratio === null || s.ratio > a.ratio ? s : a),
    null,
  );
  const unmeasuredSupport = supportRatios.filter((s) => s.ratio === null).map((s) => `${s.kind} on ${s.model}`);
  const supportModels = report.support.map((s) => s.model).join(', ');
  rows.push(
    unmeasuredSupport.length > 0 || !worstSupport
      ? {
          figure: 'support (normal, tree) / none',
          target: `≤ ${formatRatio(T.supportRatioVsNone)}`,
          measured: supportRatios.length === 0 ? 'not run' : `no figure for ${unmeasuredSupport.join(', ')}`,
          verdict: 'missing',
        }
      : row(
          `support (normal, tree) / none, ${supportModels}`,
          `≤ ${formatRatio(T.supportRatioVsNone)}`,
          worstSupport.ratio,
          (v) => v <= T.supportRatioVsNone,
          (v) => `worst ${formatRatio(v)} (${worstSupport.kind}, ${worstSupport.model})`,
        ),
  );

  rows.push(
    worstWallsRow(
      'wall, variable walls / classic',
      T.variableWallsRatioVsClassic,
      report.walls,
      (r) => r.wallRatio,
      (r) =>
        r.variable.status !== 'ok'
          ? notOk('variable', r.variable)
          : r.classic.status !== 'ok'
            ? notOk('classic', r.classic)
            : 'not measured',
    ),
  );
  rows.push(
    worstWallsRow(
      'wall, variable walls / CuraEngine',
      T.variableWallsRatioVsCura,
      report.walls,
      (r) => r.curaWallRatio,
      (r) =>
        r.variable.status !== 'ok'
          ? notOk('variable', r.variable)
          : r.cura === null
            ? 'CuraEngine not run'
            : r.cura.status !== 'ok'
              ? notOk('CuraEngine', r.cura)
              : 'not measured',
    ),
  );

  const ts = report.triangleScaling;
  rows.push(
    ts
      ? row(
          `wall, ${ts.big.model} / ${ts.small.model} (${ts.triangleRatio.toFixed(0)}× the triangles)`,
          `≤ ${formatRatio(ts.triangleRatio)} (linear)`,
          ts.wallRatio,
          (v) => v <= ts.triangleRatio,
          formatRatio,
        )
      : { figure: `wall, ${M.big} / ${M.benchy}`, target: '≤ 4.00× (linear)', measured: 'not run', verdict: 'missing' },
  );
  return rows;
}
