// Venues built in code rather than read from glTF: the bench's synthetic stage, the accuracy
// study's scene and the tests' scenes. Every function keeps Venue::boundsMin/Max around what it
// adds, so a built venue is as complete as a loaded one.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "shows/scene/venue.h"

namespace haze {

// No geometry, the default white material at index 0, empty (inverted) bounds.
Venue emptyVenue();
// A Lambertian material of albedo (linear RGB), optionally emissive (cd/m^2); its index.
int addMaterial(Venue& v, const std::string& name, glm::vec3 albedo, glm::vec3 emissive = glm::vec3(0.0f));
// Quad p0 p1 p2 p3 (in order around it) as triangles (0 1 2) and (0 2 3); the winding normal is
// (p1 - p0) x (p3 - p0). uvs (0,0) (1,0) (1,1) (0,1).
void addQuad(Venue& v, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, int material = 0);
// A horizontal square at height y, halfSizeM to each side of the origin, facing up (+Y) unless faceDown.
void addFloor(Venue& v, float y, float halfSizeM, int material = 0, bool faceDown = false);
// An axis-aligned box, each face wound outwards.
void addBox(Venue& v, glm::vec3 lo, glm::vec3 hi, int material = 0);
// A UV sphere of rings x segments quads (the poles as fans), smooth normals.
void addUvSphere(Venue& v, glm::vec3 centre, float radiusM, int rings, int segments, int material = 0);

}  // namespace haze
