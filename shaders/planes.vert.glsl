// Virtual planes (Dobashi et al. 2000): instance k is the plane at view depth
// zNear + (k + jitter) * dz of one beam, drawn only over the beam's screen footprint.
layout(location = 0) uniform vec4 uRectNdc;      // footprint: x0, y0, x1, y1 in NDC
layout(location = 1) uniform vec2 uDepthRange;   // zNear, dz (view depth, m)
flat out int vPlane;

void main() {
  vec2 corner = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1);
  vec2 p = mix(uRectNdc.xy, uRectNdc.zw, corner);
  vPlane = gl_InstanceID;
  gl_Position = vec4(p, 0.0, 1.0);
}
