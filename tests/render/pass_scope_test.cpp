// The frame's passes run in scopes (renderer/gl/scope.h): each pushes a debug group and pops it,
// and sets GL capabilities that are put back at its end. A render therefore leaves the debug
// group stack as it found it and the GL state it did not own as it was: a caller's state (the
// GUI's ImGui drawing) is not changed under it, whatever passes ran.
#include "app/bench_scene.h"
#include "render_test_util.h"
#include "renderer/gl/scope.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class PassScopeTest : public GlTest {};

GLint groupDepth() {
  GLint depth = 0;
  glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
  return depth;
}

GLboolean depthWrites() {
  GLboolean on = GL_FALSE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &on);
  return on;
}

TEST_F(PassScopeTest, GuardsPutBackWhatTheyFound) {
  const GLint depth = groupDepth();
  for (bool before : {false, true}) {
    before ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
    glDepthMask(before ? GL_TRUE : GL_FALSE);
    {
      gl::PassScope pass("test");
      EXPECT_EQ(groupDepth(), depth + 1);
      gl::Capability blend(GL_BLEND, !before);
      gl::DepthMask mask(!before);
      EXPECT_EQ(glIsEnabled(GL_BLEND) == GL_TRUE, !before);
      EXPECT_EQ(depthWrites() == GL_TRUE, !before);
    }
    EXPECT_EQ(glIsEnabled(GL_BLEND) == GL_TRUE, before);
    EXPECT_EQ(depthWrites() == GL_TRUE, before);
    EXPECT_EQ(groupDepth(), depth);
  }
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
}

// Every pass of a frame (maps, surfaces, lenses, beams, particles), timed and not: the group
// stack and the caller's state are the same after the render as before.
TEST_F(PassScopeTest, ARenderLeavesTheCallersStateAlone) {
  const Venue venue = benchVenue(4);
  FrameState frame = benchFrame(4);
  frame.particles.settings.enabled = true;
  for (bool timed : {false, true}) {
    RenderSettings s{.width = 160, .height = 90};
    s.timePasses = timed;
    auto r = Renderer::create(venue, s);
    ASSERT_TRUE(r.ok()) << r.error().str();
    const GLint depth = groupDepth();
    glEnable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    (*r)->render(frame);
    EXPECT_EQ(groupDepth(), depth);
    EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
    EXPECT_FALSE(depthWrites());
    if (timed) {
      EXPECT_GT((*r)->lastTimes().surfacesMs, 0.0);
    }
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
  }
}

}  // namespace
}  // namespace haze::test
