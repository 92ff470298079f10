/**
 * Command-line arguments of `npm run bench` (dist-dev/tools/bench/run.js). Pure: argv in, options out.
 */

export interface BenchOptions {
  /** Model filters (case-insensitive); empty = every model. See `selectModels`. */
  models: string[];
  /** Threads passed to Strata (--threads) and CuraEngine (-m); null = Strata's default, CuraEngine one per core. */
  threads: number | null;
  /** Counted runs per slicer and model (interleaved rounds); medians are reported. */
  repeat: number;
  /** Rounds run first and not counted (file cache, CPU clocks, lazily loaded libraries). */
  warmup: number;
  /** Print the results as JSON on stdout instead of Markdown. */
  json: boolean;
  /** Seconds before one slicer run is killed and reported as a timeout. */
  timeoutSeconds: number;
  /** Folder of models; null = ../shared/models beside the repository. */
  modelsDir: string | null;
  /** Strata CLI script run with node; null = dist/bin/main.js of this build. */
  strataCli: string | null;
  /** Run CuraEngine / PrusaSlicer when they are on PATH. */
  peers: boolean;
  /** Run PrusaSlicer (with peers); it is the slowest of the three. */
  prusa: boolean;
  /** The per-infill-pattern section on 3DBenchy. */
  patterns: boolean;
  /** The support section (normal and tree against none). */
  support: boolean;
  /** The walls section (--wall-generator variable against classic). */
  walls: boolean;
  /** The 1-thread against 2-thread section on 3DBenchy. */
  threadScaling: boolean;
  /** The ~1 M-triangle mesh made by subdividing 3DBenchy. */
  big: boolean;
  /** Keep the temporary folder with the G-code written. */
  keep: boolean;
  help: boolean;
}

export const BENCH_USAGE = `Usage: npm run bench -- [options]
  (or: node dist-dev/tools/bench/run.js [options])

Slices every model in ../shared/models, and a ~1 M-triangle mesh made by subdividing 3DBenchy once, with Strata
(node dist/bin/main.js slice, its default settings) and, where they are on PATH, CuraEngine and PrusaSlicer with
the common profile (0.2 mm layers, 2 walls, 0.8 mm top/bottom, 20 % grid). Runs are interleaved (A B C A B C …):
a warm-up round, then --repeat counted rounds; it prints the medians of wall time, CPU time and peak memory,
Strata/CuraEngine ratios (median of the per-round ratios), then on 3DBenchy Strata with 1 and 2 threads and
every infill pattern against grid, support (normal, tree) against none on SupportTest, Overhang, spot,
3DBenchy, BridgeTest (also scaled 2× in X and Y) and HollowCalibrationCube, variable walls against classic
(--wall-generator) on 3DBenchy, HollowCalibrationCube and BridgeTest, and the targets of the speed issue with a
verdict each. Warns when the machine is busy.

Options:
  --models NAMES     only these models: a file name or stem (3DBenchy, 3DBenchy-x4, spot …), else every model
                     whose name contains it; comma-separated or repeated (--only is the same)
  --repeat N         counted runs per slicer (default 5)
  --warmup N         uncounted rounds before them (default 1; 0 = none)
  --threads N        threads for Strata (--threads N) and CuraEngine (-mN); default: Strata's own default,
                     CuraEngine one per core
  --json             print the results as JSON instead of Markdown
  --timeout SEC      kill a slicer run after SEC seconds (default 600)
  --models-dir DIR   folder of models (default ../shared/models beside the repository)
  --strata-cli FILE  Strata CLI script to run with node (default dist/bin/main.js)
  --no-peers         do not run CuraEngine or PrusaSlicer
  --no-prusa         do not run PrusaSlicer
  --no-patterns      skip the infill-pattern section
  --no-support       skip the support section
  --no-walls         skip the walls section (--wall-generator variable against classic)
  --no-thread-scaling  skip the 1-against-2-threads section
  --no-big           skip the subdivided ~1 M-triangle mesh
  --keep             keep the temporary folder with the G-code written
  -h, --help         show this help

A quick check: npm run bench -- --models CalibrationCube --repeat 1 --warmup 0 --no-big`;

export class BenchArgsError extends Error {
  override name = 'BenchArgsError';
}

const VALUE_FLAGS = [
  '--models',
  '--only',
  '--threads',
  '--repeat',
  '--warmup',
  '--timeout',
  '--models-dir',
  '--strata-cli',
] as const;
type ValueFlag = (typeof VALUE_FLAGS)[number];
const isValueFlag = (s: string): s is ValueFlag => (VALUE_FLAGS as readonly string[]).includes(s);

const SWITCHES = [
  '--json',
  '--no-peers',
  '--no-prusa',
  '--no-patterns',
  '--no-support',
  '--no-walls',
  '--no-thread-scaling',
  '--no-big',
  '--keep',
  '--help',
] as const;

function wholeNumber(flag: string, raw: string, min: number, max: number): number {
  const n = Number(raw);
  if (!/^\d+$/.test(raw) || !Number.isInteger(n) || n < min || n > max) {
    throw new BenchArgsError(`${flag} needs a whole number from ${min} to ${max}, got "${raw}"`);
  }
  return n;
}

function positiveNumber(flag: string, raw: string): number {
  const n = Number(raw);
  if (raw.trim() === '' || !Number.isFinite(n) || n <= 0)
    throw new BenchArgsError(`${flag} needs a positive number, got "${raw}"`);
  return n;
}

export function defaultBenchOptions(): BenchOptions {
  return {
    models: [],
    threads: null,
    repeat: 5,
    warmup: 1,
    json: false,
    timeoutSeconds: 600,
    modelsDir: null,
    strataCli: null,
    peers: true,
    prusa: true,
    patterns: true,
    support: true,
    walls: true,
    threadScaling: true,
    big: true,
    keep: false,
    help: false,
  };
}

/** Parses the arguments after the script name. Throws BenchArgsError naming the bad flag. */
export function parseBenchArgs(argv: readonly string[]): BenchOptions {
  const options = defaultBenchOptions();
  for (let i = 0; i < argv.length; i++) {
    let arg = argv[i]!;
    let value: string | undefined;
    const eq = arg.indexOf('=');
    if (arg.startsWith('--') && eq > 0) {
      value = arg.slice(eq + 1);
      arg = arg.slice(0, eq);
    }
    if (isValueFlag(arg)) {
      if (value === undefined) {
        value = argv[++i];
        if (value === undefined) throw new BenchArgsError(`${arg} needs a value`);
      }
      switch (arg) {
        case '--models':
        case '--only': {
          const names = value
            .split(',')
            .map((s) => s.trim())
            .filter((s) => s !== '');
          if (names.length === 0) throw new BenchArgsError(`${arg} needs at least one model name`);
          options.models.push(...names);
          break;
        }
        case '--threads':
          options.threads = wholeNumber(arg, value, 1, 256);
          break;
        case '--repeat':
          options.repeat = wholeNumber(arg, value, 1, 1000);
          break;
        case '--warmup':
          options.warmup = wholeNumber(arg, value, 0, 100);
          break;
        case '--timeout':
          options.timeoutSeconds = positiveNumber(arg, value);
          break;
        case '--models-dir':
          options.modelsDir = value;
          break;
        case '--strata-cli':
          options.strataCli = value;
          break;
      }
      continue;
    }
    if (value !== undefined) throw new BenchArgsError(`${arg} takes no value`);
    switch (arg) {
      case '--json':
        options.json = true;
        break;
      case '--no-peers':
        options.peers = false;
        break;
      case '--no-prusa':
        options.prusa = false;
        break;
      case '--no-patterns':
        options.patterns = false;
        break;
      case '--no-support':
        options.support = false;
        break;
      case '--no-walls':
        options.walls = false;
        break;
      case '--no-thread-scaling':
        options.threadScaling = false;
        break;
      case '--no-big':
        options.big = false;
        break;
      case '--keep':
        options.keep = true;
        break;
      case '-h':
      case '--help':
        options.help = true;
        break;
      default:
        throw new BenchArgsError(
          `unknown argument "${arg}"; allowed: ${[...VALUE_FLAGS, ...SWITCHES, '-h'].join(', ')}`,
        );
    }
  }
  return options;
}

/**
 * The model file names matching the filters: a filter equal to a file's name or stem (the name up to its first
 * dot, so "3DBenchy" selects both 3DBenchy.stl.gz and 3DBenchy.3mf) selects it; a filter that selects no file
 * that way selects every file whose name contains it. Case-insensitive. No filters = every file.
 */
export function selectModels(names: readonly string[], filters: readonly string[]): string[] {
  if (filters.length === 0) return [...names];
  const stem = (name: string) => name.toLowerCase().split('.')[0]!;
  const picked = new Set<string>();
  for (const raw of filters) {
    const f = raw.toLowerCase();
    const exact = names.filter((n) => n.toLowerCase() === f || stem(n) === f);
    const hits = exact.length > 0 ? exact : names.filter((n) => n.toLowerCase().includes(f));
    for (const h of hits) picked.add(h);
  }
  return names.filter((n) => picked.has(n));
}
