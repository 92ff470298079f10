/**
 * What spiral vase mode (spiralVase) sets aside above the vase's bottom layers, and the warning that names
 * the settings given a value it sets aside: one wall, no infill, no top skin, no support, no ironing, no
 * extra walls over overhangs, no seam (so neither its position nor a scarf), and no travel between turns (so
 * no retraction or Z hop on their layer changes). The bottom layers print as set.
 */
import type { Config } from './resolve.js';
import type { SettingKey } from './schema.js';
import { WHOLE_QUOTIENT_EPS } from '../geometry/tolerances.js';

interface SetAside {
  key: SettingKey;
  /** Whether the vase sets this value aside (given the print's resolved config). */
  ignored: (value: unknown, cfg: Config) => boolean;
  /** What the vase does instead. */
  instead: string;
}

const SET_ASIDE: readonly SetAside[] = [
  { key: 'wallCount', ignored: (v) => typeof v === 'number' && v !== 1, instead: 'one wall' },
  {
    key: 'shellWallThickness',
    ignored: (v, cfg) => typeof v === 'number' && Math.round(v / cfg.lineWidthMm + WHOLE_QUOTIENT_EPS) !== 1,
    instead: 'one wall',
  },
  { key: 'infillDensity', ignored: (v) => typeof v === 'number' && v > 0, instead: 'no infill' },
  { key: 'topSkinThickness', ignored: (v) => typeof v === 'number' && v > 0, instead: 'no top skin' },
  { key: 'supportEnabled', ignored: (v) => v === true, instead: 'no support' },
  { key: 'ironingEnabled', ignored: (v) => v === true, instead: 'no ironing' },
  { key: 'extraPerimetersOnOverhangs', ignored: (v) => v === true, instead: 'one wall' },
  { key: 'scarfSeam', ignored: (v) => typeof v === 'string' && v !== 'off', instead: 'no seam' },
  { key: 'seamPosition', ignored: (v) => typeof v === 'string', instead: 'no seam' },
  { key: 'retractOnLayerChange', ignored: (v) => v === true, instead: 'no retraction between turns' },
  { key: 'zHop', ignored: (v) => typeof v === 'number' && v > 0, instead: 'no travel between turns' },
];

/**
 * One warning naming the settings given (in `given`: the print's options, objects', ranges' and modifiers'
 * own settings) a value the spiral vase sets aside above its bottom, or null when there are none or the vase
 * is off.
 */
export function vaseWarning(
  given: ReadonlyArray<Readonly<Record<string, unknown>> | undefined>,
  cfg: Config,
): string | null {
  if (!cfg.spiralVase) return null;
  const named: string[] = [];
  for (const s of SET_ASIDE) {
    const values = new Set<string>();
    for (const g of given) {
      const v = g?.[s.key];
      if (v !== undefined && s.ignored(v, cfg)) values.add(String(v));
    }
    if (values.size) named.push(`${s.key} = ${[...values].join(' / ')} (${s.instead})`);
  }
  if (!named.length) return null;
  return `spiral vase: above the ${cfg.bottomLayers} bottom layer${cfg.bottomLayers === 1 ? '' : 's'} these settings are ignored: ${named.join(', ')}`;
}
