// Headless contexts through EGL without any surface. An EGL device that is a real GPU is
// preferred; otherwise Mesa's surfaceless platform, which gives llvmpipe with no GPU and no
// display. HAZE_EGL_PLATFORM=surfaceless|device forces one.
#include <cstdlib>
#include <cstring>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "renderer/context.h"
#include "renderer/gl/debug.h"
#include "renderer/gl/gl.h"

namespace haze {
namespace {

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay d, EGLContext c, std::string platform)
      : display_(d), context_(c), platform_(std::move(platform)) {}
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  std::string description() const override { return currentGlDescription() + ", EGL " + platform_; }

 private:
  EGLDisplay display_;
  EGLContext context_;
  std::string platform_;
};

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// A hardware EGL device, or EGL_NO_DISPLAY when there is none.
EGLDisplay gpuDeviceDisplay(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay) {
  auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryDeviceString =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  if (!queryDevices || !queryDeviceString) return EGL_NO_DISPLAY;
  EGLDeviceEXT devices[16];
  EGLint count = 0;
  if (!queryDevices(16, devices, &count)) return EGL_NO_DISPLAY;
  for (EGLint i = 0; i < count; ++i) {
    const char* ext = queryDeviceString(devices[i], EGL_EXTENSIONS);
    if (hasExtension(ext, "EGL_MESA_device_software")) continue;  // llvmpipe: use surfaceless
    EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    if (d != EGL_NO_DISPLAY) return d;
  }
  return EGL_NO_DISPLAY;
}

}  // namespace

std::string currentGlDescription() {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return std::string("OpenGL ") + (version ? version : "?") + ", " + (renderer ? renderer : "?");
}

Result<std::unique_ptr<GlContext>> createHeadlessContext(const HeadlessOptions& options) {
  const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay || !hasExtension(clientExt, "EGL_EXT_platform_base"))
    return Error{"", "EGL", "this EGL has no platform displays (EGL_EXT_platform_base); install Mesa's libegl-mesa0"};

  const char* forced = std::getenv("HAZE_EGL_PLATFORM");
  const std::string want = forced ? forced : "";
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string platform;
  if (want != "surfaceless" && hasExtension(clientExt, "EGL_EXT_device_enumeration")) {
    display = gpuDeviceDisplay(getPlatformDisplay);
    if (display != EGL_NO_DISPLAY) platform = "device";
  }
  if (display == EGL_NO_DISPLAY && want != "device") {
    if (!hasExtension(clientExt, "EGL_MESA_platform_surfaceless"))
      return Error{"", "EGL", "no GPU device and no Mesa surfaceless platform (install libegl-mesa0 and libgl1-mesa-dri)"};
    display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    platform = "surfaceless";
  }
  if (display == EGL_NO_DISPLAY) return Error{"", "EGL", "no EGL display for platform '" + want + "'"};
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor))
    return Error{"", "EGL", "eglInitialize failed on the " + platform + " platform"};
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(display);
    return Error{"", "EGL", "this EGL cannot create desktop OpenGL contexts"};
  }
  const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint numConfigs = 0;
  if (!eglChooseConfig(display, configAttribs, &config, 1, &numConfigs) || numConfigs == 0) {
    const EGLint anyConfig[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    eglChooseConfig(display, anyConfig, &config, 1, &numConfigs);
  }
  const EGLint contextAttribs[] = {
      EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
      EGL_CONTEXT_OPENGL_DEBUG, options.debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
  EGLContext context = eglCreateContext(display, numConfigs > 0 ? config : EGL_NO_CONFIG_KHR,
                                        EGL_NO_CONTEXT, contextAttribs);
  if (context == EGL_NO_CONTEXT) {
    eglTerminate(display);
    return Error{"", "EGL", "cannot create an OpenGL 4.5 core context (Mesa 20 or newer gives one on llvmpipe)"};
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    eglTerminate(display);
    return Error{"", "EGL", "cannot make the context current without a surface (EGL_KHR_surfaceless_context)"};
  }
  if (options.debug) gl::enableDebugOutput();
  return std::unique_ptr<GlContext>(std::make_unique<EglContext>(display, context, platform));
}

}  // namespace haze
