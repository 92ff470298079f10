// Voronoi foam (Strata infiller, IceSL format).
// The infill is the set of walls between the cells of a 3D Voronoi diagram of jittered lattice
// points, so slices at successive heights close up into foam-like cells.
// Cell size follows the infill density: a slice through the foam has about 2.3 / cell mm of wall
// per mm^2, so cell = 2.3 * line width / density.

uniform float ui_jitter = 0.85; // How irregular the cells are (0 = cubic lattice, 1 = fully random)
uniform float ui_scale = 1.0; // Multiplier of the cell size computed from the density

uint mixBits(uint h) {
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

// Three pseudo-random numbers in [0, 1] for a lattice cell.
vec3 cellOffset(ivec3 c) {
  uint h = mixBits(uint(c.x) * 0x8da6b343u ^ uint(c.y) * 0xd8163841u ^ uint(c.z) * 0xcb1ab31fu);
  uint h2 = mixBits(h + 0x9e3779b9u);
  uint h3 = mixBits(h2 + 0x9e3779b9u);
  return vec3(float(h & 0xffffu), float(h2 & 0xffffu), float(h3 & 0xffffu)) / 65535.0;
}

vec4 cellular(vec3 world) {
  float d = clamp(density(world), 2.0, 100.0) / 100.0;
  float cell = ui_scale * 2.3 * nozzle_diameter() / d;
  vec3 p = world / cell;
  ivec3 base = ivec3(floor(p));
  vec3 f = p - vec3(base);
  float best = 1e9;
  ivec3 owner = base;
  for (int k = -1; k <= 1; k++) {
    for (int j = -1; j <= 1; j++) {
      for (int i = -1; i <= 1; i++) {
        ivec3 c = base + ivec3(i, j, k);
        vec3 site = vec3(i, j, k) + 0.5 + (cellOffset(c) - 0.5) * ui_jitter;
        vec3 r = site - f;
        float dd = dot(r, r);
        if (dd < best) {
          best = dd;
          owner = c;
        }
      }
    }
  }
  // The colour only has to differ between cells: use the owner's lattice coordinates.
  return vec4(vec3(owner), 1.0);
}
