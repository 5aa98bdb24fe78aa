// tests/backends.h — the backends every typed test runs on, and test data paths.
#pragma once

#include <genmesh/adaptors/cgal.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/soup_to_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace genmesh_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;
using Incidence_mesh = genmesh::Incidence_mesh<>;

/// Every backend a typed algorithm test runs on.
using Backends = ::testing::Types<Halfedge_mesh, Surface_mesh, Incidence_mesh>;

/// The backends that store halfedge links (MutableFaceGraph: set_next & co):
/// for tests that corrupt links on purpose or run CGAL::Euler on the mesh
/// itself. Incidence_mesh derives its links from the matrices instead.
using Pointer_backends = ::testing::Types<Halfedge_mesh, Surface_mesh>;

/// A mesh of backend G linked from a polygon soup (build_mesh's checks on).
template <class G>
G mesh_of(const genmesh::Polygon_soup& soup) {
  G g;
  genmesh::build_mesh(soup, g);
  return g;
}

/// A real mesh from libcgal-demo (fetched by scripts/run.sh setup). Missing
/// data is a failure, never a silent skip.
inline std::string real_mesh(const std::string& name) {
  std::filesystem::path p = std::filesystem::path(GENMESH_DATA_DIR) / "meshes" / name;
  if (!std::filesystem::exists(p))
    throw std::runtime_error("test data missing: " + p.string() +
                             " (run scripts/run.sh setup)");
  return p.string();
}

/// A scratch path under the build tree, private to this process (ctest runs
/// test processes in parallel).
inline std::string tmp_path(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(GENMESH_TEST_TMP_DIR) / std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

} // namespace genmesh_test
