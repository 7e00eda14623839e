// Virtual planes (Dobashi et al. 2000): instance k is the plane at view depth
// zNear + (k + jitter) * dz of one beam, drawn only over the beam's screen footprint.
// LATTICE: the paper's own form: the plane is a grid of uLattice cells whose corners (the
// lattice points) evaluate the in-scattering, and the rasteriser interpolates between them.
#include "interface.h"

// The footprint's bounding rectangle (x0, y0, x1, y1 in NDC), and the footprint itself, a convex
// polygon drawn as a triangle fan.
layout(location = HAZE_LOC_PLANES_RECT_NDC) uniform vec4 uRectNdc;
layout(location = HAZE_LOC_PLANES_POLYGON_NDC) uniform vec2 uPolygonNdc[HAZE_FOOTPRINT_MAX_VERTICES];
flat out int vPlane;

#ifdef LATTICE
#include "scatter.glsl"
out vec3 vScatter;
out float vDepth;
#endif

void main() {
#ifdef LATTICE
  // Two triangles per cell; vertex c of cell (i, j).
  int cell = gl_VertexID / 6, c = gl_VertexID % 6;
  const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
  ivec2 ij = ivec2(cell % uLattice.x, cell / uLattice.x) + corners[c];
  vec2 corner = vec2(ij) / vec2(uLattice);
  vec2 p = mix(uRectNdc.xy, uRectNdc.zw, corner);
#else
  vec2 p = uPolygonNdc[gl_VertexID];
#endif
  vPlane = gl_InstanceID;
#ifdef LATTICE
  vec3 v = eyeRay(p);
  float len = length(v);
  float z = uDepthRange.x + (float(gl_InstanceID) + 0.5) * uDepthRange.y;
  vDepth = z;
  vScatter = scatterSample(beams[uBeam], v, len, z) * uDepthRange.y * len;
#endif
  gl_Position = vec4(p, 0.0, 1.0);
}
