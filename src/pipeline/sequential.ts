/**
 * Sequential printing ("one at a time"): the order the objects are printed in, and the checks that the
 * print head can print each one without hitting those printed before it, made before anything is sliced.
 *
 * The head is modelled as PrusaSlicer models it: a cylinder of `extruderClearanceRadius` round the nozzle,
 * `extruderClearanceHeight` tall, above which the gantry spans the whole bed. So
 * - two objects whose footprints (convex hulls) come closer than the radius would have the head of the
 *   later one run into the earlier one: refused, naming both;
 * - an object taller than the gantry height would be hit by the gantry while any later object is printed:
 *   only the last object may be that tall. The tallest such object is moved to the end; a second one is
 *   refused, naming it.
 *
 * Order: as the objects were given (the order of the files, of a 3MF's objects), but for the one tall
 * object moved to the end, as PrusaSlicer prints objects in their order in the object list.
 */
import { StrataError } from '../errors.js';
import type { Config } from '../settings/resolve.js';
import { footprintHull } from './objects.js';
import { hullDistance } from '../geometry/hull-distance.js';
import type { Mesh } from '../mesh/types.js';

export { hullDistance };

/** Clearances are checked to this much (mm): hull vertices are rounded to the µm, and arranged models lie exactly the radius apart. */
export const CLEARANCE_TOLERANCE_MM = 1e-3;

/** How far above everything printed so far the nozzle travels from one object to the next, mm. */
export const BETWEEN_OBJECTS_LIFT_MM = 2;

export interface SequenceObject {
  name: string;
  mesh: Mesh;
}

export interface Sequence {
  /** Indices of the objects in print order. */
  order: number[];
  /** Each object's footprint (convex hull, counter-clockwise, mm). */
  hulls: [number, number][][];
  /** Each object's top, mm. */
  tops: number[];
}

/** Highest Z of the vertices the mesh's triangles use, mm. */
function meshTop(mesh: Mesh): number {
  let top = 0;
  const { positions, indices } = mesh;
  for (let i = 0; i < indices.length; i++) {
    const z = positions[3 * indices[i] + 2];
    if (z > top) top = z;
  }
  return top;
}

const mm = (v: number) => String(Math.round(v * 100) / 100);

/**
 * The print order of `objects` for sequential printing, after checking that the head clears them (see the
 * file comment). Throws StrataError: OVERLAPPING_OBJECTS for two objects too close together, DOES_NOT_FIT
 * for an object too tall to be printed before another, BAD_SETTING for a raft.
 */
export function sequenceObjects(
  objects: readonly SequenceObject[],
  cfg: Pick<Config, 'extruderClearanceRadius' | 'extruderClearanceHeight' | 'adhesionType'>,
): Sequence {
  if (cfg.adhesionType === 'raft') {
    throw new StrataError(
      'BAD_SETTING',
      'sequentialPrinting cannot print a raft (one raft under every object would be in the way of the print head): choose adhesionType skirt, brim or none, or turn sequentialPrinting off',
    );
  }
  const hulls = objects.map((o) => footprintHull(o.mesh));
  const tops = objects.map((o) => meshTop(o.mesh));
  const radius = cfg.extruderClearanceRadius;
  for (let i = 0; i < objects.length; i++) {
    for (let j = i + 1; j < objects.length; j++) {
      const d = hullDistance(hulls[i], hulls[j]);
      if (d < radius - CLEARANCE_TOLERANCE_MM) {
        const apart = d <= 0 ? 'their footprints touch or overlap' : `their footprints are ${mm(d)} mm apart`;
        throw new StrataError(
          'OVERLAPPING_OBJECTS',
          `sequential printing: objects "${objects[i].name}" and "${objects[j].name}" are closer than extruderClearanceRadius (${mm(radius)} mm): ${apart}, so the print head would hit the one printed first while printing the other; move them apart (arranging leaves the radius between them) or lower extruderClearanceRadius if the head is smaller`,
        );
      }
    }
  }
  const height = cfg.extruderClearanceHeight;
  const tall = objects.map((_, i) => i).filter((i) => tops[i] > height + CLEARANCE_TOLERANCE_MM);
  const order = objects.map((_, i) => i);
  if (tall.length > 0) {
    // the tallest goes last (the first of equals); any other tall object cannot be printed before it
    const last = tall.reduce((best, i) => (tops[i] > tops[best] ? i : best), tall[0]);
    const other = tall.find((i) => i !== last);
    if (other !== undefined) {
      throw new StrataError(
        'DOES_NOT_FIT',
        `sequential printing: object "${objects[other].name}" is ${mm(tops[other])} mm tall, taller than extruderClearanceHeight (${mm(height)} mm): it does not fit under the gantry, which passes over every object printed before the last, and only one object may be printed last ("${objects[last].name}", ${mm(tops[last])} mm). Print them separately, or raise extruderClearanceHeight if the gantry is higher`,
      );
    }
    order.splice(order.indexOf(last), 1);
    order.push(last);
  }
  return { order, hulls, tops };
}

/** The Z the nozzle travels at from one object to the next: above the tallest printed so far, within the build volume. */
export function liftZ(printedTop: number, buildVolumeHeight: number): number {
  return Math.max(printedTop, Math.min(buildVolumeHeight, printedTop + BETWEEN_OBJECTS_LIFT_MM));
}
