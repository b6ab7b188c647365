// A barrel cam's two groove walls (rational, closed in u, C0 knots at the base arcs' junctions)
// written to IGES and STEP and read back by Open CASCADE: no fail messages, two faces, each the
// wall's B-spline (degrees, and points within 1e-9 mm at 200 parameters) and a valid face. The
// walls of designers/cam through the writers of export/, as the cam job joins them.
#include <gtest/gtest.h>

#include <numbers>

#include "designers/cam/groove_surface.h"
#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "tests/support/export/exchange_fixtures.h"

#if POLARFORM_HAVE_OCCT
#include <BRepCheck_Analyzer.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>

#include "tests/support/export/occt_readback.h"
#endif

namespace polarform {
namespace {

using namespace exchange_test;

#if POLARFORM_HAVE_OCCT

std::vector<NurbsSurface> walls() {
  constexpr double pi = std::numbers::pi;
  SegmentSpec rise, dwell, ret;
  rise.kind = SegmentKind::Rise, rise.start = 0, rise.end = pi / 2, rise.lift = 20;
  rise.law = MotionLaw::Cycloidal;
  dwell.kind = SegmentKind::Dwell, dwell.start = pi / 2, dwell.end = pi;
  ret.kind = SegmentKind::Return, ret.start = pi, ret.end = 2 * pi, ret.lift = 20;
  ret.law = MotionLaw::Polynomial345;
  const BarrelCam cam(CamProgram({rise, dwell, ret}), 50.0, 0.0, 6.0);
  std::vector<NurbsSurface> out;
  for (int side : {-1, 1}) out.push_back(groove_surface(cam, side, {45.0, 55.0, 1e-3}).surface);
  return out;
}

void expect_walls(const TopoDS_Shape& shape, const std::vector<NurbsSurface>& s) {
  const std::vector<TopoDS_Face> faces = faces_of(shape);
  ASSERT_EQ(faces.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    SCOPED_TRACE("wall " + std::to_string(i));
    // Faces may come in either order: match by the height at the first corner.
    const gp_Pnt q = BRep_Tool::Surface(faces[i])->Value(s[0].front_u(), s[0].front_v());
    const double z0 = s[0].point(s[0].front_u(), s[0].front_v()).z();
    const std::size_t k = std::abs(q.Z() - z0) < 1e-6 ? 0 : 1;
    expect_same_surface(faces[i], s[k], false);
    EXPECT_TRUE(BRepCheck_Analyzer(faces[i]).IsValid());
  }
}

TEST(GrooveOcct, IgesWallsArriveIntact) {
  const std::vector<NurbsSurface> s = walls();
  const ScratchDir dir("groove_iges");
  IgesWriter w;
  for (const NurbsSurface& wall : s) w.add(wall, "groove wall");
  IgesHeader h;
  h.time_stamp = "20240501.120000";
  w.save(dir / "groove.igs", h);
  IGESControl_Reader reader;
  ASSERT_TRUE(Interface_Static::SetIVal("read.iges.bspline.continuity", 0));
  ASSERT_EQ(reader.ReadFile((dir / "groove.igs").c_str()), IFSelect_RetDone);
  reader.TransferRoots();
  Interface_Static::SetIVal("read.iges.bspline.continuity", 1);  // the reader's default
  EXPECT_EQ(reader_messages(reader.WS(), true), "");
  expect_walls(reader.OneShape(), s);
}

TEST(GrooveOcct, StepWallsArriveIntact) {
  const std::vector<NurbsSurface> s = walls();
  const ScratchDir dir("groove_step");
  StepWriter w("groove");
  for (const NurbsSurface& wall : s) w.add(wall, "groove wall");
  StepHeader h;
  h.time_stamp = "2024-05-01T12:00:00Z";
  w.save(dir / "groove.stp", h);
  STEPControl_Reader reader;
  ASSERT_EQ(reader.ReadFile((dir / "groove.stp").c_str()), IFSelect_RetDone);
  reader.TransferRoots();
  EXPECT_EQ(reader_messages(reader.WS(), true), "");
  expect_walls(reader.OneShape(), s);
}

#else

TEST(GrooveOcct, Skipped) {
  GTEST_SKIP() << "Open CASCADE not found at configure time: groove read-back not tested";
}

#endif

}  // namespace
}  // namespace polarform
