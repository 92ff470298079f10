// Gyroid (Strata infiller, IceSL format).
// Two labels on either side of the gyroid surface sin x cos y + sin y cos z + sin z cos x = 0;
// the boundary between them (one continuous sheet in 3D) is printed.
// The gyroid has about 3.09 / period mm^2 of surface per mm^3, i.e. 2.43 / period mm of line per
// mm^2 of slice, so period = 2.43 * line width / density.

uniform float ui_scale = 1.0; // Multiplier of the period computed from the density

const float TAU = 6.283185307179586;

vec4 cellular(vec3 world) {
  float d = clamp(density(world), 2.0, 100.0) / 100.0;
  float period = ui_scale * 2.43 * nozzle_diameter() / d;
  vec3 p = world * (TAU / period);
  float f = sin(p.x) * cos(p.y) + sin(p.y) * cos(p.z) + sin(p.z) * cos(p.x);
  return f > 0.0 ? vec4(1.0, 0.3, 0.2, 1.0) : vec4(0.2, 0.4, 1.0, 1.0);
}
