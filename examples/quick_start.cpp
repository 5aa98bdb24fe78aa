// The README's example: build a mesh, check it, write it, read it back.
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/io.h>
#include <genmesh/validity.h>

#include <filesystem>
#include <iostream>

int main() {
  genmesh::Halfedge_mesh<> mesh;                       // or CGAL::Surface_mesh, …
  genmesh::build_mesh(genmesh::make_torus(), mesh);    // any soup; refuses bad ones
  const auto path = std::filesystem::temp_directory_path() / "torus.ply";
  genmesh::write_mesh(path, mesh, {.binary = true});   // write, then rename

  genmesh::Halfedge_mesh<> copy;
  genmesh::read_mesh(path, copy);                      // OFF, OBJ, PLY, STL
  const genmesh::Mesh_report r = genmesh::check_mesh(copy);
  std::cout << r.vertices << " vertices, " << r.faces << " faces, genus "
            << r.genus.value_or(-1) << (r.valid ? ", valid\n" : ", INVALID\n");
  return r.valid && r.genus == 1 ? 0 : 1;
}
