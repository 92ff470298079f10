import { test } from 'node:test';
import assert from 'node:assert/strict';
import { flatteningTurn, inverse, turnAreas, turnPts } from '#strata/geometry/turn.js';

test('flatteningTurn lays the longest segment along +x', () => {
  const t = flatteningTurn([
    [
      { x: 0, y: 0 },
      { x: 100, y: 10 },
    ],
    [
      { x: 5, y: 5 },
      { x: 5005, y: 5005 },
    ],
  ]);
  assert.ok(t);
  const [a, b] = turnPts(
    [
      { x: 5, y: 5 },
      { x: 5005, y: 5005 },
    ],
    t,
  );
  assert.ok(Math.abs(a.y - b.y) <= 1 && b.x - a.x > 7000);
});

test('flatteningTurn: none for flat lines or no segments', () => {
  assert.equal(
    flatteningTurn([
      [
        { x: 0, y: 7 },
        { x: 900, y: 7 },
      ],
    ]),
    null,
  );
  assert.equal(flatteningTurn([[{ x: 3, y: 3 }]]), null);
  assert.equal(flatteningTurn([]), null);
});

test('turning there and back moves points by at most a micrometre and keeps integers', () => {
  const t = flatteningTurn([
    [
      { x: 0, y: 0 },
      { x: 300, y: 700 },
    ],
  ]);
  assert.ok(t);
  const pts = [
    { x: 123456, y: -98765 },
    { x: 0, y: 0 },
    { x: 7, y: 3 },
  ];
  const back = turnPts(turnPts(pts, t), inverse(t));
  back.forEach((p, i) => {
    assert.ok(Number.isInteger(p.x) && Number.isInteger(p.y) && !Object.is(p.x, -0) && !Object.is(p.y, -0));
    assert.ok(Math.hypot(p.x - pts[i].x, p.y - pts[i].y) <= 1.5);
  });
  const [isl] = turnAreas([{ outer: pts, holes: [pts] }], t);
  assert.equal(isl.holes.length, 1);
});
