#include "renderer/gl/shader_source.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

namespace haze::gl {
namespace {

constexpr int kMaxIncludeDepth = 8;

// The directive a line holds ("include", "endif"...), "" for a line that is not one.
std::string directiveOf(const std::string& line) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return "";
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos) return "";
  size_t j = i;
  while (j < line.size() && (std::isalnum(static_cast<unsigned char>(line[j])) || line[j] == '_')) ++j;
  return line.substr(i, j - i);
}

std::string lineDirective(int line, int sourceString) {
  return "#line " + std::to_string(sourceString * kLinesPerSourceString + line) + " " + std::to_string(sourceString) +
         "\n";
}

class Assembler {
 public:
  explicit Assembler(const ShaderLookup& lookup) : lookup_(lookup) { out_.files.push_back("(#version and #defines)"); }

  // Appends shaders/<name>; where is the including line, for the error when it is missing.
  Status append(const std::string& name, int depth, const std::string& where) {
    const std::string path = "shaders/" + name;
    const char* src = lookup_(name);
    if (!src) return Error{where.empty() ? path : where, "", "no shader file " + path + " (is it in shaders/?)"};
    if (depth > kMaxIncludeDepth) return Error{where, "", "#include nested deeper than 8 (a cycle?)"};
    const int self = sourceNumber(path);
    out_.text += lineDirective(1, self);
    std::istringstream in(src);
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
      if (++lineNo >= kLinesPerSourceString) return Error{path, "", "longer than the 99999 lines a shader file may have"};
      const std::string directive = directiveOf(line);
      if (directive == "include") {
        const size_t open = line.find_first_of("\"<");
        if (open != std::string::npos && line[open] == '<') {  // C++ only: a blank line keeps the count
          out_.text += '\n';
          continue;
        }
        const size_t close = open == std::string::npos ? open : line.find('"', open + 1);
        if (close == std::string::npos)
          return Error{path, "line " + std::to_string(lineNo), "expected #include \"file.glsl\""};
        Status inc = append(line.substr(open + 1, close - open - 1), depth + 1, path + ":" + std::to_string(lineNo));
        if (!inc) return inc;
        out_.text += lineDirective(lineNo + 1, self);
        continue;
      }
      out_.text += line;
      out_.text += '\n';
      // An include inside a group the preprocessor skips has its #line directives skipped too,
      // so the count is put right again where every group ends or changes branch.
      if (directive == "endif" || directive == "else" || directive == "elif")
        out_.text += lineDirective(lineNo + 1, self);
    }
    return Ok{};
  }

  ShaderSource& result() { return out_; }

 private:
  int sourceNumber(const std::string& path) {
    const auto it = std::find(out_.files.begin(), out_.files.end(), path);
    if (it != out_.files.end()) return static_cast<int>(it - out_.files.begin());
    out_.files.push_back(path);
    return static_cast<int>(out_.files.size()) - 1;
  }

  const ShaderLookup& lookup_;
  ShaderSource out_;
};

// "file:N" from the driver's source-string number and line.
std::string place(const std::vector<std::string>& files, const std::string& sourceString, const std::string& line) {
  const unsigned long encoded = std::stoul(line);
  const unsigned long s = encoded >= kLinesPerSourceString ? encoded / kLinesPerSourceString : std::stoul(sourceString);
  const std::string file = s < files.size() ? files[s] : "source string " + std::to_string(s);
  return file + ":" + std::to_string(encoded % kLinesPerSourceString);
}

}  // namespace

Result<ShaderSource> assembleShader(const std::string& file, const std::vector<std::string>& defines,
                                    const ShaderLookup& lookup) {
  Assembler a(lookup);
  a.result().text = "#version 450 core\n";
  for (const std::string& d : defines) a.result().text += "#define " + d + "\n";
  Status st = a.append(file, 0, "");
  if (!st) return st.error();
  return std::move(a.result());
}

std::string rewriteInfoLog(std::string_view log, const std::vector<std::string>& files,
                           const std::string& fallbackFile) {
  static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
  static const std::regex amd(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
  std::istringstream in{std::string(log)};
  std::string line, out;
  std::smatch m;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == '\0')) line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (!out.empty()) out += '\n';
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia))
      out += place(files, m[1], m[2]) + ": " + m[3].str();
    else if (std::regex_match(line, m, amd))
      out += place(files, m[2], m[3]) + ": " + (m[1] == "ERROR" ? "error: " : "warning: ") + m[4].str();
    else
      out += fallbackFile + ": " + line;
  }
  return out;
}

}  // namespace haze::gl
