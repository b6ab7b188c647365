#include "designers/scan/law_fit.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <optional>

#include "src/error.h"

namespace polarform {

namespace {

constexpr double kMinSpan = 1e-3;   // rad: the smallest θb − θa a step may reach
constexpr double kSccaStep = 1e-6;  // finite-difference step of the SCCA fractions

// The parameter vector (θa, θb, y_a, h[, b, d]) as a law shape and its evaluator.
class Model {
 public:
  Model(const LawShape& shape, const Eigen::VectorXd& p) : shape_(shape), p_(p) {
    if (shape_.law == MotionLaw::Scca) {
      // Fractions past the simplex (a difference step at its edge) are pulled back onto it.
      const double b = std::max(0.0, p[4]), d = std::max(0.0, p[5]), sum = std::max(1.0, b + d);
      shape_.scca = {b / sum, std::max(0.0, 1.0 - (b + d) / sum), d / sum};
      scca_.emplace(shape_.scca);
    }
  }
  const LawShape& shape() const { return shape_; }

  // y(θ), and the model's derivatives with respect to θa, θb, y_a, h into grad[0..3].
  double operator()(double theta, double* grad = nullptr) const {
    const double beta = p_[1] - p_[0], x = (theta - p_[0]) / beta;
    double S[3];
    if (scca_)
      scca_->derivatives(x, 1, S);
    else
      law_shape_derivatives(shape_, x, S);
    if (x <= 0.0 || x >= 1.0) S[1] = 0.0;
    if (grad) {
      grad[0] = p_[3] * S[1] * (x - 1.0) / beta;
      grad[1] = -p_[3] * S[1] * x / beta;
      grad[2] = 1.0;
      grad[3] = S[0];
    }
    return p_[2] + p_[3] * S[0];
  }

 private:
  LawShape shape_;
  Eigen::VectorXd p_;
  std::optional<SccaLaw> scca_;
};

// The SCCA fractions (b, d) kept in the simplex b, d >= 0, b + d <= 1.
void project(Eigen::VectorXd& p) {
  if (p.size() < 6) return;
  p[4] = std::clamp(p[4], 0.0, 1.0);
  p[5] = std::clamp(p[5], 0.0, 1.0);
  if (p[4] + p[5] > 1.0) {
    const double excess = (p[4] + p[5] - 1.0) / 2;
    p[4] -= excess, p[5] -= excess;
  }
}

double rss_of(const LawWindow& w, const Model& m) {
  double rss = 0.0;
  for (Eigen::Index k = 0; k < w.theta.size(); ++k) rss += std::pow(w.height[k] - m(w.theta[k]), 2);
  return rss;
}

// Residuals r = y − model and the model's Jacobian J (n x p); the SCCA columns by a one-sided
// difference.
void linearise(const LawWindow& w, const LawShape& shape, const Eigen::VectorXd& p,
               Eigen::VectorXd& r, Eigen::MatrixXd& J) {
  const Eigen::Index n = w.theta.size();
  r.resize(n);
  J.resize(n, p.size());
  const Model m(shape, p);
  double grad[4];
  for (Eigen::Index k = 0; k < n; ++k) {
    r[k] = w.height[k] - m(w.theta[k], grad);
    for (int c = 0; c < 4; ++c) J(k, c) = grad[c];
  }
  for (Eigen::Index c = 4; c < p.size(); ++c) {
    Eigen::VectorXd q = p;
    const double step = q[c] + kSccaStep <= 1.0 ? kSccaStep : -kSccaStep;
    q[c] += step;
    const Model mq(shape, q);
    for (Eigen::Index k = 0; k < n; ++k) J(k, c) = (mq(w.theta[k]) - (w.height[k] - r[k])) / step;
  }
}

}  // namespace

double LawFit::rms() const { return count ? std::sqrt(rss / static_cast<double>(count)) : 0.0; }

void law_shape_derivatives(const LawShape& shape, double x, double* out) {
  if (shape.law == MotionLaw::Scca) {
    SccaLaw(shape.scca).derivatives(x, 2, out);
    return;
  }
  if (!shape.reversed) {
    standard_law(shape.law, x, 2, out);
    return;
  }
  standard_law(shape.law, 1 - std::clamp(x, 0.0, 1.0), 2, out);  // 1 − S(1 − x)
  out[0] = 1 - out[0];
  out[2] = -out[2];
}

LawFit fit_law(const LawWindow& w, const LawShape& shape, const LawFit& guess, double noise) {
  const bool scca = shape.law == MotionLaw::Scca;
  const int np = scca ? 6 : 4;
  if (w.theta.size() < 4 * np || w.theta.size() != w.height.size())
    throw InputError("law fit: " + std::to_string(w.theta.size()) +
                     " samples in the motion's window; expected at least " +
                     std::to_string(4 * np));
  if (!(guess.end > guess.start))
    throw InputError("law fit: the motion's end must follow its start");
  Eigen::VectorXd p(np);
  p.head<4>() << guess.start, guess.end, guess.level, guess.lift;
  if (scca) p.tail<2>() << shape.scca.b, shape.scca.d;
  double rss = rss_of(w, Model(shape, p));
  double mu = 1e-3;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  // Levenberg–Marquardt with Marquardt's diagonal scaling (Marquardt 1963).
  for (int iteration = 0; iteration < 200 && mu < 1e12; ++iteration) {
    linearise(w, shape, p, r, J);
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool accepted = false;
    double gain = 0.0;
    while (!accepted && mu < 1e12) {
      Eigen::MatrixXd M = A;
      M.diagonal() += mu * A.diagonal().cwiseMax(1e-12);
      Eigen::VectorXd q = p + M.ldlt().solve(g);
      project(q);
      if (!(q[1] - q[0] > kMinSpan) || !q.allFinite()) {
        mu *= 10;
        continue;
      }
      const double trial = rss_of(w, Model(shape, q));
      if (trial < rss) {
        gain = rss - trial;
        p = q, rss = trial, mu = std::max(mu / 10, 1e-12), accepted = true;
      } else {
        mu *= 10;
      }
    }
    if (!accepted || gain <= 1e-14 * rss + 1e-300) break;
  }
  LawFit f;
  const Model m(shape, p);
  f.shape = m.shape();
  f.start = p[0], f.end = p[1], f.level = p[2], f.lift = p[3];
  f.parameters = np;
  f.rss = rss;
  f.count = static_cast<std::size_t>(w.theta.size());
  linearise(w, shape, p, r, J);
  const Eigen::MatrixXd A = J.transpose() * J;
  const Eigen::MatrixXd cov = noise * noise * A.ldlt().solve(Eigen::MatrixXd::Identity(np, np));
  f.sd = cov.diagonal().cwiseMax(0.0).cwiseSqrt();
  return f;
}

}  // namespace polarform
