/**
 * Command-line arguments of `npm run bench` (dist/bench/run.js). Pure: argv in, options out.
 */

export interface BenchOptions {
  /** Model filters (case-insensitive); empty = every model. See `selectModels`. */
  only: string[];
  /** Threads passed to Strata (--threads) and CuraEngine (-m); null = one per core. */
  threads: number | null;
  /** Runs per slicer and model; the median is reported. */
  repeat: number;
  /** Print the results as JSON on stdout instead of tables. */
  json: boolean;
  /** Seconds before one slicer run is killed and reported as a timeout. */
  timeoutSeconds: number;
  /** Folder of models; null = ../shared/models beside the repository. */
  modelsDir: string | null;
  /** Strata CLI script run with node; null = dist/cli/main.js of this build. */
  strataCli: string | null;
  /** Run CuraEngine / PrusaSlicer when they are on PATH. */
  peers: boolean;
  /** Run the per-infill-pattern section on 3DBenchy. */
  patterns: boolean;
  /** Keep the temporary folder with the G-code written. */
  keep: boolean;
  help: boolean;
}

export const BENCH_USAGE = `Usage: npm run bench -- [options]
  (or: node dist/bench/run.js [options])

Slices every model in ../shared/models with Strata (node dist/cli/main.js slice) and, where they are on
PATH, CuraEngine and PrusaSlicer with a comparable profile; prints wall time and peak memory per model,
then Strata's time per infill pattern on 3DBenchy relative to grid.

Options:
  --only NAME        only models whose file name or stem matches NAME (repeatable, or comma-separated)
  --threads N        threads for Strata (--threads N) and CuraEngine (-mN); default: one per core
  --repeat K         run each slicer K times per model and report the median (default 1)
  --json             print the results as JSON instead of tables
  --timeout SEC      kill a slicer run after SEC seconds (default 600)
  --models DIR       folder of models (default ../shared/models beside the repository)
  --strata-cli FILE  Strata CLI script to run with node (default dist/cli/main.js)
  --no-peers         do not run CuraEngine or PrusaSlicer
  --no-patterns      skip the per-infill-pattern section
  --keep             keep the temporary folder with the G-code written
  -h, --help         show this help`;

export class BenchArgsError extends Error {
  override name = 'BenchArgsError';
}

const VALUE_FLAGS = ['--only', '--threads', '--repeat', '--timeout', '--models', '--strata-cli'] as const;
type ValueFlag = (typeof VALUE_FLAGS)[number];
const isValueFlag = (s: string): s is ValueFlag => (VALUE_FLAGS as readonly string[]).includes(s);

function positiveInt(flag: string, raw: string, max: number): number {
  const n = Number(raw);
  if (!/^\d+$/.test(raw) || !Number.isInteger(n) || n < 1 || n > max) {
    throw new BenchArgsError(`${flag} needs a whole number from 1 to ${max}, got "${raw}"`);
  }
  return n;
}

function positiveNumber(flag: string, raw: string): number {
  const n = Number(raw);
  if (raw.trim() === '' || !Number.isFinite(n) || n <= 0) throw new BenchArgsError(`${flag} needs a positive number, got "${raw}"`);
  return n;
}

/** Parses the arguments after the script name. Throws BenchArgsError naming the bad flag. */
export function parseBenchArgs(argv: readonly string[]): BenchOptions {
  const options: BenchOptions = {
    only: [],
    threads: null,
    repeat: 1,
    json: false,
    timeoutSeconds: 600,
    modelsDir: null,
    strataCli: null,
    peers: true,
    patterns: true,
    keep: false,
    help: false,
  };
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
        case '--only':
          options.only.push(...value.split(',').map((s) => s.trim()).filter((s) => s !== ''));
          break;
        case '--threads':
          options.threads = positiveInt(arg, value, 256);
          break;
        case '--repeat':
          options.repeat = positiveInt(arg, value, 1000);
          break;
        case '--timeout':
          options.timeoutSeconds = positiveNumber(arg, value);
          break;
        case '--models':
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
      case '--no-patterns':
        options.patterns = false;
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
          `unknown argument "${arg}"; allowed: ${[...VALUE_FLAGS, '--json', '--no-peers', '--no-patterns', '--keep', '--help'].join(', ')}`,
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
