// Simplification that respects per-vertex attributes (Garland–Heckbert 1998
// quadrics over position and attribute values): a sphere painted red above
// the equator and blue below, with texture coordinates, keeps a sharp colour
// border after 90% of its faces are gone, and every vertex left gets the
// colour and texture coordinates that fit its neighbourhood best — written
// back into the mesh's own property maps. Colour and texture coordinates are
// 5 values: Attribute_quadrics<Mesh, 8> (3 + 5 ≤ 8) keeps its quadrics inline,
// without an allocation per evaluation, and gives what Attribute_quadrics<Mesh>
// would, to the bit. The result, with its attributes, goes to an OBJ file
// (v with colour, vt) and comes back with read_mesh. Then the same with
// Hoppe's 1999 metric (Hoppe_quadrics<Mesh, 5>: plain plane distance plus
// each value's deviation from its face's interpolation).
#include <genmesh/generators.h>
#include <genmesh/io.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/simplification.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <vector>

using Mesh = genmesh::Halfedge_mesh<>;

using Colour_map = Mesh::Vertex_property<Eigen::Vector3d>;
using Uv_map = Mesh::Vertex_property<std::array<double, 2>>;

// An icosphere painted red north, blue south, with planar texture coordinates.
void paint(Mesh& mesh, Colour_map& colour, Uv_map& uv) {
  genmesh::build_mesh(genmesh::make_icosphere(4), mesh);
  // Attributes are vertex property maps: here the mesh's own properties
  // (any readable and writable map keyed by vertex works).
  colour = mesh.add_vertex_property<Eigen::Vector3d>("v:colour", Eigen::Vector3d::Zero());
  uv = mesh.add_vertex_property<std::array<double, 2>>("v:uv");
  for (auto v : vertices(mesh)) {
    const Eigen::Vector3d p = mesh.point(v);
    colour[v] = p.z() > 0 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1); // red north, blue south
    uv[v] = {0.5 + 0.5 * p.x(), 0.5 + 0.5 * p.y()}; // a planar projection
  }
}

// The largest deviation from the pure colour away from the equator.
double colour_error(const Mesh& mesh, const Colour_map& colour) {
  double worst = 0;
  for (auto v : vertices(mesh)) {
    const double z = mesh.point(v).z();
    if (std::abs(z) < 0.15) continue;
    const Eigen::Vector3d pure = z > 0 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1);
    worst = std::max(worst, (colour[v] - pure).cwiseAbs().maxCoeff());
  }
  return worst;
}

int main() {
  Mesh mesh;
  Colour_map colour;
  Uv_map uv;
  paint(mesh, colour, uv);

  // Weights: model units per unit of the value (colours in [0, 1]: a full
  // colour change costs like a 0.2-unit distance).
  const auto r = genmesh::simplify(
      mesh, genmesh::Simplification_options<genmesh::Attribute_quadrics<Mesh, 8>>{
                .target_ratio = 0.1,
                .policy = {.attributes = {genmesh::vertex_attribute(colour, 0.2, "colour"),
                                          genmesh::vertex_attribute(uv, 0.5, "uv")}}});

  // A vertex away from the equator keeps its pure colour.
  const double worst = colour_error(mesh, colour);
  // To a file and back: the channels in the mesh's vertex order.
  const std::vector<genmesh::Soup_attribute> channels = {
      genmesh::make_soup_attribute(mesh, colour, "color"), genmesh::make_soup_attribute(mesh, uv, "texcoord")};
  const auto file = std::filesystem::temp_directory_path() / "genmesh_simplify_attributes.obj";
  genmesh::write_mesh(file, mesh, channels);
  Mesh back;
  const std::vector<genmesh::Soup_attribute> read = genmesh::read_mesh(file, back);
  std::filesystem::remove(file);
  const bool round_trip = read.size() == 2 && read[1].values == channels[1].values && num_faces(back) == r.faces;

  std::cout << r.faces << " faces after " << r.collapses << " collapses (" << genmesh::to_string(r.stop_reason)
            << "); colours away from the equator within " << worst << " of pure\n";

  // Hoppe's metric, same maps and weights.
  Mesh hoppe;
  Colour_map hoppe_colour;
  Uv_map hoppe_uv;
  paint(hoppe, hoppe_colour, hoppe_uv);
  const auto rh = genmesh::simplify(
      hoppe, genmesh::Simplification_options<genmesh::Hoppe_quadrics<Mesh, 5>>{
                 .target_ratio = 0.1,
                 .policy = {.attributes = {genmesh::vertex_attribute(hoppe_colour, 0.2, "colour"),
                                           genmesh::vertex_attribute(hoppe_uv, 0.5, "uv")}}});
  const double hoppe_worst = colour_error(hoppe, hoppe_colour);
  std::cout << "Hoppe 1999: " << rh.faces << " faces; colours away from the equator within " << hoppe_worst
            << " of pure\n";
  return genmesh::check_mesh(mesh).ok() && r.stop_reason == genmesh::Stop_reason::target_faces && worst < 0.05 &&
                 round_trip && genmesh::check_mesh(hoppe).ok() &&
                 rh.stop_reason == genmesh::Stop_reason::target_faces && hoppe_worst < 0.05
             ? 0
             : 1;
}
