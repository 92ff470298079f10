/**
 * Custom infillers in IceSL's layout, from file contents (no I/O here): a shader (`shader.glsl`) or
 * an image (`cells.png`), with their ui_ parameters, turned into per-layer infill paths.
 */
import type { Polyline } from '../geometry/types.js';
import { StrataError } from '../errors.js';
import type { CellImage, ImageLoadOptions } from './image.js';
import { imageLabelFn, loadCellImage } from './image.js';
import type { ExtractOptions, ShaderLayerInput } from './paths.js';
import { labelBoundaries, shaderPathsByPass } from './paths.js';
import type { CompileOptions, CompiledShader, ShaderInstance, ShaderParam } from './shader.js';
import { compileShader } from './shader.js';

export type InfillerKind = 'shader' | 'image';

export interface InfillerOptions extends ExtractOptions {
  /** Image pixel size in mm (IceSL's labeling_mm_per_pixel; default 0.1). */
  pixelSize?: number;
  /**
   * Images only (an extension; IceSL does not do this): the density (%) at which `pixelSize`
   * applies. When set, the tiling is scaled by densityReference / density so density changes the
   * cell size like the shaders' density() does.
   */
  densityReference?: number;
}

export interface Infiller {
  readonly name: string;
  readonly kind: InfillerKind;
  readonly params: readonly ShaderParam[];
  readonly warnings: readonly string[];
  readonly shader?: CompiledShader;
  readonly image?: CellImage;
  /** Paths of one layer, one list per pass (images have one pass). µm, clipped, ordered. */
  pathsByPass(layer: ShaderLayerInput, opts?: InfillerOptions): Polyline[][];
  /** All passes' paths of one layer in print order. */
  paths(layer: ShaderLayerInput, opts?: InfillerOptions): Polyline[];
}

/** File contents of one infiller folder entry (`NAME/shader.glsl` or `NAME/cells.png`). */
export interface InfillerFiles {
  name: string;
  shader?: string;
  image?: Uint8Array;
}

export interface InfillerInfo {
  name: string;
  kind: InfillerKind;
  params: ShaderParam[];
  /** Passes (shaders whose numPasses is a constant; images: 1). */
  numPasses?: number;
  warnings: string[];
}

export const DEFAULT_PIXEL_SIZE = 0.1;

/** An infiller from shader source. */
export function infillerFromShader(source: string, name = 'shader', opts: CompileOptions = {}): Infiller {
  const shader = compileShader(source, { fileName: opts.fileName ?? `${name}/shader.glsl`, ...opts });
  let inst: ShaderInstance | undefined;
  const pathsByPass = (layer: ShaderLayerInput, o: InfillerOptions = {}): Polyline[][] => {
    if (inst === undefined) inst = shader.instantiate();
    return shaderPathsByPass(inst, layer, o);
  };
  return {
    name,
    kind: 'shader',
    params: shader.params,
    warnings: shader.warnings,
    shader,
    pathsByPass,
    paths: (layer, o) => pathsByPass(layer, o).flat(),
  };
}

function densityAtCentre(layer: ShaderLayerInput): number {
  const d = layer.density;
  if (d === undefined) return 20;
  if (typeof d === 'number') return d;
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (const e of layer.region) {
    for (const p of e.outer) {
      minX = Math.min(minX, p.x);
      minY = Math.min(minY, p.y);
      maxX = Math.max(maxX, p.x);
      maxY = Math.max(maxY, p.y);
    }
  }
  return d((minX + maxX) / 2000, (minY + maxY) / 2000, layer.z);
}

/** An infiller from PNG bytes. */
export function infillerFromImage(bytes: Uint8Array, name = 'image', opts: ImageLoadOptions = {}): Infiller {
  const image = loadCellImage(bytes, { fileName: opts.fileName ?? `${name}/cells.png`, ...opts });
  const pathsByPass = (layer: ShaderLayerInput, o: InfillerOptions = {}): Polyline[][] => {
    if (layer.params !== undefined && Object.keys(layer.params).length > 0) {
      throw new StrataError('BAD_SETTING', `${image.fileName}: image infillers have no parameters`);
    }
    let ps = o.pixelSize ?? DEFAULT_PIXEL_SIZE;
    if (o.densityReference !== undefined) {
      const d = Math.max(1, densityAtCentre(layer));
      ps *= o.densityReference / d;
    }
    const label = imageLabelFn(image, ps);
    // Sample at pixel centres: crossings then fall on pixel edges.
    const res = o.resolution ?? ps;
    const phase = o.phase ?? (res === ps ? 0.5 : undefined);
    return [labelBoundaries(label, layer.region, { ...o, resolution: res, phase })];
  };
  return {
    name,
    kind: 'image',
    params: [],
    warnings: image.warnings,
    image,
    pathsByPass,
    paths: (layer, o) => pathsByPass(layer, o).flat(),
  };
}

/** An infiller from one folder entry's files (shader.glsl wins if both exist). */
export function loadInfiller(files: InfillerFiles): Infiller {
  if (files.shader !== undefined) return infillerFromShader(files.shader, files.name);
  if (files.image !== undefined) return infillerFromImage(files.image, files.name);
  throw new StrataError('BAD_FILE', `infiller ${files.name}: no shader.glsl or cells.png`);
}

export function describeInfiller(inf: Infiller): InfillerInfo {
  return {
    name: inf.name,
    kind: inf.kind,
    params: inf.params.map((p) => ({ ...p })),
    numPasses: inf.kind === 'image' ? 1 : inf.shader?.numPassesConst,
    warnings: inf.warnings.slice(),
  };
}

/** Load every entry; entries that fail are reported instead of thrown. */
export function loadInfillers(entries: readonly InfillerFiles[]): {
  infillers: Infiller[];
  errors: { name: string; error: StrataError }[];
} {
  const infillers: Infiller[] = [];
  const errors: { name: string; error: StrataError }[] = [];
  for (const e of [...entries].sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0))) {
    try {
      infillers.push(loadInfiller(e));
    } catch (err) {
      if (err instanceof StrataError) errors.push({ name: e.name, error: err });
      else throw err;
    }
  }
  return { infillers, errors };
}
