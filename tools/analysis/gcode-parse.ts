/**
 * A streaming parser of Marlin / Klipper / RepRapFirmware G-code text into layers of extrusion and travel segments.
 *
 * Understood: G0/G1 (X Y Z E F), G2/G3 arcs (I J or R, split into short chords), G90/G91, M82/M83 (E is relative
 * under G91 or M83, as in Marlin, Klipper and Repetier), G92 (axes and E), G28 (homed axes to 0), G20/G21,
 * G10/G11 firmware retraction (G10 with P or L is a tool offset and ignored), retractions spread over several
 * moves (wipes: XY with negative E) counted once, `N` line numbers and `*` checksums,
 * `;` and `( )` comments. Markers: `;LAYER:n` (Cura), `;LAYER_CHANGE` (PrusaSlicer, Orca), `; CHANGE_LAYER`
 * (Bambu), `;TYPE:name` and `; FEATURE: name` (mapped to canonical features), `;HEIGHT:h` (PrusaSlicer, Strata:
 * the layer's height).
 *
 * Lines are scanned by character code with no per-line allocation, so ~30 MB of G-code parse in about a second.
 */
import { Feature, featureCodeOf } from './feature-names.js';
import { zKey, groupLayers } from './gcode-layers.js';
import { RawRecords } from './gcode-records.js';
import type { ExtrusionMode, ParsedGcode } from './gcode-types.js';
import { RetractionKind } from './gcode-types.js';

/** Feed G-code text in chunks of any size (split anywhere), then call end() once. */
export interface GcodeParser {
  write(chunk: string): void;
  end(): ParsedGcode;
}

export function createGcodeParser(): GcodeParser {
  return new GcodeParserState();
}

export function parseGcode(text: string): ParsedGcode {
  const parser = createGcodeParser();
  parser.write(text);
  return parser.end();
}

/** XY motion shorter than this is no motion (mm). */
const XY_EPSILON_MM = 1e-6;
/** E changes smaller than this are no extrusion (mm of filament). */
const E_EPSILON_MM = 1e-7;
/** Retraction left unprimed (or over-primed) at the start of an extrusion beyond this is unbalanced (mm). */
const BALANCE_TOLERANCE_MM = 2e-3;
/** Largest distance between an arc and its chords (mm). */
const ARC_CHORD_TOLERANCE_MM = 5e-3;
const MAX_ARC_PIECES = 4096;
const MAX_REPORTED_LINES = 20;
const INCH_MM = 25.4;

const CH_TAB = 9;
const CH_CR = 13;
const CH_SPACE = 32;
const CH_LPAREN = 40;
const CH_RPAREN = 41;
const CH_STAR = 42;
const CH_PLUS = 43;
const CH_MINUS = 45;
const CH_DOT = 46;
const CH_0 = 48;
const CH_9 = 57;
const CH_SEMI = 59;
const LOWER_A = 97;
const LOWER_CASE_BIT = 0x20;

/** Bit of a word letter in the `has` mask. */
const W = (letter: string) => 1 << (letter.charCodeAt(0) - LOWER_A);
const W_E = W('e'),
  W_F = W('f'),
  W_I = W('i'),
  W_J = W('j'),
  W_L = W('l'),
  W_P = W('p'),
  W_R = W('r');
const W_X = W('x'),
  W_Y = W('y'),
  W_Z = W('z');
const IDX = (letter: string) => letter.charCodeAt(0) - LOWER_A;
const I_E = IDX('e'),
  I_F = IDX('f'),
  I_I = IDX('i'),
  I_J = IDX('j'),
  I_R = IDX('r');
const I_X = IDX('x'),
  I_Y = IDX('y'),
  I_Z = IDX('z');

class GcodeParserState implements GcodeParser {
  private readonly raw = new RawRecords();
  private rest = '';
  private lineNo = 0;
  private ended = false;

  // Machine state (positions are physical mm; offsets come from G92).
  private x = 0;
  private y = 0;
  private z = 0;
  private e = 0;
  private f = 0;
  private offX = 0;
  private offY = 0;
  private offZ = 0;
  private relAxes = false;
  private relE = false;
  private unit = 1;

  // Markers.
  private feature: number = Feature.Unknown;
  private block = 0;
  private blockZKey = NaN;
  private hasMarkers = false;
  private hasTypes = false;
  private layerChangeOrdinal = 0;
  private readonly typeCache = new Map<string, number>();
  private readonly unknownTypes = new Set<string>();

  // Filament bookkeeping.
  private extruded = 0;
  private retracted = 0;
  private primed = 0;
  private asIfRelative = 0;
  private asIfAbsolute = 0;
  private lastRawE = 0;
  private modeFlags = 0;
  private pending = 0;
  private fwRetracted = false;
  private retractions = 0;
  private primes = 0;
  private fwRetractions = 0;
  private unbalanced = 0;
  private readonly unbalancedLines: number[] = [];

  // Word scratch: value per letter and a bit mask of the letters present on the current line.
  private readonly vals = new Float64Array(26);
  private has = 0;
  private np = 0;

  write(chunk: string): void {
    if (this.ended) throw new Error('GcodeParser.write after end()');
    const s = this.rest.length > 0 ? this.rest + chunk : chunk;
    let a = 0;
    for (;;) {
      const nl = s.indexOf('\n', a);
      if (nl < 0) break;
      this.lineNo++;
      this.line(s, a, nl > a && s.charCodeAt(nl - 1) === CH_CR ? nl - 1 : nl);
      a = nl + 1;
    }
    this.rest = a < s.length ? s.slice(a) : '';
  }

  end(): ParsedGcode {
    if (this.ended) throw new Error('GcodeParser.end called twice');
    if (this.rest.length > 0) {
      const s = this.rest;
      this.lineNo++;
      this.line(s, 0, s.charCodeAt(s.length - 1) === CH_CR ? s.length - 1 : s.length);
      this.rest = '';
    }
    this.ended = true;
    const grouped = groupLayers(this.raw);
    const mode: ExtrusionMode = this.modeFlags === 2 ? 'relative' : this.modeFlags === 3 ? 'mixed' : 'absolute';
    return {
      layers: grouped.layers,
      preamble: grouped.preamble,
      retractions: grouped.retractions,
      e: {
        mode,
        extruded: this.extruded,
        retracted: this.retracted,
        primed: this.primed,
        net: this.extruded + this.primed - this.retracted,
        asIfAbsolute: this.asIfAbsolute,
        asIfRelative: this.asIfRelative,
      },
      balance: {
        retractions: this.retractions,
        primes: this.primes,
        firmwareRetractions: this.fwRetractions,
        unbalanced: this.unbalanced,
        unbalancedLines: this.unbalancedLines.slice(),
        trailingMm: Math.max(0, this.pending),
      },
      hasLayerMarkers: this.hasMarkers,
      hasTypeMarkers: this.hasTypes,
      unknownTypes: [...this.unknownTypes],
      lineCount: this.lineNo,
      extents: grouped.extents,
    };
  }

  /** One line, s[a, b) without its line break. */
  private line(s: string, a: number, b: number): void {
    let i = a;
    let c = 0;
    while (i < b && ((c = s.charCodeAt(i)) === CH_SPACE || c === CH_TAB)) i++;
    if (i >= b) return;
    if (c === CH_SEMI) {
      this.comment(s, i + 1, b);
      return;
    }
    let letter = c | LOWER_CASE_BIT;
    if (letter === 110 /* n */) {
      this.number(s, i + 1, b);
      i = this.np;
      while (i < b && ((c = s.charCodeAt(i)) === CH_SPACE || c === CH_TAB)) i++;
      if (i >= b) return;
      letter = c | LOWER_CASE_BIT;
    }
    if (letter !== 103 /* g */ && letter !== 109 /* m */) return;
    const code = this.number(s, i + 1, b);
    if (Number.isNaN(code)) return;
    i = this.np;
    this.has = 0;
    while (i < b) {
      c = s.charCodeAt(i);
      if (c === CH_SPACE || c === CH_TAB) {
        i++;
        continue;
      }
      if (c === CH_SEMI || c === CH_STAR) break;
      if (c === CH_LPAREN) {
        while (i < b && s.charCodeAt(i) !== CH_RPAREN) i++;
        i++;
        continue;
      }
      const l = (c | LOWER_CASE_BIT) - LOWER_A;
      if (l >= 0 && l < 26) {
        const v = this.number(s, i + 1, b);
        if (this.np > i + 1) {
          i = this.np;
          if (!Number.isNaN(v)) {
            this.vals[l] = v;
            this.has |= 1 << l;
          }
          continue;
        }
      }
      i++;
    }
    if (letter === 103) this.gCommand(code);
    else this.mCommand(code);
  }

  /** Parses a decimal number at s[i..b); sets this.np past it. NaN when there are no digits. */
  private number(s: string, i: number, b: number): number {
    let c = i < b ? s.charCodeAt(i) : 0;
    let neg = false;
    if (c === CH_MINUS) {
      neg = true;
      i++;
    } else if (c === CH_PLUS) i++;
    let v = 0;
    let digits = 0;
    while (i < b && (c = s.charCodeAt(i)) >= CH_0 && c <= CH_9) {
      v = v * 10 + (c - CH_0);
      i++;
      digits++;
    }
    if (i < b && s.charCodeAt(i) === CH_DOT) {
      i++;
      let frac = 0;
      let scale = 1;
      while (i < b && (c = s.charCodeAt(i)) >= CH_0 && c <= CH_9) {
        frac = frac * 10 + (c - CH_0);
        scale *= 10;
        i++;
        digits++;
      }
      v += frac / scale;
    }
    this.np = i;
    if (digits === 0) return NaN;
    return neg ? -v : v;
  }

  private comment(s: string, i: number, b: number): void {
    while (i < b && s.charCodeAt(i) === CH_SPACE) i++;
    if (s.startsWith('LAYER:', i)) {
      const n = this.number(s, i + 6, b);
      this.openMarkerBlock(Number.isNaN(n) ? this.layerChangeOrdinal : n);
      this.layerChangeOrdinal++;
    } else if (s.startsWith('LAYER_CHANGE', i) || s.startsWith('CHANGE_LAYER', i)) {
      this.openMarkerBlock(this.layerChangeOrdinal++);
    } else if (s.startsWith('HEIGHT:', i)) {
      const h = this.number(s, i + 7, b);
      if (h > 0) this.raw.declareHeight(this.block, h);
    } else if (s.startsWith('TYPE:', i)) {
      this.setType(s.slice(i + 5, b).trim());
    } else if (s.startsWith('FEATURE:', i)) {
      this.setType(s.slice(i + 8, b).trim());
    }
  }

  private setType(name: string): void {
    this.hasTypes = true;
    let code = this.typeCache.get(name);
    if (code === undefined) {
      code = featureCodeOf(name);
      if (code < 0) {
        this.unknownTypes.add(name);
        code = Feature.Unknown;
      }
      this.typeCache.set(name, code);
    }
    this.feature = code;
  }

  private openMarkerBlock(marker: number): void {
    this.block = this.raw.openBlock(marker);
    if (!this.hasMarkers) {
      this.hasMarkers = true;
      this.raw.firstMarkerBlock = this.block;
    }
    this.blockZKey = NaN;
  }

  private gCommand(code: number): void {
    switch (code) {
      case 0:
      case 1:
        this.linearMove();
        break;
      case 2:
      case 3:
        this.arcMove(code === 2);
        break;
      case 10:
        if ((this.has & (W_P | W_L)) === 0) this.firmwareRetract();
        break;
      case 11:
        this.firmwarePrime();
        break;
      case 20:
        this.unit = INCH_MM;
        break;
      case 21:
        this.unit = 1;
        break;
      case 28:
        this.home();
        break;
      case 90:
        this.relAxes = false;
        break;
      case 91:
        this.relAxes = true;
        break;
      case 92:
        this.setPosition();
        break;
      default:
        break;
    }
  }

  private mCommand(code: number): void {
    if (code === 82) this.relE = false;
    else if (code === 83) this.relE = true;
  }

  private targetAxis(bit: number, index: number, current: number, offset: number): number {
    if ((this.has & bit) === 0) return current;
    const v = this.vals[index]! * this.unit;
    return this.relAxes ? current + v : v + offset;
  }

  /** E change of the current command (mm), updating the E position and the alternative-mode views. */
  private eDelta(): number {
    if ((this.has & W_E) === 0) return 0;
    const v = this.vals[I_E]! * this.unit;
    this.asIfRelative += v;
    this.asIfAbsolute += v - this.lastRawE;
    this.lastRawE = v;
    if (this.relAxes || this.relE) {
      this.e += v;
      return v;
    }
    const d = v - this.e;
    this.e = v;
    return d;
  }

  private linearMove(): void {
    const tx = this.targetAxis(W_X, I_X, this.x, this.offX);
    const ty = this.targetAxis(W_Y, I_Y, this.y, this.offY);
    const tz = this.targetAxis(W_Z, I_Z, this.z, this.offZ);
    if ((this.has & W_F) !== 0) this.f = this.vals[I_F]! * this.unit;
    this.moveTo(tx, ty, tz, this.eDelta());
  }

  private arcMove(clockwise: boolean): void {
    const x = this.x;
    const y = this.y;
    const tx = this.targetAxis(W_X, I_X, x, this.offX);
    const ty = this.targetAxis(W_Y, I_Y, y, this.offY);
    const tz = this.targetAxis(W_Z, I_Z, this.z, this.offZ);
    if ((this.has & W_F) !== 0) this.f = this.vals[I_F]! * this.unit;
    const de = this.eDelta();
    let cx: number;
    let cy: number;
    if ((this.has & (W_I | W_J)) !== 0) {
      cx = x + ((this.has & W_I) !== 0 ? this.vals[I_I]! * this.unit : 0);
      cy = y + ((this.has & W_J) !== 0 ? this.vals[I_J]! * this.unit : 0);
    } else if ((this.has & W_R) !== 0) {
      const r = this.vals[I_R]! * this.unit;
      const dx = tx - x;
      const dy = ty - y;
      const d = Math.hypot(dx, dy);
      if (d < XY_EPSILON_MM) {
        this.moveTo(tx, ty, tz, de);
        return;
      }
      const h = Math.sqrt(Math.max(0, r * r - (d * d) / 4));
      // The centre lies left of the chord for a short counter-clockwise arc; R < 0 asks for the long arc.
      const side = (clockwise ? -1 : 1) * (r < 0 ? -1 : 1);
      cx = (x + tx) / 2 - (side * h * dy) / d;
      cy = (y + ty) / 2 + (side * h * dx) / d;
    } else {
      this.moveTo(tx, ty, tz, de);
      return;
    }
    const r = Math.hypot(x - cx, y - cy);
    const a0 = Math.atan2(y - cy, x - cx);
    let sweep = Math.atan2(ty - cy, tx - cx) - a0;
    if (clockwise) {
      if (sweep >= 0) sweep -= 2 * Math.PI;
    } else if (sweep <= 0) sweep += 2 * Math.PI;
    const step = r > ARC_CHORD_TOLERANCE_MM ? 2 * Math.acos(1 - ARC_CHORD_TOLERANCE_MM / r) : Math.PI / 2;
    const n = Math.min(MAX_ARC_PIECES, Math.max(1, Math.ceil(Math.abs(sweep) / step)));
    const z0 = this.z;
    for (let k = 1; k <= n; k++) {
      if (k === n) {
        this.moveTo(tx, ty, tz, de / n);
      } else {
        const a = a0 + (sweep * k) / n;
        this.moveTo(cx + r * Math.cos(a), cy + r * Math.sin(a), z0 + ((tz - z0) * k) / n, de / n);
      }
    }
  }

  private moveTo(tx: number, ty: number, tz: number, de: number): void {
    const dx = tx - this.x;
    const dy = ty - this.y;
    const movesXY = dx * dx + dy * dy > XY_EPSILON_MM * XY_EPSILON_MM;
    if (de > E_EPSILON_MM) {
      if (movesXY) this.extrude(tx, ty, tz, de);
      else this.prime(de);
    } else {
      if (de < -E_EPSILON_MM) this.retract(-de);
      if (movesXY || tz !== this.z) {
        this.raw.pushTravel(this.x, this.y, this.z, tx, ty, tz, this.block);
      }
    }
    this.x = tx;
    this.y = ty;
    this.z = tz;
  }

  private extrude(tx: number, ty: number, tz: number, de: number): void {
    if (Math.abs(this.pending) > BALANCE_TOLERANCE_MM || this.fwRetracted) {
      this.unbalanced++;
      if (this.unbalancedLines.length < MAX_REPORTED_LINES) this.unbalancedLines.push(this.lineNo);
      this.pending = 0;
      this.fwRetracted = false;
    }
    if (!this.hasMarkers) {
      // Without layer markers a new block starts whenever extrusion continues at another Z.
      const key = zKey(tz);
      if (key !== this.blockZKey) {
        if (!Number.isNaN(this.blockZKey)) this.block = this.raw.openBlock(NaN);
        this.blockZKey = key;
      }
    }
    this.modeFlags |= this.relAxes || this.relE ? 2 : 1;
    this.extruded += de;
    this.raw.pushExtrusion(this.x, this.y, tx, ty, tz, de, this.f, this.feature, this.block);
  }

  /**
   * Negative E. Moves that go on retracting with nothing extruded or primed in between (a retraction
   * spread along a wipe, as PrusaSlicer, OrcaSlicer and Strata write it) are one retraction.
   */
  private retract(amount: number): void {
    const continuing = this.pending > BALANCE_TOLERANCE_MM;
    this.retracted += amount;
    this.pending += amount;
    if (continuing) {
      this.raw.extendRetraction(amount);
      return;
    }
    this.retractions++;
    this.raw.pushRetraction(RetractionKind.Retract, amount, this.lineNo, this.block);
  }

  /** Positive E without XY motion: a prime when a retraction is pending, else a stationary purge. */
  private prime(amount: number): void {
    this.primed += amount;
    if (this.pending <= BALANCE_TOLERANCE_MM) return;
    this.pending -= amount;
    this.primes++;
    this.raw.pushRetraction(RetractionKind.Prime, amount, this.lineNo, this.block);
  }

  private firmwareRetract(): void {
    this.fwRetracted = true;
    this.fwRetractions++;
    this.raw.pushRetraction(RetractionKind.FirmwareRetract, 0, this.lineNo, this.block);
  }

  private firmwarePrime(): void {
    this.fwRetracted = false;
    this.raw.pushRetraction(RetractionKind.FirmwarePrime, 0, this.lineNo, this.block);
  }

  private setPosition(): void {
    const axes = W_X | W_Y | W_Z | W_E;
    const all = (this.has & axes) === 0;
    const u = this.unit;
    if (all || (this.has & W_X) !== 0) this.offX = this.x - (all ? 0 : this.vals[I_X]! * u);
    if (all || (this.has & W_Y) !== 0) this.offY = this.y - (all ? 0 : this.vals[I_Y]! * u);
    if (all || (this.has & W_Z) !== 0) this.offZ = this.z - (all ? 0 : this.vals[I_Z]! * u);
    if (all || (this.has & W_E) !== 0) {
      this.e = all ? 0 : this.vals[I_E]! * u;
      this.lastRawE = this.e;
    }
  }

  private home(): void {
    const all = (this.has & (W_X | W_Y | W_Z)) === 0;
    if (all || (this.has & W_X) !== 0) this.x = this.offX = 0;
    if (all || (this.has & W_Y) !== 0) this.y = this.offY = 0;
    if (all || (this.has & W_Z) !== 0) this.z = this.offZ = 0;
  }
}
