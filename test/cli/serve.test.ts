import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { request } from 'node:http';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { StrataError } from '#strata/errors.js';
import { hostName, matchesEtag, parseServeArgs, resolveUnder, startServer } from '#strata/cli/serve.js';

const cli = fileURLToPath(new URL('../../../dist/cli/main.js', import.meta.url));

function get(
  url: string,
  path: string,
  method = 'GET',
  headers: Record<string, string> = {},
): Promise<{ status: number; headers: Record<string, string | string[] | undefined>; body: string }> {
  return new Promise((resolve, reject) => {
    const u = new URL(url);
    const req = request({ host: u.hostname, port: u.port, path, method, headers }, (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (c) => (body += c));
      res.on('end', () => resolve({ status: res.statusCode ?? 0, headers: res.headers, body }));
    });
    req.on('error', reject);
    req.end();
  });
}

test('serves the built page on 127.0.0.1: the page, its scripts as JavaScript, cross-origin isolated; nothing outside it', async () => {
  const { server, url } = await startServer({ port: 0 });
  try {
    assert.match(url, /^http:\/\/127\.0\.0\.1:\d+\/$/);
    const page = await get(url, '/');
    assert.equal(page.status, 200);
    assert.match(String(page.headers['content-type']), /^text\/html/);
    assert.match(page.body, /<title>Strata/);
    assert.equal(page.headers['cross-origin-opener-policy'], 'same-origin');
    assert.equal(page.headers['cross-origin-embedder-policy'], 'require-corp');
    for (const script of ['/app.js', '/slice-worker.js', '/layer-worker.js']) {
      const r = await get(url, script);
      assert.equal(r.status, 200, script);
      assert.match(String(r.headers['content-type']), /^text\/javascript/, script);
    }
    const infillers = JSON.parse((await get(url, '/infillers/index.json')).body) as { name: string }[];
    assert.ok(
      infillers.some((i) => i.name === 'voronoi-foam'),
      'the shipped infillers are listed',
    );
    assert.equal((await get(url, '/no-such-file.js')).status, 404);
    assert.equal((await get(url, '/../../package.json')).status, 400);
    assert.equal((await get(url, '/%2e%2e/%2e%2e/package.json')).status, 400);
    assert.equal((await get(url, '/', 'POST')).status, 405);
    const head = await get(url, '/', 'HEAD');
    assert.equal(head.status, 200);
    assert.equal(head.body, '');
  } finally {
    server.close();
  }
});

test('resolveUnder keeps paths inside the folder', () => {
  assert.equal(resolveUnder('/srv/web', '/'), '/srv/web/index.html');
  assert.equal(resolveUnder('/srv/web', '/a/b.js?x=1'), '/srv/web/a/b.js');
  assert.equal(resolveUnder('/srv/web', '/../etc/passwd'), null);
  assert.equal(resolveUnder('/srv/web', '/..%2f..%2fetc/passwd'), null);
  assert.equal(resolveUnder('/srv/web', '/%00'), null);
  assert.equal(resolveUnder('/srv/web', '/%E0%A4%A'), null);
});

test('serve arguments: --port N, and one-line errors', () => {
  assert.deepEqual(parseServeArgs([]), { port: 8080 });
  assert.deepEqual(parseServeArgs(['--port', '9000']), { port: 9000 });
  assert.deepEqual(parseServeArgs(['--port=0']), { port: 0 });
  for (const bad of [['--port'], ['--port', 'x'], ['--port', '70000'], ['--host', 'a']]) {
    assert.throws(() => parseServeArgs(bad), StrataError, bad.join(' '));
  }
});

test('strata serve --port 0 prints the URL it serves on, and a taken port is a one-line error', async () => {
  const child = spawn(process.execPath, [cli, 'serve', '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  try {
    const url = await new Promise<string>((resolve, reject) => {
      let out = '';
      child.stdout.on('data', (c: Buffer) => {
        out += c.toString();
        const m = /Strata web page: (http:\/\/127\.0\.0\.1:\d+\/)/.exec(out);
        if (m) resolve(m[1]);
      });
      child.on('exit', (code) => reject(new Error(`serve exited (${code}) before printing its URL`)));
    });
    assert.equal((await get(url, '/')).status, 200);
    const port = new URL(url).port;
    const taken = spawn(process.execPath, [cli, 'serve', '--port', port], { stdio: ['ignore', 'pipe', 'pipe'] });
    let err = '';
    taken.stderr.on('data', (c: Buffer) => (err += c.toString()));
    const code = await new Promise<number | null>((resolve) => taken.on('exit', resolve));
    assert.equal(code, 1);
    assert.match(err, /^strata: error: port \d+ is in use: choose another with --port N\n$/);
  } finally {
    child.kill('SIGTERM');
  }
});

test('the page is sent with a Content-Security-Policy and is never framed; eval only in the workers', async () => {
  const { server, url } = await startServer({ port: 0 });
  try {
    const page = await get(url, '/');
    const csp = String(page.headers['content-security-policy']);
    assert.match(csp, /(^|; )default-src 'self'(;|$)/);
    assert.match(csp, /(^|; )frame-ancestors 'none'(;|$)/);
    assert.match(csp, /(^|; )script-src 'self' 'wasm-unsafe-eval'(;|$)/, 'no eval on the page');
    assert.match(csp, /(^|; )object-src 'none'(;|$)/);
    assert.equal(page.headers['x-frame-options'], 'DENY');
    for (const worker of ['/slice-worker.js', '/layer-worker.js']) {
      const w = await get(url, worker);
      assert.match(
        String(w.headers['content-security-policy']),
        /script-src 'self' 'wasm-unsafe-eval' 'unsafe-eval'/,
        `${worker}: custom infill shaders are compiled to JavaScript there`,
      );
    }
    assert.doesNotMatch(String((await get(url, '/app.js')).headers['content-security-policy']), /'unsafe-eval'/);
    assert.match(
      String((await get(url, '/nothing-here')).headers['content-security-policy']),
      /default-src 'self'/,
      'errors too',
    );
  } finally {
    server.close();
  }
});

test('only requests addressed to this machine by name are answered (DNS rebinding)', async () => {
  const { server, url } = await startServer({ port: 0 });
  const port = new URL(url).port;
  try {
    for (const host of [
      `127.0.0.1:${port}`,
      `localhost:${port}`,
      `LOCALHOST:${port}`,
      `[::1]:${port}`,
      'localhost',
      `localhost.:${port}`,
    ]) {
      assert.equal((await get(url, '/', 'GET', { Host: host })).status, 200, host);
    }
    for (const host of [
      `attacker.example:${port}`,
      'attacker.example',
      `127.0.0.1.attacker.example:${port}`,
      `localhost.attacker.example`,
      `192.168.1.5:${port}`,
      'a b',
    ]) {
      const r = await get(url, '/', 'GET', { Host: host });
      assert.equal(r.status, 403, `Host: ${JSON.stringify(host)}`);
      assert.doesNotMatch(r.body, /<title>/, 'no page for another name');
    }
    assert.equal(hostName('LocalHost:8080'), 'localhost');
    assert.equal(hostName('[::1]:80'), '[::1]');
    assert.equal(hostName('evil:80:80'), null);
    assert.equal(hostName(undefined), null);
  } finally {
    server.close();
  }
});

test('ETags: a reload revalidates and gets 304 without the body; a changed file is sent again', async () => {
  const root = mkdtempSync(join(tmpdir(), 'strata-serve-'));
  writeFileSync(join(root, 'index.html'), '<title>Strata</title>');
  writeFileSync(join(root, 'app.js'), 'x'.repeat(100_000));
  const { server, url } = await startServer({ port: 0, root });
  try {
    const first = await get(url, '/app.js');
    assert.equal(first.status, 200);
    const etag = String(first.headers.etag);
    assert.match(etag, /^"[0-9a-f]+-[0-9a-f]+"$/);
    const again = await get(url, '/app.js', 'GET', { 'If-None-Match': etag });
    assert.equal(again.status, 304);
    assert.equal(again.body, '');
    assert.equal(again.headers.etag, etag);
    assert.equal(
      (await get(url, '/app.js', 'GET', { 'If-None-Match': `"other", W/${etag}` })).status,
      304,
      'a list, a weak tag',
    );
    assert.equal((await get(url, '/app.js', 'GET', { 'If-None-Match': '"other"' })).status, 200);
    writeFileSync(join(root, 'app.js'), 'y'.repeat(100_001));
    const changed = await get(url, '/app.js', 'GET', { 'If-None-Match': etag });
    assert.equal(changed.status, 200, 'a new version is sent');
    assert.notEqual(changed.headers.etag, etag);
    assert.equal(changed.body.length, 100_001);
    assert.ok(matchesEtag('*', '"a"') && !matchesEtag(undefined, '"a"') && matchesEtag(' "b" , "a"', '"a"'));
  } finally {
    server.close();
  }
});
