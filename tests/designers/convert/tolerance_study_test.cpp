// Conversion studies: log-spaced tolerances land exactly on the decades; every method's measured
// error (the peers' included) meets each tolerance; tightening the tolerance never lowers a
// control-point count; the quasi-uniform quartic arc (minimax α) deviates less from the uniform
// angle than the RQB arc.
#include "designers/convert/tolerance_study.h"

#include <gtest/gtest.h>

#include "designers/cam/contour_polar_function.h"
#include "designers/convert/occt_peer.h"
#include "designers/convert/sisl_peer.h"
#include "src/error.h"
#include "src/units.h"
#include "tests/support/designers/example_cams.h"

namespace polarform {
namespace {

TEST(LogTolerances, DecadesAreExactAndOrdered) {
  const std::vector<double> t = log_tolerances(1e-2, 1e-7, 2);
  ASSERT_EQ(t.size(), 11u);
  EXPECT_EQ(t.front(), 1e-2);
  EXPECT_EQ(t[4], 1e-4);
  EXPECT_EQ(t[6], 1e-5);
  EXPECT_EQ(t.back(), 1e-7);
  EXPECT_NEAR(t[1], 3.16227766017e-3, 1e-14);
  for (std::size_t k = 1; k < t.size(); ++k) EXPECT_LT(t[k], t[k - 1]);
  EXPECT_EQ(log_tolerances(1e-3, 1e-3, 4), std::vector<double>{1e-3});
}

TEST(LogTolerances, RejectsBadRanges) {
  EXPECT_THROW(log_tolerances(1e-6, 1e-3, 2), InputError);
  EXPECT_THROW(log_tolerances(1e-3, 0.0, 2), InputError);
  EXPECT_THROW(log_tolerances(1e-2, 1e-3, 0), InputError);
}

TEST(ToleranceStudy, EveryMethodMeetsEveryTolerance) {
  const PolarFunction R = cam_polar_function(make_plate_cam(test::example_cam_design("roller")));
  const std::vector<double> tols = log_tolerances(1e-2, 1e-5, 1);
  int calls = 0;
  const std::vector<StudyRow> rows = tolerance_study(R, tols, [&](double) { ++calls; });
  ASSERT_EQ(rows.size(), tols.size());
  EXPECT_EQ(calls, static_cast<int>(tols.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const StudyRow& r = rows[k];
    EXPECT_EQ(r.tolerance, tols[k]);
    for (const StudyMethodResult* m : {&r.quartic, &r.rqb, &r.cubic, &r.exact, &r.degree3}) {
      EXPECT_GT(m->max_radial_error, 0.0);
      EXPECT_LE(m->max_radial_error, r.tolerance);
    }
    EXPECT_EQ(r.cubic.degree, 3);
    EXPECT_EQ(r.degree3.degree, 3);
    EXPECT_EQ(r.peers, kOcctPeersAvailable || kSislPeersAvailable);
    for (const StudyPeerResult* p :
         {&r.occt_degree3, &r.occt_best, &r.sisl_degree3, &r.sisl_best}) {
      if (p->found) {
        EXPECT_LE(p->max_radial_error, r.tolerance);
      }
    }
    EXPECT_GT(r.quartic.arcs, 0);
    EXPECT_GT(r.rqb.arcs, r.quartic.arcs);  // RQB arcs must be shorter for the same tolerance
    if (k > 0) {
      EXPECT_GE(r.quartic.control_points, rows[k - 1].quartic.control_points);
      EXPECT_GE(r.rqb.control_points, rows[k - 1].rqb.control_points);
      EXPECT_GE(r.cubic.control_points, rows[k - 1].cubic.control_points);
    }
  }
}

TEST(AngleDeviationStudy, QuarticMinimaxBeatsRqbAtEveryAngle) {
  const std::vector<DeviationRow> rows = angle_deviation_study(12);
  ASSERT_EQ(rows.size(), 12u);
  EXPECT_NEAR(rows.front().arc_angle, 2 * kRadiansPerDegree, 1e-15);
  EXPECT_NEAR(rows.back().arc_angle, std::numbers::pi, 1e-13);
  for (const DeviationRow& r : rows) {
    EXPECT_LT(r.quartic_minimax, r.rqb);
    EXPECT_LE(r.quartic_minimax, r.quartic_printed * (1 + 1e-12));
  }
  EXPECT_THROW(angle_deviation_study(1), InputError);
}

}  // namespace
}  // namespace polarform
