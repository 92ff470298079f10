/**
 * The kernel's CPU accounting, read from /proc (Linux). Pure parsers plus thin readers that return null where
 * /proc is missing, so the harness still runs (without CPU figures) on other systems.
 *
 * - /proc/self/stat fields 14–17 (utime, stime, cutime, cstime), in clock ticks: this process's own CPU time and
 *   that of its children it has waited for. When libuv reaps a child, the kernel adds the child's whole thread
 *   group's user and system time, plus what the child itself collected from its own waited-for children, to
 *   our cutime/cstime. So the change of cutime + cstime around one child's run is that child's CPU time: every
 *   thread (Strata's workers, CuraEngine's OpenMP threads) and every descendant it waited for, exactly, to one
 *   clock tick (10 ms at the usual 100 ticks per second) — provided no other child is reaped meanwhile, which
 *   holds because the benchmark runs one command at a time.
 * - /proc/stat's first line: the whole machine's CPU time by state, for telling how much other processes ran
 *   while we measured (see load.ts).
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';

export interface ProcTimes {
  /** User and system time of this process (all its threads), clock ticks. */
  utime: number;
  stime: number;
  /** User and system time of its reaped children (and theirs), clock ticks. */
  cutime: number;
  cstime: number;
}

/**
 * Parses a /proc/<pid>/stat line. The second field (the command name in parentheses) may itself hold spaces and
 * parentheses, so fields are counted from the last ")".
 */
export function parseProcStat(text: string): ProcTimes | null {
  const close = text.lastIndexOf(')');
  if (close < 0) return null;
  // after ")" come field 3 (state) onwards; utime is field 14 → index 11
  const f = text
    .slice(close + 1)
    .trim()
    .split(/\s+/);
  const nums = [f[11], f[12], f[13], f[14]].map((s) => (s !== undefined && /^\d+$/.test(s) ? Number(s) : NaN));
  if (nums.some((n) => !Number.isFinite(n))) return null;
  const [utime, stime, cutime, cstime] = nums as [number, number, number, number];
  return { utime, stime, cutime, cstime };
}

/** This process's times, or null without /proc. */
export function readSelfTimes(): ProcTimes | null {
  try {
    return parseProcStat(readFileSync('/proc/self/stat', 'utf8'));
  } catch {
    return null;
  }
}

/** Whole-machine CPU time in clock ticks: busy (user, nice, system, irq, softirq, steal) and the total. */
export interface MachineTicks {
  busy: number;
  total: number;
}

/**
 * Parses /proc/stat's aggregate "cpu" line: user nice system idle iowait irq softirq steal guest guest_nice.
 * Guest time is already inside user and nice, so it is not added again. Steal (time the hypervisor gave to
 * other guests) counts as busy: it slows our runs just like a local process would.
 */
export function parseMachineTicks(text: string): MachineTicks | null {
  const line = text.split('\n').find((l) => /^cpu\s/.test(l));
  if (!line) return null;
  const v = line.trim().split(/\s+/).slice(1).map(Number);
  if (v.length < 4 || v.some((n) => !Number.isFinite(n))) return null;
  const at = (i: number) => v[i] ?? 0;
  const busy = at(0) + at(1) + at(2) + at(5) + at(6) + at(7);
  return { busy, total: busy + at(3) + at(4) };
}

export function readMachineTicks(): MachineTicks | null {
  try {
    return parseMachineTicks(readFileSync('/proc/stat', 'utf8'));
  } catch {
    return null;
  }
}

let ticksPerSecond: number | null = null;

/** The kernel's USER_HZ (`getconf CLK_TCK`), 100 on every common Linux; read once. */
export function clockTicksPerSecond(): number {
  if (ticksPerSecond === null) {
    let hz = 100;
    try {
      const r = spawnSync('getconf', ['CLK_TCK'], { encoding: 'utf8', timeout: 5000 });
      const n = Number(r.stdout?.trim());
      if (r.status === 0 && Number.isInteger(n) && n > 0) hz = n;
    } catch {
      // keep 100
    }
    ticksPerSecond = hz;
  }
  return ticksPerSecond;
}
