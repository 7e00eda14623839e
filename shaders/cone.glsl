// The part [s0, s1] of [sMin, sMax] where origin + s * dir lies inside a beam's cone (apex, unit
// axis, cos^2 of the half-angle). The quadric's roots and the apex plane cut the range into
// pieces, each wholly inside or outside, decided by the inside test at its middle (the same
// method as renderer/reference/cone.cpp). Empty when s1 <= s0.
bool insideCone(vec3 x, vec3 axis, float cos2) {
  float along = dot(x, axis);
  return along > 0.0 && along * along >= cos2 * dot(x, x);
}

vec2 coneInterval(vec3 origin, vec3 dir, vec3 apex, vec3 axis, float cos2, float sMin, float sMax) {
  // Solve about the ray's closest approach to the apex, not about its origin: a ray from
  // metres away that passes millimetres from a lens has two roots millimetres apart, which
  // float loses in qb^2 - 4 qa qc (the lamp's own pixel came out black). Shifted, the
  // coefficients are of the size of that distance and the roots keep their precision.
  float sc = -dot(origin - apex, dir) / dot(dir, dir);
  vec3 o = origin + sc * dir - apex;
  sMin -= sc;
  sMax -= sc;
  float da = dot(dir, axis), oa = dot(o, axis);
  float qa = da * da - cos2 * dot(dir, dir);
  float qb = 2.0 * (da * oa - cos2 * dot(o, dir));
  float qc = oa * oa - cos2 * dot(o, o);
  float cuts[3] = float[3](sMax, sMax, sMax);
  int n = 0;
  float scale = max(abs(qa), max(abs(qb), abs(qc)));
  if (abs(qa) > 1e-7 * scale) {
    float disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0) {
      float q = -0.5 * (qb + (qb >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
      cuts[n++] = q / qa;
      if (q != 0.0) cuts[n++] = qc / q;
    }
  } else if (qb != 0.0) {
    cuts[n++] = -qc / qb;
  }
  if (da != 0.0) cuts[n++] = -oa / da;
  // Sort the (at most three) cuts and clamp them into the range.
  for (int i = 0; i < 3; ++i) cuts[i] = clamp(cuts[i], sMin, sMax);
  if (cuts[0] > cuts[1]) { float t = cuts[0]; cuts[0] = cuts[1]; cuts[1] = t; }
  if (cuts[1] > cuts[2]) { float t = cuts[1]; cuts[1] = cuts[2]; cuts[2] = t; }
  if (cuts[0] > cuts[1]) { float t = cuts[0]; cuts[0] = cuts[1]; cuts[1] = t; }
  float s0 = 0.0, s1 = 0.0, prev = sMin;
  bool any = false;
  for (int i = 0; i <= 3; ++i) {
    float next = i < 3 ? cuts[i] : sMax;
    if (next > prev && insideCone(o + 0.5 * (prev + next) * dir, axis, cos2)) {
      if (!any) s0 = prev;
      s1 = next;
      any = true;
    }
    prev = max(prev, next);
  }
  return any ? vec2(s0, s1) + sc : vec2(0.0);
}
