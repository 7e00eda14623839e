// The camera's frame, as every part of haze that turns pixels into rays or points into pixels
// sees it: the GL renderer's matrices and camera uniforms, the CPU reference's eye rays, the
// GUI's picking and the tests. One function, so a click, a GL pixel and a reference pixel
// agree, also for cameras no ordinary look-at can handle.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shows/scene/frame_state.h"

namespace haze {

struct CameraBasis {
  // Orthonormal and right-handed: right = forward x up, up = right x forward (glm::lookAt's).
  glm::vec3 forward, right, up;
  float tanY, tanX;  // tangents of the half field of view, vertical and horizontal
};

// The basis of camera with this aspect ratio (width / height). In the ordinary case it is
// glm::lookAt's: forward towards the target, right = normalize(forward x camera.up).
// Degenerate cameras get a basis too, never NaNs:
//  - target at the position: forward is -Z (the default camera's view direction);
//  - up parallel to forward (looking straight along it), or zero: the basis is the limit of
//    the ordinary one as the eye moves towards +Z (the audience side, where the default camera
//    stands), so a camera looking straight down at the stage has upstage (-Z) at the top of
//    the screen; when forward is within 25 degrees of the Z axis (|forward.z| >= 0.9), the
//    limit as the eye moves towards +Y instead.
CameraBasis cameraBasis(const CameraState& camera, float aspect);

// World to view (glm::lookAt's convention: the camera looks down -Z) from cameraBasis.
glm::mat4 cameraView(const CameraState& camera);
// View to clip: glm::perspective of the camera's vertical field of view, near and far.
glm::mat4 cameraProjection(const CameraState& camera, float aspect);
glm::mat4 cameraViewProjection(const CameraState& camera, float aspect);

}  // namespace haze
