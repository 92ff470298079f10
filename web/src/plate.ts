/**
 * The objects on the build plate: each one's file (or a project's mesh), turn, scale and place, and its
 * own settings, volumes and layer ranges; arranging them without overlap, and what is wrong with where
 * they stand. An object alone that the user has not moved stands where `strata slice` would put it, and
 * is sliced as read, so the G-code is the CLI's.
 */
import {
  ARRANGE_GAP_MM,
  IDENTITY_LINEAR,
  arrange,
  axisRotation,
  findSpot,
  footprintsOverlap,
  linearBounds,
  multiplyLinear,
  placementAffine,
  rotationBetween,
  type Bed,
  type Box,
  type Config,
  type PlacedFootprint,
  type Placement,
} from 'strata-slicer';
import { mm1 } from './format.js';
import type { LoadedModel, SliceItem, SliceVolume } from './protocol.js';
import type { Overrides } from './settings.js';
import { volumeMesh, type PlateRange, type PlateVolume } from './volumes.js';

export interface PlateItem {
  id: number;
  fileName: string;
  /** The file name without its extension (as the CLI names the G-code), or the project's object name. */
  name: string;
  /** The file as read; null for an object from a project, sliced from `model`'s mesh. */
  bytes: ArrayBuffer | null;
  model: LoadedModel;
  /** The object's own settings (object- and region-scoped ones), over the print's. */
  settings: Overrides;
  volumes: PlateVolume[];
  layerRanges: PlateRange[];
  /** A project's variable layer height profile (z0, h0, z1, h1, … mm from the object's bottom). */
  layerHeightProfile?: number[];
  /** Turns from "rotate 90°" and "lay on face", row-major 3×3. */
  rotation: number[];
  /** Turn about Z, degrees, applied after `rotation`. */
  turnZ: number;
  /** Uniform scale factor. */
  scale: number;
  /** Bed XY under the centre of the placed bounding box, mm. */
  center: [number, number];
  /** Bounds after rotation and scale (cached; follows `linear`). */
  box: Box;
}

/** The bed as the settings describe it. */
export interface BedShape {
  width: number;
  depth: number;
  height: number;
  originAtCenter: boolean;
  /** Whether a lone model is centred (the `center` setting). */
  centre: boolean;
  /** Gap Arrange and new objects keep between objects, mm: the print head's clearance radius with sequential printing. */
  gap: number;
}

export function bedShape(cfg: Config): BedShape {
  const gap = cfg.sequentialPrinting ? Math.max(ARRANGE_GAP_MM, cfg.extruderClearanceRadius) : ARRANGE_GAP_MM;
  return {
    width: cfg.buildPlateWidth,
    depth: cfg.buildPlateLength,
    height: cfg.buildVolumeHeight,
    originAtCenter: cfg.originAtCenter,
    centre: cfg.center,
    gap,
  };
}

export function bedCentre(b: BedShape): [number, number] {
  return b.originAtCenter ? [0, 0] : [b.width / 2, b.depth / 2];
}

/** Tolerance for "fits the bed", mm (as the slicer's placement allows). */
const FIT_MM = 1e-3;

export class Plate {
  items: PlateItem[] = [];
  selected: PlateItem | null = null;
  #nextId = 1;
  constructor(public bed: BedShape) {}

  linear(it: PlateItem): number[] {
    const m = it.turnZ === 0 ? it.rotation : multiplyLinear(axisRotation('z', it.turnZ), it.rotation);
    return it.scale === 1 ? [...m] : m.map((v) => v * it.scale);
  }

  /** Bed XY where `strata slice` puts this model: the bed centre, or its own XY without centring. */
  defaultCentre(it: PlateItem): [number, number] {
    if (this.bed.centre) return bedCentre(this.bed);
    const b = linearBounds(it.model.vertices);
    return [(b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2];
  }

  #footprint(it: PlateItem): PlacedFootprint {
    return { width: it.box.max[0] - it.box.min[0], depth: it.box.max[1] - it.box.min[1], center: it.center };
  }

  #bedRect(): Bed {
    return { center: bedCentre(this.bed), width: this.bed.width, depth: this.bed.depth };
  }

  /**
   * A model on the plate: a file (`bytes`), or an object of a project (`bytes` null); `at` 'own': it
   * stands where its own coordinates put it (a project's objects, as placed when saved).
   */
  add(fileName: string, bytes: ArrayBuffer | null, model: LoadedModel, at?: 'own', name?: string): PlateItem {
    const base = fileName.split(/[\\/]/).pop() ?? fileName;
    const dot = base.lastIndexOf('.');
    const it: PlateItem = {
      id: this.#nextId++,
      fileName,
      name: name ?? (dot > 0 ? base.slice(0, dot) : base),
      bytes,
      model,
      settings: {},
      volumes: [],
      layerRanges: [],
      rotation: [...IDENTITY_LINEAR],
      turnZ: 0,
      scale: 1,
      center: [0, 0],
      box: linearBounds(model.vertices),
    };
    if (at === 'own') it.center = [(it.box.min[0] + it.box.max[0]) / 2, (it.box.min[1] + it.box.max[1]) / 2];
    else if (this.items.length === 0) it.center = this.defaultCentre(it);
    else {
      const size = this.#footprint(it);
      it.center =
        findSpot(
          size,
          this.items.map((o) => this.#footprint(o)),
          this.#bedRect(),
          this.bed.gap,
        ) ?? bedCentre(this.bed);
    }
    this.items.push(it);
    this.selected = it;
    return it;
  }

  remove(it: PlateItem): void {
    this.items = this.items.filter((o) => o !== it);
    if (this.selected === it) this.selected = this.items[this.items.length - 1] ?? null;
    if (this.items.length === 1) this.#toDefaultIfUntouched(this.items[0]);
  }

  /** A lone, unturned, unscaled object goes back to where the CLI would put it. */
  #toDefaultIfUntouched(it: PlateItem): void {
    if (it.bytes && it.scale === 1 && it.turnZ === 0 && it.rotation.every((v, i) => v === IDENTITY_LINEAR[i]))
      it.center = this.defaultCentre(it);
  }

  /** Every object re-placed without overlap (one alone goes where the CLI puts it). */
  arrange(): void {
    if (this.items.length === 1) {
      const it = this.items[0];
      it.center = this.isUntransformed(it) ? this.defaultCentre(it) : bedCentre(this.bed);
      return;
    }
    const centres = arrange(
      this.items.map((it) => this.#footprint(it)),
      this.#bedRect(),
      this.bed.gap,
    );
    this.items.forEach((it, i) => (it.center = centres[i]));
  }

  isUntransformed(it: PlateItem): boolean {
    return it.scale === 1 && it.turnZ === 0 && it.rotation.every((v, i) => v === IDENTITY_LINEAR[i]);
  }

  /** The bed changed (printer or settings): keep a lone untouched object where the CLI would put it. */
  setBed(bed: BedShape): void {
    const wasDefault = this.items.length === 1 && this.isDefault(this.items[0]);
    this.bed = bed;
    if (wasDefault) this.items[0].center = this.defaultCentre(this.items[0]);
  }

  /** Stands exactly where and as `strata slice` would put it: sliced from the file as read. */
  isDefault(it: PlateItem): boolean {
    const d = this.defaultCentre(it);
    return (
      this.items.length === 1 &&
      it.bytes !== null &&
      this.isUntransformed(it) &&
      it.center[0] === d[0] &&
      it.center[1] === d[1]
    );
  }

  /** Rotation, scale or "lay on face" changed: bounds follow, the footprint centre stays. */
  relinear(it: PlateItem): void {
    it.box = linearBounds(it.model.vertices, this.linear(it));
  }

  rotate(it: PlateItem, axis: 'x' | 'y', deg: number): void {
    it.rotation = multiplyLinear(axisRotation(axis, deg), it.rotation);
    this.relinear(it);
  }

  /** Turn the object so the face with this normal (model coordinates) lies on the bed. */
  layOnFace(it: PlateItem, normal: readonly number[]): void {
    const r = it.rotation;
    const n = [0, 1, 2].map((i) => r[i * 3] * normal[0] + r[i * 3 + 1] * normal[1] + r[i * 3 + 2] * normal[2]);
    const len = Math.hypot(n[0], n[1], n[2]) || 1;
    it.rotation = multiplyLinear(
      rotationBetween(
        n.map((v) => v / len),
        [0, 0, -1],
      ),
      it.rotation,
    );
    this.relinear(it);
  }

  reset(it: PlateItem): void {
    it.rotation = [...IDENTITY_LINEAR];
    it.turnZ = 0;
    it.scale = 1;
    this.relinear(it);
    if (this.items.length === 1) it.center = this.defaultCentre(it);
  }

  placement(it: PlateItem): Placement {
    return { linear: this.linear(it), center: [it.center[0], it.center[1]] };
  }

  /** The model → bed transform the page draws with (and the worker slices with). */
  affine(it: PlateItem): Float64Array {
    return placementAffine(this.placement(it), it.box);
  }

  size(it: PlateItem): [number, number, number] {
    return [0, 1, 2].map((k) => it.box.max[k] - it.box.min[k]) as [number, number, number];
  }

  /** What is wrong with where the object stands, in words (empty: nothing). */
  problems(it: PlateItem): string[] {
    const out: string[] = [];
    const [sx, sy, sz] = this.size(it);
    const [x0, y0] = this.bed.originAtCenter ? [-this.bed.width / 2, -this.bed.depth / 2] : [0, 0];
    const minX = it.center[0] - sx / 2,
      maxX = it.center[0] + sx / 2,
      minY = it.center[1] - sy / 2,
      maxY = it.center[1] + sy / 2;
    if (sx > this.bed.width + FIT_MM || sy > this.bed.depth + FIT_MM)
      out.push(`${mm1(sx)} × ${mm1(sy)} mm is larger than the ${this.bed.width} × ${this.bed.depth} mm bed`);
    else if (
      minX < x0 - FIT_MM ||
      maxX > x0 + this.bed.width + FIT_MM ||
      minY < y0 - FIT_MM ||
      maxY > y0 + this.bed.depth + FIT_MM
    )
      out.push('reaches off the bed');
    if (sz > this.bed.height + FIT_MM) out.push(`${mm1(sz)} mm tall, the printer reaches ${this.bed.height} mm`);
    for (const o of this.items)
      if (o !== it && footprintsOverlap(this.#footprint(it), this.#footprint(o))) out.push(`overlaps ${o.name}`);
    return out;
  }

  /**
   * What the worker slices: an object in its CLI place goes as read, any other with its placement; each
   * with its settings, volumes (meshes in the model's coordinates) and layer ranges.
   */
  sliceItems(): SliceItem[] {
    return this.items.map((it) => ({
      name: it.name,
      fileName: it.fileName,
      bytes: it.bytes,
      mesh: it.bytes ? null : { positions: it.model.vertices, indices: it.model.indices },
      placement: this.isDefault(it) ? null : this.placement(it),
      settings: { ...it.settings },
      volumes: it.volumes.map((v) => {
        const out: SliceVolume = { type: v.kind, name: v.name, mesh: volumeMesh(v) };
        if (v.kind === 'modifier' && Object.keys(v.settings).length) out.settings = { ...v.settings };
        return out;
      }),
      layerRanges: it.layerRanges.map((r) => ({ fromZ: r.fromZ, toZ: r.toZ, settings: { ...r.settings } })),
      ...(it.layerHeightProfile ? { layerHeightProfile: it.layerHeightProfile } : {}),
    }));
  }

  /** The object's bounds in its own coordinates (before turning and scaling). */
  modelBox(it: PlateItem): Box {
    return linearBounds(it.model.vertices);
  }

  /** The reference of a volume's position fields in the object's coordinates: its box's centre in X and Y, its bottom in Z. */
  origin(it: PlateItem): [number, number, number] {
    const b = this.modelBox(it);
    return [(b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2, b.min[2]];
  }

  /** The G-code's file name: the first model's, as `strata slice` names it. */
  gcodeName(): string {
    return `${this.items[0]?.name ?? 'model'}.gcode`;
  }
}
