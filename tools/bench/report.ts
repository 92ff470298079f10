/**
 * The benchmark's results as data (also what --json prints), the figures derived from them, and their
 * rendering as Markdown. Pure: no I/O.
 */
import type { LoadReport } from './load.js';
import { FOREIGN_CPU_MAX_SHARE, overallForeignShare } from './load.js';
import type { MemoryMethod, Measurement } from './measure.js';
import { failureReason } from './measure.js';
import {
  formatMiB,
  formatRatio,
  formatSeconds,
  formatTriangles,
  markdownTable,
  median,
  medianOfRatios,
} from './stats.js';
import type { TargetRow } from './targets.js';

/**
 * ok: every run succeeded. failed/timeout: a run failed (no more runs were tried). missing: the slicer is not
 * installed or built. unsupported: the slicer does not read this file type. skipped: not run (e.g. interrupted).
 */
export type RunStatus = 'ok' | 'failed' | 'timeout' | 'missing' | 'unsupported' | 'skipped';

/** What one counted run measured. */
export interface RunFigures {
  wallSeconds: number;
  cpuSeconds: number | null;
  peakMiB: number | null;
}

export interface SlicerStats {
  status: RunStatus;
  /** Medians of the counted runs (null unless ok, or when not measurable). */
  wallSeconds: number | null;
  cpuSeconds: number | null;
  peakMiB: number | null;
  /** Each counted run in round order (a failed run last). */
  runs: RunFigures[];
  /** Why it failed, was missing or skipped. */
  message?: string;
}

export interface ModelRow {
  model: string;
  triangles: number | null;
  /** Set for a model the bench made (the subdivided mesh). */
  madeFrom?: string;
  strata: SlicerStats;
  cura: SlicerStats;
  prusa: SlicerStats;
  /** Strata / CuraEngine, median of the per-round ratios. */
  wallRatio: number | null;
  cpuRatio: number | null;
}

export interface ThreadScaling {
  model: string;
  one: SlicerStats;
  two: SlicerStats;
  /** 1-thread wall / 2-thread wall, median of the per-round ratios (> 1: the second thread pays). */
  speedup: number | null;
  /** 2-thread CPU / 1-thread CPU, median of the per-round ratios (the extra work a second thread costs). */
  cpuRatio: number | null;
  /** Whether the G-code of 1 thread, 2 threads and the default was byte-identical; null if any run failed. */
  gcodeIdentical: boolean | null;
}

export interface PatternRow {
  pattern: string;
  strata: SlicerStats;
  /** Wall and CPU over grid's, medians of the per-round ratios (null when either is missing). */
  relativeToGrid: number | null;
  cpuRelativeToGrid: number | null;
}

export type SupportKind = 'normal' | 'tree';

export interface SupportRow {
  model: string;
  none: SlicerStats;
  normal: SlicerStats;
  tree: SlicerStats;
  /** With support over without, medians of the per-round ratios. */
  wallRatio: Record<SupportKind, number | null>;
  cpuRatio: Record<SupportKind, number | null>;
}

export type WallGenerator = 'variable' | 'classic';

/** One model of the walls section: --wall-generator variable against classic, and variable against CuraEngine. */
export interface WallsRow {
  model: string;
  variable: SlicerStats;
  classic: SlicerStats;
  /** Variable over classic, medians of the per-round ratios (the two ran interleaved). */
  wallRatio: number | null;
  cpuRatio: number | null;
  /** CuraEngine on the same model in the models section, or null when that section has no row for it. */
  cura: SlicerStats | null;
  /**
   * Variable's median over CuraEngine's (from the models section): a ratio of medians, not of rounds, since the
   * two ran in different blocks. Null unless both ran fine.
   */
  curaWallRatio: number | null;
  curaCpuRatio: number | null;
}

/** Strata's cost against the triangle count: a model and its subdivided copy (same shape, 4× the triangles). */
export interface TriangleScaling {
  small: { model: string; triangles: number; wallSeconds: number; microsPerTriangle: number };
  big: { model: string; triangles: number; wallSeconds: number; microsPerTriangle: number };
  /** big wall / small wall: at most the triangle ratio when the cost grows at most linearly. */
  wallRatio: number;
  triangleRatio: number;
}

export interface PeerInfo {
  path: string;
  version: string | null;
}

export interface BenchReport {
  startedAt: string;
  machine: { cpus: number; cpuModel: string; node: string; platform: string };
  load: LoadReport;
  /** Load warnings (load.ts loadWarnings); shown at the top. */
  warnings: string[];
  repeat: number;
  warmup: number;
  /** --threads as given (to Strata and CuraEngine), or null: Strata's default, CuraEngine `curaThreads`. */
  threads: number | null;
  curaThreads: number;
  memoryMethod: MemoryMethod;
  /** Whether CPU time came from the kernel's accounting (/proc); false = no CPU figures. */
  cpuMeasured: boolean;
  strataCli: { path: string; built: boolean };
  peers: { cura: (PeerInfo & { definitions: string }) | null; prusa: PeerInfo | null };
  models: ModelRow[];
  threadScaling: ThreadScaling | null;
  /** The model the infill-pattern section ran on, or null when it did not run. */
  patternModel: string | null;
  patterns: PatternRow[];
  support: SupportRow[];
  walls: WallsRow[];
  triangleScaling: TriangleScaling | null;
  targets: TargetRow[];
  notes: string[];
}

/** A SlicerStats that did not run. */
export function notRun(status: Exclude<RunStatus, 'ok' | 'failed' | 'timeout'>, message?: string): SlicerStats {
  const s: SlicerStats = { status, wallSeconds: null, cpuSeconds: null, peakMiB: null, runs: [] };
  if (message !== undefined) s.message = message;
  return s;
}

/** Folds the measurements of repeated runs into medians; the first failure decides a failed status. */
export function summarize(runs: readonly Measurement[]): SlicerStats {
  const figures: RunFigures[] = runs.map((r) => ({
    wallSeconds: r.wallSeconds,
    cpuSeconds: r.cpuSeconds,
    peakMiB: r.peakMiB,
  }));
  const bad = runs.find((r) => failureReason(r) !== '');
  if (bad)
    return {
      status: bad.timedOut ? 'timeout' : 'failed',
      wallSeconds: null,
      cpuSeconds: null,
      peakMiB: null,
      runs: figures,
      message: failureReason(bad),
    };
  if (runs.length === 0) return notRun('skipped');
  const all = (xs: (number | null)[]) => (xs.every((x) => x !== null) ? median(xs as number[]) : null);
  return {
    status: 'ok',
    wallSeconds: median(figures.map((f) => f.wallSeconds)),
    cpuSeconds: all(figures.map((f) => f.cpuSeconds)),
    peakMiB: all(figures.map((f) => f.peakMiB)),
    runs: figures,
  };
}

/** a / b for one figure, as the median of the per-round ratios; null unless both ran fine. */
export function pairedRatio(a: SlicerStats, b: SlicerStats, figure: 'wallSeconds' | 'cpuSeconds'): number | null {
  if (a.status !== 'ok' || b.status !== 'ok') return null;
  return medianOfRatios(
    a.runs.map((r) => r[figure]),
    b.runs.map((r) => r[figure]),
  );
}

/** Pattern rows with their wall and CPU relative to the grid row. */
export function relativeToGrid(rows: readonly { pattern: string; strata: SlicerStats }[]): PatternRow[] {
  const grid = rows.find((r) => r.pattern === 'grid')?.strata;
  return rows.map((r) => ({
    ...r,
    relativeToGrid: grid ? pairedRatio(r.strata, grid, 'wallSeconds') : null,
    cpuRelativeToGrid: grid ? pairedRatio(r.strata, grid, 'cpuSeconds') : null,
  }));
}

/** A support row from the three runs. */
export function supportRow(model: string, none: SlicerStats, normal: SlicerStats, tree: SlicerStats): SupportRow {
  return {
    model,
    none,
    normal,
    tree,
    wallRatio: { normal: pairedRatio(normal, none, 'wallSeconds'), tree: pairedRatio(tree, none, 'wallSeconds') },
    cpuRatio: { normal: pairedRatio(normal, none, 'cpuSeconds'), tree: pairedRatio(tree, none, 'cpuSeconds') },
  };
}

/** a / b of one figure's medians (for runs of different blocks, which pair no rounds); null unless both ran fine. */
export function ratioOfMedians(a: SlicerStats, b: SlicerStats, figure: 'wallSeconds' | 'cpuSeconds'): number | null {
  if (a.status !== 'ok' || b.status !== 'ok') return null;
  const x = a[figure];
  const y = b[figure];
  return x === null || y === null || !(y > 0) ? null : x / y;
}

/** A walls row from the two interleaved runs and CuraEngine's figures on the model (null: none). */
export function wallsRow(
  model: string,
  variable: SlicerStats,
  classic: SlicerStats,
  cura: SlicerStats | null,
): WallsRow {
  return {
    model,
    variable,
    classic,
    wallRatio: pairedRatio(variable, classic, 'wallSeconds'),
    cpuRatio: pairedRatio(variable, classic, 'cpuSeconds'),
    cura,
    curaWallRatio: cura ? ratioOfMedians(variable, cura, 'wallSeconds') : null,
    curaCpuRatio: cura ? ratioOfMedians(variable, cura, 'cpuSeconds') : null,
  };
}

/** Strata's time per triangle on `small` and on `big` (its subdivided copy), when both ran. */
export function triangleScaling(models: readonly ModelRow[], small: string, big: string): TriangleScaling | null {
  const s = models.find((m) => m.model === small);
  const b = models.find((m) => m.model === big);
  const side = (m: ModelRow | undefined) =>
    m && m.triangles && m.strata.status === 'ok' && m.strata.wallSeconds !== null
      ? {
          model: m.model,
          triangles: m.triangles,
          wallSeconds: m.strata.wallSeconds,
          microsPerTriangle: (m.strata.wallSeconds * 1e6) / m.triangles,
        }
      : null;
  const a = side(s);
  const c = side(b);
  if (!a || !c) return null;
  return { small: a, big: c, wallRatio: c.wallSeconds / a.wallSeconds, triangleRatio: c.triangles / a.triangles };
}

// ── rendering ───────────────────────────────────────────────────────────────

const STATUS_CELL: Readonly<Record<Exclude<RunStatus, 'ok'>, string>> = Object.freeze({
  failed: 'failed',
  timeout: 'timeout',
  missing: '–',
  unsupported: 'n/a',
  skipped: 'skipped',
});

function statusCell(s: SlicerStats): string | null {
  return s.status === 'ok' ? null : STATUS_CELL[s.status];
}

/** "1.67 s / 2.71 s / 159 MiB" (wall / CPU / peak), or the status. */
export function figuresCell(s: SlicerStats): string {
  return statusCell(s) ?? `${formatSeconds(s.wallSeconds)} / ${formatSeconds(s.cpuSeconds)} / ${formatMiB(s.peakMiB)}`;
}

function wallCell(s: SlicerStats): string {
  return statusCell(s) ?? formatSeconds(s.wallSeconds);
}

/** "1.67 s / 2.71 s" (wall / CPU), or the status. */
function wallCpuCell(s: SlicerStats): string {
  return statusCell(s) ?? `${formatSeconds(s.wallSeconds)} / ${formatSeconds(s.cpuSeconds)}`;
}

const MEMORY_METHOD_TEXT: Readonly<Record<MemoryMethod, string>> = Object.freeze({
  'gnu-time': 'peak = max RSS from wait4 (/usr/bin/time -f %M)',
  'proc-poll': 'peak = largest VmHWM of /proc/<pid>/status, polled every 10 ms (may miss growth in the last 10 ms)',
  none: 'peak not measurable on this platform',
});

/** Notes about failed runs, one per slicer and job. */
function failureNotes(report: BenchReport): string[] {
  const notes: string[] = [];
  const add = (who: string, what: string, s: SlicerStats) => {
    if ((s.status === 'failed' || s.status === 'timeout') && s.message) notes.push(`${who} on ${what}: ${s.message}`);
  };
  for (const row of report.models) {
    add('Strata', row.model, row.strata);
    add('CuraEngine', row.model, row.cura);
    add('PrusaSlicer', row.model, row.prusa);
  }
  const t = report.threadScaling;
  if (t) {
    add('Strata --threads 1', t.model, t.one);
    add('Strata --threads 2', t.model, t.two);
  }
  for (const row of report.patterns)
    add(`Strata --infill-pattern ${row.pattern}`, report.patternModel ?? '', row.strata);
  for (const row of report.support) {
    add('Strata (no support)', row.model, row.none);
    add('Strata --support-type normal', row.model, row.normal);
    add('Strata --support-type tree', row.model, row.tree);
  }
  for (const row of report.walls) {
    add('Strata --wall-generator variable', row.model, row.variable);
    add('Strata --wall-generator classic', row.model, row.classic);
  }
  return notes;
}

/** The header: what ran, how it was measured, and the load. */
function header(report: BenchReport): string[] {
  const out: string[] = [];
  for (const w of report.warnings) out.push(`> **Warning:** ${w}`);
  if (report.warnings.length > 0) out.push('');
  const m = report.machine;
  const rounds = `${report.repeat} counted run${report.repeat === 1 ? '' : 's'} per slicer${report.warmup > 0 ? ` after ${report.warmup} warm-up round${report.warmup === 1 ? '' : 's'}` : ', no warm-up'}`;
  out.push(
    `Strata benchmark, ${report.startedAt}: ${rounds}, interleaved (A B C A B C …); figures are medians, ratios medians of the per-round ratios.`,
  );
  out.push(`- machine: ${m.cpus} × ${m.cpuModel}, node ${m.node}, ${m.platform}`);
  const l = report.load;
  const foreign = overallForeignShare(l.blocks);
  const worst = l.blocks
    .filter((b) => b.foreignShare !== null)
    .reduce<(typeof l.blocks)[number] | null>(
      (a, b) => (a === null || b.foreignShare! > a.foreignShare! ? b : a),
      null,
    );
  const during =
    foreign === null
      ? `load average up to ${Math.max(0, ...l.blocks.map((b) => b.loadAverage)).toFixed(2)} during the runs (our own slicers included)`
      : `other processes took ${(foreign * 100).toFixed(0)} % of the CPU during the runs${worst ? ` (most: ${(worst.foreignShare! * 100).toFixed(0)} % during ${worst.label})` : ''}, flagged above ${(FOREIGN_CPU_MAX_SHARE * 100).toFixed(0)} %`;
  out.push(
    `- load: 1-minute load average ${l.before.toFixed(2)} before the start (${l.before > l.busyAbove ? 'BUSY' : 'idle'}: busy above ${l.busyAbove.toFixed(2)} on ${l.cpus} cores); ${during}`,
  );
  out.push(
    report.strataCli.built
      ? `- Strata: node ${report.strataCli.path} slice, default settings, ${report.threads === null ? 'default threads' : `--threads ${report.threads}`}`
      : `- Strata: not built: ${report.strataCli.path} is missing (run \`npm run build\`); Strata columns are empty`,
  );
  const cura = report.peers.cura;
  out.push(
    cura
      ? `- CuraEngine: ${cura.path} (${cura.version ?? 'version unknown'}), -m${report.curaThreads}, ${cura.definitions}, the common profile`
      : '- CuraEngine: not run (not on PATH, no fdmprinter.def.json, or --no-peers)',
  );
  const prusa = report.peers.prusa;
  out.push(
    prusa
      ? `- PrusaSlicer: ${prusa.path} (${prusa.version ?? 'version unknown'}), the common profile`
      : '- PrusaSlicer: not run (not on PATH, --no-prusa or --no-peers)',
  );
  out.push(
    `- wall = spawn to exit (Strata's includes node's start); ${report.cpuMeasured ? "CPU = user + system of the process and all its threads and waited-for children, from the kernel's accounting (/proc/self/stat cutime + cstime around each run, to 10 ms)" : 'CPU not measurable on this platform'}; ${MEMORY_METHOD_TEXT[report.memoryMethod]}`,
  );
  return out;
}

/** The report as Markdown: warnings and header, the model table, the sections, the targets, notes. */
export function renderReport(report: BenchReport): string {
  const out: string[] = header(report);

  out.push('', '### Models (wall / CPU / peak)', '');
  out.push(
    markdownTable(
      [
        'model',
        'Strata wall / CPU / peak',
        'CuraEngine wall / CPU / peak',
        'wall ratio',
        'CPU ratio',
        'PrusaSlicer wall',
      ],
      report.models.map((r) => [
        `${r.model} (${formatTriangles(r.triangles)})`,
        report.strataCli.built || r.strata.status !== 'missing' ? figuresCell(r.strata) : 'not built',
        figuresCell(r.cura),
        formatRatio(r.wallRatio),
        formatRatio(r.cpuRatio),
        wallCell(r.prusa),
      ]),
    ),
  );
  const made = report.models.filter((r) => r.madeFrom);
  for (const r of made) out.push('', `${r.model}: made by the bench from ${r.madeFrom}.`);
  const ts = report.triangleScaling;
  if (ts) {
    out.push(
      '',
      `Strata's time per triangle: ${ts.small.model} ${ts.small.microsPerTriangle.toFixed(2)} µs (${formatTriangles(ts.small.triangles)}), ${ts.big.model} ${ts.big.microsPerTriangle.toFixed(2)} µs (${formatTriangles(ts.big.triangles)}); ${ts.triangleRatio.toFixed(1)}× the triangles took ${formatRatio(ts.wallRatio)} the wall time.`,
    );
  }

  const t = report.threadScaling;
  if (t) {
    out.push('', `### Threads on ${t.model} (wall / CPU / peak)`, '');
    out.push(
      markdownTable(
        ['threads', 'Strata wall / CPU / peak', 'speed-up', 'CPU'],
        [
          ['1', figuresCell(t.one), '1.00×', '1.00×'],
          ['2', figuresCell(t.two), formatRatio(t.speedup), formatRatio(t.cpuRatio)],
        ],
      ),
    );
    out.push(
      '',
      `G-code of 1 thread, 2 threads and the default: ${t.gcodeIdentical === null ? 'not compared (a run failed)' : t.gcodeIdentical ? 'byte-identical' : 'DIFFERENT'}.`,
    );
  }

  if (report.patternModel !== null && report.patterns.length > 0) {
    out.push('', `### Infill patterns on ${report.patternModel} (--infill-pattern P, against grid)`, '');
    out.push(
      markdownTable(
        ['pattern', 'Strata wall / CPU / peak', 'wall vs grid', 'CPU vs grid'],
        report.patterns.map((r) => [
          r.pattern,
          figuresCell(r.strata),
          formatRatio(r.relativeToGrid),
          formatRatio(r.cpuRelativeToGrid),
        ]),
      ),
    );
  }

  if (report.support.length > 0) {
    out.push('', '### Support (--support-enabled --support-type T, against none; wall / CPU)', '');
    out.push(
      markdownTable(
        ['model', 'no support', 'normal', 'normal vs none', 'tree', 'tree vs none'],
        report.support.map((r) => [
          r.model,
          wallCpuCell(r.none),
          wallCpuCell(r.normal),
          `${formatRatio(r.wallRatio.normal)} / ${formatRatio(r.cpuRatio.normal)}`,
          wallCpuCell(r.tree),
          `${formatRatio(r.wallRatio.tree)} / ${formatRatio(r.cpuRatio.tree)}`,
        ]),
      ),
    );
  }

  if (report.walls.length > 0) {
    // CuraEngine's columns only when it ran on one of these models (not with --no-peers or without CuraEngine)
    const withCura = report.walls.some((r) => r.cura !== null && r.cura.status !== 'missing');
    out.push(
      '',
      `### Walls (--wall-generator variable against classic${withCura ? ', and against CuraEngine' : ''}; wall / CPU)`,
      '',
    );
    out.push(
      markdownTable(
        [
          'model',
          'variable',
          'classic',
          'variable vs classic',
          ...(withCura ? ['CuraEngine', 'variable vs CuraEngine'] : []),
        ],
        report.walls.map((r) => [
          r.model,
          wallCpuCell(r.variable),
          wallCpuCell(r.classic),
          `${formatRatio(r.wallRatio)} / ${formatRatio(r.cpuRatio)}`,
          ...(withCura
            ? [
                r.cura ? wallCpuCell(r.cura) : 'not run',
                `${formatRatio(r.curaWallRatio)} / ${formatRatio(r.curaCpuRatio)}`,
              ]
            : []),
        ]),
      ),
    );
    out.push(
      '',
      `Variable against classic: medians of the per-round ratios (interleaved)${withCura ? "; against CuraEngine: variable's median over CuraEngine's from the models table (different blocks, so not paired by round)" : ''}.`,
    );
  }

  if (report.targets.length > 0) {
    out.push('', '### Targets (issue 11)', '');
    out.push(
      markdownTable(
        ['figure', 'target', 'measured', ''],
        report.targets.map((r) => [
          r.figure,
          r.target,
          r.measured,
          r.verdict === 'pass' ? '✓' : r.verdict === 'fail' ? '✗' : '–',
        ]),
        ['left', 'left', 'left', 'left'],
      ),
    );
    const pass = report.targets.filter((r) => r.verdict === 'pass').length;
    const fail = report.targets.filter((r) => r.verdict === 'fail').length;
    const open = report.targets.length - pass - fail;
    out.push(
      '',
      `${pass} of ${report.targets.length} targets met, ${fail} missed${open > 0 ? `, ${open} not measured` : ''}${report.warnings.length > 0 ? ' (on a busy machine: see the warning above)' : ''}.`,
    );
  }

  const notes = [...report.notes, ...failureNotes(report)];
  if (notes.length > 0) {
    out.push('', 'Notes:');
    for (const n of notes) out.push(`- ${n}`);
  }
  return out.join('\n');
}
