#include "export/step_topology.h"

#include "export/step_geometry.h"

namespace polarform {

int StepTopology::vertex(const Eigen::Vector3d& p) {
  for (const auto& [q, id] : vertices_)
    if ((p - q).norm() <= tol_) return id;
  // ISO 10303-42 vertex_point
  const int id = f_.add("VERTEX_POINT(''," + step_ref(step_point(f_, p)) + ")");
  vertices_.emplace_back(p, id);
  return id;
}

int StepTopology::edge(int start_vertex, int end_vertex, int curve) {
  // ISO 10303-42 edge_curve
  return f_.add("EDGE_CURVE(''," + step_ref(start_vertex) + "," + step_ref(end_vertex) + "," +
                step_ref(curve) + ",.T.)");
}

int StepTopology::loop(const std::vector<Use>& uses) {
  std::vector<std::string> oriented;
  for (const Use& u : uses)  // ISO 10303-42 oriented_edge (vertices derived: *)
    oriented.push_back(step_ref(
        f_.add("ORIENTED_EDGE('',*,*," + step_ref(u.edge) + "," + step_logical(u.sense) + ")")));
  return f_.add("EDGE_LOOP(''," + step_list(oriented) + ")");  // ISO 10303-42 edge_loop
}

int StepTopology::face(const std::vector<Bound>& bounds, int surface, bool same_sense,
                       const std::string& name) {
  std::vector<std::string> refs;
  for (const Bound& b : bounds)  // ISO 10303-42 face_outer_bound / face_bound
    refs.push_back(step_ref(f_.add(std::string(b.outer ? "FACE_OUTER_BOUND" : "FACE_BOUND") +
                                   "(''," + step_ref(b.loop) + "," +
                                   step_logical(b.orientation) + ")")));
  // ISO 10303-42 advanced_face
  return f_.add("ADVANCED_FACE(" + step_string(name, "face name") + "," + step_list(refs) + "," +
                step_ref(surface) + "," + step_logical(same_sense) + ")");
}

}  // namespace polarform
