// Schwarz P (primitive) surface (Strata infiller, IceSL format).
// Two labels on either side of cos x + cos y + cos z = 0; the boundary is printed.
// Schwarz P has about 2.35 / period mm^2 of surface per mm^3, i.e. 1.85 / period mm of line per
// mm^2 of slice, so period = 1.85 * line width / density.

uniform float ui_scale = 1.0; // Multiplier of the period computed from the density

const float TAU = 6.283185307179586;

vec4 cellular(vec3 world) {
  float d = clamp(density(world), 2.0, 100.0) / 100.0;
  float period = ui_scale * 1.85 * nozzle_diameter() / d;
  vec3 p = world * (TAU / period);
  float f = cos(p.x) + cos(p.y) + cos(p.z);
  return f > 0.0 ? vec4(1.0, 0.8, 0.1, 1.0) : vec4(0.1, 0.6, 0.3, 1.0);
}
