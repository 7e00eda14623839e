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

// A camera named "MVR overview" that holds every point of rigPointsM (fixtures and where they
// are aimed, haze metres) in a 16:9 picture. Candidates: from the audience side (+Z) at 18.4,
// 12, 6, 0, then 30 and 45 degrees up, straight or 30 or 60 degrees aside, each 1.26 rig
// diagonals back (the view of an open stage) or 0.3 m short of the first geometry on the way.
// From each, the line of sight is turned to the middle of the points and the field of view
// fitted to them (30 to 75 degrees). A candidate whose frame holds them all beats any other;
// then the one that sees the most rig points (a clear line to within 0.5 m of each) wins, with
// a little weight on distance; ties go to the earlier. rigPointsM must not be empty.
CameraDef mvrOverviewCamera(const std::vector<glm::vec3>& rigPointsM, const Bvh& venue);

}  // namespace haze
