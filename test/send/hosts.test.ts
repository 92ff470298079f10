import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { hostMessage, hostUrl, sendGcode } from '#strata/send/hosts.js';
import { nodeTransport } from '#strata/send/node-transport.js';
import { sendToPrinter } from '#strata/send/node.js';
import { closedPort, fakeHost, type Answer } from './test-fake-host.js';

const GCODE = ';FLAVOR:Marlin\nG28\n' + 'G1 X10 Y10 E0.5\n'.repeat(20000);
const file = { name: 'part.gcode', bytes: new TextEncoder().encode(GCODE) };

/** The one-line message a send fails with. */
async function failure(p: Promise<unknown>): Promise<string> {
  try {
    await p;
  } catch (e) {
    assert.ok(e instanceof StrataError, String(e));
    assert.ok(!e.message.includes('\n'), e.message);
    return e.message;
  }
  assert.fail('the send succeeded');
}

test('OctoPrint: the file and form fields arrive whole, with the key; progress reaches the total; print starts', async () => {
  const host = await fakeHost(() => ({
    status: 201,
    body: { done: true, effectivePrint: true, files: { local: { name: 'part.gcode', path: 'part.gcode' } } },
  }));
  try {
    const progress: number[] = [];
    const r = await sendGcode(
      file,
      {
        to: 'octoprint',
        url: host.url,
        apiKey: 'KEY',
        print: true,
        onProgress: ({ sent, total }) => progress.push(sent / total),
      },
      nodeTransport,
    );
    const got = host.received.find((r) => r.method === 'POST')!;
    assert.equal(host.received[0]!.path, '/api/version', 'the key is tried first with a small request');
    assert.equal(got.method, 'POST');
    assert.equal(got.path, '/api/files/local');
    assert.equal(got.headers['x-api-key'], 'KEY');
    assert.deepEqual(got.fields, { select: 'true', print: 'true' });
    assert.equal(got.file!.name, 'part.gcode');
    assert.ok(got.file!.bytes.equals(Buffer.from(file.bytes)), 'byte for byte');
    assert.deepEqual(r, {
      host: 'octoprint',
      url: host.url,
      name: 'part.gcode',
      bytes: file.bytes.length,
      started: true,
      queued: false,
    });
    assert.ok(
      progress.length > 3 && progress.at(-1) === 1 && progress.every((p, i) => i === 0 || p >= progress[i - 1]!),
      'progress rises to 1',
    );
  } finally {
    await host.close();
  }
});

test('Moonraker: /server/files/upload to the gcodes root; a print it did not start is said why', async () => {
  const host = await fakeHost(() => ({
    status: 201,
    body: {
      item: { path: 'sub/part.gcode', root: 'gcodes' },
      print_started: false,
      print_queued: false,
      action: 'create_file',
    },
  }));
  try {
    const r = await sendGcode(file, { to: 'moonraker', url: host.url + '/', print: true }, nodeTransport);
    const got = host.received.find((r) => r.method === 'POST')!;
    assert.equal(host.received[0]!.path, '/server/info');
    assert.equal(got.path, '/server/files/upload');
    assert.deepEqual(got.fields, { root: 'gcodes', print: 'true' });
    assert.equal(got.headers['x-api-key'], undefined, 'no key given, none sent');
    assert.equal(r.name, 'sub/part.gcode');
    assert.equal(r.started, false);
    assert.match(r.notStarted!, /^Moonraker did not start the print: Klipper is not ready/);
  } finally {
    await host.close();
  }
});

test('OctoPrint without a connected printer: uploaded, not printing, and why', async () => {
  const host = await fakeHost(() => ({
    status: 201,
    body: { done: true, effectivePrint: false, files: { local: { path: 'part.gcode' } } },
  }));
  try {
    const r = await sendToPrinter(GCODE, {
      to: 'octoprint',
      url: host.url,
      apiKey: 'K',
      print: true,
      name: 'part.gcode',
    });
    assert.equal(r.started, false);
    assert.match(r.notStarted!, /the printer is not connected, or is busy/);
  } finally {
    await host.close();
  }
});

test('refusals: wrong or missing key, full disk, upload limit, wrong address, file type, each one line', async () => {
  const cases: Array<[Answer, string | undefined, RegExp]> = [
    [
      { status: 403, body: { error: "You don't have the permission" } },
      'BAD',
      /^OctoPrint at http:\/\/127\.0\.0\.1:\d+ refused the API key \(403 Forbidden\): check apiKey \(OctoPrint: Settings › Application Keys/,
    ],
    [
      { status: 403, body: { error: 'nope' } },
      undefined,
      /^OctoPrint at .* needs an API key \(403 Forbidden\): give one with apiKey/,
    ],
    [
      { status: 507, body: { error: 'Insufficient Storage' } },
      'K',
      /has no room for the file \(disk full, 507 Insufficient Storage: Insufficient Storage\): delete old files on it$/,
    ],
    [
      { status: 500, body: { error: '[Errno 28] No space left on device' } },
      'K',
      /has no room for the file \(disk full, 500 Internal Server Error: \[Errno 28\] No space left on device\)/,
    ],
    [
      { status: 413, body: '<html><body><h1>413 Request Entity Too Large</h1></body></html>' },
      'K',
      /refused the file as too large \(413 Payload Too Large\): raise its upload limit \(OctoPrint: server\.uploads\.maxSize/,
    ],
    [
      { status: 404, body: 'not found' },
      'K',
      /has no OctoPrint upload API \(404 Not Found\): is it the OctoPrint address\?$/,
    ],
    [
      { status: 415, body: { error: 'Could not upload file, invalid type' } },
      'K',
      /does not take this type of file \(415 Unsupported Media Type: Could not upload file, invalid type\)$/,
    ],
    [
      { status: 409, body: { error: 'Trying to overwrite file that is currently being printed' } },
      'K',
      /refused the upload \(409 Conflict: Trying to overwrite file that is currently being printed\)$/,
    ],
  ];
  for (const [answer, key, message] of cases) {
    const host = await fakeHost(() => answer);
    try {
      assert.match(
        await failure(sendGcode(file, { to: 'octoprint', url: host.url, apiKey: key }, nodeTransport)),
        message,
      );
    } finally {
      await host.close();
    }
  }
  const host = await fakeHost(() => ({ status: 401, body: { error: { code: 401, message: 'Unauthorized' } } }));
  try {
    assert.match(
      await failure(
        sendGcode(file, { to: 'moonraker', url: host.url, apiKey: 'BAD', keyName: '--api-key' }, nodeTransport),
      ),
      /^Moonraker at .* refused the API key \(401 Unauthorized\): check --api-key \(Moonraker's is at \/access\/api_key from a trusted client\)$/,
    );
  } finally {
    await host.close();
  }
  const full = await fakeHost(() => ({ status: 500, body: { error: { code: 500, message: 'Unable to save file' } } }));
  try {
    assert.match(
      await failure(sendGcode(file, { to: 'moonraker', url: full.url }, nodeTransport)),
      /could not save the file \(500 Internal Server Error: Unable to save file\): is its disk full\?$/,
    );
  } finally {
    await full.close();
  }
});

test('a host that answers before reading the upload (and closes) is understood by its answer', async () => {
  // a host that lets the key through the small request but refuses the upload at once (a full disk, say)
  const host = await fakeHost((r) =>
    r.method === 'POST'
      ? { status: 507, body: { error: { message: 'Insufficient Storage' } }, early: true }
      : { status: 200, body: {} },
  );
  try {
    const big = { name: 'big.gcode', bytes: new TextEncoder().encode(GCODE.repeat(10)) };
    assert.match(
      await failure(sendGcode(big, { to: 'moonraker', url: host.url, apiKey: 'K' }, nodeTransport)),
      /has no room for the file \(disk full, 507 Insufficient Storage/,
    );
    assert.equal(host.received.find((r) => r.method === 'POST')!.complete, false, 'answered before the body');
  } finally {
    await host.close();
  }
});

test('an unreachable host, a bad address, a file that is not G-code: one line, and nothing sent', async () => {
  const port = await closedPort();
  assert.match(
    await failure(sendGcode(file, { to: 'octoprint', url: `127.0.0.1:${port}` }, nodeTransport)),
    new RegExp(`^cannot reach OctoPrint at http://127\\.0\\.0\\.1:${port}: connection refused`),
  );
  assert.match(
    await failure(sendGcode(file, { to: 'moonraker', url: 'http://no-such-host.invalid' }, nodeTransport)),
    /^cannot reach Moonraker at http:\/\/no-such-host\.invalid: (no such host name|the host name could not be looked up)/,
  );
  assert.match(
    await failure(sendGcode(file, { to: 'octoprint', url: 'ftp://printer' }, nodeTransport)),
    /reached over http:\/\/ or https:\/\//,
  );
  assert.match(
    await failure(sendGcode(file, { to: 'prusalink' as never, url: 'http://x' }, nodeTransport)),
    /one of octoprint, moonraker/,
  );
  const host = await fakeHost(() => ({ status: 201 }));
  try {
    assert.match(
      await failure(
        sendGcode(
          { name: 'part.gcode', bytes: new TextEncoder().encode('solid x\nfacet normal 0 0 1\n') },
          { to: 'octoprint', url: host.url },
          nodeTransport,
        ),
      ),
      /part\.gcode is an ASCII STL model, not G-code/,
    );
    assert.match(
      await failure(
        sendGcode({ name: 'part.stl', bytes: file.bytes }, { to: 'octoprint', url: host.url }, nodeTransport),
      ),
      /part\.stl is not a G-code file name/,
    );
    assert.equal(host.received.length, 0, 'nothing was sent');
  } finally {
    await host.close();
  }
});

test('cancelling an upload stops it with CANCELLED', async () => {
  const host = await fakeHost(() => ({ status: 201, body: {} }));
  try {
    const ac = new AbortController();
    const p = sendGcode(
      { name: 'big.gcode', bytes: new TextEncoder().encode(GCODE.repeat(20)) },
      { to: 'octoprint', url: host.url, signal: ac.signal, onProgress: () => ac.abort() },
      nodeTransport,
    );
    await assert.rejects(p, (e) => e instanceof StrataError && e.code === 'CANCELLED');
  } finally {
    await host.close();
  }
});

test('addresses: http:// assumed, a proxy prefix kept; host messages in one short line', () => {
  assert.equal(hostUrl('octopi.local').href, 'http://octopi.local/');
  assert.equal(hostUrl('https://example.com/octoprint').href, 'https://example.com/octoprint/');
  assert.equal(
    new URL('api/files/local', hostUrl('https://example.com/octoprint')).href,
    'https://example.com/octoprint/api/files/local',
  );
  assert.equal(hostMessage('{"error":{"code":401,"message":"Unauthorized"}}'), 'Unauthorized');
  assert.equal(hostMessage('<html><h1>Bad\nGateway</h1></html>'), 'Bad Gateway');
  assert.ok(hostMessage('x'.repeat(500)).length <= 200);
});
