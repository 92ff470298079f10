/**
 * Runs one command as a child process and measures its wall time, CPU time and peak resident memory.
 *
 * Wall time: performance.now() from just before spawn to the child's exit (so for Strata it includes node's
 * start-up and module loading, as a user sees it).
 *
 * CPU time (user + system): the kernel's own accounting of the child after it was reaped, read as the change
 * of this process's cutime + cstime in /proc/self/stat (see proc.ts). It covers every thread of the child and
 * every descendant it waited for, to one clock tick. Node's process.resourceUsage() cannot do this (it reports
 * RUSAGE_SELF only), and /proc/<pid>/stat of the child cannot be read once it has been reaped. Only one
 * command may be measured at a time in this process (the harness runs them one after another).
 *
 * Peak memory, in order of preference:
 *  - `gnu-time`: the command runs under `/usr/bin/time -f %M -o FILE`, which reports the child's maximum
 *    resident set size (ru_maxrss from wait4, KiB) after it exits. Exact and free of sampling error; the extra
 *    fork/exec adds about a millisecond to the wall time.
 *  - `proc-poll`: `/proc/<pid>/status` is read every 10 ms and the largest VmHWM (the kernel's own high-water mark)
 *    seen is kept. VmHWM is monotonic, so only growth in the last ~10 ms before exit can be missed.
 *  - `none`: no way to measure (not Linux); peakMiB is null.
 * Node itself cannot give a child's ru_maxrss (neither spawn nor process.resourceUsage() exposes wait4's
 * rusage), hence GNU time where it is installed; CI images without it fall back to polling.
 */
import { spawn, spawnSync } from 'node:child_process';
import { randomUUID } from 'node:crypto';
import { existsSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { performance } from 'node:perf_hooks';
import { clockTicksPerSecond, readSelfTimes } from './proc.js';

export type MemoryMethod = 'gnu-time' | 'proc-poll' | 'none';

export const GNU_TIME = '/usr/bin/time';

export interface Measurement {
  /** Exit code, or null when killed by a signal or never started. */
  exitCode: number | null;
  signal: string | null;
  timedOut: boolean;
  /** Set when the command could not be started (e.g. not found). */
  spawnError: string | null;
  wallSeconds: number;
  /** User + system CPU seconds of the child's whole process tree; null where /proc is missing. */
  cpuSeconds: number | null;
  peakMiB: number | null;
  /** The last few KiB of standard error, for failure messages. */
  stderrTail: string;
}

export interface MeasureOptions {
  method: MemoryMethod;
  timeoutMs: number;
  cwd?: string;
  env?: NodeJS.ProcessEnv;
  signal?: AbortSignal;
}

const STDERR_TAIL_BYTES = 4096;
const POLL_MS = 10;

/** Picks the best memory method this machine offers (checks that /usr/bin/time is GNU time and understands -f %M). */
export function detectMemoryMethod(): MemoryMethod {
  if (process.platform !== 'linux') return 'none';
  if (existsSync(GNU_TIME)) {
    const out = join(tmpdir(), `strata-bench-time-${randomUUID()}`);
    try {
      const r = spawnSync(GNU_TIME, ['-f', '%M', '-o', out, 'true'], { stdio: 'ignore', timeout: 10_000 });
      if (r.status === 0 && parseGnuTimeOutput(readFileSync(out, 'utf8')) !== null) return 'gnu-time';
    } catch {
      // fall through to polling
    } finally {
      rmSync(out, { force: true });
    }
  }
  return existsSync('/proc/self/status') ? 'proc-poll' : 'none';
}

/**
 * GNU time's -o file: with -f %M the last non-empty line is the peak RSS in KiB (a line such as
 * "Command exited with non-zero status 1" may come before it). Returns MiB, or null when unreadable.
 */
export function parseGnuTimeOutput(text: string): number | null {
  const lines = text
    .split('\n')
    .map((l) => l.trim())
    .filter((l) => l !== '');
  const last = lines[lines.length - 1];
  if (last === undefined || !/^\d+$/.test(last)) return null;
  return Number(last) / 1024;
}

/** VmHWM from a /proc/<pid>/status text, in MiB; null when absent (e.g. a zombie). */
export function parseVmHwm(status: string): number | null {
  const m = /^VmHWM:\s+(\d+)\s+kB/m.exec(status);
  return m ? Number(m[1]) / 1024 : null;
}

function readVmHwm(pid: number): number | null {
  try {
    return parseVmHwm(readFileSync(`/proc/${pid}/status`, 'utf8'));
  } catch {
    return null;
  }
}

/** Runs `command args`, never rejects: failures come back in the Measurement. */
export function measureCommand(
  command: string,
  args: readonly string[],
  options: MeasureOptions,
): Promise<Measurement> {
  const timeFile = options.method === 'gnu-time' ? join(tmpdir(), `strata-bench-time-${randomUUID()}`) : null;
  const [file, argv] = timeFile ? [GNU_TIME, ['-f', '%M', '-o', timeFile, command, ...args]] : [command, [...args]];

  return new Promise<Measurement>((resolve) => {
    let stderr = Buffer.alloc(0);
    let timedOut = false;
    let spawnError: string | null = null;
    let polledPeak: number | null = null;
    const hz = clockTicksPerSecond(); // (spawns getconf once: before the reading below, never inside a run)
    const before = readSelfTimes();
    const start = performance.now();
    const child = spawn(file, argv, {
      cwd: options.cwd,
      env: options.env,
      stdio: ['ignore', 'ignore', 'pipe'],
      // Own process group, so a timeout can kill the slicer together with /usr/bin/time.
      detached: true,
    });
    const killGroup = () => {
      if (child.pid === undefined || child.exitCode !== null || child.signalCode !== null) return;
      try {
        process.kill(-child.pid, 'SIGKILL');
      } catch {
        child.kill('SIGKILL');
      }
    };
    const timer = setTimeout(() => {
      timedOut = true;
      killGroup();
    }, options.timeoutMs);
    const onAbort = () => killGroup();
    options.signal?.addEventListener('abort', onAbort, { once: true });
    const poller =
      options.method === 'proc-poll'
        ? setInterval(() => {
            if (child.pid === undefined) return;
            const hwm = readVmHwm(child.pid);
            if (hwm !== null && (polledPeak === null || hwm > polledPeak)) polledPeak = hwm;
          }, POLL_MS)
        : null;

    child.stderr?.on('data', (chunk: Buffer) => {
      stderr = Buffer.concat([stderr, chunk]);
      if (stderr.length > 2 * STDERR_TAIL_BYTES) stderr = stderr.subarray(stderr.length - STDERR_TAIL_BYTES);
    });
    child.on('error', (err) => {
      spawnError = err.message;
    });
    child.on('close', (code, signal) => {
      const wallSeconds = (performance.now() - start) / 1000;
      // the child has been reaped by now ('close' comes after 'exit'), so its times are in our cutime/cstime
      const after = readSelfTimes();
      const cpuSeconds =
        before && after && child.pid !== undefined
          ? (after.cutime + after.cstime - before.cutime - before.cstime) / hz
          : null;
      clearTimeout(timer);
      if (poller) clearInterval(poller);
      options.signal?.removeEventListener('abort', onAbort);
      let peakMiB: number | null = polledPeak;
      if (timeFile) {
        try {
          peakMiB = parseGnuTimeOutput(readFileSync(timeFile, 'utf8'));
        } catch {
          peakMiB = null;
        }
        rmSync(timeFile, { force: true });
      }
      const tail = stderr.subarray(Math.max(0, stderr.length - STDERR_TAIL_BYTES)).toString('utf8');
      resolve({ exitCode: code, signal, timedOut, spawnError, wallSeconds, cpuSeconds, peakMiB, stderrTail: tail });
    });
  });
}

/** One line saying why a run failed (empty for a success). */
export function failureReason(m: Measurement): string {
  if (m.spawnError) return `could not start: ${m.spawnError}`;
  if (m.timedOut) return `timed out after ${m.wallSeconds.toFixed(0)} s`;
  if (m.signal) return `killed by ${m.signal}`;
  if (m.exitCode !== 0) {
    const lines = m.stderrTail
      .split('\n')
      .map((l) => l.trim())
      .filter((l) => l !== '' && !/^Command exited with non-zero status/.test(l) && !/^\d+$/.test(l));
    const last = lines[lines.length - 1];
    return `exit code ${m.exitCode}${last ? `: ${last.slice(0, 200)}` : ''}`;
  }
  return '';
}
