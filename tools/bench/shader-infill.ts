/**
 * Shader evaluation benchmark: a Voronoi-style shader (3 × 3 neighbour cells with a hash) at one
 * million points. Run: node dist-dev/tools/bench/shader-infill.js
 */
import { compileShader } from '#strata/shader/shader.js';

const VORONOI = (hash: string) => `
${hash}
vec4 cellular(vec3 world) {
  vec2 p = world.xy / 5.0;
  vec2 i = floor(p);
  vec2 f = fract(p);
  float best = 8.0;
  vec2 owner = vec2(0.0);
  for (int y = -1; y <= 1; y++) {
    for (int x = -1; x <= 1; x++) {
      vec2 g = vec2(float(x), float(y));
      vec2 r = g + hash2(i + g) - f;
      float d = dot(r, r);
      if (d < best) { best = d; owner = i + g; }
    }
  }
  return vec4(owner, 0.0, 1.0);
}`;

const CASES: [string, string][] = [
  [
    'voronoi 3x3, integer hash',
    `vec2 hash2(vec2 p) {
  uvec2 q = uvec2(ivec2(p));
  uint h = q.x * 0x8da6b343u ^ q.y * 0xd8163841u;
  h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15;
  uint h2 = h * 0x846ca68bu; h2 ^= h2 >> 16;
  return vec2(float(h & 0xffffu), float(h2 & 0xffffu)) / 65535.0;
}`,
  ],
  [
    'voronoi 3x3, sin hash',
    `vec2 hash2(vec2 p) {
  p = vec2(dot(p, vec2(127.1, 311.7)), dot(p, vec2(269.5, 183.3)));
  return fract(sin(p) * 43758.5453);
}`,
  ],
];

function bench(name: string, src: string, points = 1_000_000): void {
  const inst = compileShader(src).instantiate();
  inst.configure({});
  const side = Math.round(Math.sqrt(points));
  let best = Infinity;
  let sink = 0;
  for (let round = 0; round < 6; round++) {
    inst.resetWork();
    const t = performance.now();
    for (let a = 0; a < side; a++) {
      const y = a * 0.0731;
      for (let b = 0; b < side; b++) sink += inst.label(b * 0.0731, y, 0.2) & 1;
    }
    best = Math.min(best, performance.now() - t);
  }
  const n = side * side;
  console.log(
    `${name}: ${n} points in ${best.toFixed(0)} ms (${(((n / best) * 1000) / 1e6).toFixed(2)} M points/s)${sink < 0 ? '' : ''}`,
  );
}

for (const [name, hash] of CASES) bench(name, VORONOI(hash));
