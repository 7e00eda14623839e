#include "renderer/gl/program.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <set>

#include "shaders/embedded.h"

namespace haze::gl {
namespace {

std::atomic<uint64_t> g_builds{0};

std::string infoLog(GLuint object, bool program) {
  GLint len = 0;
  if (program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
  if (len <= 1) return "";
  std::string log(static_cast<size_t>(len), '\0');
  if (program) glGetProgramInfoLog(object, len, nullptr, log.data());
  else glGetShaderInfoLog(object, len, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n' || log.back() == ' ')) log.pop_back();
  return log;
}

// A program whose build succeeds with a log is reported once per process, however many
// renderers build it.
void reportWarnings(const std::string& key, const std::string& heading, const std::string& log) {
  static std::mutex mutex;
  static std::set<std::string> reported;
  std::lock_guard lock(mutex);
  if (!reported.insert(key).second) return;
  std::fprintf(stderr, "%s\n%s\n", heading.c_str(), log.c_str());
}

std::string variantKey(const ProgramDesc& desc) {
  std::string key = desc.label + "|" + desc.vertex + "|" + desc.fragment + "|" + desc.compute;
  for (const std::string& d : desc.defines) key += "|" + d;
  return key;
}

Result<GLuint> compile(GLenum stage, const std::string& file, const ProgramDesc& desc, const ShaderLookup& lookup) {
  auto src = assembleShader(file, desc.defines, lookup);
  if (!src) return src.error();
  const GLuint shader = glCreateShader(stage);
  const char* text = src->text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  const std::string path = "shaders/" + file;
  const std::string log = rewriteInfoLog(infoLog(shader, false), src->files, path);
  if (!ok) {
    glDeleteShader(shader);
    return Error{path, desc.label, "compile failed:\n" + log};
  }
  if (!log.empty()) reportWarnings(variantKey(desc) + "|" + file, path + " (" + desc.label + "): compiled with warnings:", log);
  return shader;
}

}  // namespace

uint64_t programBuildCount() { return g_builds; }

GLuint ProgramVariants::get(const std::vector<std::string>& defines) {
  for (const auto& [key, program] : built_)
    if (key == defines) return program.id();
  if (std::find(failed_.begin(), failed_.end(), defines) != failed_.end()) return 0;
  ProgramDesc desc = base_;
  desc.defines.insert(desc.defines.end(), defines.begin(), defines.end());
  auto program = buildProgram(desc);
  if (!program) {
    std::fprintf(stderr, "haze: %s (falling back to the program without this variant)\n", program.error().str().c_str());
    failed_.push_back(defines);
    return 0;
  }
  built_.emplace_back(defines, std::move(*program));
  return built_.back().second.id();
}

Result<Program> buildProgram(const ProgramDesc& desc) {
  return buildProgram(desc, [](std::string_view name) { return embeddedShader(std::string(name).c_str()); });
}

Result<Program> buildProgram(const ProgramDesc& desc, const ShaderLookup& lookup) {
  ++g_builds;
  Program program(desc.label);
  std::vector<GLuint> shaders;
  const std::string& first = desc.compute.empty() ? desc.vertex : desc.compute;
  auto vs = compile(desc.compute.empty() ? GL_VERTEX_SHADER : GL_COMPUTE_SHADER, first, desc, lookup);
  if (!vs) return vs.error();
  shaders.push_back(*vs);
  if (desc.compute.empty() && !desc.fragment.empty()) {
    auto fs = compile(GL_FRAGMENT_SHADER, desc.fragment, desc, lookup);
    if (!fs) {
      glDeleteShader(*vs);
      return fs.error();
    }
    shaders.push_back(*fs);
  }
  for (GLuint s : shaders) glAttachShader(program.id(), s);
  glLinkProgram(program.id());
  for (GLuint s : shaders) {
    glDetachShader(program.id(), s);
    glDeleteShader(s);
  }
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  const std::string log = infoLog(program.id(), true);
  if (!ok) return Error{"shaders/" + first, desc.label, "link failed:\n" + log};
  if (!log.empty()) reportWarnings(variantKey(desc), "program " + desc.label + " (shaders/" + first + "): linked with warnings:", log);
  return program;
}

}  // namespace haze::gl
