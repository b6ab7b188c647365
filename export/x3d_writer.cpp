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
  curves_.push_back({curve, name, color});
}

void X3dWriter::add(const NurbsSurface& surface, const std::string& name,
                    const Eigen::Vector3d& color) {
  require_exchangeable(surface.degree_u(), surface.knots_u(), "X3D surface '" + name + "' (u)");
  require_exchangeable(surface.degree_v(), surface.knots_v(), "X3D surface '" + name + "' (v)");
  check_color(color, "X3D surface '" + name + "'");
  surfaces_.push_back({surface, name, color});
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
  for (const Curve& c : curves_)
    for (const auto& p : control_points_of(c.curve)) all.push_back(p);
  for (const Surface& s : surfaces_)
    for (const auto& p : control_points_of(s.surface)) all.push_back(p);
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
  auto shape = [&](const std::string& def, const Eigen::Vector3d& color, bool emissive) {
    XMLElement* s = child(scene, "Shape");
    s->SetAttribute("DEF", def.c_str());
    XMLElement* material = child(child(s, "Appearance"), "Material");
    const std::string rgb = join({color.x(), color.y(), color.z()});
    // Lines are unlit in X3D: a curve shows its emissive colour.
    material->SetAttribute(emissive ? "emissiveColor" : "diffuseColor", rgb.c_str());
    return s;
  };
  auto control_points = [&](XMLElement* geometry, const std::vector<Eigen::Vector3d>& points) {
    XMLElement* coordinate = child(geometry, "Coordinate");
    coordinate->SetAttribute("containerField", "controlPoint");
    coordinate->SetAttribute("point", join_points(points).c_str());
  };

  for (const Curve& c : curves_) {
    // ISO/IEC 19775-1 §27.4.4 NurbsCurve. closed stays FALSE: it asks the browser to wrap the
    // control points periodically (X_ITE does), which would alter a curve that its own control
    // points already close.
    XMLElement* g = child(shape(ids.make(c.name, "curve"), c.color, true), "NurbsCurve");
    const NurbsCurve3d& k = c.curve;
    g->SetAttribute("order", k.degree() + 1);
    g->SetAttribute("knot", join(k.knots()).c_str());
    g->SetAttribute("weight", join(k.weights()).c_str());
    g->SetAttribute("tessellation", tessellation(k.knots(), k.degree(), k.size(), 64));
    control_points(g, control_points_of(k));
  }
  for (const Surface& s : surfaces_) {
    // ISO/IEC 19775-1 §27.4.7 NurbsPatchSurface: control point (i, j) at index i + j uDimension;
    // uClosed / vClosed stay FALSE for the reason given at NurbsCurve.
    XMLElement* g = child(shape(ids.make(s.name, "surface"), s.color, false), "NurbsPatchSurface");
    const NurbsSurface& f = s.surface;
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
  }

  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

void X3dWriter::save(const std::filesystem::path& path, const std::string& title) const {
  write_file_atomically(path, str(title));
}

}  // namespace polarform
