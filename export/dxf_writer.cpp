#include "export/dxf_writer.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "export/atomic_file.h"
#include "export/exchange_geometry.h"
#include "export/exchange_text.h"
#include "src/error.h"

namespace polarform {

namespace {

using Tags = std::vector<std::pair<int, std::string>>;

std::string real(double x) { return exchange_real(x); }

void point(Tags& t, int code, const Eigen::Vector3d& p) {
  t.emplace_back(code, real(p.x()));
  t.emplace_back(code + 10, real(p.y()));
  t.emplace_back(code + 20, real(p.z()));
}

// All points on one line within tolerance (coincident points included).
bool collinear(const std::vector<Eigen::Vector3d>& pts, double tolerance) {
  Eigen::Vector3d far = pts.front();
  for (const auto& p : pts)
    if ((p - pts.front()).norm() > (far - pts.front()).norm()) far = p;
  const double len = (far - pts.front()).norm();
  if (len <= tolerance) return true;
  const Eigen::Vector3d d = (far - pts.front()) / len;
  for (const auto& p : pts)
    if ((p - pts.front()).cross(d).norm() > tolerance) return false;
  return true;
}

// Writes tags as DXF group code / value line pairs, assigning handles.
class TagWriter {
 public:
  void tag(int code, const std::string& value) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%3d", code);
    out_ += buf;
    out_ += '\n';
    out_ += value;
    out_ += '\n';
  }
  void tag(int code, int value) { tag(code, std::to_string(value)); }
  std::string handle() {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%X", next_++);
    return buf;
  }
  int next_handle() const { return next_; }
  const std::string& text() const { return out_; }

 private:
  std::string out_;
  int next_ = 0x20;  // 0x1-0x1F: fixed table and dictionary handles below
};

}  // namespace

DxfWriter::DxfWriter(DxfOptions options) : options_(options) {
  if (options_.max_spline_degree < 1)
    throw InputError("DXF max_spline_degree " + std::to_string(options_.max_spline_degree) +
                     ": expected >= 1");
  if (!(options_.resolution > 0.0) || !std::isfinite(options_.resolution))
    throw InputError("DXF resolution " + std::to_string(options_.resolution) +
                     ": expected a finite length > 0 mm");
}

void DxfWriter::check_layer(const std::string& layer) const {
  const std::string forbidden = "<>/\\\":;?*|=`";
  bool ok = !layer.empty() && layer.size() <= 255;
  for (unsigned char c : layer)
    ok = ok && c >= 32 && c < 127 && forbidden.find(static_cast<char>(c)) == std::string::npos;
  if (!ok)
    throw InputError("DXF layer '" + layer + "': expected 1-255 printable ASCII characters "
                     "without < > / \\ \" : ; ? * | = `");
}

void DxfWriter::add(const NurbsCurve2d& curve, const std::string& layer) {
  add(lift_to_3d(curve), layer);
}

void DxfWriter::add(const NurbsCurve3d& c, const std::string& layer) {
  check_layer(layer);
  const std::string what = "DXF SPLINE on layer '" + layer + "'";
  require_exchangeable(c.degree(), c.knots(), what);
  if (c.degree() > options_.max_spline_degree)
    throw InputError(what + ": degree " + std::to_string(c.degree()) + " exceeds max_spline_degree " +
                     std::to_string(options_.max_spline_degree) +
                     " (AutoCAD draws splines up to degree 10); reduce the degree first");
  const double tol = options_.resolution;
  const std::vector<Eigen::Vector3d> pts = control_points_of(c);
  const std::optional<Eigen::Vector3d> normal = plane_normal(pts, tol);
  const bool linear = collinear(pts, tol);
  // DXF R2000 SPLINE group code 70: closed 1, periodic 2, rational 4, planar 8, linear 16.
  const int flags = (is_closed(c, tol) ? 1 : 0) | (has_periodic_structure(c.homogeneous()) ? 2 : 0) |
                    (c.is_rational() ? 4 : 0) | (normal ? 8 : 0) | (linear ? 16 : 0);
  Entity e{layer, "SPLINE", {}, pts};
  Tags& t = e.tags;
  t.emplace_back(100, "AcDbSpline");
  if (normal) point(t, 210, *normal);
  t.emplace_back(70, std::to_string(flags));
  t.emplace_back(71, std::to_string(c.degree()));
  t.emplace_back(72, std::to_string(c.knots().size()));
  t.emplace_back(73, std::to_string(c.size()));
  t.emplace_back(74, "0");
  t.emplace_back(42, real(1e-10));  // knot tolerance
  t.emplace_back(43, real(1e-10));  // control point tolerance
  for (double k : c.knots()) t.emplace_back(40, real(k));
  if (c.is_rational())
    for (int i = 0; i < c.size(); ++i) t.emplace_back(41, real(c.weight(i)));
  for (const auto& p : pts) point(t, 10, p);
  entities_.push_back(std::move(e));
}

void DxfWriter::add_line(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const std::string& layer) {
  check_layer(layer);
  if (!a.allFinite() || !b.allFinite())
    throw InputError("DXF LINE on layer '" + layer + "': end points must be finite");
  Entity e{layer, "LINE", {{100, "AcDbLine"}}, {a, b}};  // DXF R2000 LINE group codes
  point(e.tags, 10, a);
  point(e.tags, 11, b);
  entities_.push_back(std::move(e));
}

void DxfWriter::add_circle(const Eigen::Vector3d& center, double radius, const std::string& layer) {
  check_layer(layer);
  if (!center.allFinite() || !(radius > 0.0) || !std::isfinite(radius))
    throw InputError("DXF CIRCLE on layer '" + layer + "': radius " + std::to_string(radius) +
                     " mm, expected a finite radius > 0 and a finite center");
  const Eigen::Vector3d r(radius, radius, 0.0);
  Entity e{layer, "CIRCLE", {{100, "AcDbCircle"}}, {center - r, center + r}};  // DXF R2000 CIRCLE
  point(e.tags, 10, center);
  e.tags.emplace_back(40, real(radius));
  entities_.push_back(std::move(e));
}

void DxfWriter::add_polyline(const std::vector<Eigen::Vector2d>& points, bool closed,
                             const std::string& layer) {
  check_layer(layer);
  if (points.size() < 2)
    throw InputError("DXF LWPOLYLINE on layer '" + layer + "': " + std::to_string(points.size()) +
                     " points, expected at least 2");
  // DXF R2000 LWPOLYLINE group codes: 90 vertex count, 70 flags (1 closed), 10/20 vertices.
  Entity e{layer, "LWPOLYLINE", {{100, "AcDbPolyline"}}, {}};
  e.tags.emplace_back(90, std::to_string(points.size()));
  e.tags.emplace_back(70, closed ? "1" : "0");
  for (const auto& p : points) {
    if (!p.allFinite())
      throw InputError("DXF LWPOLYLINE on layer '" + layer + "': points must be finite");
    e.tags.emplace_back(10, real(p.x()));
    e.tags.emplace_back(20, real(p.y()));
    e.extent.emplace_back(p.x(), p.y(), 0.0);
  }
  entities_.push_back(std::move(e));
}

std::string DxfWriter::str() const {
  // Fixed handles of the tables and dictionaries (DXF R2000 requires owner handles, code 330).
  const std::string vport_table = "1", ltype_table = "2", layer_table = "3", style_table = "4",
                    view_table = "5", ucs_table = "6", appid_table = "7", dimstyle_table = "8",
                    block_record_table = "9", root_dict = "A", group_dict = "B";
  TagWriter body;
  auto record = [&](const std::string& type, const std::string& owner,
                    const std::string& subclass, int handle_code = 5) {
    body.tag(0, type);
    body.tag(handle_code, body.handle());
    body.tag(330, owner);
    body.tag(100, "AcDbSymbolTableRecord");
    body.tag(100, subclass);
  };
  auto table = [&](const std::string& name, const std::string& handle, int count) {
    body.tag(0, "TABLE");
    body.tag(2, name);
    body.tag(5, handle);
    body.tag(330, "0");
    body.tag(100, "AcDbSymbolTable");
    body.tag(70, count);
  };

  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  bool any = false;
  for (const Entity& e : entities_)
    for (const auto& p : e.extent) {
      lo = any ? lo.cwiseMin(p) : p;
      hi = any ? hi.cwiseMax(p) : p;
      any = true;
    }
  std::set<std::string> layers = {"0"};
  for (const Entity& e : entities_) layers.insert(e.layer);

  body.tag(0, "SECTION");
  body.tag(2, "CLASSES");
  body.tag(0, "ENDSEC");
  body.tag(0, "SECTION");
  body.tag(2, "TABLES");

  table("VPORT", vport_table, 1);  // the active viewport shows the extents
  record("VPORT", vport_table, "AcDbViewportTableRecord");
  body.tag(2, "*Active");
  body.tag(70, 0);
  const Eigen::Vector3d mid = 0.5 * (lo + hi);
  const double height = std::max({(hi - lo).y() * 1.1, (hi - lo).x() * 1.1 / 1.5, 1.0});
  for (const auto& [code, value] : Tags{{10, "0.0"}, {20, "0.0"}, {11, "1.0"}, {21, "1.0"},
                                        {12, real(mid.x())}, {22, real(mid.y())}, {13, "0.0"},
                                        {23, "0.0"}, {14, "10.0"}, {24, "10.0"}, {15, "10.0"},
                                        {25, "10.0"}, {16, "0.0"}, {26, "0.0"}, {36, "1.0"},
                                        {17, "0.0"}, {27, "0.0"}, {37, "0.0"}, {40, real(height)},
                                        {41, "1.5"}, {42, "50.0"}, {43, "0.0"}, {44, "0.0"},
                                        {50, "0.0"}, {51, "0.0"}, {71, "0"}, {72, "1000"},
                                        {73, "1"}, {74, "3"}, {75, "0"}, {76, "0"}, {77, "0"},
                                        {78, "0"}})
    body.tag(code, value);
  body.tag(0, "ENDTAB");

  table("LTYPE", ltype_table, 3);
  for (const char* name : {"ByBlock", "ByLayer", "Continuous"}) {
    record("LTYPE", ltype_table, "AcDbLinetypeTableRecord");
    body.tag(2, name);
    body.tag(70, 0);
    body.tag(3, std::string(name) == "Continuous" ? "Solid line" : "");
    body.tag(72, 65);
    body.tag(73, 0);
    body.tag(40, "0.0");
  }
  body.tag(0, "ENDTAB");

  table("LAYER", layer_table, static_cast<int>(layers.size()));
  for (const std::string& name : layers) {
    record("LAYER", layer_table, "AcDbLayerTableRecord");
    body.tag(2, name);
    body.tag(70, 0);
    body.tag(62, 7);
    body.tag(6, "Continuous");
  }
  body.tag(0, "ENDTAB");

  table("STYLE", style_table, 1);
  record("STYLE", style_table, "AcDbTextStyleTableRecord");
  for (const auto& [code, value] : Tags{{2, "Standard"}, {70, "0"}, {40, "0.0"}, {41, "1.0"},
                                        {50, "0.0"}, {71, "0"}, {42, "2.5"}, {3, "txt"}, {4, ""}})
    body.tag(code, value);
  body.tag(0, "ENDTAB");

  table("VIEW", view_table, 0);
  body.tag(0, "ENDTAB");
  table("UCS", ucs_table, 0);
  body.tag(0, "ENDTAB");

  table("APPID", appid_table, 1);
  record("APPID", appid_table, "AcDbRegAppTableRecord");
  body.tag(2, "ACAD");
  body.tag(70, 0);
  body.tag(0, "ENDTAB");

  table("DIMSTYLE", dimstyle_table, 1);
  body.tag(100, "AcDbDimStyleTable");
  record("DIMSTYLE", dimstyle_table, "AcDbDimStyleTableRecord", 105);  // DIMSTYLE handle: 105
  body.tag(2, "Standard");
  body.tag(70, 0);
  body.tag(0, "ENDTAB");

  table("BLOCK_RECORD", block_record_table, 2);
  std::string block_record[2];
  const char* block_names[2] = {"*Model_Space", "*Paper_Space"};
  for (int i = 0; i < 2; ++i) {
    body.tag(0, "BLOCK_RECORD");
    block_record[i] = body.handle();
    body.tag(5, block_record[i]);
    body.tag(330, block_record_table);
    body.tag(100, "AcDbSymbolTableRecord");
    body.tag(100, "AcDbBlockTableRecord");
    body.tag(2, block_names[i]);
  }
  body.tag(0, "ENDTAB");
  body.tag(0, "ENDSEC");

  // DXF R2000 BLOCKS: the (empty) model and paper space block definitions.
  body.tag(0, "SECTION");
  body.tag(2, "BLOCKS");
  for (int i = 0; i < 2; ++i) {
    body.tag(0, "BLOCK");
    body.tag(5, body.handle());
    body.tag(330, block_record[i]);
    body.tag(100, "AcDbEntity");
    if (i == 1) body.tag(67, 1);
    body.tag(8, "0");
    body.tag(100, "AcDbBlockBegin");
    body.tag(2, block_names[i]);
    body.tag(70, 0);
    for (const auto& [code, value] : Tags{{10, "0.0"}, {20, "0.0"}, {30, "0.0"},
                                          {3, block_names[i]}, {1, ""}})
      body.tag(code, value);
    body.tag(0, "ENDBLK");
    body.tag(5, body.handle());
    body.tag(330, block_record[i]);
    body.tag(100, "AcDbEntity");
    if (i == 1) body.tag(67, 1);
    body.tag(8, "0");
    body.tag(100, "AcDbBlockEnd");
  }
  body.tag(0, "ENDSEC");

  body.tag(0, "SECTION");
  body.tag(2, "ENTITIES");
  for (const Entity& e : entities_) {
    body.tag(0, e.kind);
    body.tag(5, body.handle());
    body.tag(330, block_record[0]);
    body.tag(100, "AcDbEntity");
    body.tag(8, e.layer);
    for (const auto& [code, value] : e.tags) body.tag(code, value);
  }
  body.tag(0, "ENDSEC");

  // DXF R2000 OBJECTS: the root dictionary with the (empty) ACAD_GROUP dictionary.
  body.tag(0, "SECTION");
  body.tag(2, "OBJECTS");
  for (const auto& [code, value] :
       Tags{{0, "DICTIONARY"}, {5, root_dict}, {330, "0"}, {100, "AcDbDictionary"}, {281, "1"},
            {3, "ACAD_GROUP"}, {350, group_dict}, {0, "DICTIONARY"}, {5, group_dict},
            {330, root_dict}, {100, "AcDbDictionary"}, {281, "1"}, {0, "ENDSEC"}, {0, "EOF"}})
    body.tag(code, value);

  // DXF R2000 HEADER, written last because $HANDSEED must exceed every handle used.
  TagWriter head;
  head.tag(0, "SECTION");
  head.tag(2, "HEADER");
  auto var = [&](const char* name, const Tags& values) {
    head.tag(9, name);
    for (const auto& [code, value] : values) head.tag(code, value);
  };
  var("$ACADVER", {{1, "AC1015"}});
  var("$DWGCODEPAGE", {{3, "ANSI_1252"}});
  var("$INSBASE", {{10, "0.0"}, {20, "0.0"}, {30, "0.0"}});
  var("$EXTMIN", {{10, real(lo.x())}, {20, real(lo.y())}, {30, real(lo.z())}});
  var("$EXTMAX", {{10, real(hi.x())}, {20, real(hi.y())}, {30, real(hi.z())}});
  var("$LUNITS", {{70, "2"}});      // decimal
  var("$LUPREC", {{70, "6"}});
  var("$INSUNITS", {{70, "4"}});    // millimetres
  var("$MEASUREMENT", {{70, "1"}}); // metric
  char seed[16];
  std::snprintf(seed, sizeof seed, "%X", body.next_handle());
  var("$HANDSEED", {{5, seed}});
  head.tag(0, "ENDSEC");
  return head.text() + body.text();
}

void DxfWriter::save(const std::filesystem::path& path) const { write_file_atomically(path, str()); }

}  // namespace polarform
