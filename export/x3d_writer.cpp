#include "export/x3d_writer.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <set>

#include "export/atomic_file.h"
#include "export/exchange_geometry.h"
#include "export/exchange_text.h"
#include "polarform_version.h"
#include "src/error.h"

namespace polarform {

namespace {

std::string join(const std::vector<double>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? " " : "") + exchange_real(values[i]);
  return out;
}

std::string join_points(const std::vector<Eigen::Vector3d>& points) {
  std::string out;
  for (std::size_t i = 0; i < points.size(); ++i)
    out += (i ? ", " : "") + join({points[i].x(), points[i].y(), points[i].z()});
  return out;
}

void check_color(const Eigen::Vector3d& c, const std::string& what) {
  if (!((c.array() >= 0.0).all() && (c.array() <= 1.0).all()))
    throw InputError(what + ": colour components must lie in [0, 1]");
}

void check_colors(const std::vector<Eigen::Vector3d>& points,
                  const std::vector<Eigen::Vector3d>& colors, const std::string& what) {
  if (colors.size() != points.size())
    throw InputError(what + ": " + std::to_string(colors.size()) + " colours for " +
                     std::to_string(points.size()) + " points; one per point");
  for (const Eigen::Vector3d& c : colors) check_color(c, what);
  for (const Eigen::Vector3d& p : points)
    if (!p.allFinite()) throw InputError(what + ": a point is not finite");
}

// Segments for a browser: 16 per knot span, at least min_steps.
int tessellation(const Knots& knots, int degree, int size, int min_steps) {
  int spans = 0;
  for (int s = degree; s < size; ++s) spans += knots[s + 1] > knots[s] ? 1 : 0;
  return std::clamp(16 * spans, min_steps, 4000);
}

// A unique DEF id: X3D ids must not start with a digit and must not hold spaces or separators.
class Ids {
 public:
  std::string make(const std::string& name, const std::string& fallback) {
    std::string id = name.empty() ? fallback : name;
    for (char& c : id)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
    if (std::isdigit(static_cast<unsigned char>(id[0])) || id[0] == '-' || id[0] == '.')
      id = "_" + id;
    std::string unique = id;
    for (int k = 2; used_.count(unique); ++k) unique = id + "_" + std::to_string(k);
    used_.insert(unique);
    return unique;
  }

 private:
  std::set<std::string> used_;
};

}  // namespace

void X3dWriter::add(const NurbsCurve2d& curve, const std::string& name, const Eigen::Vector3d& color) {
  add(lift_to_3d(curve), name, color);
}

void X3dWriter::add(const NurbsCurve3d& curve, const std::string& name, const Eigen::Vector3d& color) {
  require_exchangeable(curve.degree(), curve.knots(), "X3D curve '" + name + "'");
  check_color(color, "X3D curve '" + name + "'");
  shapes_.push_back({curve, name, color});
}

void X3dWriter::add(const NurbsSurface& surface, const std::string& name,
                    const Eigen::Vector3d& color) {
  require_exchangeable(surface.degree_u(), surface.knots_u(), "X3D surface '" + name + "' (u)");
  require_exchangeable(surface.degree_v(), surface.knots_v(), "X3D surface '" + name + "' (v)");
  check_color(color, "X3D surface '" + name + "'");
  shapes_.push_back({surface, name, color});
}

void X3dWriter::add_colored_quads(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Eigen::Vector3d>& colors,
                                  const std::vector<std::array<int, 4>>& quads,
                                  const std::string& name) {
  const std::string what = "X3D mesh '" + name + "'";
  check_colors(points, colors, what);
  for (const auto& q : quads)
    for (int k : q)
      if (k < 0 || k >= static_cast<int>(points.size()))
        throw InputError(what + ": vertex index " + std::to_string(k) + " outside [0, " +
                         std::to_string(points.size()) + ")");
  shapes_.push_back({ColoredQuads{points, colors, quads}, name, Eigen::Vector3d::Zero()});
}

void X3dWriter::add_colored_points(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<Eigen::Vector3d>& colors,
                                   const std::string& name) {
  check_colors(points, colors, "X3D points '" + name + "'");
  shapes_.push_back({ColoredPoints{points, colors}, name, Eigen::Vector3d::Zero()});
}

void X3dWriter::add_switch(const std::string& name, const std::vector<std::string>& shapes) {
  Switch sw{name, {}};
  for (const std::string& shape : shapes) {  // all checked before any is taken
    const auto it = std::find_if(shapes_.begin(), shapes_.end(),
                                 [&](const Shape& s) { return s.name == shape; });
    if (it == shapes_.end())
      throw InputError("X3D switch '" + name + "': no shape named '" + shape + "'");
    if (it->group >= 0)
      throw InputError("X3D switch '" + name + "': shape '" + shape + "' is already in switch '" +
                       switches_[it->group].name + "'");
    sw.shapes.push_back(static_cast<int>(it - shapes_.begin()));
  }
  for (int k : sw.shapes) shapes_[k].group = static_cast<int>(switches_.size());
  switches_.push_back(std::move(sw));
}

std::string X3dWriter::str(const std::string& title) const {
  using tinyxml2::XMLElement;
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration("xml version=\"1.0\" encoding=\"UTF-8\""));
  doc.InsertEndChild(doc.NewUnknown(
      "DOCTYPE X3D PUBLIC \"ISO//Web3D//DTD X3D 3.3//EN\" "
      "\"http://www.web3d.org/specifications/x3d-3.3.dtd\""));
  XMLElement* x3d = doc.NewElement("X3D");
  doc.InsertEndChild(x3d);
  x3d->SetAttribute("profile", "Immersive");
  x3d->SetAttribute("version", "3.3");
  x3d->SetAttribute("xmlns:xsd", "http://www.w3.org/2001/XMLSchema-instance");
  x3d->SetAttribute("xsd:noNamespaceSchemaLocation",
                    "http://www.web3d.org/specifications/x3d-3.3.xsd");

  auto child = [&doc](XMLElement* parent, const char* tag) {
    XMLElement* e = doc.NewElement(tag);
    parent->InsertEndChild(e);
    return e;
  };
  XMLElement* head = child(x3d, "head");
  XMLElement* component = child(head, "component");  // ISO/IEC 19775-1 §27 NURBS, level 1
  component->SetAttribute("name", "NURBS");
  component->SetAttribute("level", 1);
  XMLElement* unit = child(head, "unit");  // X3D 3.3 UNIT statement: lengths in millimetres
  unit->SetAttribute("category", "length");
  unit->SetAttribute("name", "millimetre");
  unit->SetAttribute("conversionFactor", "0.001");
  for (const auto& [name, content] :
       {std::pair<std::string, std::string>{"title", title},
        {"generator", std::string("polarform ") + POLARFORM_VERSION}}) {
    XMLElement* meta = child(head, "meta");
    meta->SetAttribute("name", name.c_str());
    meta->SetAttribute("content", content.c_str());
  }

  XMLElement* scene = child(x3d, "Scene");
  std::vector<Eigen::Vector3d> all;
  for (const Shape& shape : shapes_) {
    if (const auto* c = std::get_if<NurbsCurve3d>(&shape.geometry))
      for (const auto& p : control_points_of(*c)) all.push_back(p);
    else if (const auto* f = std::get_if<NurbsSurface>(&shape.geometry))
      for (const auto& p : control_points_of(*f)) all.push_back(p);
    else if (const auto* q = std::get_if<ColoredQuads>(&shape.geometry))
      all.insert(all.end(), q->points.begin(), q->points.end());
    else
      for (const auto& p : std::get<ColoredPoints>(shape.geometry).points) all.push_back(p);
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (!all.empty()) lo = hi = all.front();
  for (const auto& p : all) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Eigen::Vector3d center = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 1.0);
  const double fov = std::numbers::pi / 4.0;  // the Viewpoint default fieldOfView
  const Eigen::Vector3d eye = center + Eigen::Vector3d(0, 0, 1.2 * radius / std::tan(fov / 2));
  XMLElement* viewpoint = child(scene, "Viewpoint");  // ISO/IEC 19775-1 §23 Viewpoint
  viewpoint->SetAttribute("description", "overview");
  viewpoint->SetAttribute("position", join({eye.x(), eye.y(), eye.z()}).c_str());
  viewpoint->SetAttribute("centerOfRotation", join({center.x(), center.y(), center.z()}).c_str());

  Ids ids;
  auto shape_element = [&](XMLElement* parent, const std::string& def) {
    XMLElement* s = child(parent, "Shape");
    s->SetAttribute("DEF", def.c_str());
    return s;
  };
  auto material = [&](XMLElement* s, const Eigen::Vector3d& color, bool emissive) {
    XMLElement* m = child(child(s, "Appearance"), "Material");
    const std::string rgb = join({color.x(), color.y(), color.z()});
    // Lines are unlit in X3D: a curve shows its emissive colour.
    m->SetAttribute(emissive ? "emissiveColor" : "diffuseColor", rgb.c_str());
  };
  auto control_points = [&](XMLElement* geometry, const std::vector<Eigen::Vector3d>& points) {
    XMLElement* coordinate = child(geometry, "Coordinate");
    coordinate->SetAttribute("containerField", "controlPoint");
    coordinate->SetAttribute("point", join_points(points).c_str());
  };
  auto points_and_colors = [&](XMLElement* geometry, const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& colors) {
    child(geometry, "Coordinate")->SetAttribute("point", join_points(points).c_str());
    child(geometry, "Color")->SetAttribute("color", join_points(colors).c_str());
  };

  auto emit = [&](XMLElement* parent, const Shape& shape) {
    if (const auto* curve = std::get_if<NurbsCurve3d>(&shape.geometry)) {
      // ISO/IEC 19775-1 §27.4.4 NurbsCurve. closed stays FALSE: it asks the browser to wrap the
      // control points periodically (X_ITE does), which would alter a curve that its own control
      // points already close.
      XMLElement* s = shape_element(parent, ids.make(shape.name, "curve"));
      material(s, shape.color, true);
      XMLElement* g = child(s, "NurbsCurve");
      const NurbsCurve3d& k = *curve;
      g->SetAttribute("order", k.degree() + 1);
      g->SetAttribute("knot", join(k.knots()).c_str());
      g->SetAttribute("weight", join(k.weights()).c_str());
      g->SetAttribute("tessellation", tessellation(k.knots(), k.degree(), k.size(), 64));
      control_points(g, control_points_of(k));
    } else if (const auto* surface = std::get_if<NurbsSurface>(&shape.geometry)) {
      // ISO/IEC 19775-1 §27.4.7 NurbsPatchSurface: control point (i, j) at index i + j uDimension;
      // uClosed / vClosed stay FALSE for the reason given at NurbsCurve.
      XMLElement* s = shape_element(parent, ids.make(shape.name, "surface"));
      material(s, shape.color, false);
      XMLElement* g = child(s, "NurbsPatchSurface");
      const NurbsSurface& f = *surface;
      const int nu = f.size_u(), nv = f.size_v();
      std::vector<double> weights;
      std::vector<Eigen::Vector3d> points;
      for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
          weights.push_back(f.weight(i, j));
          points.push_back(f.control_point(i, j));
        }
      g->SetAttribute("solid", "false");
      g->SetAttribute("uOrder", f.degree_u() + 1);
      g->SetAttribute("vOrder", f.degree_v() + 1);
      g->SetAttribute("uDimension", nu);
      g->SetAttribute("vDimension", nv);
      g->SetAttribute("uKnot", join(f.knots_u()).c_str());
      g->SetAttribute("vKnot", join(f.knots_v()).c_str());
      g->SetAttribute("weight", join(weights).c_str());
      g->SetAttribute("uTessellation", tessellation(f.knots_u(), f.degree_u(), nu, 32));
      g->SetAttribute("vTessellation", tessellation(f.knots_v(), f.degree_v(), nv, 32));
      control_points(g, points);
    } else if (const auto* mesh = std::get_if<ColoredQuads>(&shape.geometry)) {
      // §13.3.6 IndexedFaceSet with a colour per vertex (lit: the Material gives the shading).
      XMLElement* s = shape_element(parent, ids.make(shape.name, "mesh"));
      child(child(s, "Appearance"), "Material");
      XMLElement* g = child(s, "IndexedFaceSet");
      g->SetAttribute("solid", "false");
      g->SetAttribute("colorPerVertex", "true");
      std::string index;
      for (const auto& q : mesh->quads)
        for (int k : {q[0], q[1], q[2], q[3], -1}) index += std::to_string(k) + " ";
      g->SetAttribute("coordIndex", index.c_str());
      points_and_colors(g, mesh->points, mesh->colors);
    } else {
      // §11.4.11 PointSet, one colour per point.
      const ColoredPoints& cloud = std::get<ColoredPoints>(shape.geometry);
      XMLElement* s = shape_element(parent, ids.make(shape.name, "points"));
      points_and_colors(child(s, "PointSet"), cloud.points, cloud.colors);
    }
  };

  std::vector<bool> emitted(switches_.size(), false);
  for (const Shape& shape : shapes_) {
    if (shape.group < 0) {
      emit(scene, shape);
      continue;
    }
    if (emitted[shape.group]) continue;  // with its switch
    emitted[shape.group] = true;
    // ISO/IEC 19775-1 §10.4.2 Switch: the first child shown, the others alternatives.
    const Switch& sw = switches_[shape.group];
    XMLElement* g = child(scene, "Switch");
    g->SetAttribute("DEF", ids.make(sw.name, "switch").c_str());
    g->SetAttribute("whichChoice", 0);
    for (int k : sw.shapes) emit(g, shapes_[k]);
  }

  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

void X3dWriter::save(const std::filesystem::path& path, const std::string& title) const {
  write_file_atomically(path, str(title));
}

}  // namespace polarform
