// The GLSL sources of shaders/, embedded at build time (shaders/embed.cmake).
#pragma once

namespace haze {
// The text of shaders/<name> (for example "surface.frag.glsl"), or nullptr when there is none.
const char* embeddedShader(const char* name);
}  // namespace haze
