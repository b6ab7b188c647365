// The X3D scene of a visualised field (Bae 2002, §5.3) parsed back: a Switch showing the coloured
// tessellation before the exact NURBS patch, the tessellation's vertices on the surface and
// coloured by the value F there, and the control net's points coloured by the values they carry.
#include "export/x3d_field_scene.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "export/colormap.h"
#include "src/error.h"
#include "src/nurbs/tessellation.h"
#include "tests/support/export/x3d_numbers.h"

namespace polarform {
namespace {

using exchange_test::x3d_numbers;

// p = 100 + 20 cos φ on a 10° spherical grid: a smooth field with a known range.
ScalarFieldSurface pressure_field() {
  std::vector<double> p, phi, theta;
  for (int i = 0; i <= 18; ++i)
    for (int j = 0; j < 36; ++j) {
      phi.push_back(i * std::numbers::pi / 18);
      theta.push_back(j * std::numbers::pi / 18);
      p.push_back(100 + 20 * std::cos(phi.back()));
    }
  const auto v = [](const std::vector<double>& x) {
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size())));
  };
  return visualize_spherical(v(p), v(phi), v(theta));
}

TEST(X3dFieldScene, ColouredTessellationOnTheSurfaceBeforeTheExactPatch) {
  const ScalarFieldSurface f = pressure_field();
  const int rows = 4, cols = 8;
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(field_x3d(f, "pressure", rows, cols).c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* scene = doc.RootElement()->FirstChildElement("Scene");
  const tinyxml2::XMLElement* sw = scene->FirstChildElement("Switch");
  ASSERT_NE(sw, nullptr);
  EXPECT_EQ(sw->IntAttribute("whichChoice"), 0);
  const tinyxml2::XMLElement* shown = sw->FirstChildElement("Shape");
  ASSERT_NE(shown->FirstChildElement("IndexedFaceSet"), nullptr);
  EXPECT_NE(shown->NextSiblingElement("Shape")->FirstChildElement("NurbsPatchSurface"), nullptr);
  const tinyxml2::XMLElement* faces = shown->FirstChildElement("IndexedFaceSet");
  const std::vector<double> xyz =
      x3d_numbers(faces->FirstChildElement("Coordinate")->Attribute("point"));
  const std::vector<double> rgb =
      x3d_numbers(faces->FirstChildElement("Color")->Attribute("color"));
  // The grid: rows and cols equal steps and every interior knot (src/nurbs/tessellation.h).
  const NurbsSurface& S = f.surface;
  const std::vector<double> us =
      tessellation_parameters(S.knots_u(), S.front_u(), S.back_u(), rows);
  const std::vector<double> vs =
      tessellation_parameters(S.knots_v(), S.front_v(), S.back_v(), cols);
  const std::size_t nu = us.size(), nv = vs.size();
  EXPECT_GT(nu, std::size_t(rows + 1));  // the knots of F and the base arcs add rows
  ASSERT_EQ(xyz.size(), 3 * nu * nv);
  ASSERT_EQ(rgb.size(), xyz.size());
  EXPECT_EQ(x3d_numbers(faces->Attribute("coordIndex")).size(), 5 * (nu - 1) * (nv - 1));
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double u = us[i], v = vs[j];
      const std::size_t k = 3 * (i * nv + j);
      const Eigen::Vector3d on = S.point(u, v);
      double value = 0.0;
      f.F.point(u, v, &value);
      const Eigen::Vector3d c = sequential_color(value, f.min_value, f.max_value);
      for (int d = 0; d < 3; ++d) {
        EXPECT_NEAR(xyz[k + d], on[d], 1e-9 * std::max(1.0, std::abs(on[d])));
        EXPECT_NEAR(rgb[k + d], c[d], 1e-12);
      }
    }
  // The control net: one point and one colour per control point, the colour of its value.
  const tinyxml2::XMLElement* net = sw->NextSiblingElement("Shape")->FirstChildElement("PointSet");
  const std::vector<double> net_rgb =
      x3d_numbers(net->FirstChildElement("Color")->Attribute("color"));
  ASSERT_EQ(net_rgb.size(), 3u * S.size_u() * S.size_v());
  const Eigen::Vector3d first = sequential_color(f.control_values[0], f.min_value, f.max_value);
  EXPECT_NEAR(net_rgb[0], first[0], 1e-12);
  EXPECT_THROW(field_x3d(f, "bad", 0, 8), InputError);
}

}  // namespace
}  // namespace polarform
