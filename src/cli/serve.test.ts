import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { request } from 'node:http';
import { fileURLToPath } from 'node:url';
import { StrataError } from '../errors.js';
import { parseServeArgs, resolveUnder, startServer } from './serve.js';

const cli = fileURLToPath(new URL('./main.js', import.meta.url));

function get(url: string, path: string, method = 'GET'): Promise<{ status: number; headers: Record<string, string | string[] | undefined>; body: string }> {
  return new Promise((resolve, reject) => {
    const u = new URL(url);
    const req = request({ host: u.hostname, port: u.port, path, method }, (res) => {
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
    assert.ok(infillers.some((i) => i.name === 'voronoi-foam'), 'the shipped infillers are listed');
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
