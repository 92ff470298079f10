/**
 * Where the model sits in the print's Z, and what each printed layer is. With a raft the part is raised: every
 * check reads the model's section at the part's own height, print Z minus the model's Z offset. The offset is an
 * option, or is found from the G-code: when layers with support or raft material come before the first layer
 * that prints part features, the part's second layer sits one layer height above the model's first layer height
 * (the first layer over a raft is often raised or pressed into the air gap, as CuraEngine's layer_0_z_overlap
 * does, so it does not fix the offset). Support-typed material on layers at or below the model's bottom is raft,
 * whatever its `;TYPE:` name (CuraEngine, PrusaSlicer and Strata write rafts with support names).
 *
 * Layer thicknesses are per kind of material: PrusaSlicer prints support on its own layer grid between the part's
 * layers, so the part's thickness is measured from the previous layer with part material and the support's from
 * the previous layer with support, unless the G-code declares the layer's height (`;HEIGHT:`, as PrusaSlicer and
 * Strata write): then support on a layer after one without any is as thick as declared, not down to the last.
 */
import { Feature, isPartFeature, isSupportFeature } from './feature-names.js';
import type { GcodeLayer } from './gcode-types.js';

export interface LayerFrame {
  /** Top of the layer in the model's Z: print Z minus the offset (the first layer over a raft: firstLayerHeight). */
  modelZ: number;
  /** The layer prints part features / support, interface or raft. */
  hasPart: boolean;
  hasSupport: boolean;
  /** Thickness of the part material (model Z since the previous part layer), NaN without part. */
  partThickness: number;
  /** Thickness of the support or raft material (print Z since the previous such layer), NaN without. */
  supportThickness: number;
  /** At or below the model's bottom: support-typed material here is raft. */
  raft: boolean;
  /** The first layer of the part printed over a raft: judged at the first layer's height, not on the Z grid. */
  firstOverRaft: boolean;
}

export interface ModelZ {
  /** Print Z minus model Z (mm). */
  offsetMm: number;
  source: 'option' | 'detected' | 'none';
  /** Index of the first layer printing part features above the raft, null without part. */
  firstModelLayer: number | null;
  raftLayerCount: number;
  /** Air gap from the raft's top to the bottom of the first model layer (mm), null without raft. */
  raftGapMm: number | null;
  frames: LayerFrame[];
}

export interface ModelZOptions {
  layerHeight: number;
  firstLayerHeight: number;
  zTolerance: number;
  /** Given offset (mm), or null to detect it. */
  modelZOffset: number | null;
}

/** Whether a segment of feature `code` on a layer is raft: typed raft, or support or part types on a raft layer. */
export function isRaftMaterial(code: number, frame: LayerFrame): boolean {
  return code === Feature.Raft || (frame.raft && (isSupportFeature(code) || isPartFeature(code)));
}

export function modelZFrames(layers: readonly GcodeLayer[], o: ModelZOptions): ModelZ {
  const n = layers.length;
  const hasPart = new Array<boolean>(n).fill(false);
  const hasSupport = new Array<boolean>(n).fill(false);
  for (let l = 0; l < n; l++) {
    const f = layers[l]!.extrusions.feature;
    const count = layers[l]!.extrusions.count;
    for (let i = 0; i < count; i++) {
      const c = f[i]!;
      if (isPartFeature(c)) hasPart[l] = true;
      else if (isSupportFeature(c) || c === Feature.Raft) hasSupport[l] = true;
    }
  }
  let offset = 0;
  let source: ModelZ['source'] = 'none';
  if (o.modelZOffset !== null) {
    offset = o.modelZOffset;
    source = 'option';
  } else {
    const detected = detectOffset(layers, hasPart, hasSupport, o);
    if (detected > o.zTolerance) {
      offset = detected;
      source = 'detected';
    }
  }

  const frames: LayerFrame[] = [];
  let firstModelLayer: number | null = null;
  let raftLayerCount = 0;
  let raftTop = -Infinity;
  let prevPartZ = 0;
  let prevSupportZ = 0;
  for (let l = 0; l < n; l++) {
    const z = layers[l]!.z;
    const raft = offset > o.zTolerance && z <= offset + o.zTolerance;
    const part = hasPart[l]! && !raft;
    const firstOverRaft = part && firstModelLayer === null && offset > o.zTolerance;
    if (part && firstModelLayer === null) firstModelLayer = l;
    const modelZ = firstOverRaft ? o.firstLayerHeight : z - offset;
    if (raft) {
      raftLayerCount++;
      if (hasSupport[l] || hasPart[l]) raftTop = Math.max(raftTop, z);
    }
    const frame: LayerFrame = {
      modelZ,
      hasPart: part,
      hasSupport: hasSupport[l]! || (raft && hasPart[l]!),
      partThickness: NaN,
      supportThickness: NaN,
      raft,
      firstOverRaft,
    };
    if (part) {
      frame.partThickness = modelZ - prevPartZ;
      prevPartZ = modelZ;
    }
    if (frame.hasSupport) {
      // the height the G-code declares for the layer, else the distance from the last layer with support
      frame.supportThickness = layers[l]!.declaredHeight ?? z - prevSupportZ;
      prevSupportZ = z;
    }
    frames.push(frame);
  }
  const raftGapMm =
    raftLayerCount > 0 && firstModelLayer !== null && raftTop > -Infinity
      ? Math.max(0, layers[firstModelLayer]!.z - o.firstLayerHeight - raftTop)
      : null;
  return { offsetMm: offset, source, firstModelLayer, raftLayerCount, raftGapMm, frames };
}

function detectOffset(
  layers: readonly GcodeLayer[],
  hasPart: boolean[],
  hasSupport: boolean[],
  o: ModelZOptions,
): number {
  const p0 = hasPart.indexOf(true);
  if (p0 <= 0) return 0;
  let raftBelow = false;
  for (let l = 0; l < p0; l++) if (hasSupport[l]) raftBelow = true;
  if (!raftBelow) return 0;
  const z0 = layers[p0]!.z;
  const fromFirst = z0 - o.firstLayerHeight;
  for (let l = p0 + 1; l < layers.length; l++) {
    if (!hasPart[l]) continue;
    const fromSecond = layers[l]!.z - (o.firstLayerHeight + o.layerHeight);
    // The first layer over a raft may sit higher than the grid (an air gap) but not lower.
    return z0 - fromSecond >= o.firstLayerHeight - o.zTolerance && fromSecond > 0 ? fromSecond : fromFirst;
  }
  return fromFirst;
}
