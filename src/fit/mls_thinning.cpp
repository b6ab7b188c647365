// MLS thinning of a 2D band with an adaptive radius (Kantz 2003, §4.4–4.5).
#include "src/fit/mls_thinning.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <vector>

#include "src/fit/grid_index.h"
#include "src/fit/parallel.h"

namespace polarform {

namespace {

// Kantz 2003, eq. (4.7): w = 2(h/r)³ − 3(h/r)² + 1 for h <= r (h a distance, spec K5 erratum).
double weight(double h, double r) {
  if (h >= r) return 0.0;
  const double t = h / r;
  return 2 * t * t * t - 3 * t * t + 1;
}

struct LocalLine {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero(), dir = Eigen::Vector2d::UnitX();
  double ratio = 1.0;  // λ_min / λ_max of the weighted scatter
};

LocalLine weighted_line(const Eigen::Matrix2Xd& P, const std::vector<int>& nb,
                        const Eigen::Vector2d& c, double r) {
  LocalLine L;
  double sw = 0.0;
  for (int i : nb) {
    const double w = weight((P.col(i) - c).norm(), r);
    L.mean += w * P.col(i);
    sw += w;
  }
  if (!(sw > 0.0)) return L;
  L.mean /= sw;
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();
  for (int i : nb) {
    const Eigen::Vector2d d = P.col(i) - L.mean;
    S += weight((P.col(i) - c).norm(), r) * d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(S);
  L.dir = es.eigenvectors().col(1);
  L.ratio = es.eigenvalues()[1] > 0.0 ? es.eigenvalues()[0] / es.eigenvalues()[1] : 1.0;
  return L;
}

}  // namespace

// Kantz 2003, §4.4 (Lee 2000): weighted quadratic ŷ = a0 + a1x̂ + a2x̂² in the local TLS frame; the
// point moves to (0, a0).
MlsThinning mls_thin(const Eigen::Matrix2Xd& P, const MlsOptions& o) {
  MlsThinning out;
  out.points = P;
  out.radius = Eigen::VectorXd::Zero(P.cols());
  if (P.cols() < 3) return out;
  const GridIndex2d grid(P);
  const double r0 = o.radius > 0.0 ? o.radius : 2.0 * grid.cell_size();
  out.start_radius = r0;
  const int chunks = worker_count(o.threads, static_cast<std::size_t>(P.cols()), 5000);
  parallel_chunks(
      static_cast<std::size_t>(P.cols()), chunks, [&](std::size_t begin, std::size_t end, int) {
        std::vector<int> nb, prev;
        for (std::size_t k = begin; k < end; ++k) {
          Eigen::Vector2d c = P.col(static_cast<Eigen::Index>(k));
          // Radius: grow until nearly linear or enough neighbours; stop when linearity worsens
          // (a corner's signature).
          double r = r0, used = r0, prev_ratio = 2.0;
          for (int g = 0; g <= o.growth_steps; ++g, r *= 1.5) {
            grid.radius(c, r, nb);
            if (static_cast<int>(nb.size()) < o.min_neighbours && g < o.growth_steps) continue;
            const LocalLine L = weighted_line(P, nb, c, r);
            if (L.ratio > prev_ratio && static_cast<int>(prev.size()) >= o.min_neighbours) break;
            prev = nb, prev_ratio = L.ratio, used = r;
            if (L.ratio <= o.linearity || static_cast<int>(nb.size()) >= o.max_neighbours) break;
          }
          if (static_cast<int>(prev.size()) < 3) continue;
          out.radius[static_cast<Eigen::Index>(k)] = used;
          for (int it = 0; it < o.iterations; ++it) {
            const LocalLine L = weighted_line(P, prev, c, used);
            const Eigen::Vector2d nrm(-L.dir.y(), L.dir.x());
            Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
            Eigen::Vector3d b = Eigen::Vector3d::Zero();
            for (int i : prev) {
              const Eigen::Vector2d d = P.col(i) - c;
              const double w = weight(d.norm(), used), x = d.dot(L.dir), y = d.dot(nrm);
              const Eigen::Vector3d row(1.0, x, x * x);
              A += w * row * row.transpose();
              b += w * row * y;
            }
            A.diagonal().array() += 1e-14 * A.trace();
            const Eigen::Vector3d a = A.fullPivLu().solve(b);
            const Eigen::Vector2d moved = c + a[0] * nrm;
            if (!moved.allFinite()) break;
            const double step = (moved - c).norm();
            c = moved;
            if (step <= 1e-12 * used) break;
          }
          out.points.col(static_cast<Eigen::Index>(k)) = c;
        }
      });
  return out;
}

}  // namespace polarform
