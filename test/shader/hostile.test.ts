import { test } from 'node:test';
import assert from 'node:assert/strict';
import { compileShader } from '#strata/shader/shader.js';
import { StrataError } from '#strata/errors.js';
import { shaderPaths } from '#strata/shader/paths.js';

const square = [
  {
    outer: [
      { x: 0, y: 0 },
      { x: 5000, y: 0 },
      { x: 5000, y: 5000 },
      { x: 0, y: 5000 },
    ],
    holes: [],
  },
];

function isError(code: string, re: RegExp) {
  return (e: unknown) => e instanceof StrataError && e.code === code && re.test(e.message);
}

function evaluate(src: string, opts = {}): number {
  const inst = compileShader(src, opts).instantiate();
  return inst.label(1, 2, 3);
}

test('endless and huge loops are stopped with LIMIT_EXCEEDED naming the line', { timeout: 20_000 }, () => {
  const loops: [string, number][] = [
    ['vec4 cellular(vec3 world) {\n  while (true) {}\n  return vec4(1.0);\n}', 2],
    [
      'vec4 cellular(vec3 world) {\n  float s = 0.0;\n  for (int i = 0; i < 1000000000; i++) { s += 1.0; }\n  return vec4(s);\n}',
      3,
    ],
    ['vec4 cellular(vec3 world) {\n  do { } while (world.x < 1e30);\n  return vec4(1.0);\n}', 2],
    ['vec4 cellular(vec3 world) {\n  for (;;) { continue; }\n  return vec4(1.0);\n}', 2],
    [
      'vec4 cellular(vec3 world) {\n  int n = 0;\n  for (int i = 0; i < 1000; i++)\n    for (int j = 0; j < 1000; j++) n++;\n  return vec4(n);\n}',
      4,
    ],
  ];
  for (const [src, line] of loops) {
    const t = performance.now();
    assert.throws(
      () => evaluate(src),
      isError('LIMIT_EXCEEDED', new RegExp(`^shader\\.glsl line ${line}: loop ran more than 100000 iterations`)),
      src,
    );
    assert.ok(performance.now() - t < 5000);
  }
  // A smaller budget is honoured.
  assert.throws(
    () =>
      evaluate('vec4 cellular(vec3 w) { int n = 0; for (int i = 0; i < 50; i++) n++; return vec4(n); }', {
        evalBudget: 10,
      }),
    /more than 10 iterations/,
  );
});

test('exponential call trees are stopped by the call budget', { timeout: 20_000 }, () => {
  const lines = ['float f0(float x) { return x + 1.0; }'];
  for (let i = 1; i <= 40; i++) lines.push(`float f${i}(float x) { return f${i - 1}(x) + f${i - 1}(x); }`);
  lines.push('vec4 cellular(vec3 world) { return vec4(f40(world.x)); }');
  assert.throws(() => evaluate(lines.join('\n')), isError('LIMIT_EXCEEDED', /function calls and loop iterations/));
});

test('total work per layer is bounded', { timeout: 20_000 }, () => {
  const src =
    'vec4 cellular(vec3 world) { float s = 0.0; for (int i = 0; i < 5000; i++) s += world.x; return vec4(s > 1.0 ? 1.0 : 0.0); }';
  const shader = compileShader(src, { layerBudget: 2_000_000 });
  assert.throws(
    () => shaderPaths(shader, { region: square, z: 0.2 }),
    isError('LIMIT_EXCEEDED', /one layer needed more than 2000000 shader steps/),
  );
});

test('identifiers that name JS globals are plain shader variables', () => {
  const src = [
    'float process(float x) { return x * 2.0; }',
    'float constructor = 3.0;',
    'vec4 cellular(vec3 world) {',
    '  float globalThis = 2.0; float __proto__ = 4.0; float Function = 5.0; float eval = 6.0;',
    '  float toString = 1.0; float valueOf = 1.0; float require = 1.0; float window = 1.0; float M = 1.0; float R = 1.0; float B = 1.0;',
    '  return vec4(process(0.5), globalThis, constructor, __proto__ + Function + eval + toString + valueOf + require + window + M + R + B - 7.0);',
    '}',
  ].join('\n');
  const s = compileShader(src);
  for (const word of [
    'process',
    'globalThis',
    'constructor',
    '__proto__',
    'Function',
    'eval',
    'require',
    'window',
    'toString',
  ]) {
    assert.ok(!new RegExp(`\\b${word}\\b`).test(s.js), `generated code mentions ${word}`);
  }
  const inst = s.instantiate();
  inst.label(0, 0, 0);
  assert.deepEqual(inst.lastColor(), [1, 2, 3, 15]);
});

test('undeclared JS globals are unknown identifiers', () => {
  for (const name of ['process', 'globalThis', 'constructor', '__proto__', 'Function', 'M', 'R', 'Math']) {
    assert.throws(
      () => compileShader(`vec4 cellular(vec3 world) {\n  return vec4(${name});\n}`),
      isError('BAD_SHADER', new RegExp(`line 2: unknown identifier '${name.replace(/[$]/g, '\\$&')}'`)),
      name,
    );
  }
  assert.throws(
    () => compileShader('vec4 cellular(vec3 world) { return vec4(process(1.0)); }'),
    isError('BAD_SHADER', /unknown function 'process'/),
  );
  assert.throws(
    () => compileShader('vec4 cellular(vec3 world) { return vec4(constructor(1.0)); }'),
    isError('BAD_SHADER', /unknown function 'constructor'/),
  );
});

test('recursion is rejected', () => {
  assert.throws(
    () => compileShader('float f(float x) { return f(x) + 1.0; }\nvec4 cellular(vec3 w) { return vec4(f(1.0)); }'),
    isError('BAD_SHADER', /line 1: recursion is not allowed/),
  );
  assert.throws(
    () =>
      compileShader(
        'float b(float x);\nfloat a(float x) { return b(x); }\nfloat b(float x) { return a(x); }\nvec4 cellular(vec3 w) { return vec4(a(1.0)); }',
      ),
    isError('BAD_SHADER', /recursion is not allowed/),
  );
});

test('pathological sources fail cleanly', { timeout: 20_000 }, () => {
  const deep = `vec4 cellular(vec3 w) { return vec4(${'('.repeat(3000)}1.0${')'.repeat(3000)}); }`;
  assert.throws(() => compileShader(deep), isError('BAD_SHADER', /./));
  const bomb = ['#define A0 x x'];
  for (let i = 1; i <= 40; i++) bomb.push(`#define A${i} A${i - 1} A${i - 1}`);
  bomb.push('vec4 cellular(vec3 w) { float x = 1.0; return vec4(A40); }');
  assert.throws(() => compileShader(bomb.join('\n')), isError('BAD_SHADER', /macro expansion is too large/));
  const quiet = ['#define E0(x)'];
  for (let i = 1; i <= 40; i++) quiet.push(`#define E${i}(x) E${i - 1}(x) E${i - 1}(x)`);
  quiet.push('E40(1)', 'vec4 cellular(vec3 w) { return vec4(1.0); }');
  assert.throws(() => compileShader(quiet.join('\n')), isError('BAD_SHADER', /macro expansion is too complex/));
  assert.throws(
    () => compileShader(`uniform float ui_x = ${' '.repeat(200_000)}x\nvec4 cellular(vec3 w) { return vec4(1.0); }`),
    isError('BAD_SHADER', /default value/),
  );
  assert.throws(
    () => compileShader('float a[100000000];\nvec4 cellular(vec3 w) { return vec4(a[0]); }'),
    isError('BAD_SHADER', /arrays are too large/),
  );
  assert.throws(() => compileShader('x'.repeat(300_000)), isError('BAD_SHADER', /larger than/));
  assert.throws(
    () => compileShader(`/* ${'c'.repeat(50_000)} */ ${'float x;'.repeat(14_000)}`),
    isError('BAD_SHADER', /characters of code/),
  );
  assert.throws(
    () => compileShader('#include "x"\nvec4 cellular(vec3 w) { return vec4(1.0); }'),
    isError('BAD_SHADER', /line 1: #include is not supported/),
  );
  assert.throws(
    () => compileShader('struct S { float a; };\nvec4 cellular(vec3 w) { return vec4(1.0); }'),
    isError('BAD_SHADER', /structs are not supported/),
  );
  const longExpr = `vec4 cellular(vec3 w) { float x = 0.0; x = ${Array.from({ length: 2000 }, () => 'w.x').join(' + ')}; return vec4(x); }`;
  assert.throws(() => compileShader(longExpr), isError('BAD_SHADER', /nested too deeply/));
});
