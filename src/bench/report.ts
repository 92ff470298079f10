/**
 * The benchmark's results as data, and their rendering as text tables. Pure: no I/O.
 */
import type { MemoryMethod, Measurement } from './measure.js';
import { failureReason } from './measure.js';
import { formatCount, formatMiB, formatRatio, formatSeconds, formatTable, median } from './stats.js';

/**
 * ok: every run succeeded. failed/timeout: a run failed (no more repeats were tried). missing: the slicer is not
 * installed or built. unsupported: the slicer does not read this file type. skipped: not run (e.g. interrupted).
 */
export type RunStatus = 'ok' | 'failed' | 'timeout' | 'missing' | 'unsupported' | 'skipped';

export interface SlicerStats {
  status: RunStatus;
  /** Median wall time of the runs, seconds (null unless ok). */
  wallSeconds: number | null;
  /** Median peak resident memory of the runs, MiB (null unless ok and measurable). */
  peakMiB: number | null;
  /** Wall time of each run, seconds. */
  samples: number[];
  /** Why it failed, was missing or skipped. */
  message?: string;
}

export interface ModelRow {
  model: string;
  triangles: number | null;
  strata: SlicerStats;
  cura: SlicerStats;
  prusa: SlicerStats;
}

export interface PatternRow {
  pattern: string;
  strata: SlicerStats;
  /** Wall time over grid's (null when either is missing). */
  relativeToGrid: number | null;
}

export interface PeerInfo {
  path: string;
  version: string | null;
}

export interface BenchReport {
  startedAt: string;
  machine: {
    cpus: number;
    cpuModel: string;
    node: string;
    platform: string;
    /** 1-minute load average before and after the runs: above ~0 other work on the machine skews the times. */
    loadAverage: { start: number; end: number };
  };
  threads: number;
  /** Whether --threads was given (else Strata used its automatic thread count). */
  threadsGiven?: boolean;
  repeat: number;
  memoryMethod: MemoryMethod;
  strataCli: { path: string; built: boolean };
  peers: { cura: (PeerInfo & { definitions: string }) | null; prusa: PeerInfo | null };
  models: ModelRow[];
  /** The model the infill-pattern section ran on, or null when it did not run. */
  patternModel: string | null;
  patterns: PatternRow[];
  notes: string[];
}

/** A SlicerStats that did not run. */
export function notRun(status: Exclude<RunStatus, 'ok' | 'failed' | 'timeout'>, message?: string): SlicerStats {
  return message === undefined ? { status, wallSeconds: null, peakMiB: null, samples: [] } : { status, wallSeconds: null, peakMiB: null, samples: [], message };
}

/** Folds the measurements of repeated runs into medians; the first failure decides a failed status. */
export function summarize(runs: readonly Measurement[]): SlicerStats {
  const samples = runs.map((r) => r.wallSeconds);
  const bad = runs.find((r) => failureReason(r) !== '');
  if (bad) return { status: bad.timedOut ? 'timeout' : 'failed', wallSeconds: null, peakMiB: null, samples, message: failureReason(bad) };
  if (runs.length === 0) return notRun('skipped');
  const peaks = runs.map((r) => r.peakMiB).filter((p): p is number => p !== null);
  return { status: 'ok', wallSeconds: median(samples), peakMiB: peaks.length === runs.length ? median(peaks) : null, samples };
}

/** Pattern rows with their time relative to the grid row. */
export function relativeToGrid(rows: readonly Omit<PatternRow, 'relativeToGrid'>[]): PatternRow[] {
  const grid = rows.find((r) => r.pattern === 'grid')?.strata.wallSeconds ?? null;
  return rows.map((r) => ({
    ...r,
    relativeToGrid: grid !== null && grid > 0 && r.strata.wallSeconds !== null ? r.strata.wallSeconds / grid : null,
  }));
}

const STATUS_CELL: Readonly<Record<Exclude<RunStatus, 'ok'>, string>> = Object.freeze({
  failed: 'failed',
  timeout: 'timeout',
  missing: '-',
  unsupported: 'n/a',
  skipped: 'skipped',
});

function timeCell(s: SlicerStats, missing = STATUS_CELL.missing): string {
  if (s.status === 'ok') return formatSeconds(s.wallSeconds);
  return s.status === 'missing' ? missing : STATUS_CELL[s.status];
}
function memCell(s: SlicerStats): string {
  return s.status === 'ok' ? formatMiB(s.peakMiB) : '-';
}

const MEMORY_METHOD_TEXT: Readonly<Record<MemoryMethod, string>> = Object.freeze({
  'gnu-time': 'peak memory = max RSS from /usr/bin/time -f %M',
  'proc-poll': 'peak memory = largest /proc/<pid>/status VmHWM, polled every 10 ms',
  none: 'peak memory not measurable on this platform',
});

/** Everything the report says that is not a table row: header lines and notes about failures. */
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
  for (const row of report.patterns) add(`Strata --infill-pattern ${row.pattern}`, report.patternModel ?? '', row.strata);
  return notes;
}

/** The report as text: a header, the per-model table, the per-pattern table, notes. */
export function renderReport(report: BenchReport): string {
  const out: string[] = [];
  const runs = report.repeat === 1 ? '1 run' : `median of ${report.repeat} runs`;
  out.push(`Strata benchmark: ${report.threadsGiven ? `${report.threads} thread(s)` : `Strata automatic threads, CuraEngine ${report.threads}`}, ${runs} per slicer and model; ${MEMORY_METHOD_TEXT[report.memoryMethod]}`);
  const m = report.machine;
  out.push(`machine: ${m.cpus} x ${m.cpuModel}, node ${m.node}, ${m.platform}; load average ${m.loadAverage.start.toFixed(2)} before, ${m.loadAverage.end.toFixed(2)} after`);
  out.push(
    report.strataCli.built
      ? `Strata: node ${report.strataCli.path}`
      : `strata CLI not built: ${report.strataCli.path} is missing (run \`npm run build\`); Strata columns are empty`,
  );
  const cura = report.peers.cura;
  out.push(cura ? `CuraEngine: ${cura.path} (${cura.version ?? 'version unknown'}), ${cura.definitions}` : 'CuraEngine: not run (not on PATH, no fdmprinter.def.json, or --no-peers)');
  const prusa = report.peers.prusa;
  out.push(prusa ? `PrusaSlicer: ${prusa.path} (${prusa.version ?? 'version unknown'})` : 'PrusaSlicer: not run (not on PATH or --no-peers)');
  out.push('');

  const strataMissing = report.strataCli.built ? '-' : 'not built';
  out.push(
    formatTable(
      ['model', 'triangles', 'Strata s', 'Strata MiB', 'Cura s', 'Cura MiB', 'Strata/Cura', 'Prusa s', 'Prusa MiB'],
      report.models.map((r) => [
        r.model,
        formatCount(r.triangles),
        timeCell(r.strata, strataMissing),
        memCell(r.strata),
        timeCell(r.cura),
        memCell(r.cura),
        formatRatio(r.strata.wallSeconds, r.cura.wallSeconds),
        timeCell(r.prusa),
        memCell(r.prusa),
      ]),
    ),
  );

  if (report.patternModel !== null && report.patterns.length > 0) {
    out.push('');
    out.push(`Infill patterns on ${report.patternModel} (Strata --infill-pattern P, time relative to grid)`);
    out.push(
      formatTable(
        ['pattern', 'Strata s', 'vs grid', 'Strata MiB'],
        report.patterns.map((r) => [
          r.pattern,
          timeCell(r.strata),
          r.relativeToGrid === null ? '-' : `${r.relativeToGrid.toFixed(2)}x`,
          memCell(r.strata),
        ]),
      ),
    );
  }

  const notes = [...report.notes, ...failureNotes(report)];
  const busiest = Math.max(m.loadAverage.start, m.loadAverage.end);
  if (busiest > m.cpus / 2) notes.unshift(`the machine was busy (load average up to ${busiest.toFixed(2)} on ${m.cpus} cores): times are inflated; compare slicers within one run only`);
  if (notes.length > 0) {
    out.push('');
    out.push('Notes:');
    for (const n of notes) out.push(`- ${n}`);
  }
  return out.join('\n');
}
