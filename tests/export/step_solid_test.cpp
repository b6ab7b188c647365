// The extruded cam solid read back by Open CASCADE: a valid B-rep (BRepCheck_Analyzer), exactly
// one solid with the expected faces, no reader messages, and a volume (GProp) equal to the closed
// form (pi a b - pi r^2) t of an exact rational ellipse profile with a bore, to 1e-6 relative, for
// quadratic, degree-9 and degree-12 profiles and for a clockwise profile; bad input is refused.
#include "export/step_solid.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "export/atomic_file.h"
#include "export/exchange_geometry.h"
#include "src/error.h"
#include "tests/support/export/exchange_fixtures.h"

#if POLARFORM_HAVE_OCCT
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "tests/support/export/occt_readback.h"
#endif

namespace polarform {
namespace {

using namespace exchange_test;

StepHeader header() {
  StepHeader h;
  h.time_stamp = "2024-05-01T12:00:00Z";
  return h;
}

TEST(StepSolid, WritesAnAdvancedBrepPart) {
  const std::string text = step_extruded_solid(ellipse(40, 25), 12.0, 20.0, "cam", header());
  for (const char* entity : {"ADVANCED_BREP_SHAPE_REPRESENTATION", "MANIFOLD_SOLID_BREP",
                             "CLOSED_SHELL", "B_SPLINE_SURFACE(2,1,", "CYLINDRICAL_SURFACE",
                             "FACE_OUTER_BOUND", "FACE_BOUND", "SI_UNIT(.MILLI.,.METRE.)",
                             "PRODUCT('cam','cam'", "FILE_NAME('polarform.stp','2024-05-01T12:00:00Z'"})
    EXPECT_NE(text.find(entity), std::string::npos) << entity;
  std::size_t faces = 0;
  for (std::size_t at = 0; (at = text.find("ADVANCED_FACE(", at)) != std::string::npos; ++at) ++faces;
  EXPECT_EQ(faces, 4u);  // side, bore, bottom, top
}

TEST(StepSolid, RefusesBadInput) {
  const NurbsCurve2d profile = ellipse(40, 25);
  EXPECT_THROW(step_extruded_solid(profile, 0.0, std::nullopt), InputError);
  EXPECT_THROW(step_extruded_solid(profile, std::nan(""), std::nullopt), InputError);
  EXPECT_THROW(step_extruded_solid(profile, 10.0, 50.0), InputError);   // bore wider than 2 b
  EXPECT_THROW(step_extruded_solid(profile, 10.0, -5.0), InputError);
  EXPECT_THROW(step_extruded_solid(ellipse(10, 10, {30, 0}), 10.0, 4.0), InputError);  // off axis
  const NurbsCurve2d open(2, clamped_knots(2, 0, 1), {{0, 0}, {10, 0}, {10, 10}});
  EXPECT_THROW(step_extruded_solid(open, 10.0, std::nullopt), InputError);
}

#if POLARFORM_HAVE_OCCT

struct SolidCase {
  std::string label;
  NurbsCurve2d profile;
  double a, b, thickness;
  std::optional<double> bore;
};

TEST(StepSolidOcct, ValidSolidWithClosedFormVolume) {
  const std::vector<SolidCase> cases = {
      {"quadratic ellipse with bore", ellipse(40, 25), 40, 25, 12, 20.0},
      {"degree-9 ellipse, no bore", elevate_bezier_chain(ellipse(40, 25), 9), 40, 25, 8, std::nullopt},
      {"degree-12 circle with bore", elevate_bezier_chain(ellipse(30, 30), 12), 30, 30, 15, 12.0},
      {"clockwise ellipse with bore", reversed(ellipse(35, 28)), 35, 28, 10, 16.0},
  };
  const ScratchDir dir("step_solid");
  for (const SolidCase& c : cases) {
    SCOPED_TRACE(c.label);
    const auto path = dir / "cam.stp";
    write_step_extruded_solid(path, c.profile, c.thickness, c.bore, "cam", header());
    STEPControl_Reader reader;
    ASSERT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
    reader.TransferRoots();
    // Open CASCADE re-forms the closed B-spline side face as periodic and says so.
    EXPECT_EQ(reader_messages(reader.WS()), "warning: Surface forced to be periodic\n");
    const TopoDS_Shape shape = reader.OneShape();
    TopTools_IndexedMapOfShape solids, faces;
    TopExp::MapShapes(shape, TopAbs_SOLID, solids);
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    EXPECT_EQ(solids.Extent(), 1);
    EXPECT_EQ(faces.Extent(), c.bore ? 4 : 3);
    EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props, 1e-10);
    const double r = c.bore.value_or(0.0) / 2;
    const double exact = std::numbers::pi * (c.a * c.b - r * r) * c.thickness;
    EXPECT_LT(std::abs(props.Mass() - exact) / exact, 1e-6)
        << "volume " << props.Mass() << " vs closed form " << exact;
    RecordProperty(c.label, sci(std::abs(props.Mass() - exact) / exact));
  }
}

// A placed solid (the sweep job's extrusion in its own frame): the same volume, and the centre of
// mass (the ellipse's centre at mid-height in the profile frame) moved by the placement to 1e-7.
TEST(StepSolidOcct, PlacedSolidIsRigidlyMoved) {
  Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();
  placement.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 0.5).normalized()).toRotationMatrix();
  placement.translation() = Eigen::Vector3d(12, -7, 31);
  const ScratchDir dir("step_solid_placed");
  const auto path = dir / "placed.stp";
  write_file_atomically(path, step_extruded_solid(ellipse(40, 25, {3, -2}), 12.0, std::nullopt,
                                                  "extrusion", header(), placement));
  STEPControl_Reader reader;
  ASSERT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
  reader.TransferRoots();
  const TopoDS_Shape shape = reader.OneShape();
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props, 1e-10);
  const double exact = std::numbers::pi * 40 * 25 * 12;
  EXPECT_LT(std::abs(props.Mass() - exact) / exact, 1e-6);
  const gp_Pnt g = props.CentreOfMass();
  const Eigen::Vector3d expected = placement * Eigen::Vector3d(3, -2, 6);
  EXPECT_LT((Eigen::Vector3d(g.X(), g.Y(), g.Z()) - expected).norm(), 1e-7);
}

#else

TEST(StepSolidOcct, Skipped) {
  GTEST_SKIP() << "Open CASCADE (libocct-data-exchange-dev) not found at configure time: "
                  "solid validity and volume not tested";
}

#endif

}  // namespace
}  // namespace polarform
