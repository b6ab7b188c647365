#include "src/nurbs/curve_join.h"

#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/nurbs/degree_elevation.h"

namespace polarform {

NurbsCurve2d join_curves(const std::vector<NurbsCurve2d>& pieces) {
  if (pieces.empty()) throw InputError("join curves: no pieces");
  int p = 0;
  double size = 0.0;
  for (const NurbsCurve2d& c : pieces) {
    p = std::max(p, c.degree());
    for (int i = 0; i < c.size(); ++i) size = std::max(size, c.control_point(i).norm());
  }
  Knots knots;
  std::vector<Eigen::VectorXd> coefs;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const BSpline c = elevate_degree(pieces[k].homogeneous(), p - pieces[k].degree());
    const Knots& u = c.knots();
    if (k == 0) {
      knots.assign(u.begin(), u.end() - 1);  // the end keeps p copies: the joint
      for (int i = 0; i < c.size(); ++i) coefs.push_back(c.coefs().col(i));
      continue;
    }
    if (u.front() != knots.back())
      throw InputError("join curves: piece " + std::to_string(k) + " starts at parameter " +
                       std::to_string(u.front()) + ", the one before ends at " +
                       std::to_string(knots.back()));
    const Eigen::Vector3d end = coefs.back(), start = c.coefs().col(0);
    if ((end.head<2>() / end(2) - start.head<2>() / start(2)).norm() > 1e-9 * std::max(size, 1.0))
      throw InputError("join curves: piece " + std::to_string(k) +
                       " does not start where the one before ends");
    knots.insert(knots.end(), u.begin() + p + 1, u.end() - 1);  // its end too keeps p copies
    for (int i = 1; i < c.size(); ++i) coefs.push_back(c.coefs().col(i));
  }
  knots.push_back(knots.back());  // the last end's p + 1 copies
  Eigen::MatrixXd m(3, static_cast<Eigen::Index>(coefs.size()));
  for (std::size_t i = 0; i < coefs.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = coefs[i];
  return NurbsCurve2d(BSpline(p, std::move(knots), std::move(m)));
}

}  // namespace polarform
