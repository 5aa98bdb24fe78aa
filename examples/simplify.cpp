// Simplification with CGAL's default policy (Lindstrom–Turk), feature lines,
// and a visitor that carries a per-vertex value (here: a colour channel equal
// to the height z) through every collapse; then the default policy in passes
// (Schedule::passes: no heap, less memory, faster on large meshes).
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/simplification.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using Mesh = genmesh::Halfedge_mesh<>;

// A visitor is a genmesh::Mutation_visitor with the hooks it needs.
struct Carry_height : genmesh::Mutation_visitor {
  std::vector<double> value; // by vertex index
  double next = 0;
  void on_collapse_placement(genmesh::Halfedge_index h, const Eigen::Vector3d& x, double /*cost*/, const Mesh& g) {
    // Interpolate the two ends' values at x's projection on the edge.
    const Eigen::Vector3d a = g.point(source(h, g)), b = g.point(target(h, g));
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    next = (1 - t) * value[source(h, g).idx()] + t * value[target(h, g).idx()];
  }
  void on_collapse(genmesh::Vertex_index v, const Mesh&) { value[v.idx()] = next; }
};

int main() {
  Mesh mesh;
  genmesh::build_mesh(genmesh::make_icosphere(4), mesh);
  Carry_height carry;
  carry.value.resize(mesh.number_of_vertices());
  for (auto v : vertices(mesh)) carry.value[v.idx()] = mesh.point(v).z();

  const auto r = genmesh::simplify(
      mesh, genmesh::Simplification_options<genmesh::Lindstrom_turk>{.target_ratio = 0.1, .feature_angle = 60.0},
      carry);

  double worst = 0; // how far the carried value is from the height now
  for (auto v : vertices(mesh)) worst = std::max(worst, std::abs(carry.value[v.idx()] - mesh.point(v).z()));
  std::cout << r.faces << " faces after " << r.collapses << " collapses (" << genmesh::to_string(r.stop_reason)
            << "), carried value within " << worst << " of the height\n";

  Mesh passes;
  genmesh::build_mesh(genmesh::make_icosphere(4), passes);
  const auto rp = genmesh::simplify(passes, {.target_ratio = 0.1, .schedule = genmesh::Schedule::passes});
  std::cout << "in passes: " << rp.faces << " faces after " << rp.collapses << " collapses\n";

  return genmesh::check_mesh(mesh).ok() && r.stop_reason == genmesh::Stop_reason::target_faces && worst < 0.1 &&
                 genmesh::check_mesh(passes).ok() && rp.stop_reason == genmesh::Stop_reason::target_faces
             ? 0
             : 1;
}
