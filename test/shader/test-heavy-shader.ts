/** For tests: a custom infill shader that spends tens of thousands of steps on every point, so one layer takes tens of seconds (within its budgets). */
export const HEAVY_SHADER = `// a shader that spends a long time on every point (within its budgets)
vec4 cellular(vec3 world) {
  float s = 0.0;
  for (int i = 0; i < 90000; i++) {
    s += sin(float(i) * 0.001 + world.x);
  }
  return vec4(floor(world.x / 4.0 + s * 1e-9), floor(world.y / 4.0), 0.0, 1.0);
}
`;
