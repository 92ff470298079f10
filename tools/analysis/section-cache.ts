/** Mesh sections (segments and spans) by height, computed once and dropped when the analysis has moved past. */
import type { Mesh } from '#strata/mesh/types.js';
import type { SectionSegments, Sectioner } from './section.js';
import { createSectioner, sectionSpans } from './section.js';
import type { Spans } from './spans.js';

export interface CachedSection {
  z: number;
  segments: SectionSegments;
  spans: Spans;
  /**
   * When the plane passes through mesh vertices (a horizontal face or a sharp change of shape exactly at this
   * height), `segments` and `spans` are taken VERTEX_NUDGE_MM below it and `above` holds the section as far above:
   * either is a fair reading of the model at this height.
   */
  above: { segments: SectionSegments; spans: Spans } | null;
}

/** Heights closer than 1e-5 mm share a cached section. */
const KEYS_PER_MM = 1e5;
/** A vertex this close to the plane (mm) makes the section ambiguous. */
const VERTEX_TOLERANCE_MM = 1e-5;
/** How far below and above an ambiguous plane the two readings are taken (mm). */
const VERTEX_NUDGE_MM = 1e-4;

export class SectionCache {
  private readonly sectioner: Sectioner;
  private readonly byKey = new Map<number, CachedSection>();
  /** Gap-closing joins and dropped open runs over the sections computed, for warnings about open meshes. */
  gapsClosed = 0;
  chainsDropped = 0;

  constructor(
    mesh: Mesh,
    private readonly cell: number,
  ) {
    this.sectioner = createSectioner(mesh);
  }

  get zMin(): number {
    return this.sectioner.zMin;
  }

  get zMax(): number {
    return this.sectioner.zMax;
  }

  get(z: number): CachedSection {
    const key = Math.round(z * KEYS_PER_MM);
    let hit = this.byKey.get(key);
    if (!hit) {
      const ambiguous = this.sectioner.touchesVertex(z, VERTEX_TOLERANCE_MM);
      const segments = this.sectioner.section(ambiguous ? z - VERTEX_NUDGE_MM : z);
      this.gapsClosed += segments.gapsClosed;
      this.chainsDropped += segments.chainsDropped;
      let above: CachedSection['above'] = null;
      if (ambiguous) {
        const up = this.sectioner.section(z + VERTEX_NUDGE_MM);
        above = { segments: up, spans: sectionSpans(up, this.cell) };
      }
      hit = { z, segments, spans: sectionSpans(segments, this.cell), above };
      this.byKey.set(key, hit);
    }
    return hit;
  }

  /** Forgets sections below height z. */
  dropBelow(z: number): void {
    for (const [key, entry] of this.byKey) if (entry.z < z) this.byKey.delete(key);
  }
}
