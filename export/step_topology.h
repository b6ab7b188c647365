// STEP B-rep topology instances (ISO 10303-42 topology_schema) for the shell and solid writers:
// vertices shared by position, edge curves, oriented edges in edge loops, face bounds and
// advanced faces. Loops are oriented against the face normal (the surface normal, reversed when
// same_sense is false): the face lies to the left of each loop seen from the normal's side.
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "export/step_file.h"

namespace polarform {

class StepTopology {
 public:
  StepTopology(StepFile& file, double tolerance) : f_(file), tol_(tolerance) {}

  // VERTEX_POINT at p, the same instance for points closer than the tolerance.
  int vertex(const Eigen::Vector3d& p);
  // EDGE_CURVE from start to end along curve (same_sense .T.).
  int edge(int start_vertex, int end_vertex, int curve);

  struct Use {
    int edge;
    bool sense;  // .T.: the edge's own direction
  };
  // EDGE_LOOP of ORIENTED_EDGEs.
  int loop(const std::vector<Use>& uses);

  struct Bound {
    int loop;
    bool outer;
    bool orientation = true;
  };
  // ADVANCED_FACE with FACE_OUTER_BOUND / FACE_BOUND bounds on surface.
  int face(const std::vector<Bound>& bounds, int surface, bool same_sense,
           const std::string& name = "");

 private:
  StepFile& f_;
  double tol_;
  std::vector<std::pair<Eigen::Vector3d, int>> vertices_;
};

}  // namespace polarform
