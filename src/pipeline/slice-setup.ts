/**
 * What every stage of a slice reads, decided on the calling thread before anything is sliced: the print's
 * config, the plate's layers (their Z and thickness), each object's infill parameters, and for sequential
 * printing the objects' order (with the print head's clearances checked).
 */
import { StrataError } from '../errors.js';
import { usedVertexBounds } from '../mesh/prepare.js';
import { UM_PER_MM, type Pt } from '../geometry/types.js';
import type { InfillParams } from '../infill/types.js';
import type { PrintSetup } from '../regions/objects.js';
import type { Config } from '../settings/resolve.js';
import { evenLayers } from '../slice/index.js';
import type { LayerZ } from '../slice/types.js';
import { planPlateLayers } from '../slice/z-plan.js';
import type { PlacedObject, PlateSetup } from './print-setup.js';
import { sequenceObjects, type Sequence } from './sequential.js';

export interface SliceSetup {
  /** The objects, their volumes and configs. */
  setup: PrintSetup;
  /** The print's config (`setup.configs[0]`). */
  cfg: Config;
  /** The plate's layers, bottom up. */
  layers: LayerZ[];
  /** The layers are not all `layerHeight` thick (adaptive or a layer range's own height). */
  uneven: boolean;
  /** Per object, its infill parameters. */
  infillParams: InfillParams[];
  /** Sequential printing of several objects: their order and footprints; null: layer by layer. */
  sequence: Sequence | null;
}

export function sliceSetup(plate: PlateSetup): SliceSetup {
  const { setup, objects } = plate;
  const cfg = setup.configs[0];
  let height = 0;
  for (const o of objects) {
    const p = o.mesh.positions;
    for (let i = 2; i < p.length; i += 3) if (p[i] > height) height = p[i];
  }
  const layers: LayerZ[] = planPlateLayers(
    height,
    cfg,
    objects.map((o) => o.mesh),
    plate.heightRanges,
    plate.heightProfile,
  );
  if (layers.length === 0)
    throw new StrataError('EMPTY_MODEL', 'the model is thinner than the first layer: nothing to print');
  // sequential printing: the order, and the print head's clearances checked before anything is sliced
  const sequence = cfg.sequentialPrinting && objects.length > 1 ? sequenceObjects(objects, cfg) : null;
  return {
    setup,
    cfg,
    layers,
    uneven: !evenLayers(layers, cfg.layerHeight),
    infillParams: objects.map((o, k) => infillParamsFor(setup.configs[setup.objects[k].config], o)),
    sequence,
  };
}

function bedCentre(cfg: Config): Pt {
  return cfg.originAtCenter
    ? { x: 0, y: 0 }
    : { x: Math.round((cfg.buildPlateWidth / 2) * UM_PER_MM), y: Math.round((cfg.buildPlateLength / 2) * UM_PER_MM) };
}

/** Infill parameters of one object: its bounding-box centre is the pattern origin with object centering. */
function infillParamsFor(cfg: Config, object: PlacedObject): InfillParams {
  const { min, max } = usedVertexBounds(object.mesh.positions, object.mesh.indices);
  const [x0, y0] = min,
    [x1, y1] = max;
  const objCentre: Pt = { x: Math.round(((x0 + x1) / 2) * UM_PER_MM), y: Math.round(((y0 + y1) / 2) * UM_PER_MM) };
  return {
    density: cfg.infillDensity / 100,
    lineWidthUm: Math.round(cfg.lineWidthMm * UM_PER_MM),
    nozzleDiameterUm: Math.round(cfg.nozzleDiameter * UM_PER_MM),
    angle: cfg.infillAngle,
    centering: cfg.infillPatternCentering,
    origin: cfg.infillPatternCentering === 'global' ? bedCentre(cfg) : objCentre,
    connect: cfg.infillConnect,
  };
}
