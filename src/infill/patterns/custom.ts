/**
 * Custom infill: an IceSL infiller (a GLSL cellular() shader or a cells.png image, compiled by src/shader/)
 * as an infill pattern. A slice is given the infiller as plain data (`CustomInfillSpec`, which crosses to
 * the workers), and each thread that fills layers compiles it once (`customPattern`). It takes the place of
 * every region's pattern (registry.ts `regionPattern`) and draws finished paths: clipped to the region and
 * ordered by the infiller, at the density it reads itself. The registry loads this module on first use
 * (`loadCustomInfill`): with the shader compiler it is most of the library's size.
 */
import { StrataError } from '../../errors.js';
import type { Pt } from '../../geometry/types.js';
import {
  compileShader,
  densityResolver,
  findParam,
  loadInfiller,
  type DensityInput,
  type Infiller,
  type InfillerFiles,
} from '../../shader/index.js';
import type { InfillLayerInput, InfillParams, InfillPattern, InfillResult } from '../types.js';

/** What density() returns (0–100): a constant, one value per layer, a density shader, or a JS field. */
export type CustomDensity =
  | number
  | readonly number[]
  | { shader: string; fileName?: string }
  | ((x: number, y: number, z: number) => number);

export interface CustomInfillSpec extends InfillerFiles {
  /** Values for the shader's ui_ parameters (names with or without the ui_ prefix). */
  params?: Readonly<Record<string, number | boolean>>;
  /**
   * The field density(world) reads; default: the infillDensity setting. A JS function cannot be
   * sent to worker threads, so a slice that uses one runs on the calling thread.
   */
  density?: CustomDensity;
}

/** The print settings a custom infill reads (a Config has them). */
export interface CustomInfillConfig {
  /** Image pixel size, mm. */
  infillImagePixelSize: number;
  /** Grid spacing, mm; null: the infiller's default (nozzle / 4 for shaders, one pixel for images). */
  infillShaderResolution: number | null;
}

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
 * An infiller as a per-layer generator with the InfillPattern.generate signature: paths of every pass,
 * clipped to the region and ordered, returned as `lines` (closed loops repeat their first point).
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
        z: layer.zMm,
        layerHeight: layer.layerHeightMm,
        density,
        params: infiller.kind === 'shader' ? settings.params : undefined,
      },
      {
        nozzleDiameter: params.nozzleDiameterUm / 1000,
        resolution: settings.resolution,
        pixelSize: settings.pixelSize,
        densityReference: settings.densityReference,
        start,
      },
    );
    return { lines, loops: [] };
  };
}

function densityInput(d: CustomDensity | undefined): DensityInput | undefined {
  if (d === undefined || typeof d === 'number' || typeof d === 'function' || Array.isArray(d))
    return d as DensityInput | undefined;
  const s = d as { shader: string; fileName?: string };
  return compileShader(s.shader, { entry: 'density', fileName: s.fileName ?? 'density.glsl' });
}

/** Compile the infiller into a per-layer generator (its errors are thrown here). */
export function customGenerator(spec: CustomInfillSpec, cfg: CustomInfillConfig): CustomInfillGenerator {
  return customInfillGenerator(loadInfiller(spec), {
    params: spec.params,
    pixelSize: cfg.infillImagePixelSize,
    // empty: the infiller default (nozzle / 4 for shaders, one pixel for images)
    resolution: cfg.infillShaderResolution ?? undefined,
    density: densityInput(spec.density),
  });
}

/** Compile the infiller into the pattern this thread fills every region with (its errors are thrown here). */
export function customPattern(spec: CustomInfillSpec, cfg: CustomInfillConfig): InfillPattern {
  const draw = customGenerator(spec, cfg);
  return {
    id: 'custom',
    description: `The custom infiller ${spec.name}.`,
    finished: true,
    generate: (layer, params) => draw(layer, params),
  };
}
