import { test } from 'node:test';
import assert from 'node:assert/strict';
import { compileShader } from '#strata/shader/shader.js';
import type { ShaderEnv } from '#strata/shader/shader.js';
import { StrataError } from '#strata/errors.js';

/** Evaluate `vec4 cellular(vec3 world) { BODY }` (after PRE) at one point; returns the colour. */
function run(body: string, pre = '', env: ShaderEnv = {}, at: [number, number, number] = [0.5, 0.25, 0.125]): number[] {
  const s = compileShader(`${pre}\nvec4 cellular(vec3 world) {\n${body}\n}\n`);
  const inst = s.instantiate();
  inst.configure(env);
  inst.label(at[0], at[1], at[2]);
  return inst.lastColor();
}

function close(actual: number[], expected: number[], eps = 1e-9): void {
  assert.equal(actual.length, expected.length);
  actual.forEach((v, i) =>
    assert.ok(Math.abs(v - expected[i]) <= eps, `component ${i}: ${v} vs ${expected[i]} (${JSON.stringify(actual)})`),
  );
}

test('swizzles, including as assignment targets', () => {
  close(run('vec4 v = vec4(1, 2, 3, 4); v.xy = v.yx; v.zw += vec2(10.0); return v;'), [2, 1, 13, 14]);
  close(run('vec4 v = vec4(0.0); v.wzyx = vec4(1, 2, 3, 4); return v;'), [4, 3, 2, 1]);
  close(run('vec3 c = vec3(0.1, 0.2, 0.3); c.bgr = c.rgb; return vec4(c.stp, 1.0);'), [0.3, 0.2, 0.1, 1]);
  close(run('vec4 v = vec4(1, 2, 3, 4); v.x = v.w; v.w = v.x; return v.xxyy + v.wwww;'), [8, 8, 6, 6]);
  close(run('vec3 p = world; p.yz = p.zy; return vec4(p, 0.0);'), [0.5, 0.125, 0.25, 0]);
  close(run('vec2 v = vec2(1, 2); int i = 1; v[i] = 5.0; return vec4(v, v[i], v[0]);'), [1, 5, 5, 1]);
  assert.throws(() => run('vec2 v; v.xx = vec2(1.0); return vec4(0.0);'), /repeated components/);
});

test('matrices: m*v, v*m, m*m, indexing, constructors', () => {
  close(run('mat2 m = mat2(1, 2, 3, 4); return vec4(m * vec2(1, 1), vec2(1, 1) * m);'), [4, 6, 3, 7]);
  close(
    run('mat2 a = mat2(1, 2, 3, 4); mat2 b = mat2(5, 6, 7, 8); mat2 c = a * b; return vec4(c[0], c[1]);'),
    [23, 34, 31, 46],
  );
  close(run('mat3 m = mat3(1.0); m[1][2] = 5.0; vec3 r = m * vec3(1, 2, 3); return vec4(r, m[1].z);'), [1, 2, 13, 5]);
  close(run('mat4 m = mat4(2.0); vec4 v = m * vec4(1, 2, 3, 4); return v * mat4(0.5);'), [1, 2, 3, 4]);
  close(
    run(
      'mat3 m = mat3(2,0,0, 0,4,0, 1,0,1); mat3 n = inverse(m) * m; return vec4(n[0][0], n[2][0], determinant(m), transpose(m)[0][2]);',
    ),
    [1, 0, 8, 1],
  );
  close(run('vec2 v = vec2(1, 0); v *= mat2(0, 1, -1, 0); return vec4(v, mat2(mat3(3.0))[1]);'), [0, -1, 0, 3]);
});

test('integer arithmetic: % ^ & | << >>, wrap-around, division', () => {
  close(run('int a = 7; int b = -7; return vec4(a % 3, b / 2, 5 ^ 3, (5 & 3) | 8);'), [1, -3, 6, 9]);
  close(run('int c = 2147483647; c += 1; return vec4(1 << 4, -16 >> 2, c, ~5);'), [16, -4, -2147483648, -6]);
  close(
    run(
      'int m = 65536 * 65536 + 3; ivec2 v = ivec2(7, 9) % 4; return vec4(m, v, 100000 * 100000 == 1410065408 ? 1 : 0);',
    ),
    [3, 3, 1, 1],
  );
  close(
    run('uint h = 0xffffffffu; h += 2u; uint s = 1u << 31; return vec4(h, s, s >> 31, float(0u - 1u));'),
    [1, 2147483648, 1, 4294967295],
  );
  close(run('int i = int(-2.7); int j = int(2.7); uint k = uint(3.9); return vec4(i, j, k, 7 / 2);'), [-2, 2, 3, 3]);
});

test('implicit int → float conversion', () => {
  close(run('float x = 3; float y = x + 1; return vec4(y, pow(2, 3), 1 / 2, 1.0 / 2);'), [4, 8, 0, 0.5]);
  close(run('vec3 v = vec3(1, 2, 3) * 2; return vec4(v, mix(0, 10, 0.5));'), [2, 4, 6, 5]);
});

test('#define, function-like macros, #ifdef / #else / #if', () => {
  const pre = [
    '#version 430',
    '#define SCALE 2.0',
    '#define SQ(x) ((x) * (x))',
    '#ifdef SCALE',
    '#define X 1.0',
    '#else',
    '#define X 2.0',
    '#endif',
    '#ifndef NOPE',
    '#define Y 3.0',
    '#endif',
    '#if defined(SCALE) && __VERSION__ >= 400',
    '#define Z 4.0',
    '#elif 1',
    '#define Z 5.0',
    '#endif',
  ].join('\n');
  close(run('return vec4(SQ(SCALE), X, Y, Z);', pre), [4, 1, 3, 4]);
  assert.throws(() => run('return vec4(0.0);', '#ifdef A\n'), /#if without #endif/);
});

test('user functions: in / out / inout parameters, overloads, vector returns', () => {
  const pre = 'void f(in float a, out float b, inout float c) { b = a * 2.0; c += 1.0; }';
  close(run('float b; float c = 1.0; f(3.0, b, c); return vec4(b, c, 0, 0);', pre), [6, 2, 0, 0]);
  const pre2 =
    'void g(out vec2 q) { q = vec2(1.0, 2.0); }\nfloat h(int x) { return 1.0; }\nfloat h(float x) { return 2.0; }';
  close(run('vec2 b; g(b.yx); return vec4(b, h(2), h(2.0));', pre2), [2, 1, 1, 2]);
  const pre3 =
    'vec3 twice(vec3 v) { return v * 2.0; }\nfloat later(float x);\nfloat use(float x) { return later(x) + 1.0; }\nfloat later(float x) { return x * 10.0; }';
  close(run('return vec4(twice(vec3(1, 2, 3)), use(2.0));', pre3), [2, 4, 6, 21]);
  const pre4 = 'void inc(inout int i) { i++; }\nint k = 0;';
  close(
    run('int a[3] = int[3](0, 0, 0); int j = 1; inc(a[j]); inc(a[j]); return vec4(a[0], a[1], a[2], 0);', pre4),
    [0, 2, 0, 0],
  );
});

test('control flow: for / while / do / if / break / continue / switch / ternary', () => {
  close(
    run(
      'int s = 0; for (int i = 0; i < 10; i++) { if (i == 2) continue; if (i == 6) break; s += i; } int w = 0; while (w < 5) w++; int d = 0; do { d += 2; } while (d < 7); return vec4(s, w, d, 0);',
    ),
    [13, 5, 8, 0],
  );
  close(
    run(
      'int s = 0; for (int i = 0; i < 3; i++) switch (i) { case 0: s += 1; break; case 1: s += 10; default: s += 100; } return vec4(s);',
    ),
    [211, 211, 211, 211],
  );
  close(run('int i = 1; float r = (i++ == 1) ? float(i) : 0.0; return vec4(r, i, i > 1 ? 5 : 6, 0);'), [2, 2, 5, 0]);
  close(
    run(
      'float x = 0.0; bool c = false && (x = 1.0) > 0.0; bool d = true || (x = 2.0) > 0.0; return vec4(x, c, d, true ^^ true);',
    ),
    [0, 0, 1, 0],
  );
  close(
    run(
      'int n = 0; for (int i = 0; i < 4; i++) for (int j = 0; j < 4; j++) { if (j > i) break; n++; } return vec4(n);',
    ),
    [10, 10, 10, 10],
  );
});

test('built-ins give GLSL values', () => {
  close(
    run('return vec4(mod(-1.0, 3.0), clamp(5.0, 0.0, 2.0), mix(0.0, 10.0, 0.25), step(0.5, 0.7));'),
    [2, 2, 2.5, 1],
  );
  close(
    run('return vec4(smoothstep(0.0, 1.0, 0.5), length(vec3(2, 3, 6)), normalize(vec2(3, 4)));'),
    [0.5, 7, 0.6, 0.8],
    1e-12,
  );
  close(run('return vec4(cross(vec3(1, 0, 0), vec3(0, 1, 0)), atan(1.0, 1.0));'), [0, 0, 1, Math.PI / 4]);
  close(
    run(
      'return vec4(reflect(vec2(1, -1), vec2(0, 1)), distance(vec2(0), vec2(3, 4)), dot(vec3(1, 2, 3), vec3(4, 5, 6)));',
    ),
    [1, 1, 5, 32],
  );
  close(run('return vec4(floor(-1.5), ceil(-1.5), fract(-0.25), sign(-3.0));'), [-2, -1, 0.75, -1]);
  close(
    run('return vec4(radians(180.0), degrees(3.141592653589793), exp2(3.0), inversesqrt(4.0));'),
    [Math.PI, 180, 8, 0.5],
    1e-12,
  );
  close(run('return vec4(min(3, 4), max(vec2(1, 5), 2.0), abs(-7));'), [3, 2, 5, 7]);
  close(
    run('bvec2 b = lessThan(vec2(1, 2), vec2(2, 1)); return vec4(any(b), all(b), float(b.y), all(not(b.yy)));'),
    [1, 0, 0, 1],
  );
  close(
    run(
      'return vec4(sin(0.5), cos(0.5), tan(0.5), asin(0.5)) - vec4(0.479425538604203, 0.8775825618903728, 0.5463024898437905, 0.5235987755982989);',
    ),
    [0, 0, 0, 0],
    1e-12,
  );
});

test('host built-ins: density(), nozzle_diameter(), layer_height()', () => {
  const env: ShaderEnv = { density: (x, y, z) => x * 100 + y * 10 + z, nozzleDiameter: 0.6, layerHeight: 0.3 };
  close(
    run('return vec4(density(world), nozzle_diameter(), layer_height(), 0.0);', '', env, [0.5, 0.25, 0.125]),
    [52.625, 0.6, 0.3, 0],
  );
});

test('globals are re-initialised for every evaluation; consts fold', () => {
  const s = compileShader(
    'float g = 1.0;\nconst float K = 2.0 * 3.0;\nvec4 cellular(vec3 world) { g = g + 1.0; return vec4(g, K, 0, 0); }',
  );
  const inst = s.instantiate();
  inst.label(0, 0, 0);
  inst.label(1, 0, 0);
  close(inst.lastColor(), [2, 6, 0, 0]);
});

test('arrays: constructors, dynamic indexing, length()', () => {
  close(
    run(
      'float a[3] = float[3](1.0, 2.0, 3.0); int i = 2; a[i] = 7.0; vec2 v[2]; v[1] = vec2(5.0); return vec4(a[0], a[i], v[1].y, a.length());',
    ),
    [1, 7, 5, 3],
  );
  close(
    run(
      'const int N = 4; float a[N]; for (int i = 0; i < N; i++) a[i] = float(i * i); return vec4(a[1], a[2], a[3], a[N - 1]);',
    ),
    [1, 4, 9, 9],
  );
});

test('u_Pass and numPasses: uniform or plain declarations', () => {
  for (const decl of ['uniform int u_Pass;', 'int u_Pass;']) {
    const s = compileShader(
      `int numPasses = 3;\n${decl}\nvec4 cellular(vec3 world) { return vec4(float(u_Pass), 0, 0, 1); }`,
    );
    const inst = s.instantiate();
    inst.configure({ pass: 2 });
    assert.equal(inst.numPasses(), 3);
    inst.label(0, 0, 0);
    close(inst.lastColor(), [2, 0, 0, 1]);
  }
  const one = compileShader('vec4 cellular(vec3 world) { return vec4(1.0); }').instantiate();
  assert.equal(one.numPasses(), 1);
});

test('ui_ parameters: parsed with type, default and tooltip; overridable', () => {
  const pre = [
    'uniform float ui_scale = 2.5; // Scale of the cells',
    'uniform int ui_count = 3 // Count, IceSL doc style;',
    'uniform bool ui_flag = true;',
  ].join('\n');
  const s = compileShader(
    `${pre}\nvec4 cellular(vec3 world) { return vec4(ui_scale, ui_count, ui_flag ? 1.0 : 0.0, 0.0); }`,
  );
  assert.deepEqual(s.params, [
    { name: 'ui_scale', type: 'float', default: 2.5, tooltip: 'Scale of the cells' },
    { name: 'ui_count', type: 'int', default: 3, tooltip: 'Count, IceSL doc style' },
    { name: 'ui_flag', type: 'bool', default: true, tooltip: '' },
  ]);
  const inst = s.instantiate();
  inst.label(0, 0, 0);
  close(inst.lastColor(), [2.5, 3, 1, 0]);
  inst.configure({ params: { scale: 4, ui_count: 7, flag: false } });
  inst.label(0, 0, 0);
  close(inst.lastColor(), [4, 7, 0, 0]);
  assert.throws(
    () => inst.configure({ params: { nope: 1 } }),
    (e: unknown) => e instanceof StrataError && /unknown infill parameter 'nope'/.test(e.message),
  );
  assert.throws(() => inst.configure({ params: { ui_count: 1.5 } }), /must be an integer/);
  assert.throws(
    () => compileShader('uniform float ui_x = abc; // bad\nvec4 cellular(vec3 w) { return vec4(1.0); }'),
    /ui_x: default value/,
  );
});

test('equal colours give equal labels, different colours different labels', () => {
  const s = compileShader(
    'vec4 cellular(vec3 world) { return world.x < 0.0 ? vec4(1, 0, 0, 1) : (world.x < 1.0 ? vec4(0, 0, 1, 1) : vec4(-0.0, 0, 1, 1)); }',
  );
  const inst = s.instantiate();
  assert.equal(inst.label(-1, 0, 0), inst.label(-2, 5, 0));
  assert.notEqual(inst.label(-1, 0, 0), inst.label(0.5, 0, 0));
  assert.equal(inst.label(0.5, 0, 0), inst.label(2, 0, 0));
});

test('compile errors name the line', () => {
  const cases: [string, RegExp][] = [
    ['vec4 cellular(vec3 world) {\n  float x = ;\n  return vec4(x);\n}', /^shader\.glsl line 2: syntax error/],
    ['vec4 cellular(vec3 world) {\n  return vec4(y);\n}', /^shader\.glsl line 2: unknown identifier 'y'/],
    [
      'vec4 cellular(vec3 world) {\n\n  float a = 1.0 % 2.0;\n  return vec4(a);\n}',
      /^shader\.glsl line 3: operator % needs integers/,
    ],
    ['vec4 notCellular(vec3 world) { return vec4(1.0); }', /must define vec4 cellular\(vec3 world\)/],
    [
      'uniform int u_Pass;\nvec4 cellular(vec3 world) {\n  u_Pass = 1;\n  return vec4(1.0);\n}',
      /line 3: cannot assign to uniform 'u_Pass'/,
    ],
    [
      'vec4 cellular(vec3 world) {\n  vec4 c = texture(s, world.xy);\n  return c;\n}',
      /line 2: texture\(\) is not available/,
    ],
  ];
  for (const [src, re] of cases) {
    assert.throws(
      () => compileShader(src),
      (e: unknown) => e instanceof StrataError && e.code === 'BAD_SHADER' && re.test(e.message),
      src,
    );
  }
});

test('line numbers survive comments, directives, continuations and inactive branches', () => {
  const src = [
    '#version 430', // 1
    '/* a block comment', // 2
    '   over two lines */', // 3
    '#define LONG(a) \\', // 4
    '  ((a) + 1.0)', // 5
    '#ifdef NOT_DEFINED', // 6
    'this is not GLSL', // 7
    '#endif', // 8
    'vec4 cellular(vec3 world) { // 9',
    '  float x = LONG(1.0);', // 10
    '  return vec4(x, missing, 0.0, 1.0);', // 11
    '}',
  ].join('\n');
  assert.throws(
    () => compileShader(src),
    (e: unknown) => e instanceof StrataError && /^shader\.glsl line 11: unknown identifier 'missing'/.test(e.message),
  );
  assert.throws(
    () => compileShader('vec4 cellular(vec3 world) {\n  return vec4(1.0)\n}', { fileName: 'foam/shader.glsl' }),
    (e: unknown) => e instanceof StrataError && /^foam\/shader\.glsl line [23]: syntax error/.test(e.message),
  );
});
