// simplify_probe — one simplify() configuration on one backend, for checking
// that a change keeps the meshes (an FNV-1a hash of the canonical soup) and for
// timing it in interleaved same-run pairs (thread CPU time, min and median of
// the repetitions). Not a benchmark row: the side-by-side runner
// (benchmarks/side_by_side/run.py) is where figures for docs come from; this
// is the quick check every simplification change is held to.
//
//   simplify_probe INPUT BACKEND [key=value ...]
//     INPUT   a mesh file (OFF, OBJ, PLY, STL), or grid:N (a flat N × N grid),
//             hole:N (N × N grid with a hole), tilt:N (hole:N, tilted)
//     BACKEND he | sm | im (Halfedge_mesh, CGAL::Surface_mesh, Incidence_mesh)
//     keys    loop=L (Loop levels first, default 0), ratio=R (default 0.1),
//             guard=0|1 (default 1), schedule=queue|passes, reps=N (default 1),
//             order=morton (the input renumbered in space first: how much of a
//             run is the input's memory order; another mesh, another hash)
//
// Prints one line: input, backend, options, faces, exact tests, hash, min
// and median seconds.
#include <genmesh/adaptors/cgal.h>
#include <genmesh/detail/geometry/morton.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/simplification.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <string>
#include <vector>

namespace {

using Surface_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

struct Options {
  int loop = 0;
  double ratio = 0.1;
  bool guard = true;
  genmesh::Schedule schedule = genmesh::Schedule::queue;
  int reps = 1;
  bool morton = false;
};

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::uint64_t fnv1a(const genmesh::Polygon_soup& s) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  auto add = [&h](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  };
  for (const auto& p : s.points) add(p.data(), 3 * sizeof(double));
  add(s.indices.data(), s.indices.size() * sizeof(s.indices[0]));
  add(s.offsets.data(), s.offsets.size() * sizeof(s.offsets[0]));
  return h;
}

// The soup renumbered: its vertices by the Morton code of their point (21
// bits an axis over the bounding box), its faces by their smallest new
// corner; each face keeps its corners' cyclic order.
void morton_order(genmesh::Polygon_soup& s) {
  Eigen::Vector3d lo = s.points[0], hi = s.points[0];
  for (const auto& p : s.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double scale = 2097151.0 / (hi - lo).maxCoeff();
  std::vector<std::pair<std::uint64_t, std::size_t>> key(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Eigen::Vector3d q = (s.points[i] - lo) * scale;
    using genmesh::detail::morton_spread;
    key[i] = {morton_spread(std::uint64_t(q.x())) | morton_spread(std::uint64_t(q.y())) << 1 |
                  morton_spread(std::uint64_t(q.z())) << 2,
              i};
  }
  std::sort(key.begin(), key.end());
  std::vector<std::size_t> to(s.points.size());
  decltype(s.points) pts(s.points.size());
  for (std::size_t i = 0; i < key.size(); ++i) {
    to[key[i].second] = i;
    pts[i] = s.points[key[i].second];
  }
  s.points = pts;
  std::vector<std::pair<std::size_t, std::size_t>> fk(s.num_faces());
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    std::size_t m = SIZE_MAX;
    for (auto k = s.offsets[f]; k < s.offsets[f + 1]; ++k) m = std::min<std::size_t>(m, to[s.indices[k]]);
    fk[f] = {m, f};
  }
  std::sort(fk.begin(), fk.end());
  genmesh::Polygon_soup t;
  t.points = s.points;

  for (const auto& [m, f] : fk) {
    for (auto k = s.offsets[f]; k < s.offsets[f + 1]; ++k)
      t.indices.push_back(static_cast<decltype(t.indices)::value_type>(to[s.indices[k]]));
    t.offsets.push_back(static_cast<decltype(t.offsets)::value_type>(t.indices.size()));
  }
  s = std::move(t);
}

genmesh::Polygon_soup input(const std::string& spec, int loop) {
  auto n_of = [&](std::size_t at) { return std::atoi(spec.c_str() + at); };
  genmesh::Polygon_soup s;
  if (spec.rfind("grid:", 0) == 0) s = genmesh::make_grid(n_of(5), n_of(5));
  else if (spec.rfind("hole:", 0) == 0) s = genmesh::make_grid_with_hole(n_of(5));
  else if (spec.rfind("tilt:", 0) == 0) {
    s = genmesh::make_grid_with_hole(n_of(5));
    for (auto& p : s.points) p = Eigen::Vector3d(p.x(), p.y() * 0.6, p.y() * 0.8 + 0.3 * p.x());
  } else s = genmesh::read_soup(spec);
  if (loop > 0) {
    genmesh::Halfedge_mesh<> g;
    genmesh::build_mesh(s, g);
    genmesh::loop_subdivision(g, {.iterations = loop});
    s = genmesh::to_soup(g);
  }
  return s;
}

template <class G>
int run(const std::string& spec, const char* backend, const Options& o) {
  genmesh::Polygon_soup in = input(spec, o.loop);
  if (o.morton) morton_order(in);
  const auto target = static_cast<std::size_t>(std::ceil(o.ratio * static_cast<double>(in.num_faces())));
  std::vector<double> seconds;
  genmesh::Simplification_result r;
  std::uint64_t hash = 0;
  for (int i = 0; i < o.reps; ++i) {
    G g;
    genmesh::build_mesh(in, g, {.check = false});
    const double t0 = thread_seconds();
    r = genmesh::simplify(g, genmesh::Simplification_options<>{.target_faces = target,
                                                               .prevent_self_intersections = o.guard,
                                                               .schedule = o.schedule});
    seconds.push_back(thread_seconds() - t0);
    const std::uint64_t h = fnv1a(genmesh::canonical(genmesh::to_soup(g)));
    if (i > 0 && h != hash) {
      std::fprintf(stderr, "simplify_probe: repetition %d gave another mesh\n", i);
      return 1;
    }
    hash = h;
  }
  std::vector<double> sorted = seconds;
  std::sort(sorted.begin(), sorted.end());
  std::printf("%s %s loop=%d ratio=%g guard=%d schedule=%s faces=%zu exact_tests=%zu hash=%016llx min_s=%.5f "
              "median_s=%.5f\n",
              spec.c_str(), backend, o.loop, o.ratio, o.guard ? 1 : 0,
              o.schedule == genmesh::Schedule::queue ? "queue" : "passes", r.faces, r.exact_intersection_tests,
              static_cast<unsigned long long>(hash), sorted.front(), sorted[sorted.size() / 2]);
  return 0;
}

} // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: simplify_probe INPUT he|sm|im [loop=L] [ratio=R] [guard=0|1] "
                         "[schedule=queue|passes] [order=morton] [reps=N]\n");
    return 2;
  }
  Options o;
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    const std::string k = a.substr(0, eq), v = eq == std::string::npos ? "" : a.substr(eq + 1);
    if (k == "loop") o.loop = std::stoi(v);
    else if (k == "ratio") o.ratio = std::stod(v);
    else if (k == "guard") o.guard = v != "0";
    else if (k == "schedule") o.schedule = v == "passes" ? genmesh::Schedule::passes : genmesh::Schedule::queue;
    else if (k == "order") o.morton = v == "morton";
    else if (k == "reps") o.reps = std::max(1, std::stoi(v));
    else {
      std::fprintf(stderr, "simplify_probe: unknown option '%s'\n", a.c_str());
      return 2;
    }
  }
  const std::string b = argv[2];
  if (b == "he") return run<genmesh::Halfedge_mesh<>>(argv[1], "he", o);
  if (b == "sm") return run<Surface_mesh>(argv[1], "sm", o);
  if (b == "im") return run<genmesh::Incidence_mesh<>>(argv[1], "im", o);
  std::fprintf(stderr, "simplify_probe: unknown backend '%s' (he, sm or im)\n", b.c_str());
  return 2;
} catch (const std::exception& e) {
  std::fprintf(stderr, "simplify_probe: %s\n", e.what());
  return 1;
}
