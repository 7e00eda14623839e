#include "renderer/gl/program.h"

#include <sstream>

#include "shaders/embedded.h"

namespace haze::gl {
namespace {

// Expands #include "name" lines (one level deep is all haze's shaders use; guarded to 8).
Result<std::string> expand(const std::string& name, int depth) {
  const char* src = embeddedShader(name.c_str());
  if (!src) return Error{"shaders/" + name, "", "no such embedded shader (is it in shaders/?)"};
  if (depth > 8) return Error{"shaders/" + name, "", "#include nested deeper than 8"};
  std::istringstream in(src);
  std::string line, out;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.rfind("#include", 0) == 0) {
      const auto a = line.find('"'), b = line.rfind('"');
      if (a == std::string::npos || b <= a)
        return Error{"shaders/" + name, "line " + std::to_string(lineNo), "expected #include \"file.glsl\""};
      auto inc = expand(line.substr(a + 1, b - a - 1), depth + 1);
      if (!inc) return inc.error();
      out += *inc;
    } else {
      out += line;
      out += '\n';
    }
  }
  return out;
}

Result<GLuint> compile(GLenum stage, const std::string& file, const ProgramDesc& desc) {
  auto body = expand(file, 0);
  if (!body) return body.error();
  std::string src = "#version 450 core\n";
  for (const std::string& d : desc.defines) src += "#define " + d + "\n";
  src += "#line 1\n" + *body;
  const GLuint shader = glCreateShader(stage);
  const char* text = src.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetShaderInfoLog(shader, len, nullptr, log.data());
    glDeleteShader(shader);
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return Error{"shaders/" + file, desc.label, "compile failed: " + log};
  }
  return shader;
}

}  // namespace

Result<Program> buildProgram(const ProgramDesc& desc) {
  Program program(desc.label);
  std::vector<GLuint> shaders;
  const std::string& first = desc.compute.empty() ? desc.vertex : desc.compute;
  auto vs = compile(desc.compute.empty() ? GL_VERTEX_SHADER : GL_COMPUTE_SHADER, first, desc);
  if (!vs) return vs.error();
  shaders.push_back(*vs);
  if (desc.compute.empty() && !desc.fragment.empty()) {
    auto fs = compile(GL_FRAGMENT_SHADER, desc.fragment, desc);
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
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetProgramInfoLog(program.id(), len, nullptr, log.data());
    return Error{"shaders/" + first, desc.label, "link failed: " + log};
  }
  return program;
}

}  // namespace haze::gl
