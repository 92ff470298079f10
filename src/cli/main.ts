#!/usr/bin/env node
/**
 * The `strata` command: slice, info, preview, infillers, presets, settings. Bad input gives a
 * one-line error and a non-zero exit, never a stack trace (set STRATA_DEBUG=1 to see one). Output
 * files are written whole or not at all (output.ts); a closed pipe ends the command quietly.
 */
import { realpathSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { StrataError } from '../errors.js';
import { VERSION } from '../pipeline/run.js';
import { checkFlagsFor, COMMANDS, parseArgs, type Command } from './args.js';
import { processIo, type Io } from './io.js';
import { abortPendingOutputs, PipeClosed } from './output.js';
import { tuneEngine } from './engine-flags.js';

const HELP = `strata ${VERSION}: a fast FFF slicer

Usage:
  strata slice MODEL... [-o OUT.gcode] [options]   slice STL/OBJ/3MF models (- reads stdin) to G-code
  strata info MODEL... [--json]                    triangles, size, volume, open and non-manifold edges
  strata preview MODEL [--layer N] [-o layer.svg]   slice and draw one layer as SVG (paths by feature,
                                                   --travel adds travels, --width PX sets the size)
  strata infillers [DIR...]                         list custom infillers (IceSL layout) and their parameters
  strata presets [--json]                          list printer and filament presets
  strata settings [--json]                         list every setting with its flag, unit, default and range
  strata serve [--port N]                          the web page on http://127.0.0.1:N/ (default 8080)
  strata send FILE.gcode --to octoprint|moonraker URL [--api-key KEY] [--print]
                                                   upload G-code to a print host (and start printing it)

Slice options (slice and preview):
  -o, --output FILE      where to write (- for stdout; slice's default: MODEL.gcode). The file is
                         replaced only when the slice succeeds; an input is never overwritten
  --printer NAME         printer preset (default creality-ender-3)
  --filament NAME        filament preset (default pla)
  --config FILE          settings from a JSON object (may name printer and filament), or a
                         PrusaSlicer/SuperSlicer/OrcaSlicer .ini or .json, or Cura .cfg profile; repeatable
  --set key=value        any setting by its key; repeatable
  --no-center            keep the models' own XY coordinates instead of arranging them on the bed
  --object-spacing MM    gap between models arranged on the bed (default 6)
  --scale F | X,Y,Z      scale each model (2 = twice the size), or each axis
  --rotate Z | X,Y,Z     turn each model (degrees) about Z, or about X, then Y, then Z
  --up-axis y            the models are Y-up (three.js, many OBJ exports): stand them up
  --threads N            threads (default: one per core above two cores, else one); same output for any N
  -q, --quiet            no progress bar, summary or warnings
  --infill-shader FILE   custom infill from a GLSL cellular() shader (IceSL infiller format)
  --infill-image FILE    custom infill from a cells.png image (with --infill-image-pixel-size MM)
  --infill-pattern NAME  a built-in pattern, or an infiller folder NAME/shader.glsl|cells.png
                         (shipped infillers/, ~/.icesl/icesl-infillers, or --infillers DIR)
  --infill-param N=V     set a shader's ui_ parameter; repeatable
  --infill-density-shader FILE   density() from a shader defining float density(vec3 world), 0-100
  --infill-density-layers A,B,…  density() per layer (the last value holds for the layers above)
  --<setting> VALUE      every setting has a flag, e.g. --layer-height 0.2 --infill-density 20
                         --infill-pattern gyroid --wall-count 3 (see: strata settings)
`;

/** Exit status after the reader of standard output closed it (as if killed by SIGPIPE). */
export const EXIT_PIPE_CLOSED = 141;

/** Run the command line `argv`; returns the exit status. */
export async function main(argv: readonly string[], io: Io = processIo): Promise<number> {
  const stdout = io.out;
  try {
    // the web page server parses its own few flags (serve.ts)
    if (argv[0] === 'serve') {
      await (await import('./serve.js')).cmdServe(argv.slice(1));
      return 0;
    }
    const args = parseArgs(argv);
    if (args.flags.version) {
      stdout(`strata ${VERSION}\n`);
      return 0;
    }
    if (args.flags.help || !args.command || args.command === 'help') {
      stdout(HELP);
      return 0;
    }
    if (!(COMMANDS as readonly string[]).includes(args.command)) {
      throw new StrataError(
        'BAD_SETTING',
        `unknown command "${args.command}" (commands: ${COMMANDS.join(', ')}, serve)`,
      );
    }
    checkFlagsFor(args);
    // each command's modules load when it runs (a slice does not load the listings, the server or the shader compiler)
    switch (args.command as Command) {
      case 'slice':
        await (await import('./slice.js')).cmdSlice(args, io);
        return 0;
      case 'info':
        await (await import('./info.js')).cmdInfo(args, stdout);
        return 0;
      case 'preview':
        await (await import('./slice.js')).cmdPreview(args, io);
        return 0;
      case 'infillers':
        await (await import('./lists.js')).cmdInfillers(args, stdout);
        return 0;
      case 'presets':
        (await import('./lists.js')).cmdPresets(args, stdout);
        return 0;
      case 'settings':
        (await import('./lists.js')).cmdSettings(args, stdout);
        return 0;
      case 'send':
        await (await import('./send.js')).cmdSend(args, io);
        return 0;
    }
  } catch (e) {
    if (e instanceof PipeClosed) return EXIT_PIPE_CLOSED;
    if (e instanceof StrataError) {
      io.err(`strata: error: ${e.message}\n`);
      return 1;
    }
    if (process.env.STRATA_DEBUG) throw e;
    io.err(`strata: internal error: ${e instanceof Error ? e.message : String(e)} (STRATA_DEBUG=1 shows details)\n`);
    return 2;
  }
}

/** Whether this file is the program being run (also through npm's bin link), not an import. */
function isEntryPoint(): boolean {
  const script = process.argv[1];
  if (!script) return false;
  try {
    return realpathSync(script) === realpathSync(fileURLToPath(import.meta.url));
  } catch {
    return false;
  }
}

/** Ctrl-C, a kill or a closed terminal: remove unfinished output files, then end as the signal would. */
function handleSignals(): void {
  for (const signal of ['SIGINT', 'SIGTERM', 'SIGHUP'] as const) {
    const onSignal = (): void => {
      abortPendingOutputs();
      process.removeListener(signal, onSignal);
      process.kill(process.pid, signal);
    };
    process.on(signal, onSignal);
  }
  process.on('exit', abortPendingOutputs);
  // a reader that stops early (strata settings | head): end quietly
  process.stdout.on('error', (e: NodeJS.ErrnoException) => {
    if (e.code !== 'EPIPE') throw e;
    abortPendingOutputs();
    process.exit(EXIT_PIPE_CLOSED);
  });
}

if (isEntryPoint()) {
  tuneEngine();
  handleSignals();
  process.exitCode = await main(process.argv.slice(2));
}
