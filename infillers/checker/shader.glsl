// Square grid from checker stripes (Strata infiller, IceSL format).
// Two passes: pass 0 paints stripes across the first grid direction, pass 1 across the second, so
// each pass gives long straight parallel lines and together they cross into a square grid.
// A square grid with spacing s has 2 / s mm of line per mm^2, so s = 2 * line width / density.

int numPasses = 2; // one pass per grid direction
uniform int u_Pass; // pass being rendered: 0 or 1

uniform float ui_angle = 45.0; // Grid angle in degrees
uniform float ui_scale = 1.0; // Multiplier of the spacing computed from the density

vec4 cellular(vec3 world) {
  float d = clamp(density(world), 2.0, 100.0) / 100.0;
  float spacing = ui_scale * 2.0 * nozzle_diameter() / d;
  float a = radians(ui_angle);
  // Rotate the point by -angle so the grid is rotated by +angle.
  mat2 rot = mat2(cos(a), -sin(a), sin(a), cos(a));
  vec2 q = rot * world.xy;
  float s = (u_Pass == 0) ? q.x : q.y;
  float stripe = mod(floor(s / spacing), 2.0);
  return vec4(stripe, 1.0 - stripe, float(u_Pass), 1.0);
}
