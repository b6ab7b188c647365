#include "export/x3d_field_scene.h"

#include <tinyxml2.h>

#include "export/exchange_text.h"
#include "export/x3d_writer.h"
#include "src/error.h"
#include "export/colormap.h"

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
  std::string points, colors, index;
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j <= cols; ++j) {
      const double u = S.front_u() + (S.back_u() - S.front_u()) * i / rows;
      const double v = S.front_v() + (S.back_v() - S.front_v()) * j / cols;
      double value = 0.0;
      f.F.point(u, v, &value);
      append(points, S.point(u, v));
      append(colors, sequential_color(value, lo, hi));
    }
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int a = i * (cols + 1) + j, b = a + cols + 1;
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
