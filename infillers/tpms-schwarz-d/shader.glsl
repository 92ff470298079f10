// Schwarz D (diamond) surface (Strata infiller, IceSL format).
// Two labels on either side of
//   sin x sin y sin z + sin x cos y cos z + cos x sin y cos z + cos x cos y sin z = 0;
// the boundary is printed. Schwarz D has about 3.84 / period mm^2 of surface per mm^3, i.e.
// 3.02 / period mm of line per mm^2 of slice, so period = 3.02 * line width / density.

uniform float ui_scale = 1.0; // Multiplier of the period computed from the density

const float TAU = 6.283185307179586;

vec4 cellular(vec3 world) {
  float d = clamp(density(world), 2.0, 100.0) / 100.0;
  float period = ui_scale * 3.02 * nozzle_diameter() / d;
  vec3 p = world * (TAU / period);
  vec3 s = sin(p);
  vec3 c = cos(p);
  float f = s.x * s.y * s.z + s.x * c.y * c.z + c.x * s.y * c.z + c.x * c.y * s.z;
  return f > 0.0 ? vec4(0.9, 0.2, 0.6, 1.0) : vec4(0.2, 0.8, 0.9, 1.0);
}
