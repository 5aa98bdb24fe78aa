// genmesh — the command-line program: run genmesh on files, and its demo.
//
//   genmesh info FILE      [--backend B] [--json]   counts and topology
//   genmesh check FILE     [--backend B] [--json] [--repair]
//                                                   full validity report
//   genmesh convert IN OUT [--backend B] [--json] [--binary] [--repair]
//   genmesh subdivide IN OUT --scheme S --levels N [--boundary smooth|fixed]
//                          [--creases FILE] [--backend B] [--json]
//   genmesh demo           [--json]                 every backend on built-in meshes
//   genmesh measure A [B]  [--backend B] [--json] [--samples N]
//                          quality and self-intersections of A (and B), with B
//                          the two-way Hausdorff / RMS distance
//   (--backend halfedge|surface-mesh|incidence; check --backend incidence also
//   names the fins, misoriented edges and bow-ties of a non-manifold input)
//
// Exit codes: 0 ok; 1 the mesh is invalid (reported on stdout); 2 bad input or
// usage (message on stderr). `--json` prints one line per record; `seconds` is
// the algorithm alone (building the mesh and checking it), file IO excluded.
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/local_operations.h>
#include <genmesh/measures.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>
#include <genmesh/validity.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;
using Incidence_mesh = genmesh::Incidence_mesh<>;

constexpr int exit_ok = 0;
constexpr int exit_invalid = 1;
constexpr int exit_bad_input = 2;

struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* usage_text =
    "usage: genmesh <command> [options]\n"
    "  info FILE          counts and topology of a mesh\n"
    "  check FILE         validity report (soup problems, halfedge invariants)\n"
    "  convert IN OUT     read IN, build a valid mesh, write OUT (format from extension)\n"
    "  subdivide IN OUT   subdivide IN, write OUT\n"
    "  demo               run genmesh on built-in meshes on every backend\n"
    "  measure A [B]      quality and self-intersections of A; with B also the\n"
    "                     two-way Hausdorff and RMS distance (relative to A's diagonal)\n"
    "options:\n"
    "  --backend halfedge|surface-mesh|incidence   mesh type to build (default halfedge)\n"
    "  --json             one-line machine-readable record\n"
    "  --repair           repair a non-manifold or inconsistently oriented soup\n"
    "  --binary           binary output (PLY, STL) for convert and subdivide\n"
    "  --scheme S         loop|catmull-clark|sqrt3|doo-sabin|butterfly|midpoint\n"
    "  --levels N         subdivision levels (default 1)\n"
    "  --boundary B       smooth|fixed border rule (loop, catmull-clark, sqrt3)\n"
    "  --creases FILE     lines 'u v sharpness' (input vertex indices; inf = sharp)\n"
    "  --samples N        measure: face samples per direction (default max(10 x faces, 100000))\n"
    "formats: OFF, OBJ, PLY (ASCII, binary), STL (ASCII, binary)\n";

struct Args {
  std::string command;
  std::vector<std::string> files;
  std::string backend = "halfedge";
  bool json = false;
  bool repair = false;
  bool binary = false;
  std::string scheme;
  int levels = 1;
  std::string boundary = "smooth";
  std::string creases;
  std::size_t samples = 0;  // measure --samples
};

Args parse(int argc, char** argv) {
  Args a;
  if (argc < 2) throw usage_error("no command given");
  a.command = argv[1];
  for (int i = 2; i < argc; ++i) {
    std::string s = argv[i];
    if (s == "--json") a.json = true;
    else if (s == "--repair") a.repair = true;
    else if (s == "--binary") a.binary = true;
    else if (s == "--backend" || s.rfind("--backend=", 0) == 0) {
      if (s == "--backend") {
        if (i + 1 >= argc) throw usage_error("--backend needs a value");
        a.backend = argv[++i];
      } else {
        a.backend = s.substr(10);
      }
      if (a.backend != "halfedge" && a.backend != "surface-mesh" && a.backend != "incidence")
        throw usage_error("unknown backend '" + a.backend + "' (halfedge|surface-mesh|incidence)");
    } else if (s == "--scheme" || s == "--levels" || s == "--boundary" || s == "--creases") {
      if (i + 1 >= argc) throw usage_error(s + " needs a value");
      const std::string v = argv[++i];
      if (s == "--scheme") a.scheme = v;
      else if (s == "--boundary") a.boundary = v;
      else if (s == "--creases") a.creases = v;
      else {
        std::size_t used = 0;
        try {
          a.levels = std::stoi(v, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != v.size() || a.levels < 0 || a.levels > 12)
          throw usage_error("--levels takes a whole number from 0 to 12, got '" + v + "'");
      }
    } else if (s == "--samples") {
      if (i + 1 >= argc) throw usage_error(s + " needs a value");
      const std::string v = argv[++i];
      std::size_t used = 0;
      unsigned long long n = 0;
      try {
        n = std::stoull(v, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != v.size() || v[0] == '-' || n == 0 || n > 1'000'000'000ULL)
        throw usage_error("--samples takes a whole number from 1 to 1e9, got '" + v + "'");
      a.samples = static_cast<std::size_t>(n);
    } else if (s.size() > 1 && s[0] == '-') {
      throw usage_error("unknown option '" + s + "'");
    } else {
      a.files.push_back(s);
    }
  }
  const std::map<std::string, std::size_t> files_needed{
      {"info", 1}, {"check", 1}, {"convert", 2}, {"subdivide", 2}, {"demo", 0}};
  if (a.command == "measure") {
    if (a.files.size() != 1 && a.files.size() != 2)
      throw usage_error("'measure' takes 1 or 2 file arguments, got " + std::to_string(a.files.size()));
    return a;
  }
  auto it = files_needed.find(a.command);
  if (it == files_needed.end()) throw usage_error("unknown command '" + a.command + "'");
  if (a.files.size() != it->second)
    throw usage_error("'" + a.command + "' takes " + std::to_string(it->second) + " file argument" +
                      (it->second == 1 ? "" : "s") + ", got " + std::to_string(a.files.size()));
  if (a.command == "subdivide") {
    static const std::vector<std::string> schemes{"loop", "catmull-clark", "sqrt3",
                                                  "doo-sabin", "butterfly", "midpoint"};
    if (a.scheme.empty()) throw usage_error("subdivide needs --scheme");
    if (std::find(schemes.begin(), schemes.end(), a.scheme) == schemes.end())
      throw usage_error("unknown scheme '" + a.scheme +
                        "' (loop|catmull-clark|sqrt3|doo-sabin|butterfly|midpoint)");
    if (a.boundary != "smooth" && a.boundary != "fixed")
      throw usage_error("unknown boundary rule '" + a.boundary + "' (smooth|fixed)");
    if (!a.creases.empty() && a.scheme != "loop" && a.scheme != "catmull-clark")
      throw usage_error("--creases applies to loop and catmull-clark only");
  }
  return a;
}

std::string json_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '"': r += "\\\""; break;
      case '\\': r += "\\\\"; break;
      case '\n': r += "\\n"; break;
      case '\t': r += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          r += buf;
        } else {
          r += c;
        }
    }
  }
  return r;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The fields every record shares: the mesh's counts and topology.
std::string json_counts(const genmesh::Mesh_report& r) {
  std::ostringstream o;
  o << "\"vertices\":" << r.vertices << ",\"edges\":" << r.edges << ",\"faces\":" << r.faces
    << ",\"boundary_loops\":" << r.boundary_loops << ",\"components\":" << r.components
    << ",\"euler_characteristic\":" << r.euler_characteristic
    << ",\"manifold\":" << (r.manifold ? "true" : "false")
    << ",\"valid\":" << (r.valid ? "true" : "false");
  if (r.genus) o << ",\"genus\":" << *r.genus;
  return o.str();
}

void print_counts(const std::string& name, const std::string& backend,
                  const genmesh::Mesh_report& r, double seconds) {
  std::cout << name << " (" << backend << ")\n"
            << "  vertices             " << r.vertices << "\n"
            << "  edges                " << r.edges << "\n"
            << "  faces                " << r.faces << "\n"
            << "  boundary loops       " << r.boundary_loops << "\n"
            << "  components           " << r.components << "\n"
            << "  euler characteristic " << r.euler_characteristic << "\n"
            << "  genus                " << (r.genus ? std::to_string(*r.genus) : "n/a") << "\n"
            << "  manifold             " << (r.manifold ? "yes" : "no") << "\n"
            << "  valid                " << (r.valid ? "yes" : "no") << "\n"
            << "  seconds              " << seconds << "\n";
}

// Builds the requested backend from a soup and hands it to f(mesh, backend name).
template <class F>
auto with_backend(const std::string& backend, F&& f) {
  if (backend == "surface-mesh") {
    Surface_mesh m;
    return f(m);
  }
  if (backend == "incidence") {
    Incidence_mesh m;
    return f(m);
  }
  Halfedge_mesh m;
  return f(m);
}

int cmd_info_or_check(const Args& a) {
  const std::string& file = a.files[0];
  genmesh::Polygon_soup soup = genmesh::read_soup(file);

  // The soup is checked first: a halfedge mesh cannot hold what a bad soup says.
  const auto t0 = std::chrono::steady_clock::now();
  genmesh::Soup_report soup_report = genmesh::check_soup(soup);
  if (!soup_report.ok() && !a.repair) {
    const double seconds = seconds_since(t0);
    if (a.json) {
      std::cout << "{\"command\":\"" << a.command << "\",\"file\":\"" << json_escape(file)
                << "\",\"backend\":\"" << a.backend << "\",\"valid\":false,\"manifold\":false"
                << ",\"problems\":\"" << json_escape(genmesh::to_string(soup_report))
                << "\",\"seconds\":" << seconds << "}\n";
    } else {
      std::cout << file << ": not a valid oriented 2-manifold polygon mesh\n"
                << genmesh::to_string(soup_report);
      if (a.backend == "incidence") {
        // The incidence mesh holds what a halfedge mesh cannot: load the soup
        // as it is and name the fins, misoriented edges and bow-ties.
        Incidence_mesh m;
        m.load_soup(soup);
        std::cout << "incidence mesh (" << m.n_vertices() << " vertices, " << m.n_edges()
                  << " edges, " << m.n_faces() << " faces): " << genmesh::to_string(m.manifold_report());
      }
      std::cout << "(run with --repair to fix what can be fixed)\n";
    }
    return exit_invalid;
  }

  return with_backend(a.backend, [&](auto& mesh) {
    genmesh::Build_report build;
    try {
      build = genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    } catch (const genmesh::invalid_input& e) {
      // Repair was asked for and could not make a valid mesh: the input is invalid.
      std::cout << file << ": " << e.what() << "\n";
      return exit_invalid;
    }
    genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    const double seconds = seconds_since(t0);
    if (a.json) {
      std::cout << "{\"command\":\"" << a.command << "\",\"file\":\"" << json_escape(file)
                << "\",\"backend\":\"" << a.backend << "\"," << json_counts(report)
                << ",\"seconds\":" << seconds << "}\n";
    } else {
      print_counts(file, a.backend, report, seconds);
      if (a.repair) std::cout << genmesh::to_string(build.repair);
      if (a.command == "check" || !report.ok()) std::cout << genmesh::to_string(report);
    }
    return report.ok() ? exit_ok : exit_invalid;
  });
}

int cmd_convert(const Args& a) {
  genmesh::Polygon_soup soup = genmesh::read_soup(a.files[0]);
  const auto t0 = std::chrono::steady_clock::now();
  return with_backend(a.backend, [&](auto& mesh) {
    genmesh::Build_report build = genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    const double seconds = seconds_since(t0);
    if (!report.ok()) {
      std::cout << genmesh::to_string(report);
      return exit_invalid;
    }
    genmesh::write_mesh(a.files[1], mesh, {.binary = a.binary});
    if (a.json) {
      std::cout << "{\"command\":\"convert\",\"file\":\"" << json_escape(a.files[0])
                << "\",\"output\":\"" << json_escape(a.files[1]) << "\",\"backend\":\"" << a.backend
                << "\"," << json_counts(report) << ",\"seconds\":" << seconds << "}\n";
    } else {
      if (a.repair) std::cout << genmesh::to_string(build.repair);
      std::cout << a.files[0] << " -> " << a.files[1] << ": " << report.vertices << " vertices, "
                << report.faces << " faces\n";
    }
    return exit_ok;
  });
}

// ---- subdivide ---------------------------------------------------------------

// Reads a crease file: one "u v sharpness" line per edge, u and v input vertex
// indices, sharpness a number >= 0 or "inf"; '#' starts a comment. Whether
// u-v is an edge of the mesh is checked by genmesh::crease_sharpness.
std::vector<genmesh::Crease> read_creases(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw genmesh::io_error(path, "cannot open crease file");
  std::vector<genmesh::Crease> creases;
  std::string line;
  for (std::uint64_t n = 1; std::getline(in, line); ++n) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream ls(line);
    std::string u_text, v_text, sharpness_text, extra;
    if (!(ls >> u_text)) continue;  // blank line
    if (!(ls >> v_text >> sharpness_text) || (ls >> extra))
      throw genmesh::io_error(path, "expected 'u v sharpness'", n);
    genmesh::Crease c;
    try {
      std::size_t used_u = 0, used_v = 0;
      const unsigned long u = std::stoul(u_text, &used_u), v = std::stoul(v_text, &used_v);
      if (used_u != u_text.size() || used_v != v_text.size() || u > UINT32_MAX || v > UINT32_MAX)
        throw std::invalid_argument("index");
      c.a = static_cast<std::uint32_t>(u);
      c.b = static_cast<std::uint32_t>(v);
    } catch (const std::exception&) {
      throw genmesh::io_error(path, "malformed vertex index in '" + line + "'", n);
    }
    try {
      std::size_t used = 0;
      c.sharpness = sharpness_text == "inf" ? INFINITY : std::stod(sharpness_text, &used);
      if (sharpness_text != "inf" && used != sharpness_text.size()) throw std::invalid_argument("sharpness");
    } catch (const std::exception&) {
      throw genmesh::io_error(path, "malformed sharpness '" + sharpness_text + "'", n);
    }
    creases.push_back(c);
  }
  return creases;
}

// One call of the chosen scheme.
template <class Mesh>
genmesh::Subdivision_result subdivide_once(Mesh& mesh, const Args& a, int levels,
                                           std::vector<double> sharpness) {
  const auto boundary = a.boundary == "fixed" ? genmesh::Boundary_rule::fixed : genmesh::Boundary_rule::smooth;
  if (a.scheme == "loop")
    return genmesh::loop_subdivision(
        mesh, {.iterations = levels, .boundary = boundary, .crease_sharpness = std::move(sharpness)});
  if (a.scheme == "catmull-clark")
    return genmesh::catmull_clark_subdivision(
        mesh, {.iterations = levels, .boundary = boundary, .crease_sharpness = std::move(sharpness)});
  if (a.scheme == "sqrt3")
    return genmesh::sqrt3_subdivision(mesh, {.iterations = levels, .boundary = boundary});
  if (a.scheme == "doo-sabin") return genmesh::doo_sabin_subdivision(mesh, {.iterations = levels});
  if (a.scheme == "butterfly") return genmesh::butterfly_subdivision(mesh, {.iterations = levels});
  return genmesh::midpoint_subdivision(mesh, {.iterations = levels});
}

int cmd_subdivide(const Args& a) {
  genmesh::Polygon_soup soup = genmesh::read_soup(a.files[0]);
  const std::vector<genmesh::Crease> creases =
      a.creases.empty() ? std::vector<genmesh::Crease>{} : read_creases(a.creases);
  const bool progress = !a.json && isatty(STDERR_FILENO);
  return with_backend(a.backend, [&](auto& mesh) {
    genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    std::vector<double> sharpness;
    if (!creases.empty()) {
      try {
        sharpness = genmesh::crease_sharpness(mesh, std::span<const genmesh::Crease>(creases));
      } catch (const genmesh::invalid_input& e) {
        throw genmesh::io_error(a.creases, e.what());
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    genmesh::Subdivision_result result;
    if (a.scheme == "sqrt3") {
      // √3's border rule alternates within one call: the levels go together.
      if (progress) std::fprintf(stderr, "sqrt3: %d levels...\n", a.levels);
      result = subdivide_once(mesh, a, a.levels, {});
    } else {
      for (int level = 0; level < a.levels; ++level) {
        if (progress)
          std::fprintf(stderr, "\r%s: level %d/%d", a.scheme.c_str(), level + 1, a.levels);
        result = subdivide_once(mesh, a, 1, std::move(sharpness));
        sharpness = std::move(result.edge_sharpness);
      }
      if (progress) std::fprintf(stderr, "\n");
      result.levels_done = a.levels;
    }
    const double seconds = seconds_since(t0);
    genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    genmesh::write_mesh(a.files[1], mesh, {.binary = a.binary});
    if (a.json) {
      std::cout << "{\"command\":\"subdivide\",\"file\":\"" << json_escape(a.files[0])
                << "\",\"output\":\"" << json_escape(a.files[1]) << "\",\"backend\":\"" << a.backend
                << "\",\"scheme\":\"" << a.scheme << "\",\"levels\":" << result.levels_done << ","
                << json_counts(report) << ",\"seconds\":" << seconds << "}\n";
    } else {
      std::cout << a.files[0] << " -> " << a.files[1] << ": " << a.scheme << " x" << result.levels_done
                << ", " << report.vertices << " vertices, " << report.faces << " faces, " << seconds
                << " s\n";
    }
    return report.ok() ? exit_ok : exit_invalid;
  });
}

// ---- demo ------------------------------------------------------------------

struct Demo_row {
  std::string mesh, backend, step;
  genmesh::Mesh_report report;
  genmesh::Polygon_soup result;
  double seconds = 0;
};

// Triangulates, then applies `count` seeded random flips, splits and
// collapses, picking edges by their rank in edges(g): the same edges on every
// backend, since every backend numbers elements the same way.
template <class Mesh>
void random_local_operations(Mesh& mesh, unsigned seed, int count) {
  genmesh::triangulate_faces(mesh);
  std::mt19937 rng(seed);
  std::vector<genmesh::edge_descriptor_t<Mesh>> live;
  for (int i = 0; i < count; ++i) {
    live.assign(edges(mesh).begin(), edges(mesh).end());
    const auto e = live[rng() % live.size()];
    const auto kind = rng() % 3;
    if (kind == 0) genmesh::flip_edge(halfedge(e, mesh), mesh);
    else if (kind == 1) genmesh::split_edge_and_triangulate(halfedge(e, mesh), mesh);
    else genmesh::collapse_edge(e, mesh);
  }
}

// The demo's steps: "build" (soup → mesh), "ops" (random local operations),
// "subdiv" (two levels of Loop on triangle meshes, of Catmull-Clark on the
// others). Later algorithms (simplification, remeshing) add theirs here.
const std::vector<std::string> demo_steps{"build", "ops", "subdiv"};

bool all_triangles(const genmesh::Polygon_soup& soup) {
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    if (soup.face_size(f) != 3) return false;
  return true;
}

// One step of the demo on one backend: builds the mesh, runs the step, checks.
template <class Mesh>
Demo_row run_step(const std::string& mesh_name, const std::string& backend, const std::string& step,
                  const genmesh::Polygon_soup& input) {
  Mesh mesh;
  const auto t0 = std::chrono::steady_clock::now();
  genmesh::build_mesh(input, mesh);
  if (step == "ops") random_local_operations(mesh, 2026, 300);
  if (step == "subdiv") {
    if (all_triangles(input)) genmesh::loop_subdivision(mesh, {.iterations = 2});
    else genmesh::catmull_clark_subdivision(mesh, {.iterations = 2});
  }
  Demo_row row{mesh_name, backend, step, genmesh::check_mesh(mesh), {}, 0};
  row.seconds = seconds_since(t0);
  row.result = genmesh::canonical(genmesh::to_soup(mesh));
  return row;
}

void print_demo_row(const Demo_row& r, bool same, bool json) {
  if (json) {
    std::cout << "{\"command\":\"demo\",\"mesh\":\"" << r.mesh << "\",\"step\":\"" << r.step
              << "\",\"backend\":\"" << r.backend << "\"," << json_counts(r.report)
              << ",\"same_as_reference\":" << (same ? "true" : "false") << ",\"seconds\":" << r.seconds
              << "}\n";
    return;
  }
  std::printf("%-20s %-8s %-13s %8zu %8zu %8zu %3lld %5zu %5s %-5s %-9s %10.6f\n", r.mesh.c_str(),
              r.step.c_str(), r.backend.c_str(), std::size_t(r.report.vertices),
              std::size_t(r.report.edges), std::size_t(r.report.faces),
              static_cast<long long>(r.report.euler_characteristic), std::size_t(r.report.boundary_loops),
              r.report.genus ? std::to_string(*r.report.genus).c_str() : "n/a",
              r.report.ok() ? "yes" : "NO", same ? "yes" : "DIFFERS", r.seconds);
}

int cmd_demo(const Args& a) {
  const std::vector<std::pair<std::string, genmesh::Polygon_soup>> meshes{
      {"tetrahedron", genmesh::make_tetrahedron()},
      {"cube", genmesh::make_cube()},
      {"icosphere(4)", genmesh::make_icosphere(4)},
      {"torus(48x24)", genmesh::make_torus(48, 24)},
      {"grid(32x32)", genmesh::make_grid(32, 32)},
      {"grid_with_hole(30)", genmesh::make_grid_with_hole(30)},
  };
  bool all_ok = true;
  if (!a.json) {
    std::printf("genmesh demo: every step on every backend, results compared as canonical soups\n\n");
    std::printf("%-20s %-8s %-13s %8s %8s %8s %3s %5s %5s %-5s %-9s %10s\n", "mesh", "step", "backend",
                "V", "E", "F", "chi", "loops", "genus", "valid", "same", "seconds");
  }
  for (const auto& [name, soup] : meshes) {
    for (const std::string& step : demo_steps) {
      const Demo_row rows[] = {run_step<Halfedge_mesh>(name, "halfedge", step, soup),
                               run_step<Surface_mesh>(name, "surface-mesh", step, soup),
                               run_step<Incidence_mesh>(name, "incidence", step, soup)};
      for (const Demo_row& r : rows) {
        // The reference is the first backend; every other must give the same
        // soup (and building alone must give back the input's faces).
        const bool same = r.result == rows[0].result &&
                          (step != "build" || r.result.num_faces() == soup.num_faces());
        all_ok = all_ok && same && r.report.ok();
        print_demo_row(r, same, a.json);
      }
    }
  }
  if (!a.json)
    std::printf("\n%s\n", all_ok ? "all backends agree; every mesh valid"
                                 : "MISMATCH: backends disagree or a mesh is invalid");
  return all_ok ? exit_ok : exit_invalid;
}

// genmesh measure A [B]: quality and self-intersections of A (and B); with B
// the two-way Hausdorff and RMS distances. Exit 0 whatever the numbers say.
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  std::ostringstream o;
  o.precision(17);
  o << x;
  return o.str();
}

// Self-intersecting pairs of a mesh; a polygon mesh is measured on the fan
// triangulation of its soup (built as a Halfedge_mesh).
template <class Mesh>
std::size_t count_self_intersections(const Mesh& mesh, const genmesh::Polygon_soup& soup) {
  bool triangles = true;
  for (const auto f : faces(mesh)) triangles = triangles && degree(f, mesh) == 3;
  if (triangles) return genmesh::self_intersections(mesh).size();
  genmesh::Polygon_soup fan;
  fan.points = soup.points;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    for (auto i = soup.offsets[f] + 1; i + 1 < soup.offsets[f + 1]; ++i)
      fan.add_face({soup.indices[soup.offsets[f]], soup.indices[i], soup.indices[i + 1]});
  Halfedge_mesh t;
  genmesh::build_mesh(fan, t);
  return genmesh::self_intersections(t).size();
}

int cmd_measure(const Args& a) {
  const bool progress = !a.json && isatty(STDERR_FILENO);
  std::vector<genmesh::Polygon_soup> soups;
  for (const auto& f : a.files) soups.push_back(genmesh::read_soup(f));
  return with_backend(a.backend, [&](auto& first) {
    using Mesh = std::remove_reference_t<decltype(first)>;
    std::vector<Mesh> meshes(soups.size());
    for (std::size_t i = 0; i < soups.size(); ++i) {
      try {
        genmesh::build_mesh(soups[i], meshes[i]);
      } catch (const genmesh::invalid_input& e) {
        throw genmesh::io_error(a.files[i], e.what());
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    const Mesh& ma = meshes[0];
    const double diag = genmesh::diagonal(ma);
    std::vector<genmesh::Triangle_quality> quality;
    std::vector<std::size_t> pairs;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      if (progress) std::fprintf(stderr, "\rmeasure: quality and self-intersections of %s", a.files[i].c_str());
      quality.push_back(genmesh::triangle_quality(meshes[i]));
      pairs.push_back(count_self_intersections(meshes[i], soups[i]));
    }
    if (progress) std::fprintf(stderr, "\n");
    std::optional<genmesh::Hausdorff_result> h;
    if (meshes.size() == 2) {
      genmesh::Hausdorff_options o{.samples = a.samples};
      if (progress)
        o.progress = [](std::size_t done, std::size_t all) {
          std::fprintf(stderr, "\rmeasure: Hausdorff distance, %zu / %zu samples", done, all);
        };
      h = genmesh::hausdorff_distance(meshes[0], meshes[1], o);
      if (progress) std::fprintf(stderr, "\n");
    }
    const double seconds = seconds_since(t0);
    auto rel = [&](double x) { return diag > 0 ? x / diag : std::nan(""); };
    const auto& q = quality[0];
    if (a.json) {
      std::cout << "{\"command\":\"measure\",\"file\":\"" << json_escape(a.files[0]) << "\"";
      if (h) std::cout << ",\"file_b\":\"" << json_escape(a.files[1]) << "\"";
      std::cout << ",\"backend\":\"" << a.backend << "\",\"vertices\":" << q.vertices
                << ",\"edges\":" << q.edges << ",\"faces\":" << q.faces
                << ",\"diagonal\":" << json_number(diag) << ",\"min_angle\":" << json_number(q.min_angle)
                << ",\"max_angle\":" << json_number(q.max_angle) << ",\"mean_angle\":" << json_number(q.mean_angle)
                << ",\"angles_below_30\":" << json_number(q.angles_below_30)
                << ",\"max_aspect_ratio\":" << json_number(q.max_aspect_ratio)
                << ",\"mean_aspect_ratio\":" << json_number(q.mean_aspect_ratio)
                << ",\"valence6_share\":" << json_number(q.valence6_share)
                << ",\"border_valence4_share\":" << json_number(q.border_valence4_share)
                << ",\"edge_length_mean\":" << json_number(q.edge_length_mean)
                << ",\"edge_length_deviation\":" << json_number(q.edge_length_deviation)
                << ",\"degenerate_faces\":" << q.degenerate_faces
                << ",\"self_intersecting_pairs\":" << pairs[0];
      if (h) {
        const auto& qb = quality[1];
        std::cout << ",\"vertices_b\":" << qb.vertices << ",\"faces_b\":" << qb.faces
                  << ",\"min_angle_b\":" << json_number(qb.min_angle)
                  << ",\"angles_below_30_b\":" << json_number(qb.angles_below_30)
                  << ",\"valence6_share_b\":" << json_number(qb.valence6_share)
                  << ",\"self_intersecting_pairs_b\":" << pairs[1]
                  << ",\"hausdorff\":" << json_number(rel(h->hausdorff))
                  << ",\"hausdorff_absolute\":" << json_number(h->hausdorff)
                  << ",\"hausdorff_a_to_b\":" << json_number(rel(h->a_to_b.max))
                  << ",\"hausdorff_b_to_a\":" << json_number(rel(h->b_to_a.max))
                  << ",\"rms\":" << json_number(rel(h->rms)) << ",\"rms_absolute\":" << json_number(h->rms)
                  << ",\"mean_distance\":" << json_number(rel(h->mean))
                  << ",\"samples\":" << h->a_to_b.samples + h->b_to_a.samples;
      }
      std::cout << ",\"seconds\":" << seconds << "}\n";
      return exit_ok;
    }
    auto row = [](const std::string& k, const std::string& v) {
      std::cout << "  " << k << std::string(k.size() < 28 ? 28 - k.size() : 1, ' ') << v << "\n";
    };
    auto num = [](double x) {
      std::ostringstream o;
      o.precision(6);
      o << x;
      return o.str();
    };
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      const auto& qi = quality[i];
      std::cout << a.files[i] << " (" << a.backend << ")\n";
      row("vertices / edges / faces", std::to_string(qi.vertices) + " / " + std::to_string(qi.edges) + " / " +
                                          std::to_string(qi.faces));
      row("angles min / mean / max", num(qi.min_angle) + " / " + num(qi.mean_angle) + " / " + num(qi.max_angle) + " deg");
      row("angles below 30 deg", num(100 * qi.angles_below_30) + " %");
      row("aspect ratio mean / max", num(qi.mean_aspect_ratio) + " / " + num(qi.max_aspect_ratio));
      row("interior valence 6", num(100 * qi.valence6_share) + " %");
      row("border valence 4", qi.border_vertices ? num(100 * qi.border_valence4_share) + " %" : "n/a (closed)");
      row("edge length mean (dev)", num(qi.edge_length_mean) + " (" + num(qi.edge_length_deviation) + ")");
      row("degenerate faces", std::to_string(qi.degenerate_faces));
      row("self-intersecting pairs", std::to_string(pairs[i]));
    }
    if (h) {
      std::cout << "distance (relative to the diagonal of " << a.files[0] << ", " << num(diag) << ")\n";
      row("Hausdorff", num(rel(h->hausdorff)) + "  (" + num(h->hausdorff) + ")");
      row("  A -> B / B -> A", num(rel(h->a_to_b.max)) + " / " + num(rel(h->b_to_a.max)));
      row("RMS", num(rel(h->rms)) + "  (" + num(h->rms) + ")");
      row("mean", num(rel(h->mean)) + "  (" + num(h->mean) + ")");
      row("samples", std::to_string(h->a_to_b.samples + h->b_to_a.samples));
    }
    row("seconds", num(seconds));
    return exit_ok;
  });
}

} // namespace

int main(int argc, char** argv) {
  try {
    Args a = parse(argc, argv);
    if (a.command == "demo") return cmd_demo(a);
    if (a.command == "convert") return cmd_convert(a);
    if (a.command == "subdivide") return cmd_subdivide(a);
    if (a.command == "measure") return cmd_measure(a);
    return cmd_info_or_check(a);
  } catch (const usage_error& e) {
    std::cerr << "genmesh: " << e.what() << "\n" << usage_text;
    return exit_bad_input;
  } catch (const genmesh::io_error& e) {
    std::cerr << "genmesh: " << e.what() << "\n";
    return exit_bad_input;
  } catch (const genmesh::invalid_input& e) {
    std::cerr << "genmesh: " << e.what() << "\n";
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "genmesh: error: " << e.what() << "\n";
    return exit_bad_input;
  }
}
