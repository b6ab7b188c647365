#include "export/step_writer.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "export/atomic_file.h"
#include "export/exchange_geometry.h"
#include "export/step_geometry.h"
#include "export/step_product.h"
#include "export/step_topology.h"
#include "src/error.h"

namespace polarform {

namespace {

// Same degree and knots, control points within tolerance, weights proportional.
bool same_representation(const NurbsCurve3d& a, const NurbsCurve3d& b, double tolerance) {
  if (a.degree() != b.degree() || a.size() != b.size()) return false;
  const double scale = std::max({1.0, std::abs(a.front()), std::abs(a.back())});
  for (std::size_t i = 0; i < a.knots().size(); ++i)
    if (std::abs(a.knots()[i] - b.knots()[i]) > 1e-12 * scale) return false;
  const double ratio = a.weight(0) / b.weight(0);
  for (int i = 0; i < a.size(); ++i) {
    if ((a.control_point(i) - b.control_point(i)).norm() > tolerance) return false;
    if (std::abs(a.weight(i) / b.weight(i) - ratio) > 1e-12 * ratio) return false;
  }
  return true;
}

// Builds the faces of the surfaces, sharing edges between identical boundary curves, and groups
// them into shells: one per set of faces connected through shared edges.
class ShellBuilder {
 public:
  ShellBuilder(StepFile& f, double tolerance) : f_(f), topo_(f, tolerance), tol_(tolerance) {}

  void add_face(const NurbsSurface& s, const std::string& name) {
    const int face = static_cast<int>(faces_.size());
    parent_.push_back(face);
    const int surface = step_bspline_surface(f_, s, tol_, name);
    // Boundary counter-clockwise in (u, v): v = v0 forwards, u = u1 forwards, v = v1 backwards,
    // u = u0 backwards; with the surface normal S_u x S_v the face lies to the left.
    std::vector<StepTopology::Use> uses;
    auto bound = [&](const NurbsCurve3d& c, bool forwards) {
      if (is_degenerate(c, tol_)) return;
      StepTopology::Use use = edge(c, face);
      if (!forwards) use.sense = !use.sense;
      uses.push_back(use);
    };
    bound(iso_curve_at_v(s, s.front_v()), true);
    bound(iso_curve_at_u(s, s.back_u()), true);
    bound(iso_curve_at_v(s, s.back_v()), false);
    bound(iso_curve_at_u(s, s.front_u()), false);
    if (uses.empty())
      throw InputError("STEP surface '" + name + "': all four boundaries collapse to points");
    faces_.push_back(topo_.face({{topo_.loop(uses), true}}, surface, true, name));
  }

  // One CLOSED_SHELL (every edge bounds two of its faces) or OPEN_SHELL per connected set of faces.
  std::vector<std::string> shells() {
    std::map<int, std::vector<std::string>> members;
    std::map<int, bool> closed;
    for (int face = 0; face < static_cast<int>(faces_.size()); ++face) {
      members[root(face)].push_back(step_ref(faces_[face]));
      closed.emplace(root(face), true);
    }
    for (const Edge& e : edges_)
      if (e.faces.size() != 2) closed[root(e.faces.front())] = false;
    std::vector<std::string> out;
    for (const auto& [r, refs] : members)  // ISO 10303-42 closed_shell / open_shell
      out.push_back(step_ref(f_.add(std::string(closed[r] ? "CLOSED_SHELL" : "OPEN_SHELL") +
                                    "(''," + step_list(refs) + ")")));
    return out;
  }

 private:
  struct Edge {
    NurbsCurve3d curve;
    int id;
    std::vector<int> faces;  // one entry per use
  };

  StepTopology::Use edge(const NurbsCurve3d& c, int face) {
    for (Edge& e : edges_) {
      const bool forwards = same_representation(e.curve, c, tol_);
      if (forwards || same_representation(e.curve, reversed(c), tol_)) {
        e.faces.push_back(face);
        parent_[root(face)] = root(e.faces.front());
        return {e.id, forwards};
      }
    }
    const int v0 = topo_.vertex(c.point(c.front())), v1 = topo_.vertex(c.point(c.back()));
    edges_.push_back({c, topo_.edge(v0, v1, step_bspline_curve(f_, c, tol_)), {face}});
    return {edges_.back().id, true};
  }

  int root(int face) {
    while (parent_[face] != face) face = parent_[face] = parent_[parent_[face]];
    return face;
  }

  StepFile& f_;
  StepTopology topo_;
  double tol_;
  std::vector<Edge> edges_;
  std::vector<int> faces_;   // ADVANCED_FACE ids
  std::vector<int> parent_;  // union-find over faces
};

}  // namespace

void StepWriter::add(const NurbsCurve2d& curve, const std::string& name) {
  add(lift_to_3d(curve), name);
}

void StepWriter::add(const NurbsCurve3d& curve, const std::string& name) {
  require_exchangeable(curve.degree(), curve.knots(), "STEP curve '" + name + "'");
  step_string(name, "curve name");
  curves_.emplace_back(curve, name);
}

void StepWriter::add(const NurbsSurface& surface, const std::string& name) {
  require_exchangeable(surface.degree_u(), surface.knots_u(), "STEP surface '" + name + "' (u)");
  require_exchangeable(surface.degree_v(), surface.knots_v(), "STEP surface '" + name + "' (v)");
  step_string(name, "surface name");
  surfaces_.emplace_back(surface, name);
}

std::string StepWriter::str(const StepHeader& header) const {
  const double tol = header.resolution;
  StepFile f;
  const int context = step_context(f, tol);
  std::vector<int> representations;

  if (!curves_.empty()) {
    std::vector<std::string> items;
    for (const auto& [curve, name] : curves_)
      items.push_back(step_ref(step_bspline_curve(f, curve, tol, name)));
    // ISO 10303-42 geometric_curve_set; AP214 geometrically_bounded_wireframe_shape_representation
    const int set = f.add("GEOMETRIC_CURVE_SET('curves'," + step_list(items) + ")");
    representations.push_back(
        f.add("GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION(" +
              step_string(product_, "product name") + ",(" + step_ref(set) + "," +
              step_ref(step_origin_placement(f)) + ")," + step_ref(context) + ")"));
  }
  if (!surfaces_.empty()) {
    ShellBuilder builder(f, tol);
    for (const auto& [surface, name] : surfaces_) builder.add_face(surface, name);
    // ISO 10303-42 shell_based_surface_model; AP214 manifold_surface_shape_representation
    const int model = f.add("SHELL_BASED_SURFACE_MODEL(''," + step_list(builder.shells()) + ")");
    representations.push_back(
        f.add("MANIFOLD_SURFACE_SHAPE_REPRESENTATION(" + step_string(product_, "product name") +
              ",(" + step_ref(model) + "," + step_ref(step_origin_placement(f)) + ")," +
              step_ref(context) + ")"));
  }

  int shape = 0;
  if (representations.size() == 1) {
    shape = representations.front();
  } else {
    // Several kinds of geometry (or none): a plain SHAPE_REPRESENTATION of the part, related to
    // each specific representation (ISO 10303-43 shape_representation_relationship).
    shape = f.add("SHAPE_REPRESENTATION(" + step_string(product_, "product name") + ",(" +
                  step_ref(step_origin_placement(f)) + ")," + step_ref(context) + ")");
    for (int r : representations)
      f.add("SHAPE_REPRESENTATION_RELATIONSHIP('',''," + step_ref(shape) + "," + step_ref(r) + ")");
  }
  step_product(f, product_, shape);
  return f.str(header);
}

void StepWriter::save(const std::filesystem::path& path, const StepHeader& header) const {
  StepHeader h = header;
  if (h.file_name.empty()) h.file_name = path.filename().string();
  write_file_atomically(path, str(h));
}

}  // namespace polarform
