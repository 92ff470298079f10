/**
 * Gyroid: the section of the gyroid surface sin X·cos Y + sin Y·cos Z + sin Z·cos X = 0 at each layer's
 * height, with X, Y, Z = 2π·(position)/L. The curves are traced, not approximated: the field is sampled on
 * a grid (L/12 cells, trig only per row and column), contours are followed cell to cell (marching squares,
 * saddle cells resolved by the exact value at the cell centre), and every vertex is pulled onto the surface
 * by Newton steps along the gradient. Closed and open curves, their changing topology from layer to layer
 * and the saddle layers all come from the real surface.
 *
 * Density: averaged over Z, the section's curve length per area is κ/L with κ = 2.4587 (integrated
 * numerically: 0.39132 per unit area at L = 2π); single layers range from −6 % (Z = 0 mod π/2) to +23 %
 * (the saddle layers, Z = π/4 mod π/2), so the setting holds for the volume (densityModel 'volume').
 * The surface is rotated by (angle − 45°), so the default angle gives the usual axis-aligned gyroid.
 */
import type { InfillPattern, InfillParams } from '../types.js';
import type { Pt } from '../../geometry/types.js';
import { hypot, UM_PER_MM } from '../../geometry/types.js';
import { traceContours } from '../contour.js';
import { frameBounds } from '../geom-util.js';
import { MIN_DENSITY } from '../../geometry/tolerances.js';

/** Mean section length per area times the period (see above). */
export const GYROID_KAPPA = 2.4587;
/** Sampling cells per period: fine enough that the contour topology is right; a Newton step fixes the
 * positions (after linear interpolation on L/12 cells one step leaves vertices well under 1 µm off the
 * surface; chords between them stay within about 30 µm). */
const CELLS_PER_PERIOD = 12;
const NEWTON_STEPS = 1;

/** Gyroid period (µm) for a density. */
export function gyroidPeriod(params: InfillParams): number {
  const d = Math.min(1, Math.max(MIN_DENSITY, params.density));
  return (GYROID_KAPPA * params.lineWidthUm) / d;
}

export const gyroid: InfillPattern = {
  id: 'gyroid',
  description: 'Sections of the real gyroid surface at each layer height, traced as smooth curves.',
  densityModel: 'volume',
  zPeriodMm: (params) => gyroidPeriod(params) / UM_PER_MM,
  generate(layer, params) {
    const L = gyroidPeriod(params);
    const k = (2 * Math.PI) / L;
    const phi = ((params.angle - 45) * Math.PI) / 180,
      c = Math.cos(phi),
      s = Math.sin(phi);
    const o = params.origin;
    const Z = k * (layer.zMm - layer.layerHeightMm / 2) * UM_PER_MM;
    const sz = Math.sin(Z),
      cz = Math.cos(Z);
    const { uMin, uMax, vMin, vMax } = frameBounds(layer.region, o, phi);
    if (!(uMin <= uMax)) return { lines: [], loops: [] };
    const h = L / CELLS_PER_PERIOD;
    const u0 = (Math.floor(uMin / h) - 1) * h,
      v0 = (Math.floor(vMin / h) - 1) * h;
    const nx = Math.ceil((uMax - u0) / h) + 1,
      ny = Math.ceil((vMax - v0) / h) + 1; // cells
    const sinX = new Float64Array(nx + 1),
      cosX = new Float64Array(nx + 1);
    const sinY = new Float64Array(ny + 1),
      cosY = new Float64Array(ny + 1);
    for (let i = 0; i <= nx; i++) {
      sinX[i] = Math.sin(k * (u0 + i * h));
      cosX[i] = Math.cos(k * (u0 + i * h));
    }
    for (let j = 0; j <= ny; j++) {
      sinY[j] = Math.sin(k * (v0 + j * h));
      cosY[j] = Math.cos(k * (v0 + j * h));
    }
    const W = nx + 1;
    const F = new Float64Array(W * (ny + 1));
    for (let j = 0; j <= ny; j++) {
      for (let i = 0; i <= nx; i++) F[j * W + i] = sinX[i] * cosY[j] + sinY[j] * cz + sz * cosX[i];
    }
    const field = (u: number, v: number) =>
      Math.sin(k * u) * Math.cos(k * v) + Math.sin(k * v) * cz + sz * Math.cos(k * u);
    const newton = (u0n: number, v0n: number) => {
      let u = u0n,
        v = v0n;
      for (let it = 0; it < NEWTON_STEPS; it++) {
        const X = k * u,
          Y = k * v;
        const sX = Math.sin(X),
          cX = Math.cos(X),
          sY = Math.sin(Y),
          cY = Math.cos(Y);
        const g = sX * cY + sY * cz + sz * cX;
        const gu = k * (cX * cY - sz * sX),
          gv = k * (cY * cz - sX * sY);
        const g2 = gu * gu + gv * gv;
        if (g2 < 1e-30) break;
        let du = (g * gu) / g2,
          dv = (g * gv) / g2;
        const step = hypot(du, dv);
        if (step > h / 2) {
          du *= h / 2 / step;
          dv *= h / 2 / step;
        }
        u -= du;
        v -= dv;
      }
      return { x: u, y: v };
    };
    const contours = traceContours(
      { nx, ny, x0: u0, y0: v0, h, v: F },
      0,
      (i, j) => field(u0 + (i + 0.5) * h, v0 + (j + 0.5) * h),
      newton,
    );
    const lines: Pt[][] = contours.map((cn) => {
      const pts = cn.pts.map((q) => ({ x: o.x + q.x * c - q.y * s, y: o.y + q.x * s + q.y * c }));
      if (cn.closed) pts.push(pts[0]);
      return pts;
    });
    return { lines, loops: [], linkSpacingUm: L / 2 };
  },
};
