// Corner detection on ordered points by the turning angle between one-sided regression lines.
#include "src/fit/corner_detection.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace polarform {

namespace {

// The total-least-squares direction of points idx (oriented from the first towards the last).
template <int Dim>
Eigen::Matrix<double, Dim, 1> tls_direction(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& P,
                                            const std::vector<Eigen::Index>& idx) {
  using Vec = Eigen::Matrix<double, Dim, 1>;
  Vec mean = Vec::Zero();
  for (Eigen::Index i : idx) mean += P.col(i);
  mean /= static_cast<double>(idx.size());
  Eigen::Matrix<double, Dim, Dim> C = Eigen::Matrix<double, Dim, Dim>::Zero();
  for (Eigen::Index i : idx) C += (P.col(i) - mean) * (P.col(i) - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Dim, Dim>> es(C);
  Vec d = es.eigenvectors().col(Dim - 1);
  const Vec chord = P.col(idx.back()) - P.col(idx.front());
  return d.dot(chord) < 0 ? Vec(-d) : d;
}

}  // namespace

// Spec B1: turning angle between the regression directions of the k points before and after.
template <int Dim>
Eigen::VectorXd turning_angles(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& P, bool closed,
                               int k) {
  const Eigen::Index n = P.cols();
  Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    std::vector<Eigen::Index> before, after;
    for (int j = k; j >= 0; --j) {
      const Eigen::Index b = i - j;
      if (closed || b >= 0) before.push_back((b + n) % n);
    }
    for (int j = 0; j <= k; ++j) {
      const Eigen::Index f = i + j;
      if (closed || f < n) after.push_back(f % n);
    }
    if (before.size() < 2 || after.size() < 2 || static_cast<Eigen::Index>(2 * k + 1) > n) continue;
    const auto d0 = tls_direction<Dim>(P, before), d1 = tls_direction<Dim>(P, after);
    a[i] = std::acos(std::clamp(d0.dot(d1), -1.0, 1.0));
  }
  return a;
}

template <int Dim>
std::vector<int> detect_corners(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& P, bool closed,
                                double corner_angle, int k) {
  const Eigen::VectorXd a = turning_angles<Dim>(P, closed, k);
  const Eigen::Index n = P.cols();
  // Non-maximum suppression: the largest angles first (ties: the smaller index), each suppressing
  // the candidates closer than k points to it.
  std::vector<int> cand;
  for (Eigen::Index i = 0; i < n; ++i)
    if (a[i] > corner_angle) cand.push_back(static_cast<int>(i));
  std::stable_sort(cand.begin(), cand.end(), [&](int x, int y) { return a[x] > a[y]; });
  std::vector<int> out;
  for (int c : cand) {
    bool free = true;
    for (int o : out) {
      Eigen::Index gap = std::abs(c - o);
      if (closed) gap = std::min(gap, n - gap);
      free = free && gap >= k;
    }
    if (free) out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template Eigen::VectorXd turning_angles<2>(const Eigen::Matrix<double, 2, Eigen::Dynamic>&, bool,
                                           int);
template Eigen::VectorXd turning_angles<3>(const Eigen::Matrix<double, 3, Eigen::Dynamic>&, bool,
                                           int);
template std::vector<int> detect_corners<2>(const Eigen::Matrix<double, 2, Eigen::Dynamic>&, bool,
                                            double, int);
template std::vector<int> detect_corners<3>(const Eigen::Matrix<double, 3, Eigen::Dynamic>&, bool,
                                            double, int);

}  // namespace polarform
