#include "designers/vessel/stress_optimal_head.h"

#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <numbers>
#include <vector>

#include "designers/vessel/meridian_arcs.h"
#include "designers/vessel/nlopt_stop_reason.h"
#include "designers/vessel/polar_curvature.h"
#include "designers/vessel/synthesis_space.h"
#include "src/error.h"
#include "src/fit/constrained_least_squares.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

// R̃, R̃', R̃'' (R̃ = R/radius) at angles as rows over the unknowns of `space`.
struct SampleRows {
  Eigen::MatrixXd value, slope, second;
};

SampleRows sample_rows(const SynthesisSpace& space, const std::vector<double>& angles) {
  const int p = space.degree, n = space.ordinates(), K = static_cast<int>(angles.size());
  SampleRows rows{Eigen::MatrixXd::Zero(K, n), Eigen::MatrixXd::Zero(K, n),
                  Eigen::MatrixXd::Zero(K, n)};
  for (int k = 0; k < K; ++k) {
    const int span = find_span(p, space.knots, n, angles[k]);
    const Eigen::MatrixXd d = ders_basis_funs(span, angles[k], p, 2, space.knots);
    rows.value.block(k, span - p, 1, p + 1) = d.row(0);
    rows.slope.block(k, span - p, 1, p + 1) = d.row(1);
    rows.second.block(k, span - p, 1, p + 1) = d.row(2);
  }
  rows.value *= space.map;
  rows.slope *= space.map;
  rows.second *= space.map;
  return rows;
}

// The pressure-normalised membrane forces N_φ/p = r2/2 and N_θ/p = r2 (1 − κ r2/2) at θ < π/2
// with their partial derivatives with respect to R, R', R'' (r2 = R cos θ √(R² + R'²) /
// (R' sin θ + R cos θ), membrane_stress.h; κ of DESIGN §4.4).
struct ForceJet {
  double meridional = 0.0, hoop = 0.0, kappa = 0.0;
  double d_meridional[3] = {0, 0, 0}, d_hoop[3] = {0, 0, 0}, d_kappa[3] = {0, 0, 0};
};

ForceJet force_jet(double theta, double r, double dr, double ddr) {
  const double c = std::cos(theta), s = std::sin(theta), g = std::hypot(r, dr);
  const double D = dr * s + r * c, r2 = r * c * g / D;
  const double dr2[3] = {c * g / D + r * c * (r / g) / D - r * c * g * c / (D * D),
                         r * c * (dr / g) / D - r * c * g * s / (D * D), 0.0};
  const PolarCurvature k = polar_curvature_with_gradient(r, dr, ddr);
  const double dk[3] = {k.d_r, k.d_dr, k.d_ddr};
  ForceJet out;
  out.meridional = r2 / 2;
  out.hoop = r2 * (1 - k.kappa * r2 / 2);
  out.kappa = k.kappa;
  for (int q = 0; q < 3; ++q) {
    out.d_meridional[q] = dr2[q] / 2;
    out.d_hoop[q] = dr2[q] * (1 - k.kappa * r2) - r2 * r2 / 2 * dk[q];
    out.d_kappa[q] = dk[q];
  }
  return out;
}

struct Minimax {
  SampleRows rows;
  std::vector<double> angles;  // [0, π/2], the last one the apex
  int unknowns = 0;            // the variables are (x, s)
  int evaluations = 0;

  int constraints() const { return 4 * (static_cast<int>(angles.size()) - 1) + 2; }

  // max(|N_φ|, |N_θ|)/p over the samples for the ordinates map · x (scaled by the radius).
  double peak(const Eigen::VectorXd& x) const {
    const Eigen::VectorXd R = rows.value * x, dR = rows.slope * x, ddR = rows.second * x;
    const int K = static_cast<int>(angles.size());
    double out = 1 / (2 * polar_curvature(R(K - 1), dR(K - 1), ddR(K - 1)));
    for (int k = 0; k + 1 < K; ++k) {
      const ForceJet f = force_jet(angles[k], R(k), dR(k), ddR(k));
      out = std::max({out, f.meridional, std::abs(f.hoop)});
    }
    return out;
  }

  // c(x, s) <= 0 and, if asked, its Jacobian (row-major constraints x variables).
  void evaluate(const double* z, double* c, double* jacobian) {
    const int n = unknowns + 1, K = static_cast<int>(angles.size());
    const Eigen::Map<const Eigen::VectorXd> x(z, unknowns);
    const double s = z[unknowns];
    const Eigen::VectorXd R = rows.value * x, dR = rows.slope * x, ddR = rows.second * x;
    if (jacobian) std::fill(jacobian, jacobian + constraints() * n, 0.0);
    const auto chain = [&](int row, int k, const double* d, double sign) {
      if (!jacobian) return;
      Eigen::Map<Eigen::RowVectorXd> out(jacobian + row * n, unknowns);
      out =
          sign * (d[0] * rows.value.row(k) + d[1] * rows.slope.row(k) + d[2] * rows.second.row(k));
    };
    int row = 0;
    for (int k = 0; k + 1 < K; ++k) {
      const ForceJet f = force_jet(angles[k], R(k), dR(k), ddR(k));
      const double values[4] = {f.meridional - s, f.hoop - s, -f.hoop - s, -f.kappa};
      const double* partials[4] = {f.d_meridional, f.d_hoop, f.d_hoop, f.d_kappa};
      const double signs[4] = {1, 1, -1, -1};
      for (int j = 0; j < 4; ++j, ++row) {
        c[row] = values[j];
        chain(row, k, partials[j], signs[j]);
        if (jacobian && j < 3) jacobian[row * n + unknowns] = -1.0;
      }
    }
    // The apex: N_φ = N_θ = p / (2κ), so 1/(2κ) <= s as 1 − 2κs <= 0 next to κ >= 0.
    const PolarCurvature k = polar_curvature_with_gradient(R(K - 1), dR(K - 1), ddR(K - 1));
    const double dk[3] = {k.d_r, k.d_dr, k.d_ddr};
    c[row] = 1 - 2 * k.kappa * s;
    chain(row, K - 1, dk, -2 * s);
    if (jacobian) jacobian[row * n + unknowns] = -2 * k.kappa;
    ++row;
    c[row] = -k.kappa;
    chain(row, K - 1, dk, -1);
  }
};

double objective(unsigned n, const double* z, double* grad, void* data) {
  ++static_cast<Minimax*>(data)->evaluations;
  if (grad) {
    std::fill(grad, grad + n, 0.0);
    grad[n - 1] = 1.0;
  }
  return z[n - 1];
}

void inequalities(unsigned, double* c, unsigned, const double* z, double* grad, void* data) {
  static_cast<Minimax*>(data)->evaluate(z, c, grad);
}

struct Equalities {
  Eigen::MatrixXd rows;  // over (x, s)
  Eigen::VectorXd values;
};

void equalities(unsigned m, double* c, unsigned n, const double* z, double* grad, void* data) {
  const auto* e = static_cast<Equalities*>(data);
  Eigen::Map<Eigen::VectorXd>(c, m) = e->rows * Eigen::Map<const Eigen::VectorXd>(z, n) - e->values;
  if (grad)
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(grad, m, n) =
        e->rows;
}

void validate(double radius, double depth, const StressOptimalSettings& s) {
  const std::string where = "minimum-stress head: ";
  if (!(radius > 0.0 && std::isfinite(radius)))
    throw InputError(where + "radius " + to_text(radius) + " mm, expected > 0");
  if (!(depth > 0.0 && depth <= 4 * radius))
    throw InputError(where + "depth " + to_text(depth) +
                     " mm, expected in (0, 4 · radius = " + to_text(4 * radius) + " mm]");
  if (s.degree < 3 || s.degree > 9)
    throw InputError(where + "degree " + std::to_string(s.degree) + ", expected 3..9");
  if (s.ordinates < std::max(8, s.degree + 1) || s.ordinates > 80)
    throw InputError(where + "ordinates " + std::to_string(s.ordinates) + ", expected " +
                     std::to_string(std::max(8, s.degree + 1)) + "..80");
  if (s.samples < 16 || s.samples > 2000)
    throw InputError(where + "samples " + std::to_string(s.samples) + ", expected 16..2000");
  if (s.junction_curvature && !std::isfinite(*s.junction_curvature))
    throw InputError(where + "junction curvature must be finite");
  if (s.max_iterations < 1 || s.max_iterations > 100000)
    throw InputError(where + "max-iterations " + std::to_string(s.max_iterations) +
                     ", expected 1..100000");
}

}  // namespace

// Minimax by the bound variable s (min s, g_i(x) <= s), NLopt LD_SLSQP (Kraft 1988), started from
// the least-squares B-spline of the ellipse with the same depth (Bae 2002, Appendix C).
StressOptimalHead minimum_peak_stress_head(double radius, double depth,
                                           const StressOptimalSettings& settings) {
  validate(radius, depth, settings);
  SynthesisSettings space_settings;
  space_settings.degree = settings.degree;
  space_settings.ordinates = settings.ordinates;
  space_settings.symmetric = true;
  const SynthesisSpace space = synthesis_space(space_settings);
  const int m = space.unknowns();
  const double h = depth / radius;  // scaled by the radius throughout

  Minimax problem;
  problem.unknowns = m;
  for (int i = 0; i < settings.samples; ++i)
    problem.angles.push_back(kHalfPi * i / (settings.samples - 1));
  problem.rows = sample_rows(space, problem.angles);

  // R(0) = 1, R'(0) = 0 (tangent to the cylinder), R(π/2) = depth; R''(0) = 1 − κ̃ when the
  // junction curvature is given (κ = (R − R'')/R² at R' = 0).
  const SampleRows ends = sample_rows(space, {0.0, kHalfPi});
  Eigen::MatrixXd C(settings.junction_curvature ? 4 : 3, m);
  Eigen::VectorXd d(C.rows());
  C.row(0) = ends.value.row(0), d(0) = 1.0;
  C.row(1) = ends.slope.row(0), d(1) = 0.0;
  C.row(2) = ends.value.row(1), d(2) = h;
  if (settings.junction_curvature)
    C.row(3) = ends.second.row(0), d(3) = 1.0 - *settings.junction_curvature * radius;

  std::vector<double> fit_angles;
  for (int i = 0; i <= 400; ++i) fit_angles.push_back(kHalfPi * i / 400);
  Eigen::VectorXd ellipse(fit_angles.size());
  for (std::size_t i = 0; i < fit_angles.size(); ++i)
    ellipse_polar(1.0, h, fit_angles[i], 0, &ellipse(i));
  const Eigen::VectorXd x0 =
      constrained_least_squares(sample_rows(space, fit_angles).value, ellipse, C, d);

  const int n = m + 1, constraints = problem.constraints();
  std::vector<double> z(n);
  Eigen::Map<Eigen::VectorXd>(z.data(), m) = x0;
  z[m] = 0.0;
  z[m] = problem.peak(x0);  // the start's own peak: feasible in s

  Equalities eq{Eigen::MatrixXd::Zero(C.rows(), n), d};
  eq.rows.leftCols(m) = C;
  // SLSQP restarted from its own result until a run no longer lowers the peak by 1e-9 of the
  // radius: a single run often stops on a short step long before the minimax optimum.
  nlopt::result status = nlopt::FAILURE;
  for (int run = 0; run < 50 && problem.evaluations < settings.max_iterations; ++run) {
    nlopt::opt opt(nlopt::LD_SLSQP, static_cast<unsigned>(n));
    opt.set_min_objective(objective, &problem);
    opt.add_inequality_mconstraint(inequalities, &problem, std::vector<double>(constraints, 1e-10));
    opt.add_equality_mconstraint(equalities, &eq, std::vector<double>(C.rows(), 1e-12));
    opt.set_ftol_abs(1e-12);
    opt.set_maxeval(settings.max_iterations - problem.evaluations);
    const double before = z[m];
    double value = 0.0;
    try {
      status = opt.optimize(z, value);
    } catch (const nlopt::roundoff_limited&) {
      status = nlopt::ROUNDOFF_LIMITED;
    } catch (const std::exception& e) {
      throw NumericalError(std::string("minimum-stress head: NLopt SLSQP failed (") + e.what() +
                           ") after " + std::to_string(problem.evaluations) + " evaluations");
    }
    if (!(before - z[m] > 1e-9)) break;
  }

  StressOptimalHead out;
  out.iterations = problem.evaluations;
  const char* reason = nlopt_stop_reason(status);
  if (!reason && status != nlopt::MAXEVAL_REACHED)
    throw NumericalError("minimum-stress head: SLSQP stopped with NLopt status " +
                         std::to_string(static_cast<int>(status)));
  out.termination = reason ? reason : "evaluation limit reached";  // then checked for feasibility
  std::vector<double> c(constraints);
  problem.evaluate(z.data(), c.data(), nullptr);
  const double violation =
      std::max(*std::max_element(c.begin(), c.end()),
               (C * Eigen::Map<const Eigen::VectorXd>(z.data(), m) - d).cwiseAbs().maxCoeff());
  if (violation > 1e-6)
    throw NumericalError("minimum-stress head: constraints violated by " + to_text(violation) +
                         " of the radius after SLSQP (" + out.termination +
                         "); raise the ordinates or max-iterations");
  const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(z.data(), m);
  out.profile = BSplineFunction(space.degree, space.knots, radius * (space.map * x));
  out.peak_radius = radius * problem.peak(x);
  return out;
}

}  // namespace polarform
