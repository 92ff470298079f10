import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { closedPort, fakeHost } from '../send/test-fake-host.js';

const CLI = fileURLToPath(new URL('../../../dist/cli/main.js', import.meta.url));
const DIR = mkdtempSync(join(tmpdir(), 'strata-send-'));
const GCODE = join(DIR, 'part.gcode');
writeFileSync(GCODE, ';FLAVOR:Marlin\nG28\nG1 X10 Y10 E1\n');
const STL = join(DIR, 'part.stl');
writeFileSync(STL, 'solid part\nfacet normal 0 0 1\nouter loop\n');

/** Run the CLI (asynchronously: the fake host answers in this process). */
function cli(args: string[], env: Record<string, string> = {}): Promise<{ code: number; out: string; err: string }> {
  return new Promise((resolve) => {
    const p = spawn(process.execPath, [CLI, ...args], { env: { ...process.env, STRATA_API_KEY: '', ...env } });
    let out = '',
      err = '';
    p.stdout.on('data', (d) => (out += d));
    p.stderr.on('data', (d) => (err += d));
    p.on('close', (code) => resolve({ code: code ?? -1, out, err }));
  });
}

test('strata send uploads to OctoPrint with the key and prints; the summary is one line', async () => {
  const host = await fakeHost((r) =>
    r.headers['x-api-key'] === 'GOOD'
      ? {
          status: 201,
          body: { done: true, effectivePrint: r.fields.print === 'true', files: { local: { path: 'part.gcode' } } },
        }
      : { status: 403, body: { error: 'Forbidden' } },
  );
  try {
    const ok = await cli(['send', GCODE, '--to', 'octoprint', host.url, '--api-key', 'GOOD', '--print']);
    assert.equal(ok.code, 0, ok.err);
    assert.match(
      ok.err,
      /^.*part\.gcode: sent to OctoPrint at http:\/\/127\.0\.0\.1:\d+ as part\.gcode \(1 KB\); printing\n$/,
    );
    assert.equal(host.received.filter((r) => r.method === 'POST')[0]!.fields.print, 'true');
    // the key from the environment, and the address before the file
    const env = await cli(['send', host.url, '--to', 'octoprint', GCODE], { STRATA_API_KEY: 'GOOD' });
    assert.equal(env.code, 0, env.err);
    assert.doesNotMatch(env.err, /printing/);
    assert.equal(host.received.filter((r) => r.method === 'POST')[1]!.fields.print, 'false');
    const bad = await cli(['send', GCODE, '--to', 'octoprint', host.url, '--api-key', 'WRONG']);
    assert.equal(bad.code, 1);
    assert.match(
      bad.err,
      /^strata: error: OctoPrint at http:\/\/127\.0\.0\.1:\d+ refused the API key \(403 Forbidden\): check --api-key/,
    );
    assert.equal(bad.err.trim().split('\n').length, 1);
  } finally {
    await host.close();
  }
});

test('strata send --print to a host that does not start it: uploaded, exit 1, and why', async () => {
  const host = await fakeHost(() => ({
    status: 201,
    body: { item: { path: 'part.gcode' }, print_started: false, print_queued: true },
  }));
  try {
    const r = await cli(['send', GCODE, '--to', 'moonraker', host.url, '--print']);
    assert.equal(r.code, 1);
    assert.match(
      r.err,
      /^strata: error: .*part\.gcode: sent to Moonraker at .* as part\.gcode \(1 KB\), but not printing: Moonraker put the file in its job queue/,
    );
  } finally {
    await host.close();
  }
});

test('strata send: usage, unreachable host, not G-code, missing file: one line each, exit 1', async () => {
  const port = await closedPort();
  const cases: Array<[string[], RegExp]> = [
    [['send', GCODE, `http://127.0.0.1:${port}`], /send needs --to octoprint or --to moonraker/],
    [['send', GCODE, '--to', 'prusalink', 'http://x'], /the host must be one of octoprint, moonraker/],
    [['send', GCODE, '--to', 'octoprint'], /send takes a G-code file and the host's address/],
    [
      ['send', GCODE, '--to', 'octoprint', `http://127.0.0.1:${port}`],
      new RegExp(`cannot reach OctoPrint at http://127\\.0\\.0\\.1:${port}: connection refused`),
    ],
    [['send', STL, '--to', 'moonraker', `http://127.0.0.1:${port}`], /part\.stl is not a G-code file name/],
    [
      ['send', join(DIR, 'missing.gcode'), '--to', 'moonraker', `http://127.0.0.1:${port}`],
      /cannot read .*missing\.gcode: no such file/,
    ],
    [['slice', GCODE, '--print'], /--print does not apply to strata slice \(it is for strata send\)/],
  ];
  for (const [args, message] of cases) {
    const r = await cli(args);
    assert.equal(r.code, 1, `${args.join(' ')}: ${r.err}`);
    assert.match(r.err, new RegExp(`^strata: error: ${message.source}`));
    assert.equal(r.err.trim().split('\n').length, 1, r.err);
  }
});
