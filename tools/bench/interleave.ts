/**
 * Interleaved runs: every job once per round, in the same order each round (A B C A B C …), warm-up rounds first
 * and not counted. A change in the machine's speed during the benchmark (another program, CPU clocks, the page
 * cache) then hits every job of a round alike, and the per-round ratios (stats.ts medianOfRatios) cancel it.
 */
import type { Measurement } from './measure.js';
import { notRun, summarize, type SlicerStats } from './report.js';

/** One slicer invocation to measure. */
export interface Job {
  label: string;
  command: string;
  args: string[];
}

export const isJob = (x: Job | SlicerStats): x is Job => 'command' in x;

export interface ScheduledRun<K> {
  /** 1-based; rounds 1..warmup are the warm-up. */
  round: number;
  key: K;
  counted: boolean;
}

/** The order runs happen in: `warmup` uncounted rounds, then `repeat` counted ones, each over every key in order. */
export function interleaveOrder<K>(keys: readonly K[], repeat: number, warmup: number): ScheduledRun<K>[] {
  const out: ScheduledRun<K>[] = [];
  for (let round = 1; round <= warmup + repeat; round++) {
    for (const key of keys) out.push({ round, key, counted: round > warmup });
  }
  return out;
}

export interface InterleaveOptions {
  repeat: number;
  warmup: number;
  /** Runs one job (measure.ts measureCommand in the bench, a fake in tests). */
  measure: (job: Job) => Promise<Measurement>;
  log?: (line: string) => void;
  signal?: AbortSignal;
}

const failed = (m: Measurement) => m.spawnError !== null || m.timedOut || m.exitCode !== 0;

/**
 * Runs the jobs interleaved and folds each job's counted runs into medians. A job that fails (also in a
 * warm-up round) is dropped from the later rounds and reported failed; an entry that is already a SlicerStats
 * (missing, unsupported) is passed through. Aborting stops before the next run.
 */
export async function runInterleaved<K extends string>(
  jobs: Record<K, Job | SlicerStats>,
  options: InterleaveOptions,
): Promise<Record<K, SlicerStats>> {
  const keys = (Object.keys(jobs) as K[]).filter((k) => isJob(jobs[k]));
  const runs = new Map<K, Measurement[]>(keys.map((k) => [k, []]));
  const dropped = new Set<K>();
  for (const step of interleaveOrder(keys, options.repeat, options.warmup)) {
    if (options.signal?.aborted) break;
    if (dropped.has(step.key)) continue;
    const job = jobs[step.key] as Job;
    const m = await options.measure(job);
    const bad = failed(m);
    if (step.counted || bad) runs.get(step.key)!.push(m);
    if (bad) dropped.add(step.key);
    const what = step.counted
      ? `run ${step.round - options.warmup}/${options.repeat}`
      : `warm-up ${step.round}/${options.warmup}`;
    const cpu = m.cpuSeconds === null ? '' : `, ${m.cpuSeconds.toFixed(2)} s CPU`;
    const peak = m.peakMiB === null ? '' : `, ${m.peakMiB.toFixed(0)} MiB`;
    options.log?.(`  ${job.label} ${what}: ${m.wallSeconds.toFixed(2)} s wall${cpu}${peak}${bad ? ' (failed)' : ''}`);
  }
  const out = {} as Record<K, SlicerStats>;
  for (const k of Object.keys(jobs) as K[]) {
    const job: Job | SlicerStats = jobs[k];
    if (!isJob(job)) out[k] = job;
    else {
      const r = runs.get(k)!;
      out[k] = r.length > 0 ? summarize(r) : notRun('skipped', 'interrupted');
    }
  }
  return out;
}
