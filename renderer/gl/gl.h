// The OpenGL 4.5 core API, from the system's glcorearb.h. libOpenGL (glvnd) exports every core
// entry point and dispatches to whichever context is current, EGL or GLX, so no loader is needed.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
