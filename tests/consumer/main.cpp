// Built against the *installed* genmesh package by the consumer test.
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <iostream>

int main() {
  genmesh::Halfedge_mesh<> mesh;
  genmesh::build_mesh(genmesh::make_torus(), mesh);
  const genmesh::Mesh_report report = genmesh::check_mesh(mesh);
  std::cout << "torus: " << report.vertices << " vertices, genus "
            << (report.genus ? *report.genus : -1) << "\n";
  return report.valid && report.genus == 1 ? 0 : 1;
}
