// The sweep job's extrusion bundle read back by Open CASCADE: solid.stp is one valid solid whose
// volume is the recovered section's area times the length (the exact prism's π·a·b·L within the
// fit's tolerance), placed where the points are (its centre of mass on the prism's axis);
// surface.stp is the extruded surface itself (points within 1e-9 mm). The kind sections' skin of a
// bent tube arrives as one face carrying the same surface.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <fstream>
#include <numbers>
#include <random>

#include "jobs/sweep/sweep_outputs.h"
#include "tests/support/export/exchange_fixtures.h"

#if POLARFORM_HAVE_OCCT
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "tests/support/export/occt_readback.h"
#endif

namespace polarform {
namespace {

#if POLARFORM_HAVE_OCCT
using namespace exchange_test;

TEST(SweepOcct, ExtrusionSolidAndSurfaceArriveIntact) {
  const ScratchDir dir("sweep_occt");
  const double a = 20, b = 10, length = 60;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(2, -1, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(4, 5, -6);
  {
    std::ofstream out(dir / "prism.xyz");
    out.precision(17);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 8000; ++k) {
      const double t = 2 * std::numbers::pi * U(rng);
      // Ends exactly at 0 and L so that the extent is the prism's.
      const double h = k == 0 ? 0.0 : k == 1 ? length : length * U(rng);
      const Eigen::Vector3d p = R * Eigen::Vector3d(a * std::cos(t), b * std::sin(t), h) + shift;
      out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
  }
  SweepJobOptions o;
  o.tolerance = 1e-3;
  const SweepJobResult r = run_sweep_job(dir / "prism.xyz", o);
  ASSERT_TRUE(r.is_extrusion);
  write_sweep_outputs(r, dir / "out");

  const TopoDS_Shape solid = read_exchange_file(dir / "out" / "solid.stp");
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(solid, TopAbs_SOLID, solids);
  EXPECT_EQ(solids.Extent(), 1);
  EXPECT_TRUE(BRepCheck_Analyzer(solid).IsValid());
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props, 1e-9);
  const double exact = std::numbers::pi * a * b * length;
  // The section is within 1e-3 mm of the ellipse: the area within perimeter · 1e-3.
  EXPECT_LT(std::abs(props.Mass() - exact), 97.0 * 1e-3 * length) << props.Mass();
  const gp_Pnt g = props.CentreOfMass();
  const Eigen::Vector3d centre = R * Eigen::Vector3d(0, 0, length / 2) + shift;
  EXPECT_LT((Eigen::Vector3d(g.X(), g.Y(), g.Z()) - centre).norm(), 1e-3);

  const TopoDS_Shape surface = read_exchange_file(dir / "out" / "surface.stp");
  const std::vector<TopoDS_Face> faces = faces_of(surface);
  ASSERT_EQ(faces.size(), 1u);
  expect_same_surface(faces[0], r.fit().surfaces[0], false);
}

TEST(SweepOcct, SectionsSkinArrivesIntact) {
  const ScratchDir dir("sweep_occt_sections");
  {
    std::ofstream out(dir / "bent.xyz");
    out.precision(17);
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 6000; ++k) {  // a torus segment: spine radius 40, tube radius 4, 90°
      const double phi = 0.5 * std::numbers::pi * U(rng), th = 2 * std::numbers::pi * U(rng);
      const double rho = 40 + 4 * std::cos(th);
      out << rho * std::cos(phi) << ' ' << rho * std::sin(phi) << ' ' << 4 * std::sin(th) << '\n';
    }
  }
  SweepJobOptions o;
  o.kind = SweepKind::sections;
  const SweepJobResult r = run_sweep_job(dir / "bent.xyz", o);
  ASSERT_TRUE(r.is_sections);
  write_sweep_outputs(r, dir / "out");
  const std::vector<TopoDS_Face> faces = faces_of(read_exchange_file(dir / "out" / "surface.stp"));
  ASSERT_EQ(faces.size(), 1u);
  expect_same_surface(faces[0], r.fit().surfaces[0], false);
}

#else

TEST(SweepOcct, Skipped) {
  GTEST_SKIP() << "Open CASCADE (libocct-data-exchange-dev) not found at configure time";
}

#endif

}  // namespace
}  // namespace polarform
