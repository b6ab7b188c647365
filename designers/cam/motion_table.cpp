#include "designers/cam/motion_table.h"

#include <Eigen/SparseLU>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/basis.h"

namespace polarform {

namespace {

constexpr int kDegree = 5;

// Interior knots: every inner row (Rest: n + 4 unknowns for n values and 4 end conditions), or the
// averages of five consecutive rows (Free: n unknowns; NURBS Book eq. (9.8)).
std::vector<double> interior_knots(const MotionTable& t) {
  const std::size_t n = t.x.size();
  if (t.ends == TableEnds::Rest) return std::vector<double>(t.x.begin() + 1, t.x.end() - 1);
  std::vector<double> knots;
  for (std::size_t j = 1; j + kDegree < n; ++j) {
    double sum = 0.0;
    for (std::size_t i = j; i < j + kDegree; ++i) sum += t.x[i];
    knots.push_back(sum / kDegree);
  }
  return knots;
}

}  // namespace

std::optional<TableFault> motion_table_fault(const MotionTable& t) {
  const std::size_t n = t.x.size();
  if (n != t.s.size())
    return TableFault{std::min(n, t.s.size()), "S", "as many S values as x values"};
  if (n < kMinTableRows || n > kMaxTableRows)
    return TableFault{n, "rows",
                      "between " + std::to_string(kMinTableRows) + " and " +
                          std::to_string(kMaxTableRows) + " rows"};
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(t.x[i])) return TableFault{i, "x", "a finite number"};
    if (!std::isfinite(t.s[i])) return TableFault{i, "S", "a finite number"};
    if (i > 0 && !(t.x[i] > t.x[i - 1]))
      return TableFault{i, "x", "x increasing strictly (after " + number_text(t.x[i - 1]) + ")"};
  }
  if (t.x.front() != 0.0) return TableFault{0, "x", "x = 0 in the first row"};
  if (t.s.front() != 0.0) return TableFault{0, "S", "S = 0 in the first row"};
  if (t.x.back() != 1.0) return TableFault{n - 1, "x", "x = 1 in the last row"};
  if (t.s.back() != 1.0) return TableFault{n - 1, "S", "S = 1 in the last row"};
  return std::nullopt;
}

// Collocation: one row per interpolated value, plus S'(0) = S''(0) = S'(1) = S''(1) = 0 for Rest;
// a banded system solved by sparse LU (NURBS Book §9.2.1–9.2.2).
BSplineFunction interpolate_motion_table(const MotionTable& t) {
  const std::string name = "motion table '" + t.file + "'";
  if (const auto fault = motion_table_fault(t))
    throw InputError(name + ": row " + std::to_string(fault->row + 1) + ", " + fault->field +
                     ": expected " + fault->expected);
  const Knots knots = clamped_knots(kDegree, 0.0, 1.0, interior_knots(t));
  const int size = static_cast<int>(knots.size()) - kDegree - 1;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  double ders[3 * (kDegree + 1)];
  int row = 0;
  auto add = [&](double u, int derivative, double value) {
    const int span = find_span(kDegree, knots, size, u);
    ders_basis_funs(span, u, kDegree, derivative, knots, ders);
    for (int j = 0; j <= kDegree; ++j)
      entries.emplace_back(row, span - kDegree + j, ders[derivative * (kDegree + 1) + j]);
    rhs(row++) = value;
  };
  for (std::size_t i = 0; i < t.x.size(); ++i) add(t.x[i], 0, t.s[i]);
  if (t.ends == TableEnds::Rest)
    for (double u : {0.0, 1.0})
      for (int k : {1, 2}) add(u, k, 0.0);
  Eigen::SparseMatrix<double> A(size, size);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(A);
  const Eigen::VectorXd c = solver.info() == Eigen::Success ? solver.solve(rhs) : Eigen::VectorXd();
  const double error =
      c.size() == size && c.allFinite() ? (A * c - rhs).lpNorm<Eigen::Infinity>() : HUGE_VAL;
  if (!(error <= 1e-9))
    throw InputError(name + ": rows too close together to interpolate (error " +
                     number_text(error) + " at the rows); thin the table");
  return BSplineFunction(kDegree, knots, c);
}

}  // namespace polarform
