// Honeycomb (Strata infiller, IceSL format).
// Every hexagonal cell gets its own colour; the walls between them (meeting three at a time) are
// printed. A honeycomb of side a has 2 / (sqrt(3) a) mm of wall per mm^2, so
// a = 2 * line width / (sqrt(3) * density).

uniform float ui_side = 0.0; // Hexagon side in mm (0 = computed from the density)
uniform float ui_angle = 0.0; // Rotation of the honeycomb in degrees
uniform bool ui_alternate = false; // Shift the honeycomb by half a cell on every other layer

const float SQRT3 = 1.7320508075688772;

vec4 cellular(vec3 world) {
  float d = clamp(density(world), 2.0, 100.0) / 100.0;
  float side = ui_side > 0.0 ? ui_side : 2.0 * nozzle_diameter() / (SQRT3 * d);
  float a = radians(ui_angle);
  vec2 p = mat2(cos(a), -sin(a), sin(a), cos(a)) * world.xy;
  if (ui_alternate) {
    int layer = int(floor(world.z / layer_height() + 0.5));
    if (layer % 2 == 1) p.x += 0.5 * SQRT3 * side;
  }
  // Axial coordinates of a pointy-top hexagon grid, then cube rounding.
  float q = (SQRT3 / 3.0 * p.x - p.y / 3.0) / side;
  float r = (2.0 / 3.0 * p.y) / side;
  vec3 c = vec3(q, r, -q - r);
  vec3 rc = round(c);
  vec3 diff = abs(rc - c);
  if (diff.x > diff.y && diff.x > diff.z) {
    rc.x = -rc.y - rc.z;
  } else if (diff.y > diff.z) {
    rc.y = -rc.x - rc.z;
  }
  return vec4(rc.xy, 0.0, 1.0);
}
