/**
 * V8 settings for the command line's one-shot runs. A slice is a short, cold run: most of its code is
 * optimised while it runs, on the same few cores, and every optimising compile that inlines deeply takes
 * long enough that the code it replaces runs slow meanwhile. Inlining less (small callees only) and not
 * peeling loops makes those compiles much cheaper; measured on a 2-core machine, runs paired in turn:
 * 3DBenchy 0.92 × wall, 0.81 × CPU; Overhang with tree support 0.89 × wall; the 900 k-triangle Benchy
 * 0.97 × wall. Three times V8's interrupt budget (functions optimised after running about three times as long)
 * spends less of a short run compiling code that would not have run long enough to repay it: CPU 0.88-0.95 ×,
 * wall 0.95-1.00 × on the calibration cube, HollowCalibrationCube with and without tree support, SupportTest
 * with tree support, spot and 3DBenchy (eight pairs each), the bunny unchanged; ten times the budget made
 * 3DBenchy slower. The output is the same (only how the code is compiled changes). Set only by the CLI, before
 * any slicing code has run hot; a library user's process keeps its own settings.
 */
import { getHeapSpaceStatistics, setFlagsFromString } from 'node:v8';

export const ENGINE_FLAGS = [
  '--max-inlined-bytecode-size-cumulative=100',
  '--no-turbo-loop-peeling',
  '--interrupt-budget=200000',
] as const;

/**
 * V8's young generation (both semi-spaces) grows no further once it is this large, MiB. By default it
 * doubles up to 32 MiB while much of what is allocated survives, as a slice's layers and plan do; past
 * 8 MiB that bought no speed and cost about 25 MiB of peak memory (3DBenchy 117.5 MiB against 146.9, the
 * bunny 122 against 151; wall 0.97 × on 3DBenchy, 0.93-1.00 × on the bunny, spot, the calibration cube and
 * HollowCalibrationCube with tree support, runs paired in turn). Growth is stopped, not the size set,
 * because the semi-space's maximum is fixed when node starts.
 */
export const YOUNG_GENERATION_CAP_MIB = 8;
/** How often the young generation's size is looked at until it is capped, ms (a timer runs when the slice gives the event loop a turn). */
const YOUNG_CHECK_MS = 1;

function youngGenerationBytes(): number {
  for (const s of getHeapSpaceStatistics()) if (s.space_name === 'new_space') return s.space_size;
  return 0;
}

export function tuneEngine(): void {
  for (const flag of ENGINE_FLAGS) setFlagsFromString(flag);
}

/**
 * Stop the young generation's growth once it reaches YOUNG_GENERATION_CAP_MIB, checked while a slice
 * runs (whenever it gives the event loop a turn); returns what ends the checks, for when the slice is done.
 */
export function capYoungGeneration(): () => void {
  const timer = setInterval(() => {
    if (youngGenerationBytes() < YOUNG_GENERATION_CAP_MIB * 1024 * 1024) return;
    setFlagsFromString('--semi-space-growth-factor=1');
    clearInterval(timer);
  }, YOUNG_CHECK_MS);
  // the checks never keep the process alive
  timer.unref();
  return () => clearInterval(timer);
}
