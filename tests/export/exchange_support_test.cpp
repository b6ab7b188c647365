// Shared exchange helpers: round-trip real formatting, reproducible time stamps, closure /
// periodicity / planarity facts, exact iso-curves and curve reversal, each against closed forms or
// dense evaluation.
#include <gtest/gtest.h>

#include <cstdlib>
#include <ctime>
#include <random>

#include "export/exchange_geometry.h"
#include "export/exchange_text.h"
#include "src/error.h"
#include "tests/support/export/exchange_fixtures.h"

namespace polarform {
namespace {

using namespace exchange_test;

TEST(ExchangeReal, ShortestRoundTripWithDecimalPoint) {
  EXPECT_EQ(exchange_real(1.0), "1.0");
  EXPECT_EQ(exchange_real(-0.0), "0.0");
  EXPECT_EQ(exchange_real(0.25), "0.25");
  EXPECT_EQ(exchange_real(-1e-7), "-1.0E-07");
  EXPECT_EQ(exchange_real(1e-7, 'D'), "1.0D-07");
  EXPECT_EQ(exchange_real(6.02e23), "6.02E+23");
  EXPECT_EQ(exchange_real(100.0), "100.0");
  EXPECT_THROW(exchange_real(std::nan("")), InputError);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int i = 0; i < 20000; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng) * 3);
    const std::string text = exchange_real(x);
    ASSERT_NE(text.find('.'), std::string::npos) << text;
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
  }
}

// IGES carries ASCII only: names from the user's files fold to their base letters, anything else
// (and bytes that are not UTF-8) to '_'.
TEST(ExchangeText, AsciiFoldsLatinLettersAndReplacesTheRest) {
  EXPECT_EQ(ascii_text("polarform 0.1.0 cam rôle"), "polarform 0.1.0 cam role");
  EXPECT_EQ(ascii_text("tête mesure_é Łódź Straße Æsir œuvre"),
            "tete mesure_e Lodz Strasse AEsir oeuvre");
  EXPECT_EQ(ascii_text("ÀÿĀſ"), "AyAs");                // the ends of both tables
  EXPECT_EQ(ascii_text("θ = 30° ≤ π"), "_ = 30_ _ _");  // Greek, signs: no ASCII letter
  EXPECT_EQ(ascii_text("tab\there"), "tab_here");
  EXPECT_EQ(ascii_text("latin-1 \xE9t\xE9 \xC3"), "latin-1 _t_ _");  // not UTF-8
  EXPECT_EQ(ascii_text("emoji \xF0\x9F\x99\x82!"), "emoji _!");
}

// SOURCE_DATE_EPOCH (reproducible-builds.org) fixes the files' time stamps; a malformed value is
// bad input naming the variable; without it the stamp is the current time.
TEST(ExchangeTimeStamp, SourceDateEpochFixesTheStamp) {
  const char* saved = std::getenv("SOURCE_DATE_EPOCH");
  const std::string before = saved ? saved : "";
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  EXPECT_EQ(utc_time_stamp("%Y%m%d.%H%M%S"), "20231114.221320");
  for (const char* bad : {"", "17e8", "-5", "12 ", "now"}) {
    ::setenv("SOURCE_DATE_EPOCH", bad, 1);
    try {
      utc_time_stamp("%Y");
      ADD_FAILURE() << "accepted SOURCE_DATE_EPOCH=\"" << bad << "\"";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("SOURCE_DATE_EPOCH"), std::string::npos) << e.what();
    }
  }
  ::unsetenv("SOURCE_DATE_EPOCH");
  const std::time_t now = std::time(nullptr);
  EXPECT_LE(std::abs(static_cast<double>(stamp_time() - now)), 2.0);
  if (saved) ::setenv("SOURCE_DATE_EPOCH", before.c_str(), 1);
}

TEST(ExchangeGeometry, ClosureAndPeriodicStructure) {
  const NurbsCurve3d circle = lift_to_3d(ellipse(25, 25));
  EXPECT_TRUE(is_closed(circle, 1e-12));
  EXPECT_FALSE(has_periodic_structure(circle.homogeneous()));  // clamped
  EXPECT_FALSE(is_closed(open_cubic(), 1e-6));
  const NurbsCurve3d periodic = periodic_cubic();
  EXPECT_TRUE(has_periodic_structure(periodic.homogeneous()));
  EXPECT_LT((periodic.point(periodic.front()) - periodic.point(periodic.back())).norm(), 1e-12);
  Eigen::MatrixXd c = periodic.homogeneous().coefs();
  c(2, 6) = 0.5;
  EXPECT_FALSE(has_periodic_structure(BSpline(3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, c)));
}

TEST(ExchangeGeometry, PlaneNormal) {
  const auto z = plane_normal(control_points_of(lift_to_3d(ellipse(30, 20))), 1e-9);
  ASSERT_TRUE(z.has_value());
  EXPECT_EQ(*z, Eigen::Vector3d::UnitZ());
  EXPECT_FALSE(plane_normal(control_points_of(degree12()), 1e-6).has_value());
  // Points on the tilted plane x + 2y + 2z = 3 give the normal (1, 2, 2) / 3.
  std::vector<Eigen::Vector3d> tilted;
  for (double s : {0.0, 1.0, 4.0, -3.0})
    for (double t : {0.0, 2.0, -1.0}) tilted.emplace_back(3 - 2 * s - 2 * t, s, t);
  const auto n = plane_normal(tilted, 1e-9);
  ASSERT_TRUE(n.has_value());
  EXPECT_NEAR((*n - Eigen::Vector3d(1, 2, 2) / 3).norm(), 0.0, 1e-12);
}

TEST(ExchangeGeometry, IsoCurvesReversalAndTranslation) {
  const NurbsSurface s = rational55();
  for (double u : linspace(s.front_u(), s.back_u(), 7)) {
    const NurbsCurve3d iso = iso_curve_at_u(s, u);
    for (double v : linspace(s.front_v(), s.back_v(), 11))
      EXPECT_LT((iso.point(v) - s.point(u, v)).norm(), 1e-11);
  }
  for (double v : linspace(s.front_v(), s.back_v(), 7)) {
    const NurbsCurve3d iso = iso_curve_at_v(s, v);
    for (double u : linspace(s.front_u(), s.back_u(), 11))
      EXPECT_LT((iso.point(u) - s.point(u, v)).norm(), 1e-11);
  }
  EXPECT_TRUE(is_degenerate(iso_curve_at_u(sphere_octant(10), 1.0), 1e-12));
  EXPECT_TRUE(is_closed_v(sphere(10), 1e-12));
  EXPECT_FALSE(is_closed_u(sphere(10), 1e-6));
  const NurbsCurve3d c = degree12(), r = reversed(c);
  const NurbsCurve3d moved = translated(c, Eigen::Vector3d(1, -2, 3));
  for (double u : linspace(c.front(), c.back(), 50)) {
    EXPECT_LT((r.point(c.front() + c.back() - u) - c.point(u)).norm(), 1e-10);
    EXPECT_LT((moved.point(u) - c.point(u) - Eigen::Vector3d(1, -2, 3)).norm(), 1e-10);
  }
}

TEST(ExchangeGeometry, RejectsWhatImportersCannotTake) {
  EXPECT_NO_THROW(require_exchangeable(3, clamped_knots(3, 0, 1, {0.5, 0.5, 0.5}), "c"));
  EXPECT_THROW(require_exchangeable(3, clamped_knots(3, 0, 1, {0.5, 0.5, 0.5, 0.5}), "c"),
               InputError);
  EXPECT_THROW(require_exchangeable(0, {0, 1, 2}, "c"), InputError);
}

}  // namespace
}  // namespace polarform
