#include "src/nurbs/double_normals.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace polarform {

namespace {

// Why the band: with the unit tangent T turning at rate ≤ κ, (C(s) − C(0))·T(0) = ∫ T·T(0) ≥
// ∫ cos(κσ) dσ = sin(κs)/κ > 0 for 0 < s < π/κ, so a chord with feet closer than π/κ is never
// perpendicular to the curve at its first foot; Newton started near the diagonal only finds the
// trivial solution t1 = t2, which the band and the cosine test below reject.

// F(t1, t2) = ((C1 − C2)·C1′, (C1 − C2)·C2′) and its Jacobian (the double-normal equations of
// Maekawa et al. 1998), with the cosines of the angles between the chord and the two tangents.
struct Residual {
  Eigen::Vector2d f;
  Eigen::Matrix2d jacobian;
  double length, cos1, cos2;
};

Residual residual(const NurbsCurve3d& c, double t1, double t2) {
  const auto d1 = c.derivatives(t1, 2), d2 = c.derivatives(t2, 2);
  const Eigen::Vector3d chord = d1[0] - d2[0];
  Residual r;
  r.f << chord.dot(d1[1]), chord.dot(d2[1]);
  r.jacobian << d1[1].squaredNorm() + chord.dot(d1[2]), -d1[1].dot(d2[1]), d1[1].dot(d2[1]),
      chord.dot(d2[2]) - d2[1].squaredNorm();
  r.length = chord.norm();
  r.cos1 = std::abs(r.f[0]) / (r.length * d1[1].norm());
  r.cos2 = std::abs(r.f[1]) / (r.length * d2[1].norm());
  return r;
}

class Search {
 public:
  Search(const SpineTable& table, bool closed, double separation)
      : table_(table),
        closed_(closed),
        separation_(separation),
        front_(table.spine().front()),
        period_(table.spine().back() - front_) {}

  // Arc length between the feet (the shorter way round on a closed spine).
  double apart(double s1, double s2) const {
    const double s = std::abs(s1 - s2);
    return closed_ ? std::min(s, table_.length() - s) : s;
  }

  // Newton on F from (t1, t2) with the SVD pseudo-inverse of the Jacobian (rank 1 along a family
  // of double normals, e.g. the diameters of a circle: the step is then the least-squares one onto
  // the family; NURBS Book §6.1 style orthogonality iteration). Steps are capped at a quarter of
  // the domain; closed spines wrap, open ones clamp.
  void polish(double t1, double t2) {
    for (int it = 0; it < 60; ++it) {
      const Residual r = residual(table_.spine(), t1, t2);
      Eigen::JacobiSVD<Eigen::Matrix2d> svd(r.jacobian, Eigen::ComputeFullU | Eigen::ComputeFullV);
      svd.setThreshold(1e-10);
      Eigen::Vector2d step = svd.solve(-r.f);
      if (!step.allFinite()) return;
      if (const double big = step.lpNorm<Eigen::Infinity>(); big > 0.25 * period_)
        step *= 0.25 * period_ / big;
      t1 = place(t1 + step[0]);
      t2 = place(t2 + step[1]);
      if (step.norm() <= 1e-15 * period_) break;
    }
    const Residual r = residual(table_.spine(), t1, t2);
    if (!(r.cos1 <= 1e-8 && r.cos2 <= 1e-8)) return;
    if (apart(table_.arc_length(t1), table_.arc_length(t2)) < separation_) return;
    if (r.length < best_.length) best_ = {r.length, std::min(t1, t2), std::max(t1, t2)};
  }

  // Starts: every grid cell off the band where both residuals change sign (or vanish) at its
  // corners, and every grid local minimum of |C(t_i) − C(t_j)| off the band.
  DoubleNormal run() {
    const int n = table_.size();
    const auto f = [&](int i, int j) {
      const Eigen::Vector3d chord = table_.point(i) - table_.point(j);
      return Eigen::Vector2d(chord.dot(table_.tangent(i)), chord.dot(table_.tangent(j)));
    };
    const auto dist2 = [&](int i, int j) {
      return (table_.point(i) - table_.point(j)).squaredNorm();
    };
    for (int i = 0; i + 1 < n; ++i)
      for (int j = i + 1; j + 1 < n; ++j) {
        if (apart(0.5 * (table_.arc(i) + table_.arc(i + 1)),
                  0.5 * (table_.arc(j) + table_.arc(j + 1))) < separation_)
          continue;
        const Eigen::Vector2d c[4] = {f(i, j), f(i + 1, j), f(i, j + 1), f(i + 1, j + 1)};
        bool changes = true;
        for (int k = 0; k < 2; ++k) {
          const double lo = std::min({c[0][k], c[1][k], c[2][k], c[3][k]});
          const double hi = std::max({c[0][k], c[1][k], c[2][k], c[3][k]});
          changes = changes && lo <= 0.0 && hi >= 0.0;
        }
        if (changes)
          polish(0.5 * (table_.t(i) + table_.t(i + 1)), 0.5 * (table_.t(j) + table_.t(j + 1)));
        const double d = dist2(i, j);
        bool minimum = i > 0 && j > i + 1;
        for (int di = -1; minimum && di <= 1; ++di)
          for (int dj = -1; minimum && dj <= 1; ++dj)
            if ((di != 0 || dj != 0) && i + di < j + dj) minimum = d <= dist2(i + di, j + dj);
        if (minimum && apart(table_.arc(i), table_.arc(j)) >= separation_)
          polish(table_.t(i), table_.t(j));
      }
    return best_;
  }

 private:
  double place(double t) const {
    if (!closed_) return std::clamp(t, front_, front_ + period_);
    const double u = std::fmod(t - front_, period_);
    return front_ + (u < 0.0 ? u + period_ : u);
  }

  const SpineTable& table_;
  bool closed_;
  double separation_, front_, period_;
  DoubleNormal best_{std::numeric_limits<double>::infinity(), 0.0, 0.0};
};

}  // namespace

// Maekawa, Patrikalakis, Sakkalis & Yu 1998: double normals from a sample grid, polished by
// Newton on the 2 × 2 system.
DoubleNormal shortest_double_normal(const SpineTable& table, bool closed, double separation) {
  if (!std::isfinite(separation)) return {std::numeric_limits<double>::infinity(), 0.0, 0.0};
  return Search(table, closed, separation).run();
}

}  // namespace polarform
