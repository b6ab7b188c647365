// The user motion table law: the quintic interpolant reproduces a quintic law exactly (rest ends
// for 3-4-5, free ends for a law that starts moving), converges on a cycloid, is C⁴ inside
// (simple knots of a degree-5 spline), and every broken table names its row and field.
#include "designers/cam/motion_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/cam_program.h"
#include "designers/cam/continuity.h"
#include "designers/cam/motion_law.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

MotionTable sampled(int rows, double (*law)(double), TableEnds ends) {
  MotionTable t{"law.csv", {}, {}, ends};
  for (int i = 0; i < rows; ++i) {
    const double x = i == rows - 1 ? 1.0 : static_cast<double>(i) / (rows - 1);
    t.x.push_back(x);
    t.s.push_back(i == rows - 1 ? 1.0 : law(x));
  }
  return t;
}

double p345(double x) { return x * x * x * (10 - 15 * x + 6 * x * x); }
double moving(double x) { return 0.5 * (x + std::pow(x, 5)); }  // S'(0) = ½, S'(1) = 3
double cycloid(double x) { return x - std::sin(2 * kPi * x) / (2 * kPi); }

TEST(MotionTable, RestEndsReproduceTheQuinticLawExactly) {
  const BSplineFunction f = interpolate_motion_table(sampled(11, p345, TableEnds::Rest));
  EXPECT_EQ(f.degree(), 5);
  for (int i = 0; i <= 1000; ++i) {
    const double x = i / 1000.0;
    double law[5];
    standard_law(MotionLaw::Polynomial345, x, 4, law);
    const Eigen::VectorXd d = f.derivatives(x, 4);
    for (int k = 0; k <= 4; ++k)
      EXPECT_NEAR(d(k), law[k], 1e-9 * std::max(1.0, std::abs(law[k]))) << x << " " << k;
  }
}

TEST(MotionTable, FreeEndsKeepTheDataSlope) {
  const BSplineFunction f = interpolate_motion_table(sampled(9, moving, TableEnds::Free));
  for (double x : {0.0, 0.37, 1.0}) {
    const Eigen::VectorXd d = f.derivatives(x, 2);
    EXPECT_NEAR(d(0), moving(x), 1e-12);
    EXPECT_NEAR(d(1), 0.5 * (1 + 5 * std::pow(x, 4)), 1e-10);
    EXPECT_NEAR(d(2), 10 * std::pow(x, 3), 1e-9);
  }
}

// A 101-row cycloid: within 1e-8 of the law, velocity within 1e-6; C⁴ inside (every interior knot
// simple in a quintic).
TEST(MotionTable, ACycloidTableConvergesAndIsC4Inside) {
  const BSplineFunction f = interpolate_motion_table(sampled(101, cycloid, TableEnds::Rest));
  double worst = 0, worst_v = 0;
  for (int i = 0; i <= 5000; ++i) {
    const double x = i / 5000.0;
    const Eigen::VectorXd d = f.derivatives(x, 1);
    worst = std::max(worst, std::abs(d(0) - cycloid(x)));
    worst_v = std::max(worst_v, std::abs(d(1) - (1 - std::cos(2 * kPi * x))));
  }
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_v, 1e-6);
  for (const Breakpoint& b : breakpoints(f.knots())) {
    if (b.value > 0 && b.value < 1) {
      EXPECT_EQ(b.multiplicity, 1) << b.value;
    }
  }
}

// On a segment: a rest table joins dwells with v = a = 0; a free table that starts moving shows
// up in the continuity diagnostics as a velocity jump naming both segments.
TEST(MotionTable, OnASegmentItsEndsMeetTheNeighboursOrAreReported) {
  const auto spec = [](const char* name, SegmentKind kind, double quarter, double lift,
                       MotionLaw law) {
    SegmentSpec s;
    s.name = name;
    s.kind = kind;
    s.start = quarter * kPi / 2;
    s.end = (quarter + 1) * kPi / 2;
    s.lift = lift;
    s.law = law;
    return s;
  };
  const SegmentSpec dwell1 = spec("dwell 1", SegmentKind::Dwell, 0, 0, MotionLaw::Cycloidal);
  SegmentSpec rise = spec("table", SegmentKind::Rise, 1, 10, MotionLaw::Table);
  rise.table = sampled(21, p345, TableEnds::Rest);
  const SegmentSpec dwell2 = spec("dwell 2", SegmentKind::Dwell, 2, 0, MotionLaw::Cycloidal);
  const SegmentSpec ret = spec("return", SegmentKind::Return, 3, 10, MotionLaw::Polynomial345);
  const CamProgram smooth({dwell1, rise, dwell2, ret});
  EXPECT_TRUE(check_continuity(smooth, 2).empty());
  EXPECT_NEAR(smooth(0.75 * kPi), 5, 1e-12);  // 3-4-5 at x = ½
  ASSERT_TRUE(smooth.exact());

  rise.table = sampled(21, moving, TableEnds::Free);
  const std::vector<ContinuityIssue> issues =
      check_continuity(CamProgram({dwell1, rise, dwell2, ret}), 2);
  ASSERT_FALSE(issues.empty());
  EXPECT_EQ(issues[0].derivative, 1);
  EXPECT_EQ(issues[0].after, "table");
  EXPECT_NEAR(issues[0].after_value, 10 * 0.5 / (kPi / 2), 1e-9);  // h S'(0) / β
}

TEST(MotionTable, FaultsNameRowAndField) {
  const MotionTable good = sampled(8, p345, TableEnds::Rest);
  EXPECT_FALSE(motion_table_fault(good));
  auto fault_of = [&](auto edit) {
    MotionTable t = good;
    edit(t);
    const auto f = motion_table_fault(t);
    return f ? std::to_string(f->row) + " " + f->field + ": " + f->expected : std::string("none");
  };
  EXPECT_EQ(fault_of([](MotionTable& t) { t.x[3] = t.x[2]; }),
            "3 x: x increasing strictly (after 0.285714)");
  EXPECT_EQ(fault_of([](MotionTable& t) { t.s[4] = std::nan(""); }), "4 S: a finite number");
  EXPECT_EQ(fault_of([](MotionTable& t) { t.s.back() = 0.9; }), "7 S: S = 1 in the last row");
  EXPECT_EQ(fault_of([](MotionTable& t) { t.x.front() = 0.1; }), "0 x: x = 0 in the first row");
  EXPECT_EQ(fault_of([](MotionTable& t) { t.x.resize(5), t.s.resize(5); }),
            "5 rows: between 6 and 100000 rows");
  MotionTable bad = good;
  std::swap(bad.x[2], bad.x[3]);
  try {
    interpolate_motion_table(bad);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "motion table 'law.csv': row 4, x: expected x increasing strictly (after 0.428571)");
  }
}

}  // namespace
}  // namespace polarform
