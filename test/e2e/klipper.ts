/**
 * Klipper's own host software (klippy) in batch mode, for the end-to-end tests of the Klipper flavour and
 * of the time estimate: `python -m klippy.klippy printer.cfg -i in.gcode -o out.serial -d sim-mcu.dict`
 * reads the G-code, plans every move with Klipper's look-ahead planner and writes the MCU commands it would
 * send to a file instead of a serial port. Installed by `.ci/klipper.sh` (PyPI, pinned) at $STRATA_KLIPPER
 * (default ~/.cache/strata/klipper); the printer is `klipper/printer.cfg` (or a config given), its MCU the
 * data dictionary `klipper/sim-mcu.dict`.
 *
 * The print time: klippy's toolhead keeps `print_time`, the printer clock at the end of the moves planned so
 * far (it is what it logs as "Exiting (print time …s)"). After an M400 (the look-ahead queue flushed) the
 * macro STRATA_PRINT_TIME of printer.cfg logs it; the run inserts `M400` + `STRATA_PRINT_TIME` at the start,
 * before the first `;LAYER:` line, after the last `;TIME_ELAPSED:` line (the end of the last layer in
 * Strata's G-code) and at the end. Both layer markers stand where the head is stopped anyway (a retraction or
 * the end), so they change no timing. `printTimeSeconds` is the time between the layer markers (what Strata's
 * estimate covers: the layers, not the start and end G-code, homing or heating), else of the whole file.
 *
 * Errors: a command Klipper does not know (it ignores it: "Unknown command"), or one it refuses ("Move out of
 * range", "Move exceeds maximum extrusion", …), which in batch mode also ends the run.
 */
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { homedir, tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { inCi } from './models-dir.js';
import assert from 'node:assert/strict';

export const KLIPPER_DIR = process.env.STRATA_KLIPPER || join(homedir(), '.cache', 'strata', 'klipper');
export const KLIPPER_PYTHON = join(KLIPPER_DIR, 'venv', 'bin', 'python');
export const KLIPPER_SRC = join(KLIPPER_DIR, 'src');
/** printer.cfg and sim-mcu.dict (in src/, not copied to dist/). */
const FILES = fileURLToPath(new URL('../../../test/e2e/klipper/', import.meta.url));
export const KLIPPER_CONFIG = join(FILES, 'printer.cfg');
export const KLIPPER_DICT = join(FILES, 'sim-mcu.dict');

/** The motion limits of klipper/printer.cfg, as Strata settings (the estimate is checked with these). */
export const KLIPPER_CONFIG_SETTINGS = {
  gcodeFlavor: 'klipper',
  maxSpeed: 300,
  acceleration: 3000,
  cornerVelocity: 5,
  minimumCruiseRatio: 0.5,
  maxSpeedZ: 15,
  maxAccelerationZ: 300,
} as const;

/** For a test's `skip`: false when klippy is installed; else the reason, or under CI an error. */
export function skipWithoutKlipper(): string | false {
  if (existsSync(join(KLIPPER_SRC, 'klippy', 'chelper', 'c_helper.so')) && existsSync(KLIPPER_PYTHON)) return false;
  const why = `Klipper (klippy) is not installed at ${KLIPPER_DIR} (.ci/klipper.sh installs it; STRATA_KLIPPER chooses where)`;
  if (inCi()) throw new Error(`${why}: under CI the Klipper batch-mode tests fail rather than skip`);
  return why;
}

export interface KlipperResult {
  /** klippy read the whole file and exited normally, with no error and no unknown command. */
  accepted: boolean;
  /** Unknown commands and refused moves, as klippy words them. */
  errors: string[];
  /** Seconds from the first layer's start to the last layer's end (the whole file without layer comments). */
  printTimeSeconds: number;
  /** Seconds of the whole file (homing and the start and end G-code included; heating takes none in batch mode). */
  totalSeconds: number;
  /** klippy's log (stderr), for messages. */
  log: string;
}

const MARK = 'M400\nSTRATA_PRINT_TIME';

/** The G-code with the time markers inserted (see the module comment). */
export function markGcode(gcode: string): string {
  const lines = gcode.split('\n');
  const first = lines.findIndex((l) => l.startsWith(';LAYER:'));
  let last = -1;
  for (let i = lines.length - 1; i >= 0; i--) {
    if (lines[i]!.startsWith(';TIME_ELAPSED:')) {
      last = i;
      break;
    }
  }
  const out: string[] = [MARK];
  lines.forEach((line, i) => {
    if (i === first && last > first) out.push(MARK);
    out.push(line);
    if (i === last && first >= 0 && last > first) out.push(MARK);
  });
  out.push(MARK, '');
  return out.join('\n');
}

/** Run klippy's batch mode on `gcode` (text). `config`: a printer.cfg path (default klipper/printer.cfg). */
export async function runKlipper(
  gcode: string,
  options: { config?: string; timeoutMs?: number } = {},
): Promise<KlipperResult> {
  const dir = mkdtempSync(join(tmpdir(), 'strata-klipper-'));
  try {
    const input = join(dir, 'in.gcode');
    writeFileSync(input, markGcode(gcode));
    const args = [
      '-m',
      'klippy.klippy',
      options.config ?? KLIPPER_CONFIG,
      '-i',
      input,
      '-o',
      join(dir, 'out.serial'),
      '-d',
      KLIPPER_DICT,
    ];
    const child = spawn(KLIPPER_PYTHON, args, { cwd: KLIPPER_SRC, stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr!.on('data', (d) => (stderr = (stderr + d).slice(-1_000_000)));
    const timer = setTimeout(() => child.kill('SIGKILL'), options.timeoutMs ?? 120_000);
    const code = await new Promise<number | null>((resolve) => child.on('exit', (c) => resolve(c)));
    clearTimeout(timer);
    return parseKlipperLog(stderr, code);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** Read a klippy batch-mode log (its exit code `code`) into a result. */
export function parseKlipperLog(log: string, code: number | null): KlipperResult {
  const errors: string[] = [];
  const marks: number[] = [];
  const lines = log.split('\n');
  for (let i = 0; i < lines.length; i++) {
    const line = lines[i]!;
    const mark = /STRATA_PRINT_TIME (\d+(?:\.\d+)?)/.exec(line);
    if (mark) marks.push(Number(mark[1]));
    else if (/Unknown command/.test(line)) errors.push(line.replace(/^.*?Unknown command/, 'Unknown command'));
    // a refused command: logged as a warning (its detail lines follow without a level)
    else if (/^(?:WARNING|ERROR):root:/.test(line) || /^!! /.test(line))
      errors.push(line.replace(/^(?:WARNING|ERROR):root:|^!! /, ''));
  }
  const totalSeconds = marks.length >= 2 ? marks[marks.length - 1]! - marks[0]! : NaN;
  const printTimeSeconds = marks.length >= 4 ? marks[2]! - marks[1]! : totalSeconds;
  return {
    accepted: code === 0 && errors.length === 0 && marks.length >= 2,
    errors,
    printTimeSeconds,
    totalSeconds,
    log,
  };
}

/**
 * Run Klipper on `gcode` and assert what the tests hold it to: no command unknown and no move refused, the
 * whole file accepted, and Strata's estimate (`strataSeconds`) within 2 % of Klipper's print time.
 */
export async function assertKlipperAgrees(name: string, gcode: string, strataSeconds: number): Promise<KlipperResult> {
  const klipper = await runKlipper(gcode, { timeoutMs: 60_000 });
  assert.deepEqual(klipper.errors, [], `${name}: Klipper reported errors`);
  assert.ok(klipper.accepted, `${name}: Klipper did not accept the file:\n${klipper.log.slice(-3000)}`);
  const ratio = strataSeconds / klipper.printTimeSeconds;
  assert.ok(
    Math.abs(ratio - 1) <= 0.02,
    `${name}: Strata ${strataSeconds.toFixed(1)} s, Klipper ${klipper.printTimeSeconds.toFixed(1)} s (${((ratio - 1) * 100).toFixed(2)} %)`,
  );
  return klipper;
}
