/**
 * A small, fast pull tokenizer for XML in UTF-8 bytes, enough for 3MF and OPC parts: elements,
 * attributes, comments, processing instructions, CDATA (skipped). Text content is skipped unless a caller
 * asks for an element's text (textContent).
 * It does not build a tree or allocate per element: callers compare names and read attribute
 * values (numbers straight from the bytes) through the scanner. DTDs are refused (no entity expansion).
 *
 * Why not an XML library: a 3MF mesh is millions of <vertex>/<triangle> elements, and the parsers that
 * build objects or strings per element (fast-xml-parser, the DOMParser) take several times the time and
 * memory; the streaming ones (saxes, sax) still decode every attribute to a string. This scanner reads
 * numbers from the bytes, refuses DTDs outright and bounds its work by the input's length: its limits
 * are why it stays.
 */
import { StrataError } from '../errors.js';
import { printable } from './printable.js';

export const XML_EOF = 0;
export const XML_START = 1;
export const XML_END = 2;

/** 10^0 … 10^22: every one is exact in float64, which makes the fast number path correctly rounded. */
const POW10 = Object.freeze([
  1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20,
  1e21, 1e22,
]);

function isWs(c: number): boolean {
  return c === 32 || c === 10 || c === 13 || c === 9;
}

export class XmlScanner {
  readonly buf: Uint8Array;
  /** Names the document in error messages ("3MF model part 3D/3dmodel.model"). */
  readonly what: string;
  readonly maxDepth: number;
  depth = 0;
  /** Current element (after XML_START / XML_END): qualified name, local name, attribute region. */
  nameStart = 0;
  nameEnd = 0;
  localStart = 0;
  attrStart = 0;
  attrEnd = 0;
  selfClosing = false;
  /** Current attribute (after nextAttr()). */
  attrNameStart = 0;
  attrNameEnd = 0;
  valueStart = 0;
  valueEnd = 0;

  private pos = 0;
  private cursor = 0;
  private readonly stack: Int32Array;
  private readonly decoder = new TextDecoder('utf-8');

  constructor(buf: Uint8Array, what: string, maxDepth = 64) {
    this.buf = buf;
    this.what = printable(what, 100);
    this.maxDepth = maxDepth;
    this.stack = new Int32Array(maxDepth * 2);
    if (buf[0] === 0xef && buf[1] === 0xbb && buf[2] === 0xbf) this.pos = 3;
    else if ((buf[0] === 0xfe && buf[1] === 0xff) || (buf[0] === 0xff && buf[1] === 0xfe)) {
      throw new StrataError('BAD_FILE', `${this.what} is UTF-16; only UTF-8 XML is supported`);
    }
  }

  fail(message: string, at = this.pos): never {
    let line = 1;
    const end = Math.min(at, this.buf.length);
    for (let i = 0; i < end; i++) if (this.buf[i] === 10) line++;
    throw new StrataError('BAD_FILE', `${this.what}, line ${line}: ${printable(message, 200)}`);
  }

  /** Advance to the next start or end tag. A self-closing element yields only XML_START. */
  next(): number {
    const b = this.buf;
    for (;;) {
      const n = b.length;
      let lt = this.pos;
      while (lt < n && b[lt] !== 60) lt++;
      if (lt >= n) {
        if (this.depth > 0) this.fail(`the XML ends inside <${this.nameAt(this.depth - 1)}> (truncated?)`, b.length);
        this.pos = b.length;
        return XML_EOF;
      }
      const c = b[lt + 1];
      if (c === 63 /* ? */) {
        this.pos = this.find(63, 62, lt + 2, 'processing instruction') + 2;
        continue;
      }
      if (c === 33 /* ! */) {
        if (b[lt + 2] === 45 && b[lt + 3] === 45) {
          this.pos = this.findComment(lt + 4);
          continue;
        }
        if (this.startsWith(lt + 2, '[CDATA[')) {
          let i = lt + 9;
          for (;;) {
            i = b.indexOf(93, i);
            if (i < 0) this.fail('unterminated CDATA section', lt);
            if (b[i + 1] === 93 && b[i + 2] === 62) break;
            i++;
          }
          this.pos = i + 3;
          continue;
        }
        this.fail('DOCTYPE and other <! declarations are not allowed', lt);
      }
      if (c === 47 /* / */) {
        const s = lt + 2;
        let i = s;
        while (i < b.length && !isWs(b[i]) && b[i] !== 62) i++;
        const gt = b.indexOf(62, i);
        if (gt < 0) this.fail('the XML ends inside an end tag (truncated?)', lt);
        if (this.depth === 0) this.fail(`unexpected end tag </${this.text(s, i)}>`, lt);
        const d = --this.depth;
        const os = this.stack[d * 2],
          oe = this.stack[d * 2 + 1];
        if (oe - os !== i - s || !this.sameBytes(os, s, i - s)) {
          this.fail(`</${this.text(s, i)}> does not close <${this.text(os, oe)}>`, lt);
        }
        this.setName(s, i);
        this.selfClosing = false;
        this.attrStart = this.attrEnd = i;
        this.pos = gt + 1;
        return XML_END;
      }
      // Start tag.
      const s = lt + 1;
      let i = s;
      while (i < b.length && !isWs(b[i]) && b[i] !== 62 && b[i] !== 47) i++;
      if (i === s) this.fail('"<" that does not start a tag', lt);
      // Find the closing ">" outside quoted attribute values.
      let j = i;
      for (;;) {
        if (j >= n) this.fail(`the XML ends inside <${this.text(s, i)}> (truncated?)`, lt);
        const ch = b[j];
        if (ch === 62) break;
        if (ch === 34 || ch === 39) {
          j++;
          while (j < n && b[j] !== ch) j++;
          if (j >= n) this.fail(`unterminated attribute value in <${this.text(s, i)}>`, lt);
          j++;
        } else if (ch === 60) {
          this.fail(`"<" inside the tag <${this.text(s, i)}>`, lt);
        } else {
          j++;
        }
      }
      this.setName(s, i);
      this.selfClosing = b[j - 1] === 47;
      this.attrStart = i;
      this.attrEnd = this.selfClosing ? j - 1 : j;
      this.cursor = i;
      this.pos = j + 1;
      if (!this.selfClosing) {
        if (this.depth >= this.maxDepth) {
          throw new StrataError('LIMIT_EXCEEDED', `${this.what}: elements nested deeper than ${this.maxDepth} levels`);
        }
        this.stack[this.depth * 2] = s;
        this.stack[this.depth * 2 + 1] = i;
        this.depth++;
      }
      return XML_START;
    }
  }

  /** Local name (after any "prefix:") equals `name`. */
  is(name: string): boolean {
    return this.nameEnd - this.localStart === name.length && this.bytesEqual(this.localStart, name);
  }

  /** The namespace prefix of the current element ("" when none). */
  prefix(): string {
    return this.localStart > this.nameStart ? this.text(this.nameStart, this.localStart - 1) : '';
  }

  /** Move to the next attribute of the current start tag; false when there are no more. */
  nextAttr(): boolean {
    const b = this.buf;
    let i = this.cursor;
    const end = this.attrEnd;
    while (i < end && isWs(b[i])) i++;
    if (i >= end) {
      this.cursor = end;
      return false;
    }
    const ns = i;
    while (i < end && b[i] !== 61 && !isWs(b[i])) i++;
    const ne = i;
    while (i < end && isWs(b[i])) i++;
    if (b[i] !== 61 || ne === ns) this.fail(`malformed attribute in <${this.text(this.nameStart, this.nameEnd)}>`, ns);
    i++;
    while (i < end && isWs(b[i])) i++;
    const q = b[i];
    if (q !== 34 && q !== 39)
      this.fail(`attribute value without quotes in <${this.text(this.nameStart, this.nameEnd)}>`, ns);
    let ve = i + 1;
    while (ve < end && b[ve] !== q) ve++;
    this.attrNameStart = ns;
    this.attrNameEnd = ne;
    this.valueStart = i + 1;
    this.valueEnd = ve;
    this.cursor = ve + 1;
    return true;
  }

  /** The current attribute's full name (with any prefix) equals `name`. */
  attrIs(name: string): boolean {
    return this.attrNameEnd - this.attrNameStart === name.length && this.bytesEqual(this.attrNameStart, name);
  }

  /** The current attribute has a prefix and its local name equals `local` ("p:path" for "path"). */
  attrIsPrefixed(local: string): boolean {
    const n = this.attrNameEnd - this.attrNameStart;
    return (
      n > local.length + 1 &&
      this.buf[this.attrNameEnd - local.length - 1] === 58 &&
      this.bytesEqual(this.attrNameEnd - local.length, local)
    );
  }

  attrName(): string {
    return this.text(this.attrNameStart, this.attrNameEnd);
  }

  /** The current attribute value, entity-decoded. */
  value(): string {
    return decodeEntities(this.text(this.valueStart, this.valueEnd));
  }

  /** The current attribute value as a number (NaN when it is not a decimal number). */
  number(): number {
    return parseDecimal(this.buf, this.valueStart, this.valueEnd);
  }

  /** The current attribute value as a non-negative integer below 2^32 (-1 when it is not one). */
  uint(): number {
    const b = this.buf;
    let i = this.valueStart;
    let e = this.valueEnd;
    while (i < e && isWs(b[i])) i++;
    while (e > i && isWs(b[e - 1])) e--;
    if (i === e || e - i > 10) return -1;
    let v = 0;
    for (; i < e; i++) {
      const d = b[i] - 48;
      if (d < 0 || d > 9) return -1;
      v = v * 10 + d;
    }
    return v > 0xffffffff ? -1 : v;
  }

  /** Where the content of the element just started begins (after XML_START of an element that is not self-closing). */
  contentStart(): number {
    return this.attrEnd + 1;
  }

  /**
   * After XML_END: the element's text from `start` (its contentStart()) to this end tag, entity-decoded,
   * CDATA sections unwrapped. Meant for elements that hold only text (`<metadata name="…">value</metadata>`).
   */
  textContent(start: number): string {
    const raw = this.text(start, this.nameStart - 2);
    if (raw.indexOf('<![CDATA[') < 0) return decodeEntities(raw);
    let out = '';
    let at = 0;
    for (let i = raw.indexOf('<![CDATA['); i >= 0; i = raw.indexOf('<![CDATA[', at)) {
      const end = raw.indexOf(']]>', i + 9);
      if (end < 0) break;
      out += decodeEntities(raw.slice(at, i)) + raw.slice(i + 9, end);
      at = end + 3;
    }
    return out + decodeEntities(raw.slice(at));
  }

  text(s: number, e: number): string {
    return this.decoder.decode(this.buf.subarray(s, e));
  }

  private nameAt(d: number): string {
    return this.text(this.stack[d * 2], this.stack[d * 2 + 1]);
  }

  private setName(s: number, e: number): void {
    this.nameStart = s;
    this.nameEnd = e;
    let l = s;
    for (let k = s; k < e; k++) if (this.buf[k] === 58) l = k + 1;
    this.localStart = l;
  }

  private bytesEqual(at: number, s: string): boolean {
    const b = this.buf;
    for (let k = 0; k < s.length; k++) if (b[at + k] !== s.charCodeAt(k)) return false;
    return true;
  }

  private sameBytes(a: number, c: number, n: number): boolean {
    const b = this.buf;
    for (let k = 0; k < n; k++) if (b[a + k] !== b[c + k]) return false;
    return true;
  }

  private startsWith(at: number, s: string): boolean {
    return at + s.length <= this.buf.length && this.bytesEqual(at, s);
  }

  /** Index of the two-byte sequence c1 c2 at or after `from`. */
  private find(c1: number, c2: number, from: number, what: string): number {
    const b = this.buf;
    let i = from;
    for (;;) {
      i = b.indexOf(c1, i);
      if (i < 0 || i + 1 >= b.length) this.fail(`unterminated ${what}`, from);
      if (b[i + 1] === c2) return i;
      i++;
    }
  }

  private findComment(from: number): number {
    const b = this.buf;
    let i = from;
    for (;;) {
      i = b.indexOf(45, i);
      if (i < 0 || i + 2 >= b.length) this.fail('unterminated comment', from);
      if (b[i + 1] === 45 && b[i + 2] === 62) return i + 3;
      i++;
    }
  }
}

/** Replace the predefined and numeric character references. */
export function decodeEntities(s: string): string {
  if (s.indexOf('&') < 0) return s;
  return s.replace(/&(#x[0-9a-fA-F]{1,6}|#[0-9]{1,7}|lt|gt|amp|quot|apos);/g, (m, ref: string) => {
    switch (ref) {
      case 'lt':
        return '<';
      case 'gt':
        return '>';
      case 'amp':
        return '&';
      case 'quot':
        return '"';
      case 'apos':
        return "'";
    }
    const code = ref[1] === 'x' ? parseInt(ref.slice(2), 16) : parseInt(ref.slice(1), 10);
    return code <= 0x10ffff ? String.fromCodePoint(code) : m;
  });
}

/**
 * Parse a decimal number ("-1.25", "3e-2", " 7 ") from bytes [s, e). Up to 15 significant digits
 * and a power of ten within ±22 are computed exactly and rounded once (as parseFloat would);
 * anything else falls back to Number(). Returns NaN for non-numbers, including "", "inf", "0x10".
 */
export function parseDecimal(b: Uint8Array, s: number, e: number): number {
  while (s < e && isWs(b[s])) s++;
  while (e > s && isWs(b[e - 1])) e--;
  let i = s;
  let neg = false;
  if (b[i] === 45 || b[i] === 43) {
    neg = b[i] === 45;
    i++;
  }
  let mant = 0;
  let digits = 0;
  let scale = 0;
  let any = false;
  while (i < e) {
    const d = b[i] - 48;
    if (d < 0 || d > 9) break;
    mant = mant * 10 + d;
    digits++;
    any = true;
    i++;
  }
  if (i < e && b[i] === 46) {
    i++;
    while (i < e) {
      const d = b[i] - 48;
      if (d < 0 || d > 9) break;
      mant = mant * 10 + d;
      digits++;
      scale--;
      any = true;
      i++;
    }
  }
  if (!any) return NaN;
  if (i < e && (b[i] === 101 || b[i] === 69)) {
    i++;
    let eneg = false;
    if (b[i] === 45 || b[i] === 43) {
      eneg = b[i] === 45;
      i++;
    }
    let ex = 0;
    let edigits = 0;
    while (i < e) {
      const d = b[i] - 48;
      if (d < 0 || d > 9) break;
      if (ex < 100000) ex = ex * 10 + d;
      edigits++;
      i++;
    }
    if (edigits === 0) return NaN;
    scale += eneg ? -ex : ex;
  }
  if (i !== e) return NaN;
  if (digits <= 15 && scale >= -22 && scale <= 22) {
    const v = scale === 0 ? mant : scale > 0 ? mant * POW10[scale] : mant / POW10[-scale];
    return neg ? -v : v;
  }
  let str = '';
  for (let k = s; k < e; k++) str += String.fromCharCode(b[k]);
  return Number(str);
}
