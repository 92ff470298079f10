/**
 * Glue for the infill registry and the CLI: a custom infiller as a per-layer generator with the
 * InfillPattern.generate signature, and parsing of `--infill-param NAME=VALUE` options.
 */
import { StrataError } from '../errors.js';
import type { InfillLayerInput, InfillParams, InfillResult } from '../infill/types.js';
import type { Pt } from '../geometry/types.js';
import type { DensityInput } from './density-source.js';
import { densityResolver } from './density-source.js';
import type { Infiller } from './infiller.js';
import type { ShaderParam } from './shader.js';
import { findParam, parseParamValue } from './shader.js';

export interface CustomInfillSettings {
  /** ui_ parameter values (`--infill-param`), names with or without `ui_`. */
  params?: Readonly<Record<string, number | boolean>>;
  /** Image pixel size, mm (`--infill-image-pixel-size`, IceSL's labeling_mm_per_pixel). */
  pixelSize?: number;
  /** Grid spacing, mm (default nozzle / 4; images: the pixel size). */
  resolution?: number;
  /** density() source; default: the infill density setting (InfillParams.density × 100). */
  density?: DensityInput;
  /** Images: scale the tiling with density (see InfillerOptions.densityReference). */
  densityReference?: number;
}

export type CustomInfillGenerator = (layer: InfillLayerInput, params: InfillParams, start?: Pt) => InfillResult;

/**
 * A generator for the infill registry: paths of every pass, clipped to the region and ordered,
 * returned as `lines` (closed loops repeat their first point).
 */
export function customInfillGenerator(infiller: Infiller, settings: CustomInfillSettings = {}): CustomInfillGenerator {
  // Check parameter names and types once, up front.
  if (settings.params !== undefined) {
    for (const k of Object.keys(settings.params)) {
      if (findParam(infiller.params, k) === undefined) {
        const known = infiller.params.map((p) => p.name).join(', ') || 'none';
        throw new StrataError(
          'BAD_SETTING',
          `infiller ${infiller.name}: unknown parameter '${k.slice(0, 60)}' (parameters: ${known})`,
        );
      }
    }
  }
  const densityFor = settings.density !== undefined ? densityResolver(settings.density) : undefined;
  return (layer, params, start) => {
    const density = densityFor !== undefined ? densityFor(layer.layerIndex) : params.density * 100;
    const lines = infiller.paths(
      {
        region: layer.region,
        z: layer.z,
        layerHeight: layer.layerHeight,
        density,
        params: infiller.kind === 'shader' ? settings.params : undefined,
      },
      {
        nozzleDiameter: params.nozzleDiameter / 1000,
        resolution: settings.resolution,
        pixelSize: settings.pixelSize,
        densityReference: settings.densityReference,
        start,
      },
    );
    return { lines, loops: [] };
  };
}

/** Parse `NAME=VALUE` strings (CLI `--infill-param`) against an infiller's parameters. */
export function parseInfillParams(
  params: readonly ShaderParam[],
  assignments: readonly string[],
): Record<string, number | boolean> {
  const out: Record<string, number | boolean> = {};
  for (const a of assignments) {
    const eq = a.indexOf('=');
    if (eq <= 0) throw new StrataError('BAD_SETTING', `--infill-param expects NAME=VALUE, got '${a.slice(0, 60)}'`);
    const name = a.slice(0, eq).trim();
    const p = findParam(params, name);
    if (p === undefined) {
      const known = params.map((q) => q.name).join(', ') || 'none';
      throw new StrataError('BAD_SETTING', `unknown infill parameter '${name.slice(0, 60)}' (parameters: ${known})`);
    }
    out[p.name] = parseParamValue(p, a.slice(eq + 1));
  }
  return out;
}
