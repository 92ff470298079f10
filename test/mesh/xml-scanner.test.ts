import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { decodeEntities, parseDecimal, XML_END, XML_EOF, XML_START, XmlScanner } from '#strata/mesh/xml-scanner.js';

const enc = (s: string): Uint8Array => new TextEncoder().encode(s);
const num = (s: string): number => {
  const b = enc(s);
  return parseDecimal(b, 0, b.length);
};

test('parseDecimal equals Number() bit for bit on many decimal forms', () => {
  let seed = 7;
  const rnd = (n: number): number => {
    seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
    return seed % n;
  };
  const digits = (n: number): string => Array.from({ length: n }, () => String(rnd(10))).join('');
  for (let i = 0; i < 20000; i++) {
    let s = (rnd(3) === 0 ? '-' : '') + digits(1 + rnd(9));
    if (rnd(2)) s += '.' + digits(1 + rnd(12));
    if (rnd(4) === 0) s += 'e' + (rnd(2) ? '-' : '+') + String(rnd(40));
    assert.equal(Object.is(num(s), Number(s)), true, s);
  }
  for (const s of [
    '0',
    '-0',
    '1.',
    '.5',
    '+3',
    ' 7 ',
    '1e5',
    '1E-5',
    '123456789012345678',
    '0.000000000000000000001',
    '1e400',
  ]) {
    assert.ok(Object.is(num(s), Number(s)), s);
  }
  for (const s of ['', '-', '.', 'e5', '1e', '1e+', '0x10', 'Infinity', 'NaN', '1,5', '1 2', '--1']) {
    assert.ok(Number.isNaN(num(s)), s);
  }
});

test('decodeEntities handles predefined and numeric references', () => {
  assert.equal(decodeEntities('a &amp; b &lt;c&gt; &quot;&apos; &#65;&#x42; &bogus;'), 'a & b <c> "\' AB &bogus;');
});

test('the scanner yields starts, ends and attributes, skipping comments, PIs and CDATA', () => {
  const x = new XmlScanner(
    enc('<?xml version="1.0"?><!-- c --><a k="v&amp;" q=\'>\'><b/><![CDATA[<x>]]><c:d/></a>'),
    't',
  );
  const seen: string[] = [];
  for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) {
    if (ev === XML_START) {
      const attrs: string[] = [];
      while (x.nextAttr()) attrs.push(`${x.attrName()}=${x.value()}`);
      seen.push(`<${x.text(x.nameStart, x.nameEnd)}${x.selfClosing ? '/' : ''} ${attrs.join(',')}`);
    } else if (ev === XML_END) {
      seen.push(`</${x.text(x.nameStart, x.nameEnd)}`);
    }
  }
  assert.deepEqual(seen, ['<a k=v&,q=>', '<b/ ', '<c:d/ ', '</a']);
});

test('malformed XML throws BAD_FILE with a line number', () => {
  const bad = [
    '<a>',
    '<a></b>',
    '<a x="1></a>',
    '<a><!-- never closed </a>',
    '</a>',
    '<a x=1/>',
    '<a <b>',
    '<!DOCTYPE a><a/>',
    '<a><![CDATA[x</a>',
  ];
  for (const s of bad) {
    assert.throws(
      () => {
        const x = new XmlScanner(enc(s), 'doc');
        for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) while (x.nextAttr());
      },
      (e: unknown) => e instanceof StrataError && e.code === 'BAD_FILE' && /^doc, line \d+: /.test(e.message),
      s,
    );
  }
});

test("textContent reads an element's text, entities decoded and CDATA unwrapped", () => {
  const x = new XmlScanner(
    enc('<m><v n="a">80 &amp; up</v><v n="b"><![CDATA[<raw> &amp;]]> tail</v><v n="c"></v></m>'),
    't',
  );
  const got: string[] = [];
  let start = -1;
  for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) {
    if (ev === XML_START && x.is('v')) start = x.contentStart();
    else if (ev === XML_END && x.is('v')) got.push(x.textContent(start));
  }
  assert.deepEqual(got, ['80 & up', '<raw> &amp; tail', '']);
});
