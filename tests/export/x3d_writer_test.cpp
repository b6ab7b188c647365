// X3D 3.3 writer parsed back with tinyxml2: document structure (profile, NURBS component, mm unit,
// Viewpoint framing every control point, one Shape with Appearance per item, unique DEFs) and
// every number; a NurbsPatchSurface rebuilt from the parsed arrays with the X3D ordering
// (index i + j uDimension) evaluates to the original surface.
#include "export/x3d_writer.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include "export/exchange_geometry.h"
#include "src/error.h"
#include "tests/support/export/exchange_fixtures.h"
#include "tests/support/export/x3d_numbers.h"

namespace polarform {
namespace {

using namespace exchange_test;
using tinyxml2::XMLElement;

struct Parsed {
  tinyxml2::XMLDocument doc;
  const XMLElement* scene = nullptr;
  explicit Parsed(const std::string& text) {
    if (doc.Parse(text.c_str()) != tinyxml2::XML_SUCCESS)
      throw std::runtime_error(std::string("X3D is not well-formed XML: ") + doc.ErrorStr());
    scene = doc.RootElement()->FirstChildElement("Scene");
  }
};

TEST(X3dWriter, DocumentStructure) {
  X3dWriter w;
  w.add(ellipse(25, 25), "circle");
  w.add(degree12(), "circle");  // same name: the DEF is made unique
  w.add(rational55(), "3 patch");
  const Parsed x(w.str("cam"));
  const XMLElement* root = x.doc.RootElement();
  EXPECT_STREQ(root->Name(), "X3D");
  EXPECT_STREQ(root->Attribute("profile"), "Immersive");
  EXPECT_STREQ(root->Attribute("version"), "3.3");
  const XMLElement* head = root->FirstChildElement("head");
  ASSERT_NE(head, nullptr);
  EXPECT_STREQ(head->FirstChildElement("component")->Attribute("name"), "NURBS");
  EXPECT_EQ(head->FirstChildElement("component")->IntAttribute("level"), 1);
  const XMLElement* unit = head->FirstChildElement("unit");
  ASSERT_NE(unit, nullptr);
  EXPECT_STREQ(unit->Attribute("category"), "length");
  EXPECT_EQ(unit->DoubleAttribute("conversionFactor"), 0.001);
  ASSERT_NE(x.scene, nullptr);
  std::set<std::string> defs;
  int shapes = 0;
  for (const XMLElement* s = x.scene->FirstChildElement("Shape"); s; s = s->NextSiblingElement("Shape")) {
    ++shapes;
    defs.insert(s->Attribute("DEF"));
    ASSERT_NE(s->FirstChildElement("Appearance"), nullptr);
    ASSERT_NE(s->FirstChildElement("Appearance")->FirstChildElement("Material"), nullptr);
  }
  EXPECT_EQ(shapes, 3);
  EXPECT_EQ(defs, (std::set<std::string>{"circle", "circle_2", "_3_patch"}));

  // The Viewpoint (default fieldOfView pi/4, looking along -z) sees every control point.
  const XMLElement* vp = x.scene->FirstChildElement("Viewpoint");
  ASSERT_NE(vp, nullptr);
  const std::vector<double> eye = x3d_numbers(vp->Attribute("position"));
  ASSERT_EQ(eye.size(), 3u);
  std::vector<Eigen::Vector3d> all = control_points_of(lift_to_3d(ellipse(25, 25)));
  for (const auto& p : control_points_of(degree12())) all.push_back(p);
  for (const auto& p : control_points_of(rational55())) all.push_back(p);
  for (const auto& p : all) {
    const Eigen::Vector3d d = p - Eigen::Vector3d(eye[0], eye[1], eye[2]);
    EXPECT_LT(std::atan2(std::hypot(d.x(), d.y()), -d.z()), std::numbers::pi / 8);
  }
}

TEST(X3dWriter, CurveNumbers) {
  X3dWriter w;
  const NurbsCurve3d c = degree12();
  w.add(c, "c");
  const Parsed x(w.str());
  const XMLElement* g = x.scene->FirstChildElement("Shape")->FirstChildElement("NurbsCurve");
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->IntAttribute("order"), 13);
  EXPECT_EQ(x3d_numbers(g->Attribute("knot")), c.knots());
  EXPECT_EQ(x3d_numbers(g->Attribute("weight")), c.weights());
  EXPECT_FALSE(g->BoolAttribute("closed"));
  EXPECT_GE(g->IntAttribute("tessellation"), 64);
  const XMLElement* coord = g->FirstChildElement("Coordinate");
  ASSERT_NE(coord, nullptr);
  EXPECT_STREQ(coord->Attribute("containerField"), "controlPoint");
  const std::vector<double> p = x3d_numbers(coord->Attribute("point"));
  ASSERT_EQ(static_cast<int>(p.size()), 3 * c.size());
  for (int i = 0; i < c.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(p[3 * i + k], c.control_point(i)[k]);
  EXPECT_EQ(x3d_numbers(x.scene->FirstChildElement("Shape")
                            ->FirstChildElement("Appearance")
                            ->FirstChildElement("Material")
                            ->Attribute("emissiveColor")),
            (std::vector<double>{0.1, 0.2, 0.8}));
}

TEST(X3dWriter, PatchSurfaceRebuiltFromParsedArrays) {
  for (const NurbsSurface& s : {rational55(), sphere_octant(10)}) {
    X3dWriter w;
    w.add(s, "s");
    const Parsed x(w.str());
    const XMLElement* g = x.scene->FirstChildElement("Shape")->FirstChildElement("NurbsPatchSurface");
    ASSERT_NE(g, nullptr);
    const int nu = g->IntAttribute("uDimension"), nv = g->IntAttribute("vDimension");
    EXPECT_EQ(nu, s.size_u());
    EXPECT_EQ(nv, s.size_v());
    EXPECT_FALSE(g->BoolAttribute("solid", true));
    const std::vector<double> uk = x3d_numbers(g->Attribute("uKnot")),
                              vk = x3d_numbers(g->Attribute("vKnot"));
    const std::vector<double> wt = x3d_numbers(g->Attribute("weight"));
    const std::vector<double> pt =
        x3d_numbers(g->FirstChildElement("Coordinate")->Attribute("point"));
    ASSERT_EQ(static_cast<int>(uk.size()), nu + g->IntAttribute("uOrder"));
    ASSERT_EQ(static_cast<int>(vk.size()), nv + g->IntAttribute("vOrder"));
    ASSERT_EQ(static_cast<int>(wt.size()), nu * nv);
    ASSERT_EQ(static_cast<int>(pt.size()), 3 * nu * nv);
    NurbsSurface::Points points(nu * nv);
    std::vector<double> weights(nu * nv);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        const int k = i + j * nu;  // X3D: u runs fastest
        points[i * nv + j] = Eigen::Vector3d(pt[3 * k], pt[3 * k + 1], pt[3 * k + 2]);
        weights[i * nv + j] = wt[k];
      }
    const NurbsSurface back(g->IntAttribute("uOrder") - 1, g->IntAttribute("vOrder") - 1, uk, vk,
                            points, weights);
    double worst = 0.0;
    for (double u : linspace(s.front_u(), s.back_u(), 20))
      for (double v : linspace(s.front_v(), s.back_v(), 10))
        worst = std::max(worst, (back.point(u, v) - s.point(u, v)).norm());
    EXPECT_LT(worst, 1e-12);
  }
}

// Coloured quads and points come back with one colour per point and their quads as written; a
// Switch holds the named shapes in the order given, the first shown, in the scene where the
// first of them was added.
TEST(X3dWriter, ColouredMeshesPointsAndSwitches) {
  const std::vector<Eigen::Vector3d> points = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 1}};
  const std::vector<Eigen::Vector3d> colors = {
      {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0.5}, {0.25, 0.75, 1}};
  X3dWriter w;
  w.add_colored_quads(points, colors, {{0, 1, 2, 3}, {1, 4, 2, 3}}, "mesh");
  w.add(rational55(), "exact");
  w.add_colored_points(points, colors, "net");
  w.add_switch("views", {"mesh", "exact"});
  const Parsed x(w.str());
  const XMLElement* sw = x.scene->FirstChildElement("Switch");
  ASSERT_NE(sw, nullptr);
  EXPECT_STREQ(sw->Attribute("DEF"), "views");
  EXPECT_EQ(sw->IntAttribute("whichChoice"), 0);
  const XMLElement* mesh = sw->FirstChildElement("Shape");
  EXPECT_STREQ(mesh->Attribute("DEF"), "mesh");
  EXPECT_STREQ(mesh->NextSiblingElement("Shape")->Attribute("DEF"), "exact");
  EXPECT_NE(mesh->NextSiblingElement("Shape")->FirstChildElement("NurbsPatchSurface"), nullptr);
  const XMLElement* faces = mesh->FirstChildElement("IndexedFaceSet");
  EXPECT_EQ(x3d_numbers(faces->Attribute("coordIndex")),
            (std::vector<double>{0, 1, 2, 3, -1, 1, 4, 2, 3, -1}));
  const std::vector<double> xyz =
      x3d_numbers(faces->FirstChildElement("Coordinate")->Attribute("point"));
  const std::vector<double> rgb =
      x3d_numbers(faces->FirstChildElement("Color")->Attribute("color"));
  ASSERT_EQ(xyz.size(), 15u);
  ASSERT_EQ(rgb.size(), 15u);
  for (std::size_t k = 0; k < points.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(xyz[3 * k + c], points[k][c]);
      EXPECT_EQ(rgb[3 * k + c], colors[k][c]);
    }
  // The points stand after the switch, in the scene itself.
  const XMLElement* net = sw->NextSiblingElement("Shape");
  ASSERT_NE(net, nullptr);
  EXPECT_STREQ(net->Attribute("DEF"), "net");
  EXPECT_EQ(x3d_numbers(
                net->FirstChildElement("PointSet")->FirstChildElement("Color")->Attribute("color")),
            rgb);
}

TEST(X3dWriter, RejectsBadInput) {
  X3dWriter w;
  EXPECT_THROW(w.add(ellipse(2, 1), "c", Eigen::Vector3d(1.5, 0, 0)), InputError);
  EXPECT_THROW(w.add(NurbsCurve2d(0, {0, 1, 2}, {{0, 0}, {1, 1}})), InputError);
  const std::vector<Eigen::Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_THROW(w.add_colored_points(two, {{1, 0, 0}}, "p"), InputError);             // one colour
  EXPECT_THROW(w.add_colored_points(two, {{1, 0, 0}, {0, 2, 0}}, "p"), InputError);  // > 1
  EXPECT_THROW(w.add_colored_quads(two, {{1, 0, 0}, {0, 1, 0}}, {{0, 1, 2, 0}}, "q"), InputError);
  w.add_colored_points(two, {{1, 0, 0}, {0, 1, 0}}, "p");
  EXPECT_THROW(w.add_switch("s", {"p", "missing"}), InputError);
  w.add_switch("s", {"p"});
  EXPECT_THROW(w.add_switch("t", {"p"}), InputError);  // already in a switch
}

}  // namespace
}  // namespace polarform
