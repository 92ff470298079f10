/**
 * Start and end templates in the chosen flavour's own dialect. The presets (and most users) write
 * templates in Marlin's words; a template line is translated where another firmware has its own
 * command for the same thing, so every flavour gets only commands its firmware takes:
 *
 * - RepRapFirmware: nozzle heating M104/M109 (deprecated there, and M109 selects a tool as a side
 *   effect) becomes tool temperatures `G10 P<tool> S R`, `T<tool>` and `M116 P<tool>` to wait;
 *   Marlin's mesh commands become G29 (`M420 S1` loads the saved height map: `G29 S1`; Prusa's G80
 *   probes: `G29`); Prusa's printer checks (M862.x) are kept as comments.
 * - Klipper: `M420 S1` loads the default bed mesh (BED_MESH_PROFILE LOAD=default), G29 and G80 probe
 *   one (BED_MESH_CALIBRATE); Prusa's checks become comments.
 * - Marlin and RepRapFirmware cannot run Klipper macros (START_PRINT…): a template calling one is an
 *   error naming the line, instead of G-code that would start without heating or homing.
 *
 * Without a heated bed (heatedBed false), bed temperature commands (M140, M190) become comments.
 */
import { StrataError } from '../errors.js';
import type { GcodeFlavor } from './flavor.js';

type Rewrite = (words: readonly string[], comment: string) => string[];

const param = (words: readonly string[], letter: string): string | undefined => {
  const w = words.find((x, i) => i > 0 && x[0]?.toUpperCase() === letter);
  return w?.slice(1);
};

const note = (comment: string, what: string) => ` ; ${comment || what}`;

const commentOut =
  (why: string): Rewrite =>
  (words, comment) => [`; ${words.join(' ')}${comment ? ` (${comment})` : ''} (${why})`];

const REPRAP_NOZZLE =
  (wait: boolean): Rewrite =>
  (words, comment) => {
    const temp = param(words, 'S') ?? param(words, 'R');
    if (temp === undefined) return [words.join(' ') + (comment ? ` ; ${comment}` : '')];
    const tool = param(words, 'T') ?? '0';
    const set = `G10 P${tool} S${temp} R${temp}${note(comment, wait ? 'nozzle temperature' : 'nozzle heat, no wait')}`;
    return wait ? [set, `T${tool} ; select the tool`, `M116 P${tool} ; wait for the nozzle`] : [set];
  };

/** Per flavour: command word → its rewrite. */
const REWRITES: Readonly<Record<GcodeFlavor, Readonly<Record<string, Rewrite>>>> = {
  marlin: {},
  klipper: {
    M420: (words, comment) =>
      param(words, 'S') === '0'
        ? [`BED_MESH_CLEAR${note(comment, 'no bed mesh')}`]
        : [`BED_MESH_PROFILE LOAD=default${note(comment, 'load the saved bed mesh')}`],
    G29: (_w, comment) => [`BED_MESH_CALIBRATE${note(comment, 'probe the bed mesh')}`],
    G80: (_w, comment) => [`BED_MESH_CALIBRATE${note(comment, 'probe the bed mesh')}`],
    M862: commentOut('a Prusa printer check; Klipper has none'),
  },
  reprap: {
    M104: REPRAP_NOZZLE(false),
    M109: REPRAP_NOZZLE(true),
    M420: (words, comment) =>
      param(words, 'S') === '0'
        ? [`G29 S2${note(comment, 'no height map')}`]
        : [`G29 S1${note(comment, 'load the saved height map')}`],
    G80: (_w, comment) => [`G29${note(comment, 'probe the bed')}`],
    M862: commentOut('a Prusa printer check; RepRapFirmware has none'),
  },
};

const NO_BED: Readonly<Record<string, Rewrite>> = {
  M140: commentOut('no heated bed'),
  M190: commentOut('no heated bed'),
};

const FIRMWARE: Readonly<Record<GcodeFlavor, string>> = {
  marlin: 'Marlin',
  klipper: 'Klipper',
  reprap: 'RepRapFirmware',
};

/** A G-code command word: a letter and a number (G1, M104, M862.3, T0). */
const GCODE_WORD = /^[GMTD]\d+(\.\d+)?$/i;

function split(line: string): { words: string[]; comment: string } {
  const semi = line.indexOf(';');
  const code = semi < 0 ? line : line.slice(0, semi);
  return { words: code.trim().split(/\s+/).filter(Boolean), comment: semi < 0 ? '' : line.slice(semi + 1).trim() };
}

/**
 * The template's lines for `flavor` (see the file comment). Throws StrataError BAD_SETTING for a
 * Klipper macro under another flavour. `name` is the setting, for messages.
 */
export function templateForFlavor(
  lines: readonly string[],
  flavor: GcodeFlavor,
  name: string,
  heatedBed = true,
): string[] {
  const rewrites: Readonly<Record<string, Rewrite>> = heatedBed ? REWRITES[flavor] : { ...REWRITES[flavor], ...NO_BED };
  const out: string[] = [];
  lines.forEach((line, i) => {
    const { words, comment } = split(line);
    if (words.length === 0) {
      out.push(line);
      return;
    }
    const cmd = words[0].toUpperCase();
    if (!GCODE_WORD.test(cmd)) {
      if (flavor !== 'klipper') {
        throw new StrataError(
          'BAD_SETTING',
          `${name} line ${i + 1} "${line.trim().slice(0, 60)}" is a Klipper macro, which ${FIRMWARE[flavor]} firmware does not run: use gcodeFlavor klipper, or give a ${name} for this printer`,
        );
      }
      out.push(line);
      return;
    }
    const rewrite = rewrites[cmd] ?? rewrites[cmd.split('.')[0]];
    if (rewrite) out.push(...rewrite(words, comment));
    else out.push(line);
  });
  return out;
}

/** Whether the template sets the nozzle temperature itself, in Marlin's words or the flavour's own. */
export function templateHeatsNozzle(template: string, flavor: GcodeFlavor): boolean {
  if (/^\s*M10[49]\b/im.test(template)) return true;
  return flavor === 'reprap' && (/^\s*G10\b[^;\n]*\bS\d/im.test(template) || /^\s*M116\b/im.test(template));
}
