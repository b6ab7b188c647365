// BaseCircle: every configuration lies on the unit circle, its knot structure, and the parameter
// synchronization (2.7)–(2.8) for both arc kinds: the point at parameter(θ) is on the ray at θ and
// angle() inverts it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "src/base/base_circle.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

struct Config {
  std::string name;
  BaseCircle circle;
};

std::vector<Config> configs() {
  std::vector<Config> out;
  for (ArcKind kind : {ArcKind::rqb, ArcKind::quartic}) {
    const std::string k = kind == ArcKind::rqb ? "rqb" : "quartic";
    for (int arcs : {3, 4, 6})
      out.push_back({k + " closed " + std::to_string(arcs),
                     BaseCircle::equal_arcs(kind, 0.0, 2 * kPi, arcs)});
    for (int arcs = 1; arcs <= 8; ++arcs) {
      const double start = -1.3 + 0.7 * arcs;
      const double total = std::min(arcs * 2.9, 2 * kPi * 0.97);
      out.push_back({k + " partial " + std::to_string(arcs),
                     BaseCircle::equal_arcs(kind, start, start + total, arcs)});
      if (arcs >= 3)
        out.push_back({k + " closed unit " + std::to_string(arcs),
                       BaseCircle::equal_arcs(kind, start, start + 2 * kPi, arcs, AlphaRule::printed,
                                              ArcParametrization::unit)});
    }
    out.push_back({k + " unequal", BaseCircle(kind, {-0.4, 0.1, 1.9, 2.2, 4.5, 5.0})});
    out.push_back({k + " unequal closed",
                   BaseCircle(kind, {-2.0, -1.95, 0.5, 1.0, 3.5, -2.0 + 2 * kPi}, AlphaRule::minimax,
                              ArcParametrization::unit)});
    out.push_back({k + " fewest full", BaseCircle::fewest_arcs(kind, 1.0, 1.0 + 2 * kPi)});
    out.push_back({k + " fewest partial", BaseCircle::fewest_arcs(kind, 0.2, 3.0)});
    out.push_back({k + " square-based", BaseCircle::with_max_sweep(kind, 0.0, 5.0, kPi / 2)});
  }
  out.push_back({"quartic half circle", BaseCircle::equal_arcs(ArcKind::quartic, 0.3, 0.3 + kPi, 1)});
  out.push_back({"quartic two 180", BaseCircle::equal_arcs(ArcKind::quartic, -0.7, -0.7 + 2 * kPi, 2)});
  return out;
}

double wrap(double a) { return std::remainder(a, 2 * kPi); }

TEST(BaseCircle, EveryPointOnTheUnitCircle) {
  for (const Config& c : configs()) {
    const NurbsCurve2d& B = c.circle.curve();
    double worst = 0;
    const int n = 2000 * c.circle.arcs();
    for (int i = 0; i <= n; ++i) {
      const double u = B.front() + (B.back() - B.front()) * i / n;
      worst = std::max(worst, std::abs(B(u).norm() - 1.0));
    }
    EXPECT_LT(worst, 1e-14) << c.name;
  }
}

TEST(BaseCircle, KnotsWeightsAndBreakpoints) {
  for (const Config& c : configs()) {
    const BaseCircle& b = c.circle;
    const NurbsCurve2d& B = b.curve();
    const int p = b.kind() == ArcKind::rqb ? 2 : 4, k = b.arcs();
    ASSERT_EQ(B.degree(), p) << c.name;
    ASSERT_EQ(B.size(), k * p + 1) << c.name;
    ASSERT_EQ(static_cast<int>(b.parameters().size()), k + 1);
    for (int j = 0; j <= k; ++j) {
      const double u = b.parameters()[j];
      EXPECT_EQ(u, b.parametrization() == ArcParametrization::angle ? b.breakpoints()[j] : j);
      EXPECT_EQ(multiplicity(B.knots(), u), j == 0 || j == k ? p + 1 : p) << c.name;
      EXPECT_NEAR(wrap(std::atan2(B(u).y(), B(u).x()) - b.breakpoints()[j]), 0.0, 1e-15) << c.name;
      EXPECT_NEAR(b.angle(u), b.breakpoints()[j], 1e-15);
    }
    for (int j = 0; j < k; ++j) {
      const double half = (b.breakpoints()[j + 1] - b.breakpoints()[j]) / 2;
      EXPECT_EQ(b.alpha(j), b.kind() == ArcKind::rqb ? 1.0 : quartic_alpha(half, b.alpha_rule()));
      if (b.kind() == ArcKind::rqb) {
        EXPECT_NEAR(B.weight(2 * j + 1), std::cos(half), 1e-16);
      }
    }
    EXPECT_EQ(b.closed(), std::abs(b.breakpoints().back() - b.breakpoints().front() - 2 * kPi) < 1e-12)
        << c.name;
  }
}

TEST(BaseCircle, SynchronizationPutsThePointOnTheRay) {
  std::mt19937 rng(11);
  for (const Config& c : configs()) {
    const BaseCircle& b = c.circle;
    const double t0 = b.breakpoints().front(), t1 = b.breakpoints().back();
    // A closed circle accepts any angle; an open one its range.
    std::uniform_real_distribution<double> angle(b.closed() ? t0 - 13.0 : t0, b.closed() ? t1 + 9.0 : t1);
    std::vector<double> theta(100000), u(theta.size());
    for (double& t : theta) t = angle(rng);
    b.parameters(theta.data(), u.data(), theta.size());
    double ray = 0, back = 0;
    for (std::size_t i = 0; i < theta.size(); ++i) {
      EXPECT_EQ(u[i], b.parameter(theta[i]));
      ASSERT_GE(u[i], b.curve().front());
      ASSERT_LE(u[i], b.curve().back());
      const Eigen::Vector2d p = b.curve()(u[i]);
      ray = std::max(ray, std::abs(wrap(std::atan2(p.y(), p.x()) - theta[i])));
      const double a = b.angle(u[i]);
      back = std::max(back, std::abs(b.closed() ? wrap(a - theta[i]) : a - theta[i]));
    }
    EXPECT_LT(ray, 1e-13) << c.name;
    EXPECT_LT(back, 1e-13) << c.name;
  }
}

TEST(BaseCircle, AngleIsIncreasingAndInvertsParameter) {
  std::mt19937 rng(5);
  for (const Config& c : configs()) {
    const BaseCircle& b = c.circle;
    const NurbsCurve2d& B = b.curve();
    std::uniform_real_distribution<double> param(B.front(), B.back());
    double worst = 0, ray = 0;
    for (int i = 0; i < 20000; ++i) {
      const double u = param(rng), a = b.angle(u);
      worst = std::max(worst, std::abs(b.parameter(a) - u));
      ray = std::max(ray, std::abs(wrap(std::atan2(B(u).y(), B(u).x()) - a)));
    }
    EXPECT_LT(worst, 1e-13) << c.name;
    EXPECT_LT(ray, 1e-13) << c.name;
    double previous = b.angle(B.front());
    for (int i = 1; i <= 5000; ++i) {
      const double a = b.angle(B.front() + (B.back() - B.front()) * i / 5000);
      ASSERT_GT(a, previous) << c.name;
      previous = a;
    }
    EXPECT_NEAR(previous, b.breakpoints().back(), 1e-15);
  }
}

TEST(BaseCircle, FewestArcs) {
  EXPECT_EQ(BaseCircle::fewest_arcs(ArcKind::rqb, 0, 2 * kPi).arcs(), 3);
  EXPECT_EQ(BaseCircle::fewest_arcs(ArcKind::quartic, 0, 2 * kPi).arcs(), 2);
  EXPECT_EQ(BaseCircle::fewest_arcs(ArcKind::rqb, 0, kPi).arcs(), 2);
  EXPECT_EQ(BaseCircle::fewest_arcs(ArcKind::quartic, 0, kPi).arcs(), 1);
  EXPECT_EQ(BaseCircle::fewest_arcs(ArcKind::rqb, 0, 3.0).arcs(), 1);
  EXPECT_EQ(BaseCircle::with_max_sweep(ArcKind::rqb, 0, 2 * kPi, kPi / 2).arcs(), 4);
  EXPECT_EQ(BaseCircle::with_max_sweep(ArcKind::quartic, 0, 2 * kPi, kPi / 3).arcs(), 6);
  EXPECT_EQ(BaseCircle::with_max_sweep(ArcKind::rqb, 0, kPi / 2 + 1e-3, kPi / 2).arcs(), 2);
}

TEST(BaseCircle, MalformedInputThrows) {
  EXPECT_THROW(BaseCircle(ArcKind::rqb, {0.0, 1.0, 0.5}), InputError);          // unsorted
  EXPECT_THROW(BaseCircle(ArcKind::rqb, {0.0, 1.0, 1.0, 2.0}), InputError);     // repeated
  EXPECT_THROW(BaseCircle(ArcKind::rqb, {0.0, kPi}), InputError);               // RQB arc of π
  EXPECT_THROW(BaseCircle(ArcKind::rqb, {0.0, 3.5}), InputError);               // RQB arc > π
  EXPECT_THROW(BaseCircle(ArcKind::quartic, {0.0, 3.2}), InputError);           // quartic arc > π
  EXPECT_THROW(BaseCircle(ArcKind::quartic, {0.0, 3.0, 6.0, 6.3}), InputError); // total > 2π
  EXPECT_THROW(BaseCircle(ArcKind::quartic, {1.0}), InputError);
  EXPECT_THROW(BaseCircle(ArcKind::quartic, {0.0, NAN}), InputError);
  EXPECT_THROW(BaseCircle::equal_arcs(ArcKind::rqb, 0, 1, 0), InputError);
  EXPECT_THROW(BaseCircle::equal_arcs(ArcKind::rqb, 0, 2 * kPi, 2), InputError);
  EXPECT_THROW(BaseCircle::fewest_arcs(ArcKind::rqb, 0, 7), InputError);
  EXPECT_THROW(BaseCircle::fewest_arcs(ArcKind::rqb, 1, 1), InputError);
  EXPECT_NO_THROW(BaseCircle(ArcKind::quartic, {0.0, kPi}));
  const BaseCircle open = BaseCircle::equal_arcs(ArcKind::rqb, 0.0, 3.0, 2);
  EXPECT_THROW(open.parameter(3.1), InputError);
  EXPECT_THROW(open.parameter(-0.1), InputError);
  EXPECT_THROW(open.angle(3.1), InputError);
  EXPECT_THROW(open.alpha(2), InputError);
  EXPECT_NO_THROW(BaseCircle::equal_arcs(ArcKind::rqb, 0.0, 2 * kPi, 3).parameter(-100.0));
}

}  // namespace
}  // namespace polarform
