// Simplification that respects a per-vertex colour (Garland–Heckbert 1998
// quadrics over position and colour): a sphere painted red above the
// equator and blue below keeps a sharp colour border after 90% of its faces
// are gone, and every vertex left gets the colour that fits its
// neighbourhood best.
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

int main() {
  Mesh mesh;
  genmesh::build_mesh(genmesh::make_icosphere(4), mesh);
  std::vector<double> rgb(3 * mesh.number_of_vertices()); // by vertex index
  for (auto v : vertices(mesh)) {
    const bool north = mesh.point(v).z() > 0;
    rgb[3 * v.idx()] = north ? 1.0 : 0.0;     // red
    rgb[3 * v.idx() + 2] = north ? 0.0 : 1.0; // blue
  }

  genmesh::Attribute_quadrics colours{
      .dimension = 3,
      .read = [&](std::size_t v, double* out) { std::copy_n(&rgb[3 * v], 3, out); },
      .write = [&](std::size_t v, const double* in) { std::copy_n(in, 3, &rgb[3 * v]); },
      .weights = {0.2, 0.2, 0.2}};
  const auto r = genmesh::simplify(
      mesh, genmesh::Simplification_options<genmesh::Attribute_quadrics>{.target_ratio = 0.1, .policy = colours});

  // A vertex away from the equator keeps its pure colour.
  double worst = 0;
  for (auto v : vertices(mesh)) {
    const double z = mesh.point(v).z();
    if (std::abs(z) < 0.15) continue;
    const double red = z > 0 ? 1.0 : 0.0;
    worst = std::max({worst, std::abs(rgb[3 * v.idx()] - red), std::abs(rgb[3 * v.idx() + 2] - (1 - red))});
  }
  std::cout << r.faces << " faces after " << r.collapses << " collapses (" << genmesh::to_string(r.stop_reason)
            << "); colours away from the equator within " << worst << " of pure\n";
  return genmesh::check_mesh(mesh).ok() && r.stop_reason == genmesh::Stop_reason::target_faces && worst < 0.05 ? 0
                                                                                                               : 1;
}
