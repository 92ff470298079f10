/**
 * `npm run bench` entry point: parses the arguments, runs the benchmark in a temporary folder and prints the
 * tables (or JSON with --json) on stdout; progress goes to stderr. See args.ts for the options.
 */
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { BENCH_USAGE, BenchArgsError, parseBenchArgs } from './args.js';
import { runBench } from './bench.js';
import { renderReport } from './report.js';

async function main(argv: readonly string[]): Promise<number> {
  let options;
  try {
    options = parseBenchArgs(argv);
  } catch (err) {
    if (err instanceof BenchArgsError) {
      process.stderr.write(`bench: ${err.message}\n\n${BENCH_USAGE}\n`);
      return 2;
    }
    throw err;
  }
  if (options.help) {
    process.stdout.write(`${BENCH_USAGE}\n`);
    return 0;
  }

  const workDir = mkdtempSync(join(tmpdir(), 'strata-bench-'));
  const abort = new AbortController();
  const onSigint = () => abort.abort();
  process.once('SIGINT', onSigint);
  try {
    const report = await runBench(options, {
      workDir,
      log: (line) => process.stderr.write(`${line}\n`),
      signal: abort.signal,
    });
    process.stdout.write(options.json ? `${JSON.stringify(report, null, 2)}\n` : `${renderReport(report)}\n`);
    if (options.keep) process.stderr.write(`G-code kept in ${join(workDir, 'out')}\n`);
    return abort.signal.aborted ? 130 : 0;
  } catch (err) {
    process.stderr.write(`bench: ${err instanceof Error ? err.message : String(err)}\n`);
    return 1;
  } finally {
    process.off('SIGINT', onSigint);
    if (!options.keep) rmSync(workDir, { recursive: true, force: true });
  }
}

process.exitCode = await main(process.argv.slice(2));
