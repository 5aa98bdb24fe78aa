// Isotropic remeshing: the whole loop, one step alone, and a face patch.
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/remeshing.h>
#include <genmesh/renumbering.h>
#include <genmesh/validity.h>

#include <algorithm>
#include <iostream>
#include <vector>

int main() {
  genmesh::Halfedge_mesh<> mesh;                                  // or CGAL::Surface_mesh, …
  genmesh::build_mesh(genmesh::make_icosphere(3), mesh);
  const genmesh::Remeshing_result r =
      genmesh::isotropic_remeshing(mesh, {.relative_edge_length = 0.5, .iterations = 3});
  std::cout << r.iterations << " rounds: " << r.splits << " splits, " << r.collapses << " collapses, "
            << r.flips << " flips, " << r.faces << " faces at L = " << r.target_edge_length << "\n";

  // One step alone, with the same options: bring valences towards 6.
  const std::size_t flips = genmesh::equalize_valences(mesh);

  // A patch: only the first half of a grid's faces; its border and the
  // other faces stay as they are.
  genmesh::Halfedge_mesh<> grid;
  genmesh::build_mesh(genmesh::make_grid(10, 10), grid);
  genmesh::Remeshing_options patch{.target_edge_length = 0.04, .iterations = 3};
  patch.faces.assign(200, 0);
  for (std::size_t f = 0; f < 100; ++f) patch.faces[f] = 1;
  const auto p = genmesh::isotropic_remeshing(grid, patch);
  std::cout << "patch: " << p.faces << " faces; then " << flips << " more flips on the sphere\n";

  // Renumbering (what the remesher does between rounds): vertices sorted
  // along x, edges and faces after their first vertex in that order.
  std::vector<genmesh::Vertex_index> order(vertices(mesh).begin(), vertices(mesh).end());
  std::stable_sort(order.begin(), order.end(),
                   [&](auto a, auto b) { return mesh.point(a).x() < mesh.point(b).x(); });
  const auto o = genmesh::spatial_orders(mesh, order);
  const genmesh::Renumbering_maps maps = genmesh::renumber(mesh, o.vertices, o.edges, o.faces);
  const bool sorted = mesh.point(genmesh::Vertex_index(0)).x() <= mesh.point(genmesh::Vertex_index(1)).x();
  std::cout << "renumbered: old vertex 0 is now " << maps.vertices[0] << "\n";

  return sorted && genmesh::check_mesh(mesh).ok() && genmesh::check_mesh(grid).ok() && p.faces > 200 ? 0 : 1;
}
