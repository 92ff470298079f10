/**
 * The whole-model passes: work that reads every layer's regions (or their outlines) at once, and so waits for
 * the regions stage to finish, then runs on the calling thread (see schedule.ts for what the workers do
 * meanwhile). Each is a `WholeModelPass` with a typed output; `runPasses` runs those a slice needs, in order:
 * - support (support/): the areas under each layer's overhangs, written onto the layers, where the raft, the
 *   skirt and the paths stage read them;
 * - lightning, the whole-model pass of an infill pattern (InfillPattern.prepare): the trees' lines on each
 *   layer, handed to the paths stage;
 * - raft (regions/raft.ts): the raft's layers under the first layer and its support, and how far the model
 *   is raised.
 * A custom infill (IceSL) fills every layer on its own: it has none.
 */
import { LENGTH_EPS_MM } from '../geometry/tolerances.js';
import type { ExPolygon, Polyline } from '../geometry/types.js';
import { PATTERNS } from '../infill/registry.js';
import type { PatternId } from '../infill/types.js';
import { layerSparse, layerTopSkin } from '../regions/layer-regions.js';
import { raftUnder, type Raft } from '../regions/raft.js';
import type { LayerOutlines, LayerRegions } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';
import { attachSupport, objectsSupport, type LayerSupport } from '../support/index.js';
import type { PassName, PassNeed } from './schedule.js';
import type { SliceSetup } from './slice-setup.js';

/** What the passes are given besides the layers. */
export interface PassSetup extends SliceSetup {
  /** The slice has a custom infill, which fills every region in place of its pattern. */
  custom: boolean;
}

/** Every layer as the regions stage left it for the passes. */
export interface PassLayers {
  /** Every layer's outlines (its full regions when those were kept). */
  outlines: LayerOutlines[];
  /** Every layer's full regions, when the schedule kept them (the passes' output is read by the model's paths). */
  regions: LayerRegions[] | null;
}

export interface WholeModelPass<Out> {
  readonly name: PassName;
  /** Whether the slice needs the pass (decided before anything is sliced). */
  needed(s: PassSetup): boolean;
  /** Whether the model's own paths read what the pass makes (else they are made before it, with the regions). */
  modelPathsWait(s: PassSetup): boolean;
  /** The pass takes long enough that the workers make the model's paths meanwhile. */
  readonly long: boolean;
  /** Run the pass over every layer, yielding between steps. */
  run(layers: PassLayers, s: PassSetup): Generator<void, Out>;
}

/** What each pass makes. */
export interface PassOutputs {
  /** Per layer, its support (written onto the layers too), null: none. */
  support: (LayerSupport | null)[];
  /** Per layer, the lines the whole-model infill pattern draws on it, µm. */
  lightning: Polyline[][];
  raft: Raft;
}

/** Whether some object gets support (on, or enforced by a volume). */
function anySupport(s: PassSetup): boolean {
  return s.setup.objects.some((o) => s.setup.configs[o.config].supportEnabled || o.enforcers.length > 0);
}

/**
 * Whether support under layer i touches it, a top Z gap of no layers (with uneven layers, a gap in mm less
 * than half the layer's height; layer -1: on any layer).
 */
function noTopGap(c: Config, s: SliceSetup, i: number): boolean {
  if (!s.uneven) return c.supportTopGapLayers === 0;
  if (c.supportZGap === null) return false;
  const half = (h: number) => h / 2 > c.supportZGap! + LENGTH_EPS_MM;
  return i >= 0 ? half(s.layers[i].height) : s.layers.some((l) => half(l.height));
}

/** The support of layer i − 1 where it holds layer i with no Z gap (skin resting on it is no bridge), µm. */
export function supportUnder(layers: readonly LayerOutlines[], i: number, s: SliceSetup): ExPolygon[] {
  const r = layers[i - 1];
  if (!r?.support) return [];
  const held = (o: number) => noTopGap(s.setup.configs[s.setup.objects[o].config], s, i);
  if (!r.supports) return held(0) ? [...r.support.body, ...r.support.roof] : [];
  return r.supports.flatMap((a, o) => (a && held(o) ? [...a.body, ...a.roof] : []));
}

const support: WholeModelPass<PassOutputs['support']> = {
  name: 'support',
  needed: anySupport,
  // skin resting on support with no top Z gap is no bridge: the paths of the layer above read the support
  modelPathsWait: (s) =>
    s.setup.objects.some((o) => {
      const c = s.setup.configs[o.config];
      return (c.supportEnabled || o.enforcers.length > 0) && noTopGap(c, s, -1);
    }),
  long: true,
  *run(layers, s) {
    const out = yield* objectsSupport(
      layers.outlines,
      s.setup.configs,
      s.setup.objects.map((o) => o.config),
    );
    attachSupport(layers.outlines, out);
    return out;
  },
};

/** The config of the first region whose pattern has a whole-model pass (lightning), if any. */
function modelInfillConfig(s: PassSetup): Config | undefined {
  if (s.custom) return undefined;
  return s.setup.configs.find((c) => !!PATTERNS[c.infillPattern as PatternId].prepare && c.infillDensity > 0);
}

const lightning: WholeModelPass<PassOutputs['lightning']> = {
  name: 'lightning',
  needed: (s) => !!modelInfillConfig(s),
  modelPathsWait: () => true,
  long: true,
  *run(layers, s) {
    const { regions } = layers;
    if (!regions) throw new Error('the lightning pass needs every layer’s regions');
    const cfg = modelInfillConfig(s)!;
    // every region printed with the pattern, with the first such region's density
    const pattern = cfg.infillPattern;
    const ofPattern =
      s.setup.configs.length === 1 ? undefined : (region: number) => s.setup.configs[region].infillPattern === pattern;
    const density = cfg.infillDensity / 100;
    const params = s.infillParams[0];
    return PATTERNS[pattern as PatternId].prepare!(
      {
        layers: regions.map((r) => ({
          layerIndex: r.index,
          zMm: r.z,
          layerHeightMm: r.height,
          region: layerSparse(r, ofPattern),
        })),
        supportNeeded: regions.map((_, i) => (i + 1 < regions.length ? layerTopSkin(regions[i + 1]) : [])),
      },
      params.density === density ? params : { ...params, density },
    );
  },
};

const raft: WholeModelPass<PassOutputs['raft']> = {
  name: 'raft',
  needed: (s) => s.cfg.adhesionType === 'raft',
  modelPathsWait: () => false,
  long: false,
  // biome-ignore lint/correctness/useYield: one call
  *run(layers, s) {
    return raftUnder(layers.outlines[0], s.cfg);
  },
};

/** Every pass, in the order they run (the raft goes round the support). */
const PASSES: { [K in PassName]: WholeModelPass<PassOutputs[K]> } = { support, lightning, raft };
const ORDER: readonly PassName[] = ['support', 'lightning', 'raft'];

/** The passes a slice needs, in order, as the schedule reads them. */
export function neededPasses(s: PassSetup): PassNeed[] {
  return ORDER.filter((name) => PASSES[name].needed(s)).map((name) => ({
    name,
    modelPathsWait: PASSES[name].modelPathsWait(s),
    long: PASSES[name].long,
  }));
}

function* runPass<K extends PassName>(
  name: K,
  layers: PassLayers,
  s: PassSetup,
  out: Partial<PassOutputs>,
): Generator<void, void> {
  out[name] = yield* PASSES[name].run(layers, s);
}

/** Run the passes, in the order given, on this thread; yields between steps. */
export function* runPasses(
  names: readonly PassName[],
  layers: PassLayers,
  s: PassSetup,
): Generator<void, Partial<PassOutputs>> {
  const out: Partial<PassOutputs> = {};
  for (const name of names) yield* runPass(name, layers, s, out);
  return out;
}
