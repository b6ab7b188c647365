// BaseCircle: a unit circle or arc made of RQB or quasi-uniform quartic arcs between breakpoint
// angles, merged into one NurbsCurve2d, with the parameter synchronization θ ↔ u of Bae 2002,
// eqs. (2.7)–(2.8) generalised to both arc kinds. It is the base geometry of polar curve fitting
// and of the converter: C(u) = F(u)·B(u) (Bae 2002, eq. (2.1)).
#pragma once

#include <cstddef>
#include <vector>

#include "src/base/arc_angle.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

class BaseCircle {
 public:
  // An empty base (no arcs), to be assigned a real one.
  BaseCircle() = default;
  // Arcs between breakpoints θ_0 < θ_1 < … < θ_k (radians, k >= 1), each sweep < π (rqb) or
  // <= π (quartic), total <= 2π. A total within kAngleSlack of 2π makes a closed circle (θ_k is
  // then set to θ_0 + 2π). The curve has degree 2 (rqb) or 4 (quartic) and interior knots of
  // multiplicity = degree at the breakpoints, placed at u_j = θ_j (angle) or u_j = j (unit).
  BaseCircle(ArcKind kind, std::vector<double> breakpoints, AlphaRule rule = AlphaRule::minimax,
             ArcParametrization param = ArcParametrization::angle);

  // `arcs` equal arcs over [start, end]: 3, 4, 6 arcs over 2π are the triangle-, square- and
  // hexagon-based circles.
  static BaseCircle equal_arcs(ArcKind kind, double start, double end, int arcs,
                               AlphaRule rule = AlphaRule::minimax,
                               ArcParametrization param = ArcParametrization::angle);
  // The fewest equal arcs the kind allows over [start, end].
  static BaseCircle fewest_arcs(ArcKind kind, double start, double end,
                                AlphaRule rule = AlphaRule::minimax,
                                ArcParametrization param = ArcParametrization::angle);
  // The fewest equal arcs over [start, end] with sweeps <= max_sweep (and within the kind's
  // limit); max_sweep = π/2 is the square-based construction (NURBS Book A7.1, Bae 2002, (3.3)).
  static BaseCircle with_max_sweep(ArcKind kind, double start, double end, double max_sweep,
                                   AlphaRule rule = AlphaRule::minimax,
                                   ArcParametrization param = ArcParametrization::angle);

  const NurbsCurve2d& curve() const { return curve_; }
  ArcKind kind() const { return kind_; }
  AlphaRule alpha_rule() const { return rule_; }
  ArcParametrization parametrization() const { return param_; }
  int arcs() const { return static_cast<int>(theta_.size()) - 1; }
  const std::vector<double>& breakpoints() const { return theta_; }
  // α of a quartic arc (5.2); 1 for RQB arcs (the quartic reparametrization s(η) = η).
  double alpha(int arc) const;
  // The knot value u_j at each breakpoint θ_j.
  const Knots& parameters() const { return u_; }
  bool closed() const { return closed_; }

  // The u whose point B(u) lies on the ray at angle θ; Bae 2002, eqs. (2.7)–(2.8) (rqb) and the
  // inverse of (5.3) (quartic). θ must lie in [θ_0, θ_k] (within kAngleSlack); a closed circle
  // accepts any θ and wraps it.
  double parameter(double theta) const;
  // parameter() for n angles at once: u[i] = parameter(theta[i]).
  void parameters(const double* theta, double* u, std::size_t n) const;
  // The polar angle of B(u) in [θ_0, θ_k], continuous and increasing; u in the curve's domain
  // (within kAngleSlack).
  double angle(double u) const;

 private:
  ArcKind kind_ = ArcKind::quartic;
  AlphaRule rule_ = AlphaRule::minimax;
  ArcParametrization param_ = ArcParametrization::angle;
  std::vector<double> theta_;
  Knots u_;
  std::vector<double> alpha_;
  bool closed_ = false;
  NurbsCurve2d curve_;
};

}  // namespace polarform
