// View depth of the scene at each scattering texel's centre, for the depth-aware upsample.
#include "camera.glsl"
in vec2 vUv;
layout(location = HAZE_FRAG_OUT) out float outDepth;
void main() { outDepth = sceneViewDepth(vUv); }
