// Ray against a beam's cone: the quadric's roots and the apex plane cut [tMin, tMax] into
// pieces; each piece is inside or outside as a whole, decided by the exact inside test at its
// middle. That is simpler to get right than reasoning about the quadric's cases (camera inside,
// back cone, grazing rays, rays through the apex) and it is exact up to double rounding.
#include "renderer/reference/cone.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace haze {

namespace {

struct D3 {
  double x, y, z;
};
D3 d3(const glm::vec3& v) { return {v.x, v.y, v.z}; }
double dot(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace

ConeInterval intersectCone(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& apex,
                           const glm::vec3& axis, float halfAngleRad, double tMin, double tMax) {
  ConeInterval out;
  if (!(tMax > tMin) || !(halfAngleRad > 0.0f)) return out;
  const D3 o{double(origin.x) - apex.x, double(origin.y) - apex.y, double(origin.z) - apex.z};
  const D3 d = d3(dir);
  const D3 a = d3(axis);
  const double cosA = std::cos(double(halfAngleRad));
  const double c2 = cosA * cosA;
  const double da = dot(d, a), oa = dot(o, a);
  const double qa = da * da - c2 * dot(d, d);
  const double qb = 2.0 * (da * oa - c2 * dot(o, d));
  const double qc = oa * oa - c2 * dot(o, o);

  std::array<double, 3> cuts{};
  int n = 0;
  auto addCut = [&](double t) {
    if (n < 3 && std::isfinite(t) && t > tMin && t < tMax) cuts[n++] = t;
  };
  const double scale = std::max({std::fabs(qa), std::fabs(qb), std::fabs(qc)});
  if (scale > 0.0) {
    if (std::fabs(qa) > 1e-12 * scale) {
      const double disc = qb * qb - 4.0 * qa * qc;
      if (disc >= 0.0) {
        // The numerically stable pair of roots.
        const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
        addCut(q / qa);
        if (q != 0.0) addCut(qc / q);
      }
    } else if (qb != 0.0) {
      addCut(-qc / qb);  // ray parallel to the cone's surface: one crossing
    }
  }
  if (da != 0.0) addCut(-oa / da);  // the apex plane separates the cone from its back cone
  // At most three cuts: an insertion sort (std::sort trips GCC 12's -Warray-bounds here).
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);

  auto inside = [&](double t) {
    const D3 x{o.x + t * d.x, o.y + t * d.y, o.z + t * d.z};
    const double along = dot(x, a);
    return along > 0.0 && along * along >= c2 * dot(x, x);
  };
  double prev = tMin;
  bool any = false;
  for (int i = 0; i <= n; ++i) {
    const double next = i < n ? cuts[i] : tMax;
    if (next > prev && inside(0.5 * (prev + next))) {
      if (!any) out.t0 = prev;
      out.t1 = next;
      any = true;
    }
    prev = next;
  }
  if (!any) out = ConeInterval{};
  return out;
}

}  // namespace haze
