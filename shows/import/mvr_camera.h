// The "MVR overview" camera of an imported rig. MVR carries no camera, and a venue exported
// with the rig (walls, ceiling) usually encloses it: a camera set back from the rig by its size
// ends up outside the building and sees only the unlit outside of a wall. So candidate
// viewpoints are tested by casting rays against the venue (the scene's BVH): each stands inside the geometry
// that lies between it and the rig, and the one that sees most of the rig wins.
#pragma once

#include <limits>
#include <vector>

#include <glm/vec3.hpp>

#include "shows/scene/bvh.h"
#include "shows/show.h"

namespace haze {

// The distance to the first venue triangle along origin + t * dir (dir unit length), with
// 1e-6 < t < maxM, or -1 when there is none.
float firstHitM(const Bvh& venue, const glm::vec3& origin, const glm::vec3& dir,
                float maxM = std::numeric_limits<float>::max());

// A camera named "MVR overview" looking at the middle of rigPointsM (fixtures and where they
// are aimed, haze metres). Candidates: from the audience side (+Z) at 18.4, 12, 6 and 0
// degrees up, straight or 30 degrees aside, each 1.26 rig diagonals back (the view of an open
// stage) or 0.3 m short of the first geometry on the way. The winner sees the most rig points
// (a clear line to within 0.5 m of each), with a little weight on distance; ties go to the
// earlier candidate. Nearer than the full distance, the field of view widens (at most 75
// degrees) to keep the rig in frame. rigPointsM must not be empty.
CameraDef mvrOverviewCamera(const std::vector<glm::vec3>& rigPointsM, const Bvh& venue);

}  // namespace haze
