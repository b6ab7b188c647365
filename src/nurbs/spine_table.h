// A spine curve tabulated on a sample grid for the pipe self-intersection searches
// (pipe_self_intersection.h): parameters (every knot span sampled uniformly, so breakpoints are
// nodes), points, first derivatives and the cumulative arc length, integrated by Gauss–Legendre
// quadrature between nodes.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

class SpineTable {
 public:
  // At least `min_nodes` nodes and 4(p + 1) per knot span. Throws InputError when C′ vanishes
  // (|C′|·(domain length) < 1e-12·extent) at a node: the spine is not regular there.
  SpineTable(const NurbsCurve3d& spine, int min_nodes);

  const NurbsCurve3d& spine() const { return *spine_; }
  int size() const { return static_cast<int>(t_.size()); }
  double t(int i) const { return t_[i]; }
  const Eigen::Vector3d& point(int i) const { return point_[i]; }
  const Eigen::Vector3d& tangent(int i) const { return tangent_[i]; }  // C′, not unit
  double extent() const { return extent_; }  // diagonal of the control points' bounding box
  double length() const { return arc_.back(); }
  double arc(int i) const { return arc_[i]; }  // s at node i

  // s(t) = ∫ |C′| from the front to t; Gauss–Legendre (8 points) from the node below t.
  double arc_length(double t) const;
  // The parameter where s(t) = s (clamped to the domain); bisection on the monotone s(t).
  double parameter_at(double s) const;

 private:
  double integral(double a, double b) const;

  const NurbsCurve3d* spine_;
  std::vector<double> t_, arc_;
  std::vector<Eigen::Vector3d> point_, tangent_;
  double extent_ = 0.0;
};

}  // namespace polarform
