// genmesh — the command-line program: run genmesh on files, and its demo.
//
//   genmesh info FILE      [--backend B] [--json]   counts and topology
//   genmesh check FILE     [--backend B] [--json] [--repair]
//                                                   full validity report
//   genmesh convert IN OUT [--backend B] [--json] [--binary] [--repair]
//   genmesh demo           [--json]                 every backend on built-in meshes
//
// Exit codes: 0 ok; 1 the mesh is invalid (reported on stdout); 2 bad input or
// usage (message on stderr). `--json` prints one line per record; `seconds` is
// the algorithm alone (building the mesh and checking it), file IO excluded.
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/io.h>
#include <genmesh/local_operations.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;

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
    "  demo               run genmesh on built-in meshes on every backend\n"
    "options:\n"
    "  --backend halfedge|surface-mesh   mesh type to build (default halfedge)\n"
    "  --json             one-line machine-readable record\n"
    "  --repair           repair a non-manifold or inconsistently oriented soup\n"
    "  --binary           binary output (PLY, STL) for convert\n"
    "formats: OFF, OBJ, PLY (ASCII, binary), STL (ASCII, binary)\n";

struct Args {
  std::string command;
  std::vector<std::string> files;
  std::string backend = "halfedge";
  bool json = false;
  bool repair = false;
  bool binary = false;
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
      if (a.backend != "halfedge" && a.backend != "surface-mesh")
        throw usage_error("unknown backend '" + a.backend + "' (halfedge|surface-mesh)");
    } else if (s.size() > 1 && s[0] == '-') {
      throw usage_error("unknown option '" + s + "'");
    } else {
      a.files.push_back(s);
    }
  }
  const std::map<std::string, std::size_t> files_needed{
      {"info", 1}, {"check", 1}, {"convert", 2}, {"demo", 0}};
  auto it = files_needed.find(a.command);
  if (it == files_needed.end()) throw usage_error("unknown command '" + a.command + "'");
  if (a.files.size() != it->second)
    throw usage_error("'" + a.command + "' takes " + std::to_string(it->second) + " file argument" +
                      (it->second == 1 ? "" : "s") + ", got " + std::to_string(a.files.size()));
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
                << genmesh::to_string(soup_report) << "(run with --repair to fix what can be fixed)\n";
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

// The demo's steps: "build" (soup → mesh), "ops" (random local operations).
// Later algorithms (subdivision, simplification, remeshing) add theirs here.
const std::vector<std::string> demo_steps{"build", "ops"};

// One step of the demo on one backend: builds the mesh, runs the step, checks.
template <class Mesh>
Demo_row run_step(const std::string& mesh_name, const std::string& backend, const std::string& step,
                  const genmesh::Polygon_soup& input) {
  Mesh mesh;
  const auto t0 = std::chrono::steady_clock::now();
  genmesh::build_mesh(input, mesh);
  if (step == "ops") random_local_operations(mesh, 2026, 300);
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
                               run_step<Surface_mesh>(name, "surface-mesh", step, soup)};
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

} // namespace

int main(int argc, char** argv) {
  try {
    Args a = parse(argc, argv);
    if (a.command == "demo") return cmd_demo(a);
    if (a.command == "convert") return cmd_convert(a);
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
