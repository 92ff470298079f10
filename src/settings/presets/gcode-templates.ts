/**
 * Builders for the printer presets' start and end G-code. Each returns a template string whose `{key}`
 * placeholders are setting keys (see schema.ts), filled in by the G-code writer.
 *
 * Convention shared with the schema's default start code: a start template leaves the printer in absolute
 * positioning (G90) and absolute extrusion (M82) with E reset to 0; the writer switches to relative E (M83)
 * after it when `extruderMode` is relative. Prime lines are therefore written with absolute E.
 */

/** One prime (purge) line: a polyline on the bed, drawn at `z` mm. Coordinates are printer coordinates. */
export interface PrimeLine {
  points: readonly (readonly [number, number])[];
  /** Height of the prime line, mm (default 0.3). */
  z?: number;
  /** Filament pushed per mm of line (default 0.08 mm: a ~0.6 × 0.3 mm line from 1.75 mm filament). */
  ePerMm?: number;
  /** Feed rate while priming, mm/min (default 1500). */
  feed?: number;
}

/** Numbers with at most 3 decimals and no trailing zeros. */
const n = (x: number) => String(Math.round(x * 1000) / 1000);

/** Moves to the start of the line, then extrudes along it with cumulative (absolute) E. */
export function primeLineGcode(line: PrimeLine): string[] {
  const z = line.z ?? 0.3;
  const ePerMm = line.ePerMm ?? 0.08;
  const feed = line.feed ?? 1500;
  const [first, ...rest] = line.points;
  if (!first) return [];
  const out = [
    'M82 ; absolute extrusion for the prime line',
    'G92 E0',
    'G1 Z2 F3000',
    `G1 X${n(first[0])} Y${n(first[1])} Z${n(z)} F5000 ; prime line start`,
  ];
  let e = 0;
  let prev = first;
  for (const p of rest) {
    e += Math.hypot(p[0] - prev[0], p[1] - prev[1]) * ePerMm;
    out.push(`G1 X${n(p[0])} Y${n(p[1])} E${n(e)} F${feed}`);
    prev = p;
  }
  out.push('G92 E0', 'G1 Z2 F3000');
  return out;
}

/** The two parallel lines along the left edge that Creality-style printers draw (as the schema's default). */
export function leftEdgePrime(fromY: number, toY: number, x = 0.1): PrimeLine {
  return {
    points: [
      [x, fromY],
      [x, toY],
      [x + 0.3, toY],
      [x + 0.3, fromY],
    ],
  };
}

/** One line along the front edge, from x0 to x1 at y. */
export function frontEdgePrime(y: number, x0: number, x1: number, z = 0.3): PrimeLine {
  return {
    points: [
      [x0, y],
      [x1, y],
    ],
    z,
  };
}

export interface MarlinStartOptions {
  /** The homing command (default "G28 ; home all axes"). */
  home?: string;
  /** Lines after homing (bed levelling: "G29", "M420 S1"…). */
  afterHome?: readonly string[];
  /** Lines before everything (printer checks such as Prusa's M862). */
  preamble?: readonly string[];
  /** Heat the nozzle only to this before homing/levelling (avoids ooze on the probe); default: full temperature. */
  probeNozzleTemperature?: number;
  prime: PrimeLine | null;
}

/** Plain Marlin-style start: heat (bed and nozzle in parallel), home, level, wait, prime. */
export function marlinStart(o: MarlinStartOptions): string {
  const lines = [
    ...(o.preamble ?? []),
    'G90 ; absolute positioning',
    'M82 ; absolute extrusion',
    'M140 S{firstLayerBedTemperature} ; bed heat, no wait',
  ];
  lines.push(
    o.probeNozzleTemperature === undefined
      ? 'M104 S{firstLayerNozzleTemperature} ; nozzle heat, no wait'
      : `M104 S${o.probeNozzleTemperature} ; nozzle warm but not oozing while homing and probing`,
  );
  lines.push(o.home ?? 'G28 ; home all axes', ...(o.afterHome ?? []));
  if (o.probeNozzleTemperature !== undefined)
    lines.push('M104 S{firstLayerNozzleTemperature} ; nozzle to printing temperature');
  lines.push(
    'M190 S{firstLayerBedTemperature} ; wait for bed',
    'M109 S{firstLayerNozzleTemperature} ; wait for nozzle',
  );
  if (o.prime) lines.push(...primeLineGcode(o.prime));
  else lines.push('G92 E0');
  return lines.join('\n');
}

export interface KlipperMacroStartOptions {
  /** The macro call, with placeholders, e.g. "START_PRINT EXTRUDER_TEMP={firstLayerNozzleTemperature} BED_TEMP={firstLayerBedTemperature}". */
  macro: string;
  /** Lines before the macro (e.g. heating for macros that do not heat). */
  before?: readonly string[];
  /** Lines after the macro, before the prime line. */
  after?: readonly string[];
  prime: PrimeLine | null;
}

/** Klipper start: the printer's own start macro (homing, levelling, heating), then a prime line. */
export function klipperMacroStart(o: KlipperMacroStartOptions): string {
  const lines = ['G90 ; absolute positioning', ...(o.before ?? []), o.macro, ...(o.after ?? [])];
  if (o.prime) lines.push(...primeLineGcode(o.prime));
  else lines.push('M82 ; absolute extrusion', 'G92 E0');
  return lines.join('\n');
}

export interface EndOptions {
  /**
   * How to leave the print: `bed-forward` moves the bed (or head) to the back so the print faces the user
   * (X0, Y = buildPlateLength), `park-rear` parks the head at the back centre, `home` re-homes (deltas),
   * `lower-bed` drops the bed (Ender-5 style printers whose bed moves in Z); `{x, y}` moves the head there.
   */
  present: 'bed-forward' | 'park-rear' | 'home' | 'lower-bed' | { readonly x: number; readonly y: number };
  /** Lines after the present move, before the fan and heaters are turned off. */
  extra?: readonly string[];
}

const PRESENT_MOVES = Object.freeze({
  'bed-forward': 'G1 X0 Y{buildPlateLength} F3000 ; present the print',
  'park-rear': 'G1 X{buildPlateWidth} Y{buildPlateLength} F6000 ; park the head at the back',
  home: 'G28 ; home: carriages to the top',
  'lower-bed': 'G1 Z{buildVolumeHeight} F600 ; lower the bed\nG1 X0 Y0 F3000',
} as const);

/** End: retract, lift, present the print, fan and heaters off, motors off. */
export function marlinEnd(o: EndOptions): string {
  const lines = [
    'G91 ; relative positioning',
    'G1 E-2 F2700 ; retract',
    'G1 Z10 F3000 ; lift',
    'G90 ; absolute positioning',
  ];
  if (typeof o.present === 'object') {
    lines.push(`G1 X${n(o.present.x)} Y${n(o.present.y)} F3000 ; present the print`);
  } else {
    lines.push(PRESENT_MOVES[o.present]);
  }
  lines.push(
    ...(o.extra ?? []),
    'M106 S0 ; fan off',
    'M104 S0 ; nozzle off',
    'M140 S0 ; bed off',
    'M84 X Y E ; motors off',
  );
  return lines.join('\n');
}

/** Klipper end: retract, then the printer's end macro (which lifts, parks and turns everything off). */
export function klipperMacroEnd(macro: string): string {
  return ['G91 ; relative positioning', 'G1 E-2 F2700 ; retract', 'G90 ; absolute positioning', macro].join('\n');
}
