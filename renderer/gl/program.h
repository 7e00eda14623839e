// Building GLSL programs from the embedded shaders/ sources. Variants come from #defines
// injected after #version (never from copies of files); `#include "x.glsl"` pulls in another
// embedded file (renderer/gl/shader_source.h). Compile and link logs name the program and, per
// message, the file and line it is about; warnings of programs that build are printed too.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "renderer/gl/objects.h"
#include "renderer/gl/shader_source.h"

namespace haze::gl {

struct ProgramDesc {
  std::string label;                  // also the debugger's name
  std::string vertex;                 // shaders/<file>, e.g. "surface.vert.glsl"; "" with compute
  std::string fragment;               // "" for none (depth-only passes)
  std::string compute;                // a compute program (no vertex or fragment stage)
  std::vector<std::string> defines;   // "SHADOWS", "LATTICE 1"...
};

// From the shaders embedded in the binary.
Result<Program> buildProgram(const ProgramDesc& desc);
// From other sources (tests): files are looked up by name through `lookup`.
Result<Program> buildProgram(const ProgramDesc& desc, const ShaderLookup& lookup);

// Programs built (or attempted) so far in this process: compiling is the costly part of
// making a renderer, so tests check that what should reuse programs does.
uint64_t programBuildCount();

}  // namespace haze::gl
