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

// Variants of one program that differ only in #defines, each built on first use and kept. For
// switches fixed for a whole frame that a uniform would make every pixel pay for: llvmpipe runs
// both sides of a branch, so code behind an `if` on a uniform costs whether or not it runs.
// get() gives 0 for a variant that does not build (its error printed once), so the caller can
// fall back to a program that reads the switches from uniforms.
class ProgramVariants {
 public:
  ProgramVariants() = default;
  explicit ProgramVariants(ProgramDesc base) : base_(std::move(base)) {}
  GLuint get(const std::vector<std::string>& defines);
  size_t built() const { return built_.size(); }

 private:
  ProgramDesc base_;
  std::vector<std::pair<std::vector<std::string>, Program>> built_;
  std::vector<std::vector<std::string>> failed_;
};

// Programs built (or attempted) so far in this process: compiling is the costly part of
// making a renderer, so tests check that what should reuse programs does.
uint64_t programBuildCount();

}  // namespace haze::gl
