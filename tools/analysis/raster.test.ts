import { test } from 'node:test';
import assert from 'node:assert/strict';
import { countSet, gridAround, newBitmap } from './grid.js';
import { beadWidth, stampCapsule, volumeWidth } from './raster.js';

const near = (a: number, b: number, tol: number, what = '') =>
  assert.ok(Math.abs(a - b) <= tol, `${what} ${a} is not within ${tol} of ${b}`);

test('capsules cover their area at any angle', () => {
  const grid = gridAround(-10, -10, 10, 10, 0.02, 1);
  for (const angle of [0, 0.3, Math.PI / 4, Math.PI / 2, 2]) {
    const bitmap = newBitmap(grid);
    const len = 12;
    const r = 0.2;
    const dx = (Math.cos(angle) * len) / 2;
    const dy = (Math.sin(angle) * len) / 2;
    // Off the lattice's symmetry lines, so that 45° edges do not run exactly through cell centres.
    stampCapsule(bitmap, grid, 0.0137 - dx, 0.0071 - dy, 0.0137 + dx, 0.0071 + dy, r);
    near(countSet(bitmap) * 0.02 * 0.02, 2 * r * len + Math.PI * r * r, 0.1, `angle ${angle}`);
  }
  const dot = newBitmap(grid);
  stampCapsule(dot, grid, 1, 1, 1, 1, 1);
  near(countSet(dot) * 0.0004, Math.PI, 0.02, 'zero-length capsule is a disc');
});

test('bead width from extruded volume', () => {
  const area = (Math.PI * 1.75 * 1.75) / 4;
  // Cura extrudes w·h per mm: the volume width is w, the bead a little wider.
  const e = (0.4 * 0.2 * 10) / area;
  near(volumeWidth(e, 10, 0.2, area), 0.4, 1e-9);
  near(beadWidth(e, 10, 0.2, area), 0.4 + 0.2 * (1 - Math.PI / 4), 1e-9);
  // PrusaSlicer extrudes (w - h)·h + π h²/4 per mm: the bead width is w.
  const eP = (((0.45 - 0.2) * 0.2 + (Math.PI * 0.04) / 4) * 10) / area;
  near(beadWidth(eP, 10, 0.2, area), 0.45, 1e-9);
});
