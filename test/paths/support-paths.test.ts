import { test } from 'node:test';
import assert from 'node:assert/strict';
import { offset, pointInArea } from '#strata/geometry/clip.js';
import { rect, square } from '../geometry/test-shapes.js';
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { supportGroups } from '#strata/paths/support-paths.js';
import type { PathGroup, PathRole } from '#strata/paths/types.js';

const layer = { index: 4, z: 1, height: 0.2, sliceZ: 0.9 };
const origin = { x: 0, y: 0 };

/** Every path of the groups with `role`, and whether each is closed. */
function pathsOf(groups: readonly PathGroup[], role: PathRole): { path: Pt[]; closed: boolean }[] {
  const out: { path: Pt[]; closed: boolean }[] = [];
  for (const g of groups)
    for (const e of g.entries) if (e.role === role) for (const path of e.paths) out.push({ path, closed: e.closed });
  return out;
}

/** Whether every point of the paths lies in `area` (grown by a micrometre for rounding). */
const allIn = (paths: readonly { path: Pt[] }[], area: readonly ExPolygon[]) => {
  const grown = offset(area, 1);
  return paths.every(({ path }) => path.every((p) => grown.some((a) => pointInArea(p, a))));
};

test('support walls go round the body only: the roof beside it is dense lines, no wall', () => {
  const cfg = resolveConfig({ supportEnabled: true, supportWallCount: 1 });
  // a 10 mm body and a 10 × 4 mm roof beside it, one support area
  const body = [rect(0, 0, 10_000, 10_000)];
  const roof = [rect(10_000, 0, 14_000, 10_000)];
  const groups = supportGroups({ body, roof, floor: [] }, cfg, layer, origin);
  const walls = pathsOf(groups, 'support').filter((p) => p.closed);
  const roofLines = pathsOf(groups, 'support-roof');
  assert.ok(walls.length >= 1, 'the body has its wall');
  assert.ok(allIn(walls, body), 'every wall lies in the body');
  assert.ok(roofLines.length > 0, 'the roof has lines');
  assert.ok(
    roofLines.every((p) => !p.closed),
    'the roof has no wall',
  );
  assert.ok(allIn(roofLines, roof), 'every roof line lies in the roof');
  // dense: the lines' length covers the roof at about the interface density (70 %)
  const w = cfg.supportLineWidthMm * 1000;
  let length = 0;
  for (const { path } of roofLines)
    for (let k = 1; k < path.length; k++) length += Math.hypot(path[k].x - path[k - 1].x, path[k].y - path[k - 1].y);
  const share = (length * w) / (4_000 * 10_000);
  assert.ok(share > 0.55 && share < 0.85, `roof lines cover ${(share * 100).toFixed(0)} % of the roof`);
});

test("a tree's straight columns are printed as normal support's body: no wall unless one is asked for", () => {
  // a tree branch's body (walled) and a column under a pocket beside it, apart
  const branch = rect(0, 0, 4_000, 4_000);
  const column = rect(10_000, 0, 20_000, 10_000);
  const areas = { body: [branch, column], roof: [], floor: [], columnBody: [column] };
  const tree = resolveConfig({ supportEnabled: true, supportType: 'tree' });
  const walls = pathsOf(supportGroups(areas, tree, layer, origin), 'support').filter((p) => p.closed);
  assert.ok(walls.length >= 1 && allIn(walls, [branch]), 'the branch has its wall, the column none');
  const lines = pathsOf(supportGroups(areas, tree, layer, origin), 'support').filter(
    (p) => !p.closed && allIn([p], [column]),
  );
  let length = 0;
  for (const { path } of lines)
    for (let k = 1; k < path.length; k++) length += Math.hypot(path[k].x - path[k - 1].x, path[k].y - path[k - 1].y);
  // sparse lines at the support density over the column's 100 mm²
  const expected = (100e6 * tree.supportDensity) / 100 / (tree.supportLineWidthMm * 1000);
  assert.ok(
    length > 0.6 * expected && length < 1.4 * expected,
    `the column's lines: ${(length / 1000).toFixed(1)} mm, ${(expected / 1000).toFixed(1)} mm expected`,
  );
  const asked = resolveConfig({ supportEnabled: true, supportType: 'tree', supportWallCount: 1 });
  const both = pathsOf(supportGroups(areas, asked, layer, origin), 'support').filter((p) => p.closed);
  assert.ok(
    both.some((p) => allIn([p], [column])),
    'with supportWallCount 1 the column has its wall too',
  );
});

test('a roof sliver that no interface line crosses is printed as its outline', () => {
  const cfg = resolveConfig({ supportEnabled: true, supportAngle: 0 });
  // interface lines on this even layer run at supportAngle + 90°, along y, w / 0.7 apart from x = 0: a strip
  // along y, 0.5 mm wide and between two of them, meets none (its middle 0.1 mm, where lines may lie, least)
  const w = cfg.supportLineWidthMm * 1000;
  const spacing = w / (cfg.supportInterfaceDensity / 100);
  const x0 = Math.round(spacing * 10 + 0.1 * spacing);
  const sliver = [rect(x0, 0, x0 + 500, 8_000)];
  const groups = supportGroups({ body: [square(0, 0, 5_000)], roof: sliver, floor: [] }, cfg, layer, origin);
  const roofPaths = pathsOf(groups, 'support-roof');
  assert.equal(roofPaths.length, 1, 'one outline');
  assert.ok(roofPaths[0].closed, 'a loop');
  assert.ok(allIn(roofPaths, sliver), 'inside the sliver');
});
