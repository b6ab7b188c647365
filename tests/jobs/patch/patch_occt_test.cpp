// The patch job's surface.stp and surface.igs read back by Open CASCADE: one face, the fitted
// B-spline surface itself (degrees, knots, poles and points within 1e-9 mm) and a valid face.
#include <gtest/gtest.h>

#include <fstream>

#include "jobs/patch/patch_outputs.h"
#include "tests/support/export/exchange_fixtures.h"
#include "tests/support/src/synthetic_patches.h"

#if POLARFORM_HAVE_OCCT
#include <BRepCheck_Analyzer.hxx>

#include "tests/support/export/occt_readback.h"
#endif

namespace polarform {
namespace {

#if POLARFORM_HAVE_OCCT

using namespace exchange_test;

TEST(PatchOcct, TheFittedSurfaceArrivesIntact) {
  const ScratchDir dir("patch_occt");
  const NurbsSurface truth = patch_test::wavy_patch(1.5);
  const auto sample = patch_test::sample_patch(truth, 3000, 0.01, 3);
  {
    std::ofstream scan(dir / "scan.xyz"), boundary(dir / "boundary.csv");
    scan.precision(17);
    boundary.precision(17);
    for (Eigen::Index k = 0; k < sample.points.cols(); ++k)
      scan << sample.points(0, k) << ' ' << sample.points(1, k) << ' ' << sample.points(2, k)
           << '\n';
    boundary << "curve,x,y,z\n";
    const auto loop = patch_test::boundary_polylines(truth, 80);
    for (int c = 0; c < 4; ++c)
      for (Eigen::Index k = 0; k < 80; ++k)
        boundary << c << ',' << loop[static_cast<std::size_t>(c)](0, k) << ','
                 << loop[static_cast<std::size_t>(c)](1, k) << ','
                 << loop[static_cast<std::size_t>(c)](2, k) << '\n';
  }
  PatchJobOptions o;
  o.boundary_file = dir / "boundary.csv";
  const PatchJobResult r = run_patch_job(dir / "scan.xyz", o);
  write_patch_outputs(r, dir / "out");
  for (const char* file : {"surface.stp", "surface.igs"}) {
    SCOPED_TRACE(file);
    const std::vector<TopoDS_Face> faces = faces_of(read_exchange_file(dir / "out" / file));
    ASSERT_EQ(faces.size(), 1u);
    expect_same_surface(faces[0], r.patch.fit.surface);
    EXPECT_TRUE(BRepCheck_Analyzer(faces[0]).IsValid());
  }
}

#else
TEST(PatchOcct, SkippedWithoutOpenCascade) { GTEST_SKIP() << "Open CASCADE is not installed"; }
#endif

}  // namespace
}  // namespace polarform
