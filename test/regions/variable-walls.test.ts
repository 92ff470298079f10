/**
 * Property tests of the variable-width walls (variable-walls.ts) on shapes made here: strips of every width
 * from 0.1 to 2 mm (also rotated), wedges, rings, a star, a T junction and shapes of known Arachne failures.
 * Each test measures the walls as printed: a bead is a stroke of its mean width along each segment (round
 * ends), the extruded area is Σ length × mean width over the segments, and the inner area (skin and infill)
 * counts as filled. Overlap is between beads (Σ of each path's footprint - their union), not a path with itself.
 * Tests marked todo are properties that fail on a defect of variable-walls.ts, left for a decision (TODO_*).
 *
 * STRATA_WALL_REPORT=1 prints the measured numbers; STRATA_WALL_SVG=<dir> also draws each measured shape there
 * (outline, inner area, footprints, centre lines, unfilled gaps).
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { variableWalls } from '#strata/regions/variable-walls.js';
import type { IslandWalls } from '#strata/regions/walls.js';
import { area, difference, intersection, offset, opening, strokeArea, union } from '#strata/geometry/clip.js';
import { disc, rect } from '../geometry/test-shapes.js';
import type { ExPolygon, Polygon, Pt } from '#strata/geometry/types.js';
import { resolveConfig, type Config } from '#strata/settings/resolve.js';

const REPORT = process.env.STRATA_WALL_REPORT === '1';
const report = (...args: unknown[]) => {
  if (REPORT) console.log(...args);
};

const MM = 1000;
const MM2 = MM * MM;
const CFG2 = resolveConfig({});
const CFG3 = resolveConfig({ wallCount: 3 });
const LINE_MM = CFG2.lineWidthMm;
const LINE_UM = LINE_MM * MM;
const MIN_FEATURE_MM = (CFG2.minFeatureSize / 100) * CFG2.nozzleDiameter;
const MIN_BEAD_MM = Math.max(MIN_FEATURE_MM, (CFG2.minBeadWidth / 100) * CFG2.nozzleDiameter);
const MAX_BEAD_MM = (CFG2.maxBeadWidth / 100) * CFG2.nozzleDiameter;
/** Rounding slack on a width, mm. */
const WIDTH_EPS_MM = 1e-6;

// ---------------------------------------------------------------- shapes (µm)

function rotatePt(p: Pt, deg: number, c: Pt = { x: 0, y: 0 }): Pt {
  const a = (deg * Math.PI) / 180,
    cs = Math.cos(a),
    sn = Math.sin(a);
  const dx = p.x - c.x,
    dy = p.y - c.y;
  return { x: Math.round(c.x + dx * cs - dy * sn), y: Math.round(c.y + dx * sn + dy * cs) };
}

function rotate(shape: ExPolygon, deg: number, c: Pt = { x: 0, y: 0 }): ExPolygon {
  if (deg === 0) return shape;
  return {
    outer: shape.outer.map((p) => rotatePt(p, deg, c)),
    holes: shape.holes.map((h) => h.map((p) => rotatePt(p, deg, c))),
  };
}

/** A strip `lengthMm` long and `widthMm` wide centred on the origin along x, rotated by `deg`. */
function strip(widthMm: number, deg = 0, lengthMm = 20): ExPolygon {
  const w = Math.round(widthMm * MM),
    l = lengthMm * MM;
  return rotate(rect(-l / 2, -Math.round(w / 2), l / 2, w - Math.round(w / 2)), deg);
}

/** A polygon from mm coordinates (counter-clockwise expected). */
function poly(ptsMm: readonly [number, number][], holes: readonly (readonly [number, number][])[] = []): ExPolygon {
  const ring = (r: readonly [number, number][]): Polygon =>
    r.map(([x, y]) => ({ x: Math.round(x * MM), y: Math.round(y * MM) }));
  return { outer: ring(ptsMm), holes: holes.map(ring) };
}

/** A clockwise copy of a ring (for holes). */
const cw = (ring: Polygon): Polygon => ring.slice().reverse();

/** The one island of a union (asserting there is one). */
function one(areas: ExPolygon[]): ExPolygon {
  assert.equal(areas.length, 1, 'the shape is one island');
  return areas[0];
}

// ---------------------------------------------------------------- measuring the walls

interface Bead {
  points: Pt[];
  /** Width per point, mm. */
  widths: number[];
  closed: boolean;
}

/** Every path of an island's walls with its per-point widths (mm), after checking the sets are well formed. */
function beadsOf(res: IslandWalls, lineMm = LINE_MM): Bead[] {
  const out: Bead[] = [];
  for (const set of res.walls) {
    assert.ok(set.role === 'wall' || set.role === 'wall-gap', `role ${set.role}`);
    if (set.widths) assert.equal(set.widths.length, set.paths.length, 'one width list per path');
    set.paths.forEach((path, i) => {
      const ws = set.widths?.[i] ?? null;
      if (ws) assert.equal(ws.length, path.length, 'one width per point');
      for (const p of path) assert.ok(Number.isFinite(p.x) && Number.isFinite(p.y), 'finite point');
      const widths = ws ? Array.from(ws) : path.map(() => lineMm);
      for (const w of widths) assert.ok(Number.isFinite(w), 'finite width');
      out.push({ points: path, widths, closed: set.closed });
    });
  }
  return out;
}

function dist(a: Pt, b: Pt): number {
  return Math.sqrt((a.x - b.x) ** 2 + (a.y - b.y) ** 2);
}

/** Σ over segments of length × mean width, mm². */
function extrudedMm2(beads: readonly Bead[]): number {
  let s = 0;
  for (const b of beads) {
    const n = b.points.length;
    const edges = b.closed ? n : n - 1;
    for (let e = 0; e < edges; e++) {
      const j = (e + 1) % n;
      s += (dist(b.points[e], b.points[j]) / MM) * ((b.widths[e] + b.widths[j]) / 2);
    }
  }
  return s;
}

/** Width buckets of the footprints, mm: a segment is stroked at its mean width rounded to this. */
const BUCKET_MM = 0.01;

/**
 * A bead's footprint: each segment stroked at its mean width (rounded to BUCKET_MM), round joins and ends;
 * segments of one width in a row form one polyline. A closed bead of one width is stroked as a loop.
 */
function footprint(b: Bead): ExPolygon[] {
  const n = b.points.length;
  if (n === 0) return [];
  if (n === 1) return strokeArea([[b.points[0], b.points[0]]], [], b.widths[0] * MM);
  const edges = b.closed ? n : n - 1;
  const bucket = (e: number) => Math.max(1, Math.round((b.widths[e] + b.widths[(e + 1) % n]) / 2 / BUCKET_MM));
  const byWidth = new Map<number, Pt[][]>();
  const first = bucket(0);
  let allSame = true;
  for (let e = 1; e < edges; e++) if (bucket(e) !== first) allSame = false;
  if (b.closed && allSame) return strokeArea([], [b.points], first * BUCKET_MM * MM);
  let run: Pt[] = [];
  let runBucket = -1;
  const flush = () => {
    if (run.length >= 2) {
      const list = byWidth.get(runBucket);
      if (list) list.push(run);
      else byWidth.set(runBucket, [run]);
    }
    run = [];
  };
  for (let e = 0; e < edges; e++) {
    const k = bucket(e);
    const a = b.points[e],
      c = b.points[(e + 1) % n];
    if (k !== runBucket) {
      flush();
      runBucket = k;
      run = [a];
    }
    run.push(c);
  }
  flush();
  let fp: ExPolygon[] = [];
  for (const [k, lines] of byWidth) fp = union(fp, strokeArea(lines, [], k * BUCKET_MM * MM));
  return fp;
}

interface Measure {
  shapeMm2: number;
  beads: Bead[];
  /** Per bead, its footprint. */
  prints: ExPolygon[][];
  /** Union of the footprints. */
  printed: ExPolygon[];
  innerMm2: number;
  extrudedMm2: number;
  /** (extruded + inner) / shape. */
  fill: number;
  /** (Σ footprint areas - union) / shape: beads lying on other beads. */
  overlap: number;
  /** Footprints outside the shape grown by 0.05 mm, / shape. */
  outside: number;
  /** Largest footprint area outside the shape grown by 0.05 mm, mm², one piece. */
  outsideMaxMm2: number;
  minWidth: number;
  maxWidth: number;
  lostMm2: number;
  res: IslandWalls[];
}

function measure(shape: ExPolygon, cfg: Config): Measure {
  const res = variableWalls([shape], cfg, cfg.lineWidthMm * MM);
  assert.equal(res.length, 1, 'one result per island');
  return measureWalls(shape, res[0], cfg.lineWidthMm);
}

/** The measures of one island's walls. */
function measureWalls(shape: ExPolygon, r: IslandWalls, lineMm = LINE_MM): Measure {
  const beads = beadsOf(r, lineMm);
  const prints = beads.map(footprint);
  let printed: ExPolygon[] = [];
  for (const p of prints) printed = union(printed, p);
  const shapeMm2 = area([shape]) / MM2;
  const innerMm2 = area(r.inner) / MM2;
  const ext = extrudedMm2(beads);
  let sum = 0;
  for (const p of prints) sum += area(p);
  const out = difference(printed, offset([shape], 50, 'round'));
  let minWidth = Infinity,
    maxWidth = -Infinity;
  for (const b of beads)
    for (const w of b.widths) {
      minWidth = Math.min(minWidth, w);
      maxWidth = Math.max(maxWidth, w);
    }
  return {
    shapeMm2,
    beads,
    prints,
    printed,
    innerMm2,
    extrudedMm2: ext,
    fill: (ext + innerMm2) / shapeMm2,
    overlap: (sum - area(printed)) / MM2 / shapeMm2,
    outside: area(out) / MM2 / shapeMm2,
    outsideMaxMm2: Math.max(0, ...out.map((p) => area([p]) / MM2)),
    minWidth,
    maxWidth,
    lostMm2: r.lostMm2,
    res: [r],
  };
}

/** Share of `region` covered by the footprints or the inner area (skin and infill fill it). */
function coverage(m: Measure, region: readonly ExPolygon[]): number {
  const a = area(region);
  if (a === 0) return 1;
  const filled = union(m.printed, m.res[0].inner);
  return area(intersection(region, filled)) / a;
}

/** The largest piece of `region` neither printed nor inner, after dropping slivers under 2·`sliverUm` thick, mm². */
function largestGapMm2(m: Measure, region: readonly ExPolygon[], sliverUm = 25): number {
  const filled = union(m.printed, m.res[0].inner);
  const gaps = opening(difference(region, filled), sliverUm);
  return Math.max(0, ...gaps.map((g) => area([g]) / MM2));
}

/** The part of a shape thicker than `mm` (where a disc that thick fits). */
const thickerThan = (shape: ExPolygon, mm: number): ExPolygon[] => opening([shape], (mm * MM) / 2);

const SVG_DIR = process.env.STRATA_WALL_SVG;

/** Draws a measured shape into SVG_DIR (a debugging aid, off unless STRATA_WALL_SVG is set). */
function draw(label: string, shape: ExPolygon, m: Measure): void {
  if (!SVG_DIR) return;
  const pts = shape.outer;
  const x0 = Math.min(...pts.map((p) => p.x)) - 500,
    x1 = Math.max(...pts.map((p) => p.x)) + 500;
  const y0 = Math.min(...pts.map((p) => p.y)) - 500,
    y1 = Math.max(...pts.map((p) => p.y)) + 500;
  const ring = (r: readonly Pt[]) => 'M' + r.map((p) => `${p.x} ${-p.y}`).join('L') + 'Z';
  const areaPath = (as: readonly ExPolygon[], style: string) =>
    `<path fill-rule="evenodd" ${style} d="${as.map((a) => ring(a.outer) + a.holes.map(ring).join('')).join('')}"/>`;
  const gaps = opening(difference([shape], union(m.printed, m.res[0].inner)), 25);
  const lines = m.beads
    .map(
      (b) =>
        `<path fill="none" stroke="${b.closed ? 'blue' : 'red'}" stroke-width="15" d="M${b.points.map((p) => `${p.x} ${-p.y}`).join('L')}${b.closed ? 'Z' : ''}"/>`,
    )
    .join('');
  const svg =
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${x0} ${-y1} ${x1 - x0} ${y1 - y0}" width="${Math.min(2000, (x1 - x0) / 5)}">` +
    areaPath([shape], 'fill="#eee" stroke="black" stroke-width="10"') +
    areaPath(m.res[0].inner, 'fill="#cfc"') +
    m.prints.map((p) => areaPath(p, 'fill="orange" fill-opacity="0.35" stroke="#a60" stroke-width="5"')).join('') +
    lines +
    areaPath(gaps, 'fill="magenta"') +
    '</svg>';
  mkdirSync(SVG_DIR, { recursive: true });
  writeFileSync(`${SVG_DIR}/${label.replace(/[^\w.-]+/g, '_')}.svg`, svg);
}

const f3 = (x: number) => (Number.isFinite(x) ? x.toFixed(3) : String(x));
const pct = (x: number) => `${(100 * x).toFixed(1)} %`;

function widthsInRange(m: Measure): boolean {
  return m.beads.length === 0 || (m.minWidth >= MIN_BEAD_MM - WIDTH_EPS_MM && m.maxWidth <= MAX_BEAD_MM + WIDTH_EPS_MM);
}

// ---------------------------------------------------------------- the measures themselves

test('the measures see what they should: a bead off the part, a doubled bead, a missing bead, a width out of range', () => {
  const shape = strip(0.4);
  const line = (dy: number): Pt[] => [
    { x: -9800, y: dy },
    { x: 9800, y: dy },
  ];
  const walls = (paths: Pt[][], w: number): IslandWalls => ({
    outline: shape,
    inner: [],
    lostMm2: 0,
    walls: [{ role: 'wall', wall: 0, closed: false, paths, widths: paths.map((p) => Float64Array.from(p, () => w)) }],
  });
  assert.equal(CFG2.wallCount, 2, 'default settings: two walls');
  assert.equal(CFG3.wallCount, 3);
  assert.equal(LINE_MM, 0.4);
  const good = measureWalls(shape, walls([line(0)], 0.4));
  assert.ok(good.outside < 0.001 && good.overlap < 0.001 && Math.abs(good.fill - 1) < 0.03 && widthsInRange(good));
  assert.ok(coverage(good, [shape]) > 0.98, `coverage ${pct(coverage(good, [shape]))}`);
  const off = measureWalls(shape, walls([line(300)], 0.4));
  assert.ok(off.outside > 0.5, `outside ${pct(off.outside)}`);
  const doubled = measureWalls(shape, walls([line(0), line(10)], 0.4));
  assert.ok(doubled.overlap > 0.9 && doubled.fill > 1.9, `overlap ${pct(doubled.overlap)}, fill ${pct(doubled.fill)}`);
  const none = measureWalls(shape, walls([], 0.4));
  assert.ok(coverage(none, [shape]) === 0 && largestGapMm2(none, [shape]) > 7);
  assert.ok(!widthsInRange(measureWalls(shape, walls([line(0)], 0.9))));
  assert.ok(!widthsInRange(measureWalls(shape, walls([line(0)], 0.15))));
});

// ---------------------------------------------------------------- strips

const STRIP_WIDTHS = Array.from({ length: 39 }, (_, k) => (2 + k) * 0.05).map((w) => Math.round(w * 1000) / 1000);
const ANGLES = [0, 30];
const WALLS: [string, Config][] = [
  ['2 walls', CFG2],
  ['3 walls', CFG3],
];

const stripCache = new Map<string, Measure>();
function stripMeasure(widthMm: number, deg: number, cfg: Config): Measure {
  const key = `${widthMm}/${deg}/${cfg.wallCount}`;
  let m = stripCache.get(key);
  if (!m) {
    m = measure(strip(widthMm, deg), cfg);
    stripCache.set(key, m);
  }
  return m;
}

/** Runs `check` on every strip, collects the failures, and fails once listing them all. */
function everyStrip(cfg: Config, check: (m: Measure, widthMm: number, deg: number) => string | null): void {
  const bad: string[] = [];
  for (const deg of ANGLES) {
    for (const w of STRIP_WIDTHS) {
      const m = stripMeasure(w, deg, cfg);
      const why = check(m, w, deg);
      if (why) bad.push(`${w} mm at ${deg}°: ${why}`);
    }
  }
  assert.deepEqual(bad, [], `failing strips:\n${bad.join('\n')}`);
}

for (const [name, cfg] of WALLS) {
  test(`strips 0.1-2 mm (0° and 30°), ${name}: every bead within [minBead, maxBead]; none only below minFeatureSize, reported lost`, () => {
    everyStrip(cfg, (m, w) => {
      if (m.beads.length === 0) {
        // nothing printed is right only for a strip too thin for any line, and then the loss is reported
        if (w > MIN_FEATURE_MM + 1e-9) return 'no bead at all, though thicker than minFeatureSize';
        if (!(m.lostMm2 >= 0.5 * m.shapeMm2)) return `no bead, but lostMm2 ${f3(m.lostMm2)} of ${f3(m.shapeMm2)} mm²`;
        return null;
      }
      if (!widthsInRange(m))
        return `widths ${f3(m.minWidth)}..${f3(m.maxWidth)} mm outside [${MIN_BEAD_MM}, ${MAX_BEAD_MM}]`;
      return null;
    });
  });

  /**
   * Extruded area + inner area within 8 % of the strip's, ends included. A middle line stops where the medial
   * axis does, half the strip's width w short of each end, so Σ length × width misses w²/2 per end (its round
   * end covers π/8 w² of that, but the bead's volume is length × width): w / 20 mm of the strip, 4 % for a
   * single 0.8 mm line, the worst case measured (-4.0 %, +0.9 % at most). Loops going round the ends lose
   * nothing: a mitred rectangle loop's length × width is its band's area exactly. Strips under minBeadWidth are
   * left out: their line is minBeadWidth wide by design (+32 % at 0.15 mm).
   */
  test(`strips 0.2-2 mm, ${name}: extruded + inner area within 8 % of the strip's`, () => {
    const rows: string[] = [];
    everyStrip(cfg, (m, w, deg) => {
      rows.push(`${w}@${deg}: ${pct(m.fill - 1)}`);
      if (w < MIN_BEAD_MM - 1e-9) return null;
      return Math.abs(m.fill - 1) <= 0.08
        ? null
        : `extruded ${f3(m.extrudedMm2)} + inner ${f3(m.innerMm2)} = ${pct(m.fill)} of ${f3(m.shapeMm2)} mm²`;
    });
    report(`fill error, ${name}:`, rows.join('  '));
  });

  test(`strips 0.1-2 mm, ${name}: beads overlap other beads by at most 10 % of the strip`, () => {
    const rows: string[] = [];
    everyStrip(cfg, (m, w, deg) => {
      rows.push(`${w}@${deg}: ${pct(m.overlap)}`);
      return m.overlap <= 0.1 ? null : `overlap ${pct(m.overlap)} of ${f3(m.shapeMm2)} mm²`;
    });
    report(`overlap, ${name}:`, rows.join('  '));
  });

  test(`strips 0.1-2 mm, ${name}: nothing printed beyond the strip grown by 0.05 mm (≤ 2 % of it)`, () => {
    const rows: string[] = [];
    everyStrip(cfg, (m, w, deg) => {
      rows.push(`${w}@${deg}: ${pct(m.outside)}`);
      return m.outside <= 0.02 ? null : `${pct(m.outside)} outside (largest piece ${f3(m.outsideMaxMm2)} mm²)`;
    });
    report(`outside, ${name}:`, rows.join('  '));
  });
}

/** The strip's middle line is as wide as the strip (the file comment's "as wide as the strip there"). */
test("strips 0.25-0.75 mm, one middle line: its width in the middle matches the strip within 3 % (the medial axis's accuracy)", () => {
  const rows: string[] = [];
  everyStrip(CFG2, (m, w, deg) => {
    if (w < 0.25 - 1e-9 || w > 0.75 + 1e-9) return null;
    const open = m.beads.filter((b) => !b.closed);
    if (open.length !== 1 || m.beads.length !== 1)
      return `${m.beads.length} beads, ${open.length} open: not one middle line`;
    const b = open[0];
    const mid = b.widths[Math.floor(b.widths.length / 2)];
    rows.push(`${w}@${deg}: ${f3(mid)} (${pct(mid / w - 1)})`);
    return Math.abs(mid / w - 1) <= 0.03 ? null : `middle-line width ${f3(mid)} mm on a ${w} mm strip`;
  });
  report('middle-line width:', rows.join('  '));
});

// ---------------------------------------------------------------- wedges

const WEDGES: [string, ExPolygon][] = [
  [
    'a 20 mm taper from 0 to 2 mm',
    poly([
      [0, 0],
      [20, -1],
      [20, 1],
    ]),
  ],
  [
    'a 15° wedge 20 mm long',
    poly([
      [0, 0],
      [20, -20 * Math.tan((7.5 * Math.PI) / 180)],
      [20, 20 * Math.tan((7.5 * Math.PI) / 180)],
    ]),
  ],
];

for (const [name, cfg] of WALLS) {
  for (const [shapeName, shape] of WEDGES) {
    test(`${shapeName}, ${name}: ≥ 85 % covered where thicker than 0.2 mm, widths in range, nothing outside`, () => {
      const m = measure(shape, cfg);
      draw(`${shapeName}, ${name}`, shape, m);
      const cov = coverage(m, thickerThan(shape, 0.2));
      report(
        `${shapeName}, ${name}: coverage ${pct(cov)}, outside ${pct(m.outside)}, widths ${f3(m.minWidth)}..${f3(m.maxWidth)}, fill ${pct(m.fill)}, overlap ${pct(m.overlap)}, gap ${f3(largestGapMm2(m, thickerThan(shape, 0.2)))} mm²`,
      );
      assert.ok(widthsInRange(m), `widths ${f3(m.minWidth)}..${f3(m.maxWidth)} mm`);
      assert.ok(cov >= 0.85, `coverage ${pct(cov)}`);
      assert.ok(m.outside <= 0.02, `outside ${pct(m.outside)}`);
    });
  }
}

// ---------------------------------------------------------------- rings

/** A square tube 10 mm across with walls `t` mm thick. */
function tube(t: number): ExPolygon {
  const T = Math.round(t * MM);
  return { outer: rect(0, 0, 10 * MM, 10 * MM).outer, holes: [cw(rect(T, T, 10 * MM - T, 10 * MM - T).outer)] };
}

const RINGS: [string, ExPolygon][] = [
  ...[0.3, 0.5, 1.0, 1.7].map((t): [string, ExPolygon] => [`a square tube with ${t} mm walls`, tube(t)]),
  [
    'a circular ring 0.6 mm thick',
    { outer: disc(0, 0, 5 * MM, 128).outer, holes: [cw(disc(0, 0, 4.4 * MM, 128).outer)] },
  ],
];

for (const [name, cfg] of WALLS) {
  for (const [shapeName, shape] of RINGS) {
    test(`${shapeName}, ${name}: only closed loops (≥ 3 points, not repeating the first), widths in range, area within 5 %`, () => {
      const m = measure(shape, cfg);
      draw(`${shapeName}, ${name}`, shape, m);
      report(
        `${shapeName}, ${name}: ${m.beads.length} beads (${m.beads.filter((b) => !b.closed).length} open), fill ${pct(m.fill)}, widths ${f3(m.minWidth)}..${f3(m.maxWidth)}, overlap ${pct(m.overlap)}, outside ${pct(m.outside)}, coverage ${pct(coverage(m, [shape]))}`,
      );
      assert.ok(m.beads.length > 0, 'walls');
      for (const set of m.res[0].walls) {
        assert.ok(
          set.closed,
          `wall ${set.wall}: a ring of even thickness has no open line (${set.paths.length} paths, lengths ${set.paths.map((p) => p.length).join(', ')})`,
        );
        for (const p of set.paths) {
          assert.ok(p.length >= 3, `a closed loop of ${p.length} points`);
          const a = p[0],
            b = p[p.length - 1];
          assert.ok(a.x !== b.x || a.y !== b.y, 'a closed loop repeats its first point');
        }
      }
      assert.ok(widthsInRange(m), `widths ${f3(m.minWidth)}..${f3(m.maxWidth)} mm`);
      assert.ok(
        Math.abs(m.fill - 1) <= 0.05,
        `extruded ${f3(m.extrudedMm2)} + inner ${f3(m.innerMm2)} mm² = ${pct(m.fill)} of ${f3(m.shapeMm2)} mm²`,
      );
      assert.ok(m.outside <= 0.02, `outside ${pct(m.outside)}`);
    });
  }
}

// ---------------------------------------------------------------- a star and a T junction

/** Five arms 0.5 mm wide and 8 mm long from a common centre. */
const STAR = one(union([0, 72, 144, 216, 288].map((deg) => rotate(rect(0, -250, 8 * MM, 250), deg))));
/** A 20 mm strip 0.6 mm wide with a 10 mm one of the same width standing on its middle. */
const TEE = one(union([rect(-10 * MM, -300, 10 * MM, 300), rect(-300, 0, 300, 10 * MM)]));

for (const [name, cfg] of WALLS) {
  for (const [shapeName, shape] of [
    ['a star of five 0.5 mm arms', STAR],
    ['a T junction of two 0.6 mm strips', TEE],
  ] as const) {
    test(`${shapeName}, ${name}: ≥ 90 % covered, widths in range, nothing outside`, () => {
      const m = measure(shape, cfg);
      draw(`${shapeName}, ${name}`, shape, m);
      const cov = coverage(m, [shape]);
      report(
        `${shapeName}, ${name}: coverage ${pct(cov)}, outside ${pct(m.outside)}, widths ${f3(m.minWidth)}..${f3(m.maxWidth)}, fill ${pct(m.fill)}, overlap ${pct(m.overlap)}, largest gap ${f3(largestGapMm2(m, [shape]))} mm²`,
      );
      assert.ok(widthsInRange(m), `widths ${f3(m.minWidth)}..${f3(m.maxWidth)} mm`);
      assert.ok(cov >= 0.9, `coverage ${pct(cov)}`);
      assert.ok(m.outside <= 0.02, `outside ${pct(m.outside)}`);
    });
  }
}

// ---------------------------------------------------------------- determinism

test('determinism: two calls on the same islands give deep-equal walls', () => {
  const islands = [STAR, TEE, WEDGES[0][1], tube(0.5), strip(1.3, 30)];
  for (const cfg of [CFG2, CFG3]) {
    const a = variableWalls(islands, cfg, LINE_UM);
    const b = variableWalls(islands, cfg, LINE_UM);
    assert.deepEqual(a, b);
  }
});

// ---------------------------------------------------------------- regressions: known Arachne failures

/* Failing properties, left as todo for a decision (see each test's numbers with STRATA_WALL_REPORT=1). */
const TODO_TRANSITION =
  'known limit: no blended transition from one line to two: the middle line ends in a round end facing the ' +
  "loop's round end; the hole beside it is about one round end's corner (0.035 against 0.034 mm²)";
const TODO_POINT_AXIS =
  'known limit: a piece whose medial axis is one point gets a loop half its thickness wide (or widens the walls beside ' +
  'it); under 2 × minBeadWidth that loop is a minBeadWidth dot larger than the pin, and a pocket between a small ' +
  "hole's walls and the outer walls can stay (0.11 mm²)";

/** A 6 × 6 mm block with a `t` mm fin `l` mm long standing out of its right side, centred. */
function blockWithFin(t: number, l: number, block = 6): ExPolygon {
  const B = block * MM,
    T = Math.round(t * MM),
    L = Math.round(l * MM);
  return one(union([rect(0, 0, B, B), rect(B - 10, B / 2 - Math.round(T / 2), B + L, B / 2 - Math.round(T / 2) + T)]));
}

/** Checks every regression shape shares: widths in range, nothing outside, and returns the measure. */
function regression(shape: ExPolygon, cfg: Config, label: string): Measure {
  const m = measure(shape, cfg);
  draw(label, shape, m);
  report(
    `${label}: beads ${m.beads.length}, widths ${f3(m.minWidth)}..${f3(m.maxWidth)}, fill ${pct(m.fill)}, overlap ${pct(m.overlap)}, outside ${pct(m.outside)}, coverage ${pct(coverage(m, [shape]))}, largest gap ${f3(largestGapMm2(m, [shape]))} mm², lost ${f3(m.lostMm2)} mm²`,
  );
  assert.ok(widthsInRange(m), `${label}: widths ${f3(m.minWidth)}..${f3(m.maxWidth)} mm`);
  assert.ok(m.outside <= 0.02, `${label}: ${pct(m.outside)} outside`);
  return m;
}

for (const [name, cfg] of WALLS) {
  test(`regression, ${name}: no gap where a thin fin (0.35, 0.45, 0.6 mm) meets a thick block (thin-to-thick transition)`, () => {
    for (const t of [0.35, 0.45, 0.6]) {
      const shape = blockWithFin(t, 5);
      const m = regression(shape, cfg, `fin ${t} mm on a block, ${name}`);
      // the junction: the fin's root and the block's edge beside it
      const junction = intersection([shape], [rect(5 * MM, 2 * MM, 7 * MM, 4 * MM)]);
      const cov = coverage(m, junction);
      const gap = largestGapMm2(m, junction);
      report(`  junction: coverage ${pct(cov)}, largest gap ${f3(gap)} mm²`);
      assert.ok(cov >= 0.95, `fin ${t} mm: junction ${pct(cov)} covered`);
      // a round bead end in a square corner leaves (1 - π/4)·(t/2)² (0.019 mm² at 0.6 mm): more is a gap
      assert.ok(gap <= 0.03, `fin ${t} mm: a ${f3(gap)} mm² hole at the junction`);
      assert.ok(coverage(m, [shape]) >= 0.97, `fin ${t} mm: ${pct(coverage(m, [shape]))} covered`);
    }
  });

  test(`regression, ${name}: a thin fin's line runs into the block's wall, not stopping short of it (thin-to-thick bond)`, () => {
    const bad: string[] = [];
    for (const t of [0.35, 0.45, 0.6]) {
      const shape = blockWithFin(t, 5);
      const m = measure(shape, cfg);
      // the fin's line: the open bead right of the block; the block's walls: the closed ones
      const fin = m.beads.filter((b) => !b.closed && b.points.some((p) => p.x > 7 * MM));
      const walls = m.beads.filter((b) => b.closed);
      const finPrint = union(fin.flatMap(footprint)),
        wallPrint = union(walls.flatMap(footprint));
      const bond = area(intersection(finPrint, wallPrint)) / MM2;
      const reach = Math.min(...fin.flatMap((b) => b.points.map((p) => p.x))) / MM;
      report(
        `fin ${t} mm, ${name}: line starts at x = ${f3(reach)} mm (block edge 6 mm), overlap with the walls ${f3(bond)} mm²`,
      );
      if (fin.length !== 1) bad.push(`fin ${t} mm: ${fin.length} lines`);
      else if (reach > 6 + t / 4)
        bad.push(`fin ${t} mm: its line stops ${f3(reach - 6)} mm short of the block (bond ${f3(bond)} mm²)`);
    }
    assert.deepEqual(bad, []);
  });

  test(`regression, ${name}: no gap where a strip steps from one line to two (0.6 → 1.2 mm)`, () => {
    const shape = one(union([rect(-10 * MM, -300, 0, 300), rect(-10, -600, 10 * MM, 600)]));
    const m = regression(shape, cfg, `step 0.6 → 1.2 mm, ${name}`);
    const step = intersection([shape], [rect(-1.5 * MM, -MM, 1.5 * MM, MM)]);
    const cov = coverage(m, step),
      gap = largestGapMm2(m, step);
    report(`  step: coverage ${pct(cov)}, largest gap ${f3(gap)} mm²`);
    assert.ok(cov >= 0.93, `step ${pct(cov)} covered`);
    assert.ok(gap <= 0.03, `a ${f3(gap)} mm² hole at the step`);
    assert.ok(Math.abs(m.fill - 1) <= 0.05, `fill ${pct(m.fill)}`);
  });

  test(`regression, ${name}: tiny islands (0.3 and 0.5 mm squares, 0.4 mm disc, 0.25 × 1 mm pin) do not vanish`, () => {
    const islands: [string, ExPolygon][] = [
      ['0.3 mm square', rect(0, 0, 300, 300)],
      ['0.5 mm square', rect(2 * MM, 0, 2.5 * MM, 500)],
      ['0.4 mm disc', disc(5 * MM, 0, 200, 24)],
      ['0.25 × 1 mm pin', rect(8 * MM, 0, 8.25 * MM, MM)],
    ];
    const res = variableWalls(
      islands.map(([, s]) => s),
      cfg,
      LINE_UM,
    );
    assert.equal(res.length, islands.length, 'one result per island');
    const bad: string[] = [];
    islands.forEach(([label, shape], i) => {
      const m = regression(shape, cfg, `${label}, ${name}`);
      assert.deepEqual(res[i], m.res[0], `${label}: the same walls alone as among the others`);
      const cov = coverage(m, [shape]);
      if (m.beads.length === 0) bad.push(`${label}: no bead at all (lost ${f3(m.lostMm2)} of ${f3(m.shapeMm2)} mm²)`);
      else if (cov < 0.75) bad.push(`${label}: ${pct(cov)} covered`);
    });
    assert.deepEqual(bad, []);
  });

  test(`regression, ${name}: a tiny 0.15 mm pin (thicker than minFeatureSize) gets a line, and never vanishes unreported`, {
    todo: TODO_POINT_AXIS,
  }, () => {
    const bad: string[] = [];
    for (const [label, shape] of [
      ['0.15 mm disc', disc(0, 0, 75, 16)],
      ['0.15 × 0.6 mm pin', rect(0, 0, 150, 600)],
    ] as const) {
      const m = regression(shape, cfg, `${label}, ${name}`);
      if (m.beads.length === 0 && m.lostMm2 < 0.5 * m.shapeMm2)
        bad.push(`${label}: nothing printed and lost only ${f3(m.lostMm2)} of ${f3(m.shapeMm2)} mm²`);
      else if (m.beads.length === 0)
        bad.push(
          `${label}: thicker than minFeatureSize (${MIN_FEATURE_MM} mm) but no line (lost ${f3(m.lostMm2)} mm²)`,
        );
    }
    assert.deepEqual(bad, []);
  });

  test(`regression, ${name}: a sliver thinner than minFeatureSize (0.06 mm) prints nothing and is reported lost`, () => {
    const shape = strip(0.06, 10);
    const m = regression(shape, cfg, `0.06 mm sliver, ${name}`);
    assert.equal(m.beads.length, 0, 'no bead on a sliver below minFeatureSize');
    assert.ok(m.lostMm2 >= 0.5 * m.shapeMm2, `lost ${f3(m.lostMm2)} of ${f3(m.shapeMm2)} mm²`);
  });

  test(`regression, ${name}: no zig-zag over-extrusion in slightly tapered walls (0.35 → 0.45, 0.7 → 0.9, 1.1 → 1.3 mm over 20 mm)`, () => {
    for (const [a, b] of [
      [0.7, 0.9],
      [1.1, 1.3],
      [0.35, 0.45],
    ]) {
      const shape = poly([
        [-10, -a / 2],
        [10, -b / 2],
        [10, b / 2],
        [-10, a / 2],
      ]);
      const m = regression(shape, cfg, `taper ${a} → ${b} mm, ${name}`);
      // over-extrusion: no more plastic than the taper holds, and no bead on another
      assert.ok(m.fill <= 1.03, `taper ${a} → ${b}: extruded + inner ${pct(m.fill)} of the area`);
      assert.ok(m.fill >= 0.92, `taper ${a} → ${b}: extruded + inner only ${pct(m.fill)} of the area`);
      assert.ok(m.overlap <= 0.03, `taper ${a} → ${b}: overlap ${pct(m.overlap)}`);
      // zig-zag: open lines turn no more than a few degrees along the taper (ends excepted)
      let worst = 0,
        pieces = 0;
      for (const bead of m.beads) {
        if (bead.closed) continue;
        pieces++;
        let turn = 0;
        for (let i = 1; i + 1 < bead.points.length; i++) {
          const p = bead.points[i - 1],
            q = bead.points[i],
            r = bead.points[i + 1];
          const a1 = Math.atan2(q.y - p.y, q.x - p.x),
            a2 = Math.atan2(r.y - q.y, r.x - q.x);
          let d = Math.abs(a2 - a1);
          if (d > Math.PI) d = 2 * Math.PI - d;
          turn += d;
        }
        worst = Math.max(worst, (turn * 180) / Math.PI);
      }
      report(`  taper ${a} → ${b}: ${pieces} open lines, worst total turning ${worst.toFixed(1)}°`);
      assert.ok(worst <= 45, `taper ${a} → ${b}: an open line turns ${worst.toFixed(0)}° in all (zig-zag)`);
      assert.ok(pieces <= 2, `taper ${a} → ${b}: ${pieces} open lines (fragmented middle line)`);
    }
  });

  test(`regression, ${name}: no hole where a taper's middle line turns into a loop (0.7 → 0.9 mm, one line to two)`, {
    todo: TODO_TRANSITION,
  }, () => {
    const shape = poly([
      [-10, -0.35],
      [10, -0.45],
      [10, 0.45],
      [-10, 0.35],
    ]);
    const m = measure(shape, cfg);
    const gap = largestGapMm2(m, [shape]);
    // one bead's round end in a square corner leaves (1 - π/4)·(w/2)², 0.034 mm² at 0.8 mm: more is a hole
    const corner = (1 - Math.PI / 4) * 0.4 ** 2;
    report(
      `taper 0.7 → 0.9 mm transition, ${name}: largest gap ${f3(gap)} mm² (one round end's corner ${f3(corner)} mm²)`,
    );
    assert.ok(gap <= corner, `a ${f3(gap)} mm² hole where the line meets the loop`);
  });

  test(`regression, ${name}: walls follow narrow slots (0.3 and 0.6 mm wide, 4 mm deep) instead of bridging them`, () => {
    // an 8 × 8 mm block with two slots cut in from the top
    const block = one(
      difference(
        [rect(0, 0, 8 * MM, 8 * MM)],
        [rect(2 * MM, 4 * MM, 2.3 * MM, 9 * MM), rect(5 * MM, 4 * MM, 5.6 * MM, 9 * MM)],
      ),
    );
    const m = regression(block, cfg, `slotted block, ${name}`);
    for (const [x0, x1] of [
      [2 * MM, 2.3 * MM],
      [5 * MM, 5.6 * MM],
    ]) {
      const slot = rect(x0 + 50, 4 * MM + 50, x1 - 50, 8 * MM);
      const inSlot = area(intersection(m.printed, [slot])) / MM2;
      assert.ok(inSlot <= 0.01, `${f3(inSlot)} mm² printed inside the ${(x1 - x0) / MM} mm slot`);
    }
    // the material between and beside the slots is printed
    const cov = coverage(m, [block]),
      gap = largestGapMm2(m, [block]);
    assert.ok(cov >= 0.97, `${pct(cov)} covered`);
    // a 0.8 mm bead's round end in a square pocket leaves (1 - π/4)·0.4² = 0.034 mm² in each corner
    assert.ok(gap <= 0.05, `a ${f3(gap)} mm² hole`);
  });

  test(`regression, ${name}: small holes (0.4 and 1 mm) stay open, the walls round them whole`, () => {
    const plate: ExPolygon = {
      outer: rect(0, 0, 6 * MM, 6 * MM).outer,
      holes: [cw(disc(1.5 * MM, 3 * MM, 200, 24).outer), cw(disc(4 * MM, 3 * MM, 500, 48).outer)],
    };
    const m = regression(plate, cfg, `plate with small holes, ${name}`);
    for (const [cx, r] of [
      [1.5 * MM, 200],
      [4 * MM, 500],
    ]) {
      const inHole = area(intersection(m.printed, [disc(cx, 3 * MM, r - 50, 24)])) / MM2;
      assert.ok(inHole <= 0.005, `${f3(inHole)} mm² printed inside the ${(2 * r) / MM} mm hole`);
    }
    assert.ok(coverage(m, [plate]) >= 0.97, `${pct(coverage(m, [plate]))} covered`);
  });

  test(`regression, ${name}: no pocket left where a small hole's walls meet the outer walls (1.3 mm of material between)`, {
    todo: TODO_POINT_AXIS,
  }, () => {
    const plate: ExPolygon = {
      outer: rect(0, 0, 6 * MM, 6 * MM).outer,
      holes: [cw(disc(1.5 * MM, 3 * MM, 200, 24).outer), cw(disc(4 * MM, 3 * MM, 500, 48).outer)],
    };
    const m = measure(plate, cfg);
    const neck = intersection([plate], [rect(0, 2 * MM, 1.3 * MM, 4 * MM)]);
    const gap = largestGapMm2(m, neck),
      cov = coverage(m, neck);
    report(
      `pocket by the 0.4 mm hole, ${name}: neck coverage ${pct(cov)}, largest gap ${f3(gap)} mm², lost ${f3(m.lostMm2)} mm²`,
    );
    assert.ok(
      gap <= 0.03 || m.lostMm2 >= gap,
      `a ${f3(gap)} mm² pocket in the neck, unreported (lost ${f3(m.lostMm2)} mm²)`,
    );
    assert.ok(gap <= 0.03, `a ${f3(gap)} mm² pocket in the neck (coverage ${pct(cov)})`);
  });

  test(`regression, ${name}: a very sharp 3° spike (alone and on a block) does not crash, stays inside, is covered where thicker than 0.2 mm`, () => {
    const half = 10 * Math.tan((1.5 * Math.PI) / 180);
    const spike = poly([
      [0, 0],
      [10, -half],
      [10, half],
    ]);
    const onBlock = one(union([spike, rect(10 * MM - 10, -2 * MM, 14 * MM, 2 * MM)]));
    for (const [label, shape] of [
      ['3° spike', spike],
      ['3° spike on a block', onBlock],
    ] as const) {
      const m = regression(shape, cfg, `${label}, ${name}`);
      const region = thickerThan(shape, 0.2);
      const cov = coverage(m, region);
      report(`  ${label}: coverage where thicker than 0.2 mm ${pct(cov)}`);
      assert.ok(cov >= 0.85, `${label}: ${pct(cov)} covered where thicker than 0.2 mm`);
    }
  });

  test(`regression, ${name}: a collinear duplicate point (and a zero-length edge) changes nothing`, () => {
    const clean = strip(0.6);
    const [a, b, c, d] = clean.outer;
    const mid = { x: (a.x + b.x) / 2, y: a.y };
    const dirty: ExPolygon = { outer: [a, mid, mid, { x: mid.x + 3000, y: a.y }, b, b, c, d], holes: [] };
    const m0 = regression(clean, cfg, `clean 0.6 mm strip, ${name}`);
    const m1 = regression(dirty, cfg, `0.6 mm strip with duplicate and collinear points, ${name}`);
    assert.ok(
      Math.abs(m1.extrudedMm2 / m0.extrudedMm2 - 1) <= 0.01,
      `extruded ${f3(m1.extrudedMm2)} vs ${f3(m0.extrudedMm2)} mm²`,
    );
    assert.equal(m1.beads.length, m0.beads.length, 'as many beads');
    assert.ok(coverage(m1, [dirty]) >= 0.95, `${pct(coverage(m1, [dirty]))} covered`);
  });

  test(`regression, ${name}: a short thin fin on a large part still gets its line`, () => {
    // the fin's leftover (0.45 × 1.5 mm) is smaller than the wall band's sliver margin round a 20 mm block
    const shape = blockWithFin(0.45, 1.5, 20);
    const m = regression(shape, cfg, `short fin on a 20 mm block, ${name}`);
    const fin = rect(20 * MM + 100, 9 * MM, 21.5 * MM, 11 * MM);
    const cov = coverage(m, intersection([shape], [fin]));
    assert.ok(cov >= 0.8, `the fin is ${pct(cov)} covered`);
  });
}
