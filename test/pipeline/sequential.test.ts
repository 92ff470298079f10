import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StrataError } from '#strata/errors.js';
import { box } from '../e2e/test-meshes.js';
import { hullDistance, liftZ, sequenceObjects } from '#strata/pipeline/sequential.js';

const square = (x: number, y: number, s: number): [number, number][] => [
  [x, y],
  [x + s, y],
  [x + s, y + s],
  [x, y + s],
];
const CFG = { extruderClearanceRadius: 45, extruderClearanceHeight: 20, adhesionType: 'skirt' } as const;

test('hull distance: apart side by side, apart diagonally, overlapping, one inside the other', () => {
  assert.equal(hullDistance(square(0, 0, 10), square(30, 0, 10)), 20);
  assert.ok(Math.abs(hullDistance(square(0, 0, 10), square(13, 14, 10)) - 5) < 1e-9);
  assert.equal(hullDistance(square(0, 0, 10), square(5, 5, 10)), 0);
  assert.equal(hullDistance(square(0, 0, 10), square(2, 2, 3)), 0);
  assert.equal(hullDistance(square(2, 2, 3), square(0, 0, 10)), 0);
  // a footprint's corner cut off: a triangle's hypotenuse faces the square
  assert.ok(
    Math.abs(
      hullDistance(
        [
          [0, 0],
          [10, 0],
          [0, 10],
        ],
        square(10, 10, 5),
      ) -
        Math.SQRT2 * 5,
    ) < 1e-9,
  );
});

test('order: as given, the one object taller than the gantry moved last; clearances checked', () => {
  const objects = [
    { name: 'tall', mesh: box(0, 0, 0, 10, 10, 30) },
    { name: 'a', mesh: box(60, 0, 0, 70, 10, 5) },
    { name: 'b', mesh: box(120, 0, 0, 130, 10, 20) },
  ];
  const s = sequenceObjects(objects, CFG);
  assert.deepEqual(s.order, [1, 2, 0]);
  assert.deepEqual(s.tops, [30, 5, 20]);
  assert.deepEqual(sequenceObjects(objects.slice(1), CFG).order, [0, 1]);
  // exactly the radius apart passes (arranged models are); a hair closer does not
  assert.doesNotThrow(() => sequenceObjects(objects, { ...CFG, extruderClearanceRadius: 50 }));
  assert.throws(
    () => sequenceObjects(objects, { ...CFG, extruderClearanceRadius: 50.01 }),
    (e: unknown) => e instanceof StrataError && /"tall" and "a"/.test(e.message),
  );
  assert.throws(
    () => sequenceObjects(objects, { ...CFG, extruderClearanceHeight: 19 }),
    (e: unknown) => e instanceof StrataError && e.code === 'DOES_NOT_FIT' && /"b" is 20 mm tall/.test(e.message),
  );
  assert.throws(
    () => sequenceObjects(objects, { ...CFG, adhesionType: 'raft' }),
    (e: unknown) => e instanceof StrataError && e.code === 'BAD_SETTING',
  );
});

test('the lift between objects: above the printed ones, within the build volume', () => {
  assert.equal(liftZ(10, 250), 12);
  assert.equal(liftZ(249, 250), 250);
  assert.equal(liftZ(250, 250), 250);
});
