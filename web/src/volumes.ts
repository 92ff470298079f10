/**
 * What an object on the plate holds besides its mesh: volumes (modifiers, negative volumes, support
 * blockers and enforcers) and layer ranges, each with settings of its own. A volume is a box, a
 * cylinder or a mesh from a file, kept as the centre and size of its bounding box in the object's own
 * coordinates (the model file's), so it turns, scales and moves with the object.
 */
import type { VolumeKind } from 'strata-slicer';
import type { Overrides } from './settings.js';
import { boxMesh, cylinderMesh, fitMesh, meshBox, type ShapeMesh } from './shapes.js';

export type { VolumeKind };
export type VolumeShape = 'box' | 'cylinder' | 'mesh';

export interface PlateVolume {
  id: number;
  kind: VolumeKind;
  name: string;
  shape: VolumeShape;
  /** Centre of its bounding box in the object's coordinates, mm. */
  centre: [number, number, number];
  /** Size of its bounding box, mm (each > 0). */
  size: [number, number, number];
  /** A mesh volume's triangles as read (what `centre` and `size` move and stretch). */
  source?: ShapeMesh;
  /** A modifier's settings (region-scoped ones). */
  settings: Overrides;
}

export interface PlateRange {
  id: number;
  /** Heights above the bed, mm: the layers whose Z lies in [fromZ, toZ). */
  fromZ: number;
  toZ: number;
  settings: Overrides;
}

export const VOLUME_KINDS: readonly VolumeKind[] = ['modifier', 'negative', 'support-blocker', 'support-enforcer'];

/** Words and colours per kind (the 3D view draws volumes translucent in these). */
export const KIND_INFO: Readonly<Record<VolumeKind, { label: string; colour: string; help: string }>> = {
  modifier: {
    label: 'Modifier',
    colour: '#e9b824',
    help: 'Inside it, the object prints with the modifier’s settings.',
  },
  negative: { label: 'Negative volume', colour: '#8c939c', help: 'Cut out of the object: nothing prints inside it.' },
  'support-blocker': { label: 'Support blocker', colour: '#e0473d', help: 'No support is generated inside it.' },
  'support-enforcer': {
    label: 'Support enforcer',
    colour: '#2f7fe0',
    help: 'Overhangs inside it get support, even with support turned off.',
  },
};

export const SHAPE_LABELS: Readonly<Record<VolumeShape, string>> = { box: 'box', cylinder: 'cylinder', mesh: 'mesh' };

/** The volume's triangles in the object's coordinates. */
export function volumeMesh(v: PlateVolume): ShapeMesh {
  if (v.shape === 'box') return boxMesh(v.centre, v.size);
  if (v.shape === 'cylinder') return cylinderMesh(v.centre, v.size);
  if (!v.source) throw new Error(`volume ${v.name} has no mesh`);
  return fitMesh(v.source, v.centre, v.size);
}

/** The centre and size of a mesh's bounding box (where a mesh volume starts). */
export function boxOf(m: ShapeMesh): { centre: [number, number, number]; size: [number, number, number] } {
  const { min, max } = meshBox(m);
  return {
    centre: [0, 1, 2].map((k) => (min[k] + max[k]) / 2) as [number, number, number],
    size: [0, 1, 2].map((k) => max[k] - min[k]) as [number, number, number],
  };
}
