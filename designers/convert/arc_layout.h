// Arc layout for the converter: where to break the base circle so that the synchronization error
// |F(ξ(u)) − F(u)| of every arc meets its budget with as few arcs as possible. Arcs are unequal —
// long where |F'| is small (a dwell takes a half circle), short where it is large — and every
// breakpoint of R is an arc junction, so F's knots and the base circle's share positions.
#pragma once

#include <vector>

#include "src/base/arc_angle.h"
#include "src/nurbs/bspline.h"

namespace polarform {

struct ArcLayoutOptions {
  ArcKind kind = ArcKind::quartic;
  AlphaRule alpha = AlphaRule::minimax;
  double tolerance = 1e-3;  // budget for the synchronization error of each arc
};

// Max over one arc [a, b] of |F(a + ξ(η)) − F(a + 2φη)| (Bae 2002, eq. (5.4) without the
// linearisation), sampled at `samples` interior η.
double arc_synchronization_error(const BSplineFunction& F, double a, double b, ArcKind kind,
                                 AlphaRule alpha, int samples = 24);

// Breakpoints θ_0 = F.front() < … < θ_k = F.back() of the arcs: every `forced` angle is one of
// them, and between forced angles arcs are grown greedily to the longest sweep whose sampled
// synchronization error meets the tolerance.
std::vector<double> layout_arcs(const BSplineFunction& F, const std::vector<double>& forced,
                                const ArcLayoutOptions& options);

// The longest sweep an arc of the kind may have: π for quartic arcs, 2π/3 for RQB arcs (whose
// middle weight cos φ must stay well away from 0).
double max_arc_sweep(ArcKind kind);

}  // namespace polarform
