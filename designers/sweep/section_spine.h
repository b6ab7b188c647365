// The spine of a section sweep (a discrete generalized cylinder, MIT 13.472J §8.6; spec M9): a
// straight line or a cubic through the section centres, its rotation-minimising frames
// (src/nurbs/sweep_frames.h) tabulated by arc length, and every point's spine coordinates
// (s, x, y): s the arc length of its foot on the spine, (x, y) its place in the normal plane there.
// Beyond its ends the spine runs on along the end tangents, so every point has coordinates.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/spine_table.h"
#include "src/nurbs/sweep_frames.h"

namespace polarform {

class SectionSpine {
 public:
  // The segment from `start` along `direction` (unit or not) of the given length; the first
  // frame's x is x_hint made orthogonal to the direction. Throws InputError for a zero direction
  // or length, or x_hint parallel to the direction.
  static SectionSpine straight(const Eigen::Vector3d& start, const Eigen::Vector3d& direction,
                               double length, const Eigen::Vector3d& x_hint);
  // The cubic interpolating the centres (at least 3, distinct, in order) at chord-length
  // parameters, extended at both ends by a quarter of their chord length along the parabolas
  // through the three end centres (one point each), with Bessel end tangents (NURBS Book §9.2.4
  // with given end derivatives), so that points beyond the end centres still find a spine that
  // bends with the part.
  static SectionSpine through(const std::vector<Eigen::Vector3d>& centres,
                              const Eigen::Vector3d& x_hint);

  const NurbsCurve3d& curve() const { return *curve_; }
  bool straight() const { return straight_; }
  double length() const { return table_->length(); }

  // The frame at arc length s (extended along the end tangents outside [0, length]): its point,
  // unit tangent and the RMF x, y.
  SpineFrame frame(double s) const;
  // Columns (s, x, y) of every point: s of its closest spine point (or along an end tangent), (x,
  // y) of the point in that frame.
  Eigen::Matrix3Xd coordinates(const Eigen::Matrix3Xd& points, int threads) const;
  // The point at (s, x, y).
  Eigen::Vector3d point(double s, double x, double y) const;

 private:
  SectionSpine(NurbsCurve3d curve, bool straight, const Eigen::Vector3d& x_hint);
  SpineFrame frame_at(double t, double s) const;  // inside: t the spine parameter of arc length s

  std::shared_ptr<const NurbsCurve3d> curve_;
  std::shared_ptr<const SpineTable> table_;
  std::vector<SpineFrame> nodes_;  // RMF at the table's nodes
  bool straight_ = false;
};

}  // namespace polarform
