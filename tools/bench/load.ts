/**
 * Is the machine quiet enough to measure on? Two signals:
 *
 * - Before the start, the 1-minute load average (os.loadavg()): above IDLE_LOAD_PER_CORE per core the machine is
 *   busy and the run should not be trusted.
 * - During the run the load average is no use on its own: our own slicer keeps one or two cores busy, so it
 *   sits near the core count even on an idle machine. Instead each interleaved block measures how much CPU
 *   *other* processes took: the machine's busy ticks from /proc/stat minus this process's own and its reaped
 *   children's ticks (/proc/self/stat), over the block's wall time and the core count. The load average at the
 *   end of each block is kept too, for the record (and decides where /proc is missing).
 *
 * Why it matters: CuraEngine spreads its work over every core, Strata (on two cores) mostly over one; a
 * second program on the machine takes a core away from CuraEngine more than from Strata, so ratios measured on
 * a loaded machine flatter Strata.
 */
import { loadavg } from 'node:os';
import { performance } from 'node:perf_hooks';
import { clockTicksPerSecond, readMachineTicks, readSelfTimes, type MachineTicks, type ProcTimes } from './proc.js';

/** 1-minute load average per core above which the machine counts as busy before the start (0.7 on two cores). */
export const IDLE_LOAD_PER_CORE = 0.35;
/** Share of the machine's CPU (0–1) other processes may take during a block before the block is flagged. */
export const FOREIGN_CPU_MAX_SHARE = 0.1;

/** The load in one interleaved block (one model, or one section). */
export interface BlockLoad {
  label: string;
  seconds: number;
  /** 1-minute load average at the block's end (includes our own slicers). */
  loadAverage: number;
  /** Share of all cores' time (0–1) that other processes used during the block; null without /proc. */
  foreignShare: number | null;
}

export interface LoadReport {
  cpus: number;
  /** The 1-minute load average above which the machine counts as busy (IDLE_LOAD_PER_CORE × cpus). */
  busyAbove: number;
  /** 1-minute load average just before the first run. */
  before: number;
  blocks: BlockLoad[];
}

/** A point in time to measure a block's load from. */
export interface LoadMark {
  at: number;
  machine: MachineTicks | null;
  self: ProcTimes | null;
}

export function loadMark(): LoadMark {
  return { at: performance.now(), machine: readMachineTicks(), self: readSelfTimes() };
}

/**
 * Share of the machine other processes used between two marks: (Δ machine busy − Δ our own and our reaped
 * children's time) / (elapsed × cores), clamped to 0–1. Both counters are in clock ticks.
 */
export function foreignShare(from: LoadMark, to: LoadMark, cpus: number, hz: number): number | null {
  if (!from.machine || !to.machine || !from.self || !to.self) return null;
  const seconds = (to.at - from.at) / 1000;
  if (!(seconds > 0) || cpus < 1) return null;
  const own = (t: ProcTimes) => t.utime + t.stime + t.cutime + t.cstime;
  const others = to.machine.busy - from.machine.busy - (own(to.self) - own(from.self));
  return Math.min(1, Math.max(0, others / hz / (seconds * cpus)));
}

/** Closes a block begun at `from`. */
export function blockLoad(label: string, from: LoadMark, cpus: number): BlockLoad {
  const to = loadMark();
  return {
    label,
    seconds: (to.at - from.at) / 1000,
    loadAverage: loadavg()[0]!,
    foreignShare: foreignShare(from, to, cpus, clockTicksPerSecond()),
  };
}

export function busyThreshold(cpus: number): number {
  return IDLE_LOAD_PER_CORE * Math.max(1, cpus);
}

const WHY =
  'CuraEngine spreads its work over every core, so a loaded machine slows it more than Strata and the ratios flatter Strata: measure again on an idle machine';

/** The warning for the load average before the start, or null when the machine was quiet. */
export function startLoadWarning(before: number, cpus: number): string | null {
  const limit = busyThreshold(cpus);
  if (!(before > limit)) return null;
  return `the machine is busy: 1-minute load average ${before.toFixed(2)} before the start, above ${limit.toFixed(2)} for ${cpus} core${cpus === 1 ? '' : 's'}; ${WHY}`;
}

/** Every warning the load report calls for (empty when the machine was quiet throughout). */
export function loadWarnings(load: LoadReport): string[] {
  const out: string[] = [];
  const start = startLoadWarning(load.before, load.cpus);
  if (start) out.push(start);
  const busy = load.blocks.filter((b) => b.foreignShare !== null && b.foreignShare > FOREIGN_CPU_MAX_SHARE);
  if (busy.length > 0) {
    const worst = busy.reduce((a, b) => (b.foreignShare! > a.foreignShare! ? b : a));
    const names = busy.map((b) => `${b.label} ${(b.foreignShare! * 100).toFixed(0)} %`).join(', ');
    out.push(
      `other processes used more than ${(FOREIGN_CPU_MAX_SHARE * 100).toFixed(0)} % of the CPU while measuring (${names}; worst ${worst.label}): those figures are disturbed${start ? '' : `; ${WHY}`}`,
    );
  }
  // Without /proc, fall back on the load average: above what our own slicer (at most one per core) explains.
  const blind = load.blocks.filter((b) => b.foreignShare === null && b.loadAverage > load.cpus + load.busyAbove);
  if (blind.length > 0) {
    const worst = Math.max(...blind.map((b) => b.loadAverage));
    out.push(
      `the load average rose to ${worst.toFixed(2)} during the run, more than our own slicer explains on ${load.cpus} cores (${blind.map((b) => b.label).join(', ')})`,
    );
  }
  return out;
}

/** Average share of the CPU other processes used, weighted by each block's time; null without /proc. */
export function overallForeignShare(blocks: readonly BlockLoad[]): number | null {
  const known = blocks.filter((b) => b.foreignShare !== null && b.seconds > 0);
  const seconds = known.reduce((s, b) => s + b.seconds, 0);
  if (known.length === 0 || seconds <= 0) return null;
  return known.reduce((s, b) => s + b.foreignShare! * b.seconds, 0) / seconds;
}
