/** `strata send FILE.gcode --to octoprint|moonraker URL [--api-key KEY] [--print]`: upload to a print host. */
import { readFileSync, statSync } from 'node:fs';
import { basename } from 'node:path';
import { StrataError } from '../errors.js';
import { GCODE_EXTENSIONS } from '../send/gcode-check.js';
import { checkHostKind } from '../send/hosts.js';
import { sendToPrinter } from '../send/node.js';
import type { ParsedArgs } from './args.js';
import type { Io } from './io.js';
import { progressBar } from './progress.js';

function isFile(path: string): boolean {
  try {
    return statSync(path).isFile();
  } catch {
    return false;
  }
}

function size(bytes: number): string {
  return bytes >= 1024 * 1024
    ? `${(bytes / 1024 / 1024).toFixed(1)} MB`
    : `${Math.max(1, Math.round(bytes / 1024))} KB`;
}

export async function cmdSend(args: ParsedArgs, io: Io): Promise<void> {
  const usage = 'usage: strata send FILE.gcode --to octoprint|moonraker URL [--api-key KEY] [--print]';
  if (typeof args.flags.to !== 'string')
    throw new StrataError(
      'BAD_SETTING',
      `send needs --to octoprint or --to moonraker, then the host's address (${usage})`,
    );
  const to = checkHostKind(args.flags.to.toLowerCase());
  if (args.positional.length !== 2)
    throw new StrataError('BAD_SETTING', `send takes a G-code file and the host's address (${usage})`);
  // the file is the one that is a file (or named like G-code); the other is the address, in either order
  const [a, b] = args.positional as [string, string];
  const fileFirst = isFile(a) || (!isFile(b) && GCODE_EXTENSIONS.some((e) => a.toLowerCase().endsWith(e)));
  const [file, url] = fileFirst ? [a, b] : [b, a];
  let bytes: Uint8Array;
  try {
    bytes = readFileSync(file);
  } catch (e) {
    const code = (e as NodeJS.ErrnoException).code;
    throw new StrataError(
      'BAD_FILE',
      `cannot read ${file}: ${code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'it is a folder' : (e as Error).message}`,
    );
  }
  const apiKey =
    typeof args.flags['api-key'] === 'string' ? args.flags['api-key'] : process.env.STRATA_API_KEY || undefined;
  const print = args.flags.print === true;
  const bar = io.errIsTTY ? progressBar(process.stderr) : null;
  let result;
  try {
    result = await sendToPrinter(bytes, {
      to,
      url,
      apiKey,
      print,
      name: basename(file),
      keyName: '--api-key',
      onProgress: bar ? ({ sent, total }) => bar.update(sent / total, 'uploading') : undefined,
    });
  } finally {
    bar?.done();
  }
  const host = to === 'octoprint' ? 'OctoPrint' : 'Moonraker';
  const what = `${file}: sent to ${host} at ${result.url} as ${result.name} (${size(result.bytes)})`;
  if (print && !result.started)
    throw new StrataError('WRITE_FAILED', `${what}, but not printing: ${result.notStarted}`);
  io.err(`${what}${result.started ? '; printing' : ''}\n`);
}
