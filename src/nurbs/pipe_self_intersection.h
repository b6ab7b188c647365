// Global self-intersection of a pipe around a spine (Patrikalakis & Maekawa, MIT 13.472J §8.4, the
// theorem after (8.46); Maekawa, Patrikalakis, Sakkalis & Yu 1998): a pipe of radius r is
// nonsingular iff r < δ = min{1/κ_max, r_ee, r_bb, r_eb} — the local bound, the radius at which the
// two end circles meet, half the shortest double normal of the spine (body–body), and the radius at
// which an end circle touches the tube around the rest of the spine (end–body). Nonsingular is
// meant of the open pipe surface: the tube around the body may come within r of an end point
// beyond the pipe's open end below δ (every point of the pipe is then not at distance r from the
// spine, yet the surface does not meet itself).
#pragma once

#include <string>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct PipeBounds {
  double local = 0.0;      // 1/κ_max (infinity for a straight spine)
  double end_end = 0.0;    // infinity when the end circles never meet (or a closed spine)
  double body_body = 0.0;  // half the shortest double normal (infinity when there is none)
  double end_body = 0.0;   // infinity for a closed spine
  double delta = 0.0;      // the smallest of the four
  std::string limiting_mode;  // "local", "end-end", "body-body" or "end-body"
  // Where the limiting mode occurs: local — t1 = t2 = the parameter of κ_max; body–body — the feet
  // of the shortest double normal (t1 < t2); end–end — the front and the back; end–body — the end
  // (t1) and the foot on the body where its circle first touches the tube (t2).
  double t1 = 0.0, t2 = 0.0;
};

// closed: the spine is a closed curve (no end circles). Throws InputError for a spine that is not
// regular (C′ = 0) somewhere.
PipeBounds pipe_bounds(const NurbsCurve3d& spine, bool closed);

}  // namespace polarform
