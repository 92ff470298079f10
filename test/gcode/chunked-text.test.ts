import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ChunkedText } from '#strata/gcode/chunked-text.js';
import { fixedDecimal } from '#strata/gcode/format.js';

function collect(chunkBytes: number, write: (t: ChunkedText) => void): string[] {
  const chunks: string[] = [];
  const t = new ChunkedText((c) => chunks.push(c), chunkBytes);
  write(t);
  t.flush();
  return chunks;
}

test('fixed() writes the same text as fixedDecimal() for positions and E values', () => {
  const values = [
    0, 1, -1, 9, 10, 99, 100, 101, 999, 1000, 1001, 10500, -10500, 123456, 220000, 1999999, 10000000000, -7, 50,
    12345678901,
  ];
  let seed = 12345;
  for (let i = 0; i < 2000; i++) {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    values.push((seed % 4000001) - 2000000);
  }
  for (const [scale, decimals] of [
    [1000, 3],
    [100000, 5],
  ] as const) {
    const expected = values.map((v) => fixedDecimal(v, scale)).join('\n') + '\n';
    const text = collect(1 << 20, (t) => {
      for (const v of values) {
        t.fixed(v, scale, decimals);
        t.endLine();
      }
    }).join('');
    assert.equal(text, expected);
  }
});

test('int() writes integers; text() handles non-ASCII; chunks end at line ends', () => {
  const chunks = collect(16, (t) => {
    t.int(0);
    t.text(' ');
    t.int(-42);
    t.text(' ');
    t.int(9007199254740991);
    t.endLine();
    t.line('; 215 °C, Ω');
    t.line('x'.repeat(10000));
    t.line('end');
  });
  assert.equal(chunks.join(''), `0 -42 9007199254740991\n; 215 °C, Ω\n${'x'.repeat(10000)}\nend\n`);
  for (const c of chunks) assert.ok(c.endsWith('\n'));
  assert.equal(chunks.length, 3); // the short second line shares a chunk with the long one
});
