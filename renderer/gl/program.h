// Building GLSL programs from the embedded shaders/ sources. Variants come from #defines
// injected after #version (never from copies of files); `#include "x.glsl"` pulls in another
// embedded file. Compile and link logs name the program, the stage and the file.
#pragma once

#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "renderer/gl/objects.h"

namespace haze::gl {

struct ProgramDesc {
  std::string label;                  // also the debugger's name
  std::string vertex;                 // shaders/<file>, e.g. "surface.vert.glsl"; "" with compute
  std::string fragment;               // "" for none (depth-only passes)
  std::string compute;                // a compute program (no vertex or fragment stage)
  std::vector<std::string> defines;   // "SHADOWS", "LATTICE 1"...
};

Result<Program> buildProgram(const ProgramDesc& desc);

}  // namespace haze::gl
