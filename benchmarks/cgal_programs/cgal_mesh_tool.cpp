// benchmarks/cgal_programs/cgal_mesh_tool.cpp — what a CGAL user writes for
// each genmesh CLI command, with CGAL's own IO, checks and subdivision, for
// end-to-end comparisons (wall time and peak memory of the whole process).
//
//   cgal_mesh_tool info FILE                 read → validate → counts
//   cgal_mesh_tool check FILE                same as info
//   cgal_mesh_tool convert IN OUT            read → validate → write
//   cgal_mesh_tool subdivide IN OUT SCHEME LEVELS
//                  (SCHEME: loop, catmull-clark, sqrt3, doo-sabin)
//                                            read → check soup → subdivide → validate → write
//
// Each step is the CGAL call a user would reach for: CGAL::IO::read_polygon_soup,
// PMP::is_polygon_soup_a_polygon_mesh (the soup check), PMP::polygon_soup_to_polygon_mesh,
// CGAL::is_valid_polygon_mesh, PMP::connected_components and
// PMP::extract_boundary_cycles (the counts genmesh info prints),
// CGAL::Subdivision_method_3, CGAL::IO::write_polygon_mesh with 17 digits
// (genmesh's default precision). The soup is freed once the mesh is built.
// Exit status 0 valid, 2 invalid, 1 error (as genmesh's).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

namespace {

bool read_and_build(const std::string& path, Mesh& mesh) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, points, polygons)) {
    std::cerr << path << ": cannot read\n";
    std::exit(1);
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    std::cout << path << ": not a valid oriented 2-manifold polygon mesh\n";
    return false;
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return true;
}

// What genmesh info prints: counts, boundary loops, components, χ, validity.
bool report(const std::string& name, Mesh& mesh) {
  const bool valid = CGAL::is_valid_polygon_mesh(mesh);
  std::vector<Mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:cc", 0).first;
  const std::size_t components = PMP::connected_components(mesh, component);
  const long chi = static_cast<long>(mesh.number_of_vertices()) - static_cast<long>(mesh.number_of_edges()) +
                   static_cast<long>(mesh.number_of_faces());
  std::cout << name << " (CGAL Surface_mesh)\n"
            << "  vertices             " << mesh.number_of_vertices() << "\n"
            << "  edges                " << mesh.number_of_edges() << "\n"
            << "  faces                " << mesh.number_of_faces() << "\n"
            << "  boundary loops       " << borders.size() << "\n"
            << "  components           " << components << "\n"
            << "  euler characteristic " << chi << "\n"
            << "  valid                " << (valid ? "yes" : "no") << "\n";
  return valid;
}

void write(const std::string& path, const Mesh& mesh) {
  if (!CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << path << ": cannot write\n";
    std::exit(1);
  }
}

} // namespace

int main(int argc, char** argv) {
  const std::string command = argc > 1 ? argv[1] : "";
  if ((command == "info" || command == "check") && argc == 3) {
    Mesh mesh;
    if (!read_and_build(argv[2], mesh)) return 2;
    return report(argv[2], mesh) ? 0 : 2;
  }
  if (command == "convert" && argc == 4) {
    Mesh mesh;
    if (!read_and_build(argv[2], mesh)) return 2;
    if (!CGAL::is_valid_polygon_mesh(mesh)) return 2;
    write(argv[3], mesh);
    return 0;
  }
  if (command == "subdivide" && argc == 6) {
    Mesh mesh;
    if (!read_and_build(argv[2], mesh)) return 2;
    const std::string scheme = argv[4];
    const auto levels = CGAL::parameters::number_of_iterations(std::atoi(argv[5]));
    if (scheme == "loop") CGAL::Subdivision_method_3::Loop_subdivision(mesh, levels);
    else if (scheme == "catmull-clark") CGAL::Subdivision_method_3::CatmullClark_subdivision(mesh, levels);
    else if (scheme == "sqrt3") CGAL::Subdivision_method_3::Sqrt3_subdivision(mesh, levels);
    else if (scheme == "doo-sabin") CGAL::Subdivision_method_3::DooSabin_subdivision(mesh, levels);
    else {
      std::cerr << "unknown scheme " << scheme << "\n";
      return 1;
    }
    if (!CGAL::is_valid_polygon_mesh(mesh)) return 2;
    std::cout << argv[2] << " -> " << argv[3] << ": " << scheme << " x" << argv[5] << ", "
              << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces\n";
    write(argv[3], mesh);
    return 0;
  }
  std::cerr << "usage: cgal_mesh_tool info|check FILE | convert IN OUT | subdivide IN OUT SCHEME LEVELS\n";
  return 1;
}
