// One shader stage's GLSL as the driver receives it: #version, the variant's #defines, then the
// file with its `#include "x"` lines replaced by the files they name. Each file gets a GLSL
// source-string number (`#line N S`), and `files` maps the numbers back to names, so the
// driver's info log can be rewritten to name the file and line a message is about.
//
// Mesa reports source string 0 for most errors whatever the #line said (the parser's locations
// of non-terminals drop the source number), so the number is also carried in the line itself:
// line N of source string S is declared as line S * kLinesPerSourceString + N.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "fixtures/core/result.h"

namespace haze::gl {

// The text of a shader file by its name in shaders/ ("camera.glsl"); nullptr when none.
using ShaderLookup = std::function<const char*(std::string_view name)>;

constexpr int kLinesPerSourceString = 100000;  // so no shader file may be longer

struct ShaderSource {
  std::string text;
  // files[S] names source string S ("shaders/scatter.glsl"); 0 is the #version and #defines.
  std::vector<std::string> files;
};

// `#include <x>` lines are C++-only (shaders/interface.h's glm headers) and become blank lines.
Result<ShaderSource> assembleShader(const std::string& file, const std::vector<std::string>& defines,
                                    const ShaderLookup& lookup);

// Rewrites the driver's "S:L(C): msg" (Mesa), "S(L) : msg" (NVIDIA) or "ERROR: S:L: msg" lines
// into "file:N: msg", with the file and line N decoded from L (or S, for lines below
// kLinesPerSourceString); lines in no known form get "fallbackFile: " in front.
std::string rewriteInfoLog(std::string_view log, const std::vector<std::string>& files,
                           const std::string& fallbackFile);

}  // namespace haze::gl
