/**
 * The real print hosts for the end-to-end tests: OctoPrint (with its virtual printer) and Moonraker (no
 * Klipper attached, which uploads and metadata do not need), started on 127.0.0.1 from the Python
 * environments `.ci/run` installs from PyPI (`.ci/print-hosts.sh`: pinned versions, one venv each, since
 * their dependencies conflict). Found at $STRATA_PRINT_HOSTS (default ~/.cache/strata/print-hosts): the
 * executables `octoprint/bin/octoprint` and `moonraker/bin/python`. Missing, the tests skip with the reason;
 * under CI=true they fail instead.
 */
import { spawn, type ChildProcess } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { homedir, tmpdir } from 'node:os';
import { join } from 'node:path';
import { inCi } from './models-dir.js';

export const PRINT_HOSTS_DIR = process.env.STRATA_PRINT_HOSTS || join(homedir(), '.cache', 'strata', 'print-hosts');
export const OCTOPRINT = join(PRINT_HOSTS_DIR, 'octoprint', 'bin', 'octoprint');
export const MOONRAKER_PYTHON = join(PRINT_HOSTS_DIR, 'moonraker', 'bin', 'python');

/** For a test's `skip`: false when the host is installed; else the reason, or under CI an error. */
export function skipWithout(executable: string, what: string): string | false {
  if (existsSync(executable)) return false;
  const why = `${what} is not installed at ${executable} (.ci/print-hosts.sh installs it; STRATA_PRINT_HOSTS chooses where)`;
  if (inCi()) throw new Error(`${why}: under CI the print-host tests fail rather than skip`);
  return why;
}

async function freePort(): Promise<number> {
  const server = createServer();
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const port = (server.address() as { port: number }).port;
  await new Promise<void>((resolve) => server.close(() => resolve()));
  return port;
}

export interface RunningHost {
  url: string;
  dir: string;
  /** The host's output so far (for messages when it fails). */
  log: () => string;
  stop: () => Promise<void>;
}

/** Start a server process and wait until `ready` answers 200 (or the process ends, or `timeoutMs` passes). */
async function start(
  command: string,
  args: string[],
  url: string,
  ready: string,
  dir: string,
  headers: Record<string, string> = {},
  timeoutMs = 90_000,
): Promise<RunningHost> {
  const child: ChildProcess = spawn(command, args, {
    cwd: dir,
    stdio: ['ignore', 'pipe', 'pipe'],
    env: { ...process.env, PYTHONUNBUFFERED: '1' },
  });
  let output = '';
  child.stdout!.on('data', (d) => (output = (output + d).slice(-20_000)));
  child.stderr!.on('data', (d) => (output = (output + d).slice(-20_000)));
  let exited = false;
  const exit = new Promise<void>((resolve) => child.on('exit', () => ((exited = true), resolve())));
  const stop = async () => {
    if (!exited) {
      child.kill('SIGTERM');
      const killer = setTimeout(() => child.kill('SIGKILL'), 10_000);
      await exit;
      clearTimeout(killer);
    }
  };
  const until = Date.now() + timeoutMs;
  for (;;) {
    if (exited) throw new Error(`${command} ended before it answered:\n${output}`);
    try {
      const r = await fetch(url + ready, { headers });
      if (r.status === 200) break;
    } catch {
      // not listening yet
    }
    if (Date.now() > until) {
      await stop();
      throw new Error(`${command} did not answer ${ready} in ${timeoutMs / 1000} s:\n${output}`);
    }
    await new Promise((r) => setTimeout(r, 250));
  }
  return { url, dir, log: () => output, stop };
}

export const OCTOPRINT_KEY = 'STRATA0TEST0KEY0000000000000000A';

/**
 * OctoPrint with a global API key, its first-run wizard done, nothing fetched from the internet, and the
 * virtual printer (fast: little per-line throttling, the nozzle pinned at `nozzleC` so heating takes no time).
 */
export async function startOctoPrint(nozzleC: number): Promise<RunningHost> {
  const dir = mkdtempSync(join(tmpdir(), 'strata-octoprint-'));
  const port = await freePort();
  writeFileSync(
    join(dir, 'config.yaml'),
    [
      'api:',
      `  key: ${OCTOPRINT_KEY}`,
      'server:',
      '  firstRun: false',
      '  onlineCheck:',
      '    enabled: false',
      '  pluginBlacklist:',
      '    enabled: false',
      '  pythonEolCheck:',
      '    enabled: false',
      'serial:',
      '  autoconnect: false',
      'plugins:',
      '  virtual_printer:',
      '    enabled: true',
      '    throttle: 0.0005',
      '    pinnedExtruders:',
      `      0: ${nozzleC}`,
      '  tracking:',
      '    enabled: false',
      '  announcements:',
      '    enabled: false',
      '  errortracking:',
      '    enabled: false',
      '  softwareupdate:',
      '    check_overlay_url: ""',
      '',
    ].join('\n'),
  );
  // OctoPrint refuses to run as root unless told (CI machines often are root)
  const root = process.getuid?.() === 0 ? ['--iknowwhatimdoing'] : [];
  return start(
    OCTOPRINT,
    ['serve', ...root, '--basedir', dir, '--host', '127.0.0.1', '--port', String(port)],
    `http://127.0.0.1:${port}`,
    '/api/version',
    dir,
    { 'X-Api-Key': OCTOPRINT_KEY },
  );
}

/** Moonraker with no Klipper, this machine a trusted client (for /access/api_key) and any page origin allowed. */
export async function startMoonraker(): Promise<RunningHost> {
  const dir = mkdtempSync(join(tmpdir(), 'strata-moonraker-'));
  const port = await freePort();
  mkdirSync(join(dir, 'config'));
  mkdirSync(join(dir, 'gcodes'));
  writeFileSync(
    join(dir, 'config', 'moonraker.conf'),
    [
      '[server]',
      'host: 127.0.0.1',
      `port: ${port}`,
      `klippy_uds_address: ${join(dir, 'comms', 'klippy.sock')}`,
      '',
      '[file_manager]',
      'enable_object_processing: False',
      '',
      '[authorization]',
      'trusted_clients:',
      '    127.0.0.1/32',
      'cors_domains:',
      '    *',
      '',
    ].join('\n'),
  );
  return start(MOONRAKER_PYTHON, ['-m', 'moonraker', '-d', dir, '-n'], `http://127.0.0.1:${port}`, '/server/info', dir);
}

/** GET a host's JSON. */
export async function getJson(url: string, headers: Record<string, string> = {}): Promise<Record<string, unknown>> {
  const r = await fetch(url, { headers });
  if (!r.ok) throw new Error(`GET ${url}: ${r.status} ${await r.text()}`);
  return (await r.json()) as Record<string, unknown>;
}

/** GET a host's file. */
export async function getBytes(url: string, headers: Record<string, string> = {}): Promise<Uint8Array> {
  const r = await fetch(url, { headers });
  if (!r.ok) throw new Error(`GET ${url}: ${r.status}`);
  return new Uint8Array(await r.arrayBuffer());
}
