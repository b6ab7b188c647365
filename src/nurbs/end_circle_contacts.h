// Where the end circles of an open pipe meet the pipe (Maekawa, Patrikalakis, Sakkalis & Yu 1998;
// MIT 13.472J §8.4, Figs. 8.12–8.14): the smallest radius at which an end circle touches the tube
// around the rest of the spine (end–body, r_eb) and at which the two end circles meet (end–end,
// r_ee). Both reduce to closed forms in r, so the bisection on r of the spec is solved exactly:
// see each function.
#pragma once

#include "src/nurbs/spine_table.h"

namespace polarform {

struct EndContact {
  double radius = 0.0;   // infinity when there is no contact at any radius
  double t_end = 0.0;    // the end whose circle makes contact (front or back)
  double t_other = 0.0;  // the foot on the body (end–body) or the other end (end–end)
};

// End–body. The end circle E(θ) = C(e) + r(cos θ n + sin θ b) (n, b ⊥ C′(e)) is inside the tube
// around C(t) iff min_θ |E(θ) − C(t)| < r. With v = C(t) − C(e) and v⊥ its part normal to C′(e),
// min_θ |E − C(t)|² = r² − 2r|v⊥| + |v|², so the contact condition r > g(t) = |v|² / (2|v⊥|) is
// monotone in r, and the bisection on r with this exact distance oracle converges to a minimum
// of g: r_eb is the smallest interior local minimum of g (an interior foot; see the .cpp for why a
// foot at the other end is not a contact). Feet closer than `separation` in arc length to the
// end itself are left out (see the .cpp); the caller passes π/(2κ_max).
EndContact end_body_contact(const SpineTable& table, double separation);

// End–end. The circles of equal radius r around C(a) and C(b) in the normal planes of C′(a) and
// C′(b) meet at X iff X lies in both planes and |X − C(a)| = |X − C(b)| = r, i.e. X is in the
// intersection S of the two normal planes with the bisector plane of C(a)C(b). So r_ee is the
// distance from C(a) to S (a point, a line or a plane; the minimum-norm least-squares solution
// of the 3 × 3 system), and infinity when S is empty (e.g. a straight spine).
EndContact end_end_contact(const NurbsCurve3d& spine);

}  // namespace polarform
