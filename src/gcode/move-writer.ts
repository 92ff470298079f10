/**
 * The MoveSink that prints the body of the file: per layer `;LAYER:n`, `;Z:`, `;HEIGHT:`, temperature
 * and fan changes, `G92 E0` (absolute E, when E is not already 0), the moves with `;TYPE:` markers when
 * the feature changes, `;TIME_ELAPSED:` at the layer end.
 *
 * With `progressM73`, each layer starts with `M73 P<percent> R<minutes left>` from the estimate (written
 * when either changes; P rounded down, R up, so both move one way only). Object labels come from
 * object-labels.ts. Firmware retraction writes G10/G11 instead of E moves.
 *
 * Custom per-layer G-code (custom-gcode.ts) comes before the layer's temperatures (beforeLayerChangeGcode,
 * colour changes, pauses) and after its first Z move (layerChangeGcode); a `G92 E` in it resets the E the
 * writer counts from, as it resets the printer's.
 *
 * Travels are G0, the rest G1 (arcs G2 clockwise / G3 counter-clockwise, with I J from the start point as
 * written to the centre); axes and F are modal (written only when they change); X/Y/Z to the µm,
 * E to 1e-5 mm, F whole mm/min. E is accumulated unrounded and each written value is rounded from the
 * running total, so relative E words add up to exactly the absolute values and rounding never drifts.
 * A class with fields rather than closures, so the per-segment doubles are updated in place.
 */
import type { ExtrudeStep, FeatureType, LayerPlan } from '../plan/types.js';
import type { ChunkedText } from './chunked-text.js';
import type { FlavorCommands } from './flavor.js';
import { E_SCALE, POSITION_SCALE, compact, feedrate, mm } from './format.js';
import type { MoveSink } from '../plan/moves.js';
import type { ObjectLabels } from './object-labels.js';
import type { LayerGcode } from './custom-gcode.js';
import { layerChangeMarker } from './host-metadata.js';
import { WHOLE_QUOTIENT_EPS } from '../geometry/tolerances.js';

/** The `;TYPE:` marker of each feature, as Cura names them (Cura writes its brim as SKIRT, its raft as SUPPORT-INTERFACE); skin over air is BRIDGE, as OrcaSlicer names it. */
export const TYPE_MARKERS = {
  'WALL-OUTER': 'WALL-OUTER',
  'WALL-INNER': 'WALL-INNER',
  SKIN: 'SKIN',
  FILL: 'FILL',
  BRIDGE: 'BRIDGE',
  SUPPORT: 'SUPPORT',
  'SUPPORT-INTERFACE': 'SUPPORT-INTERFACE',
  SKIRT: 'SKIRT',
  BRIM: 'SKIRT',
  RAFT: 'SUPPORT-INTERFACE',
  IRONING: 'IRONING',
} as const satisfies Record<FeatureType, string>;

const E_DECIMALS = 5;
const POSITION_DECIMALS = 3;

export interface MoveWriterOptions {
  flavor: FlavorCommands;
  relativeE: boolean;
  heatedBed: boolean;
  /** Estimated seconds per layer, for `;TIME_ELAPSED:`. */
  layerSeconds: readonly number[];
  /** Temperatures the start G-code leaves the heaters at (NaN = unknown). */
  nozzleTemperature: number;
  bedTemperature: number;
  /** Write M73 progress at each layer start. */
  progress: boolean;
  /** Retract with G10/G11. */
  firmwareRetraction: boolean;
  /** Object label lines, or null for none. */
  labels: ObjectLabels | null;
  /** Custom per-layer G-code, or null for none. */
  layerGcode?: LayerGcode | null;
}

/** `G92 E<value>` (with other axes or a comment too): the E the printer counts from is set. */
const SETS_E = /^\s*G92\b[^;]*?\bE\s*([-+]?(?:\d+\.?\d*|\.\d+))/i;

export class MoveWriter implements MoveSink {
  /** Position as written, µm (NaN = not written yet). */
  private x = NaN;
  private y = NaN;
  /** Modal feed rate as written, mm/min (-1 = not written yet). */
  private f = -1;
  /** Filament since the last G92 E0, unrounded, and the same rounded to E_SCALE as last written. */
  private eTotal = 0;
  private eUnits = 0;
  private feature = '';
  private nozzle: number;
  private bed: number;
  private fan = NaN;
  /** The current layer's fan, which a step with its own fan (bridges) returns to. */
  private layerFan = NaN;
  /** Filament extruded so far, mm (for the per-layer templates). */
  private extruded = 0;
  /** The layer whose layerChangeGcode waits for its first Z move (-1: none). */
  private pendingAfter = -1;
  private pendingLayer: LayerPlan | null = null;
  private elapsed = 0;
  private readonly totalSeconds: number;
  /** Last M73 values written (-1 = none yet). */
  private percent = -1;
  private minutesLeft = -1;

  constructor(
    private readonly out: ChunkedText,
    private readonly o: MoveWriterOptions,
  ) {
    this.nozzle = o.nozzleTemperature;
    this.bed = o.bedTemperature;
    let total = 0;
    for (const t of o.layerSeconds) total += t;
    this.totalSeconds = total;
  }

  /** `M73 P R` for `elapsed` seconds into the print, when a value changed. */
  private progress(elapsed: number): void {
    const total = this.totalSeconds;
    const percent = total > 0 ? Math.min(100, Math.floor((100 * elapsed) / total)) : 0;
    const left = Math.max(0, Math.ceil((total - elapsed) / 60 - WHOLE_QUOTIENT_EPS));
    const p = Math.max(percent, this.percent);
    const r = this.minutesLeft < 0 ? left : Math.min(left, this.minutesLeft);
    if (p === this.percent && r === this.minutesLeft) return;
    this.percent = p;
    this.minutesLeft = r;
    this.out.line(`M73 P${p} R${r}`);
  }

  /** The final `M73 P100 R0`, after the last layer (when progress is on). */
  finish(): void {
    if (!this.o.progress) return;
    this.percent = 100;
    this.minutesLeft = 0;
    this.out.line('M73 P100 R0');
  }

  private feed(speed: number): void {
    const value = feedrate(speed);
    if (value === this.f) return;
    this.f = value;
    this.out.text(' F');
    this.out.int(value);
  }

  /** Write the X/Y words that changed (both rounded to the µm, at least one differing). */
  private xy(ux: number, uy: number): void {
    if (ux !== this.x) {
      this.out.text(' X');
      this.out.fixed(ux, POSITION_SCALE, POSITION_DECIMALS);
      this.x = ux;
    }
    if (uy !== this.y) {
      this.out.text(' Y');
      this.out.fixed(uy, POSITION_SCALE, POSITION_DECIMALS);
      this.y = uy;
    }
  }

  private e(delta: number): void {
    this.eTotal += delta;
    const units = Math.round(this.eTotal * E_SCALE);
    const written = this.o.relativeE ? units - this.eUnits : units;
    this.eUnits = units;
    this.out.text(' E');
    this.out.fixed(written, E_SCALE, E_DECIMALS);
  }

  layerStart(layer: LayerPlan, position: number): void {
    const { out, o } = this;
    out.line(`;LAYER:${position}`);
    out.line(`;Z:${mm(layer.z)}`);
    out.line(`;HEIGHT:${mm(layer.height)}`);
    for (const l of layerChangeMarker(layer.z)) out.line(l);
    if (o.progress) this.progress(this.elapsed);
    if (o.layerGcode) {
      this.custom(o.layerGcode.before(layer, position, this.extruded));
      this.pendingAfter = position;
      this.pendingLayer = layer;
    }
    if (layer.nozzleTemperature !== undefined && layer.nozzleTemperature !== this.nozzle) {
      this.nozzle = layer.nozzleTemperature;
      for (const l of o.flavor.setNozzle(this.nozzle)) out.line(l);
    }
    if (o.heatedBed && layer.bedTemperature !== undefined && layer.bedTemperature !== this.bed) {
      this.bed = layer.bedTemperature;
      out.line(o.flavor.setBed(this.bed));
    }
    this.layerFan = layer.fan;
    this.setFan(layer.fan);
    if (this.eUnits !== 0 && !o.relativeE) out.line('G92 E0');
    this.eTotal = 0;
    this.eUnits = 0;
    this.feature = '';
  }

  layerEnd(_layer: LayerPlan, position: number): void {
    if (this.pendingAfter >= 0) this.afterLayerChange();
    this.elapsed += this.o.layerSeconds[position] ?? 0;
    this.out.line(`;TIME_ELAPSED:${compact(this.elapsed, 3)}`);
  }

  zMove(z: number, _distance: number, speed: number): void {
    this.out.text('G0');
    this.feed(speed);
    this.out.text(' Z');
    this.out.fixed(Math.round(z * POSITION_SCALE), POSITION_SCALE, POSITION_DECIMALS);
    this.out.endLine();
    if (this.pendingAfter >= 0) this.afterLayerChange();
  }

  /** The layer's layerChangeGcode, after its first Z move (or before its first move if it has none). */
  private afterLayerChange(): void {
    const position = this.pendingAfter;
    this.pendingAfter = -1;
    this.custom(this.o.layerGcode!.after(this.pendingLayer!, position, this.extruded));
  }

  /** Lines of custom G-code; a `G92 E` among them sets the E counted from. */
  private custom(lines: readonly string[]): void {
    for (const l of lines) {
      this.out.line(l);
      const e = SETS_E.exec(l);
      if (e) {
        this.eTotal = Number(e[1]);
        this.eUnits = Math.round(this.eTotal * E_SCALE);
      }
    }
  }

  extrudeZ(x: number, y: number, z: number, _length: number, filament: number, speed: number): void {
    this.extruded += filament;
    const ux = Math.round(x);
    const uy = Math.round(y);
    this.out.text('G1');
    this.feed(speed);
    if (ux !== this.x || uy !== this.y) this.xy(ux, uy);
    this.out.text(' Z');
    this.out.fixed(Math.round(z * POSITION_SCALE), POSITION_SCALE, POSITION_DECIMALS);
    this.e(filament);
    this.out.endLine();
  }

  travel(x: number, y: number, _length: number, speed: number): void {
    if (this.pendingAfter >= 0) this.afterLayerChange();
    const ux = Math.round(x);
    const uy = Math.round(y);
    if (ux === this.x && uy === this.y) return;
    this.out.text('G0');
    this.feed(speed);
    this.xy(ux, uy);
    this.out.endLine();
  }

  private setFan(fan: number): void {
    if (fan === this.fan) return;
    this.fan = fan;
    this.out.line(this.o.flavor.fan(fan));
  }

  extrudeStart(step: ExtrudeStep): void {
    if (this.pendingAfter >= 0) this.afterLayerChange();
    this.setFan(step.fan ?? this.layerFan);
    const marker = TYPE_MARKERS[step.feature];
    if (marker === this.feature) return;
    this.feature = marker;
    this.out.line(';TYPE:' + marker);
  }

  extrude(x: number, y: number, _length: number, filament: number, speed: number): void {
    this.extruded += filament;
    const ux = Math.round(x);
    const uy = Math.round(y);
    if (ux === this.x && uy === this.y) {
      this.eTotal += filament; // shorter than a micrometre: carried into the next segment
      return;
    }
    this.out.text('G1');
    this.feed(speed);
    this.xy(ux, uy);
    this.e(filament);
    this.out.endLine();
  }

  arc(
    x: number,
    y: number,
    cx: number,
    cy: number,
    clockwise: boolean,
    _length: number,
    filament: number,
    speed: number,
  ): void {
    this.extruded += filament;
    const ux = Math.round(x);
    const uy = Math.round(y);
    if (ux === this.x && uy === this.y) {
      this.eTotal += filament; // an arc that ends where it starts would be a full circle: carried instead
      return;
    }
    const i = Math.round(cx) - this.x;
    const j = Math.round(cy) - this.y;
    this.out.text(clockwise ? 'G2' : 'G3');
    this.feed(speed);
    this.out.text(' X');
    this.out.fixed(ux, POSITION_SCALE, POSITION_DECIMALS);
    this.out.text(' Y');
    this.out.fixed(uy, POSITION_SCALE, POSITION_DECIMALS);
    this.x = ux;
    this.y = uy;
    this.out.text(' I');
    this.out.fixed(i, POSITION_SCALE, POSITION_DECIMALS);
    this.out.text(' J');
    this.out.fixed(j, POSITION_SCALE, POSITION_DECIMALS);
    this.e(filament);
    this.out.endLine();
  }

  retract(filament: number, speed: number): void {
    if (this.o.firmwareRetraction) {
      this.out.line('G10');
      return;
    }
    this.out.text('G1');
    this.feed(speed);
    this.e(-filament);
    this.out.endLine();
  }

  /** A wipe: G1 to (x, y) retracting `filament` on the way (no E with firmware retraction, whose wipe retracts nothing). */
  wipe(x: number, y: number, _length: number, filament: number, speed: number): void {
    const ux = Math.round(x);
    const uy = Math.round(y);
    if (ux === this.x && uy === this.y) {
      this.eTotal -= filament; // shorter than a micrometre: carried into the next E written
      return;
    }
    this.out.text('G1');
    this.feed(speed);
    this.xy(ux, uy);
    if (filament > 0) this.e(-filament);
    this.out.endLine();
  }

  prime(filament: number, speed: number): void {
    if (this.o.firmwareRetraction) {
      this.out.line('G11');
      return;
    }
    this.out.text('G1');
    this.feed(speed);
    this.e(filament);
    this.out.endLine();
  }

  objectStart(index: number): void {
    if (this.pendingAfter >= 0) this.afterLayerChange();
    for (const l of this.o.labels?.start(index) ?? []) this.out.line(l);
  }

  objectEnd(index: number): void {
    for (const l of this.o.labels?.end(index) ?? []) this.out.line(l);
  }
}
