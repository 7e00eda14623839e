// Shader compile errors name the file and line they are in, also inside an #include (even one
// after a skipped #ifdef holding another include), not the line of the assembled source.
#include <map>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "render_test_util.h"
#include "renderer/gl/program.h"
#include "shaders/embedded.h"

namespace haze::test {
namespace {

class ShaderDiagnosticsTest : public GlTest {
 protected:
  // The test's own files first, then the embedded shaders/ (so interface.h resolves too).
  gl::ShaderLookup lookup() const {
    return [this](std::string_view name) -> const char* {
      const auto it = files_.find(std::string(name));
      return it != files_.end() ? it->second.c_str() : embeddedShader(std::string(name).c_str());
    };
  }
  std::map<std::string, std::string> files_;
};

TEST_F(ShaderDiagnosticsTest, ErrorInAnIncludeNamesThatFileAndLine) {
  files_["broken_helper.glsl"] =
      "// A helper with a mistake on line 4.\n"
      "#include \"interface.h\"\n"
      "float helper(float x) {\n"
      "  return x * undeclaredThing;\n"
      "}\n";
  files_["broken.frag.glsl"] =
      "// Includes camera.glsl only in a variant that is not built here.\n"
      "#ifdef NOT_DEFINED\n"
      "#include \"camera.glsl\"\n"
      "#endif\n"
      "#include \"broken_helper.glsl\"\n"
      "layout(location = HAZE_FRAG_OUT) out vec4 outColor;\n"
      "void main() {\n"
      "  outColor = vec4(helper(1.0));\n"
      "  float y = alsoUndeclared;\n"
      "}\n";
  const auto before = gl::programBuildCount();
  auto program = gl::buildProgram(
      {.label = "broken", .vertex = "fullscreen.vert.glsl", .fragment = "broken.frag.glsl"}, lookup());
  ASSERT_FALSE(program.ok()) << "the shader is broken on purpose";
  EXPECT_EQ(gl::programBuildCount(), before + 1);
  const std::string message = program.error().str();
  EXPECT_NE(message.find("shaders/broken_helper.glsl:4: error:"), std::string::npos) << message;
  EXPECT_NE(message.find("undeclaredThing"), std::string::npos) << message;
  // The including file's own count is restored after each include and after the #endif.
  EXPECT_NE(message.find("shaders/broken.frag.glsl:9: error:"), std::string::npos) << message;
  EXPECT_FALSE(std::regex_search(message, std::regex(R"((^|\n)\d+:\d+\()")))
      << "no raw source-string numbers left: " << message;
}

TEST_F(ShaderDiagnosticsTest, WarningsOfAProgramThatBuildsArePrintedOnce) {
  // An unknown extension asked for with `warn` is a warning every GLSL compiler must give (GLSL
  // 4.50, 3.3), where warnings about style or uninitialised variables are the driver's choice.
  // The first line differs on every run: Mesa's shader cache returns an empty log for a source it
  // has compiled before (in an earlier run), which would hide the warning.
  const auto nonce = std::chrono::steady_clock::now().time_since_epoch().count();
  files_["warns.frag.glsl"] =
      "#extension GL_HAZE_no_such_extension : warn // run " + std::to_string(nonce) + "\n"
      "#include \"interface.h\"\n"
      "layout(location = HAZE_FRAG_OUT) out vec4 outColor;\n"
      "void main() {\n"
      "  outColor = vec4(1.0);\n"
      "}\n";
  const gl::ProgramDesc desc{.label = "warns", .vertex = "fullscreen.vert.glsl", .fragment = "warns.frag.glsl"};
  ::testing::internal::CaptureStderr();
  auto first = gl::buildProgram(desc, lookup());
  const std::string printed = ::testing::internal::GetCapturedStderr();
  ASSERT_TRUE(first.ok()) << first.error().str();
  EXPECT_NE(printed.find("shaders/warns.frag.glsl (warns)"), std::string::npos) << printed;
  EXPECT_NE(printed.find("shaders/warns.frag.glsl:1: warning"), std::string::npos) << printed;
  ::testing::internal::CaptureStderr();
  auto second = gl::buildProgram(desc, lookup());
  EXPECT_TRUE(second.ok());
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "the same program's warnings again";
}

TEST_F(ShaderDiagnosticsTest, MissingIncludeNamesTheIncludingLine) {
  files_["lonely.frag.glsl"] = "// One line of comment.\n#include \"nowhere.glsl\"\nvoid main() {}\n";
  auto program = gl::buildProgram(
      {.label = "lonely", .vertex = "fullscreen.vert.glsl", .fragment = "lonely.frag.glsl"}, lookup());
  ASSERT_FALSE(program.ok());
  const std::string message = program.error().str();
  EXPECT_NE(message.find("shaders/lonely.frag.glsl:2"), std::string::npos) << message;
  EXPECT_NE(message.find("shaders/nowhere.glsl"), std::string::npos) << message;
}

TEST(ShaderInfoLog, RewritesMesaAndNvidiaForms) {
  const std::vector<std::string> files = {"(#version and #defines)", "shaders/a.glsl", "shaders/b.glsl"};
  EXPECT_EQ(gl::rewriteInfoLog("2:12(3): error: oops\n1:4(1): warning: hmm\n", files, "shaders/a.glsl"),
            "shaders/b.glsl:12: error: oops\nshaders/a.glsl:4: warning: hmm");
  EXPECT_EQ(gl::rewriteInfoLog("1(7) : error C0000: bad", files, "shaders/a.glsl"), "shaders/a.glsl:7: error C0000: bad");
  // Mesa's source string 0 on a line that carries its file (shader_source.h).
  EXPECT_EQ(gl::rewriteInfoLog("0:200012(3): error: oops", files, "shaders/a.glsl"), "shaders/b.glsl:12: error: oops");
  EXPECT_EQ(gl::rewriteInfoLog("ERROR: 2:5: bad", files, "shaders/a.glsl"), "shaders/b.glsl:5: error: bad");
  EXPECT_EQ(gl::rewriteInfoLog("something else", files, "shaders/a.glsl"), "shaders/a.glsl: something else");
}

}  // namespace
}  // namespace haze::test
