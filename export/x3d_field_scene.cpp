#include "export/x3d_field_scene.h"

#include <tinyxml2.h>

#include "export/colormap.h"
#include "export/exchange_text.h"
#include "export/x3d_writer.h"
#include "src/error.h"
#include "src/nurbs/tessellation.h"

namespace polarform {

namespace {

using tinyxml2::XMLElement;

void append(std::string& out, const Eigen::Vector3d& v) {
  if (!out.empty()) out += ", ";
  out += exchange_real(v.x()) + " " + exchange_real(v.y()) + " " + exchange_real(v.z());
}

// Coordinate and Color children of a geometry node.
void points_and_colors(tinyxml2::XMLDocument& doc, XMLElement* geometry, const std::string& points,
                       const std::string& colors) {
  XMLElement* c = doc.NewElement("Coordinate");
  c->SetAttribute("point", points.c_str());
  geometry->InsertEndChild(c);
  XMLElement* k = doc.NewElement("Color");
  k->SetAttribute("color", colors.c_str());
  geometry->InsertEndChild(k);
}

XMLElement* shape(tinyxml2::XMLDocument& doc, const char* def) {
  XMLElement* s = doc.NewElement("Shape");
  s->SetAttribute("DEF", def);
  return s;
}

}  // namespace

std::string field_x3d(const ScalarFieldSurface& f, const std::string& title, int rows, int cols) {
  if (rows < 1 || cols < 1)
    throw InputError("field X3D: the tessellation needs at least 1 x 1 quads");
  X3dWriter writer;
  writer.add(f.surface, "field_nurbs");
  tinyxml2::XMLDocument doc;
  const std::string base = writer.str(title);
  if (doc.Parse(base.c_str(), base.size()) != tinyxml2::XML_SUCCESS)
    throw NumericalError("field X3D: the writer's output does not parse");
  XMLElement* scene = doc.FirstChildElement("X3D")->FirstChildElement("Scene");
  XMLElement* nurbs = scene->FirstChildElement("Shape");

  // ISO/IEC 19775-1 §10.4.2 Switch: the coloured tessellation is shown, the exact patch is the
  // alternative.
  XMLElement* sw = doc.NewElement("Switch");
  sw->SetAttribute("DEF", "views");
  sw->SetAttribute("whichChoice", 0);
  scene->InsertEndChild(sw);
  const double lo = f.min_value, hi = f.max_value;
  const NurbsSurface& S = f.surface;
  const SurfaceTessellation grid = tessellate(S, rows, cols);
  const int nu = static_cast<int>(grid.u.size()), nv = static_cast<int>(grid.v.size());
  std::string points, colors, index;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      double value = 0.0;
      f.F.point(grid.u[i], grid.v[j], &value);
      append(points, grid.points[i * nv + j]);
      append(colors, sequential_color(value, lo, hi));
    }
  for (int i = 0; i + 1 < nu; ++i)
    for (int j = 0; j + 1 < nv; ++j) {
      const int a = i * nv + j, b = a + nv;
      index += std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(b + 1) + " " +
               std::to_string(a + 1) + " -1 ";
    }
  XMLElement* mesh_shape = shape(doc, "field_colored");
  XMLElement* appearance = doc.NewElement("Appearance");
  appearance->InsertEndChild(doc.NewElement("Material"));
  mesh_shape->InsertEndChild(appearance);
  XMLElement* mesh = doc.NewElement("IndexedFaceSet");  // §13.3.6, colours per vertex
  mesh->SetAttribute("solid", "false");
  mesh->SetAttribute("colorPerVertex", "true");
  mesh->SetAttribute("coordIndex", index.c_str());
  points_and_colors(doc, mesh, points, colors);
  mesh_shape->InsertEndChild(mesh);
  sw->InsertEndChild(mesh_shape);
  sw->InsertEndChild(nurbs);

  std::string net_points, net_colors;
  for (int i = 0; i < S.size_u(); ++i)
    for (int j = 0; j < S.size_v(); ++j) {
      append(net_points, S.control_point(i, j));
      append(net_colors, sequential_color(f.control_values[i * S.size_v() + j], lo, hi));
    }
  XMLElement* net_shape = shape(doc, "control_values");
  XMLElement* cloud = doc.NewElement("PointSet");  // §11.4.11, one colour per control point
  points_and_colors(doc, cloud, net_points, net_colors);
  net_shape->InsertEndChild(cloud);
  scene->InsertEndChild(net_shape);

  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace polarform
