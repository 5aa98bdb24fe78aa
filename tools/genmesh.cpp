// genmesh — the command-line program: run genmesh on files, and its demo.
//
//   genmesh info FILE      [--backend B] [--json]   counts and topology
//   genmesh check FILE     [--backend B] [--json] [--repair]
//                                                   full validity report
//   genmesh convert IN OUT [--backend B] [--json] [--binary] [--repair]
//   genmesh subdivide IN OUT --scheme S --levels N [--boundary smooth|fixed]
//                          [--creases FILE] [--backend B] [--json]
//   genmesh simplify IN OUT (--faces N | --ratio R | --error E)
//                          [--policy quadric|probabilistic|length]
//                          [--boundary preserve|lock|free] [--backend B] [--json]
//   genmesh demo           [--json]                 every backend on built-in meshes
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
#include <genmesh/simplification.h>
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
    "  simplify IN OUT    simplify IN by edge collapses, write OUT\n"
    "  demo               run genmesh on built-in meshes on every backend\n"
    "options:\n"
    "  --backend halfedge|surface-mesh|incidence   mesh type to build (default halfedge)\n"
    "  --json             one-line machine-readable record\n"
    "  --repair           repair a non-manifold or inconsistently oriented soup\n"
    "  --binary           binary output (PLY, STL) for convert and subdivide\n"
    "  --scheme S         loop|catmull-clark|sqrt3|doo-sabin|butterfly|midpoint\n"
    "  --levels N         subdivision levels (default 1)\n"
    "  --boundary B       smooth|fixed border rule (loop, catmull-clark, sqrt3)\n"
    "  --creases FILE     lines 'u v sharpness' (input vertex indices; inf = sharp)\n"
    "  --faces N | --ratio R | --error E   simplify: face target, face ratio, or max error\n"
    "                     (a distance, relative to the bounding-box diagonal)\n"
    "  --policy P         simplify: quadric|probabilistic|length (default quadric)\n"
    "                     --boundary for simplify: preserve|lock|free (default preserve)\n"
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
  // simplify
  std::optional<std::size_t> faces;
  std::optional<double> ratio, error;
  std::string policy = "quadric";
  bool boundary_given = false;
};

// A number option's value, or a usage error naming the option.
double number_option(const std::string& option, const std::string& v, double lo, double hi) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != v.size() || !(x >= lo && x <= hi))
    throw usage_error(option + " takes a number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                      ", got '" + v + "'");
  return x;
}

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
    } else if (s == "--faces" || s == "--ratio" || s == "--error" || s == "--policy" || s == "--features") {
      if (i + 1 >= argc) throw usage_error(s + " needs a value");
      const std::string v = argv[++i];
      if (s == "--faces") a.faces = static_cast<std::size_t>(number_option(s, v, 0, 4e9));
      else if (s == "--ratio") a.ratio = number_option(s, v, 0, 1);
      else if (s == "--error") a.error = number_option(s, v, 0, 1e300);
      else if (s == "--policy") a.policy = v;
      else throw usage_error("--features is not implemented yet (simplify keeps no feature lines)");
    } else if (s == "--scheme" || s == "--levels" || s == "--boundary" || s == "--creases") {
      if (i + 1 >= argc) throw usage_error(s + " needs a value");
      const std::string v = argv[++i];
      if (s == "--scheme") a.scheme = v;
      else if (s == "--boundary") {
        a.boundary = v;
        a.boundary_given = true;
      }
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
    } else if (s.size() > 1 && s[0] == '-') {
      throw usage_error("unknown option '" + s + "'");
    } else {
      a.files.push_back(s);
    }
  }
  const std::map<std::string, std::size_t> files_needed{
      {"info", 1}, {"check", 1}, {"convert", 2}, {"subdivide", 2}, {"simplify", 2}, {"demo", 0}};
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
  if (a.command == "simplify") {
    if (!a.faces && !a.ratio && !a.error) throw usage_error("simplify needs --faces, --ratio or --error");
    if (a.policy == "lindstrom-turk")
      throw usage_error("--policy lindstrom-turk is not implemented yet (quadric|probabilistic|length)");
    if (a.policy != "quadric" && a.policy != "probabilistic" && a.policy != "length")
      throw usage_error("unknown policy '" + a.policy + "' (quadric|probabilistic|length)");
    if (!a.boundary_given) a.boundary = "preserve";
    if (a.boundary != "preserve" && a.boundary != "lock" && a.boundary != "free")
      throw usage_error("unknown boundary mode '" + a.boundary + "' (preserve|lock|free)");
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

// ---- simplify ----------------------------------------------------------------

template <class Policy, class Mesh>
genmesh::Simplification_result simplify_with(Mesh& mesh, const Args& a, bool progress) {
  genmesh::Simplification_options<Policy> o;
  o.target_faces = a.faces;
  o.target_ratio = a.ratio;
  if (a.error) {
    o.max_error = *a.error;
    o.max_error_relative = true;
  }
  o.border = a.boundary == "lock"   ? genmesh::Border_mode::lock
             : a.boundary == "free" ? genmesh::Border_mode::free
                                    : genmesh::Border_mode::preserve;
  if (progress)
    o.visitor.on_progress = [](std::size_t faces, std::size_t target) {
      std::fprintf(stderr, "\rsimplify: %zu faces (target %zu)   ", faces, target);
    };
  const auto r = genmesh::simplify(mesh, o);
  if (progress) std::fprintf(stderr, "\n");
  return r;
}

int cmd_simplify(const Args& a) {
  genmesh::Polygon_soup soup = genmesh::read_soup(a.files[0]);
  const bool progress = !a.json && isatty(STDERR_FILENO);
  return with_backend(a.backend, [&](auto& mesh) {
    genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    const auto t0 = std::chrono::steady_clock::now();
    genmesh::Simplification_result r;
    if (a.policy == "probabilistic") r = simplify_with<genmesh::Probabilistic_quadrics>(mesh, a, progress);
    else if (a.policy == "length") r = simplify_with<genmesh::Edge_length>(mesh, a, progress);
    else r = simplify_with<genmesh::Plane_quadrics>(mesh, a, progress);
    const double seconds = seconds_since(t0);
    genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    genmesh::write_mesh(a.files[1], mesh, {.binary = a.binary});
    if (a.json) {
      std::cout << "{\"command\":\"simplify\",\"file\":\"" << json_escape(a.files[0]) << "\",\"output\":\""
                << json_escape(a.files[1]) << "\",\"backend\":\"" << a.backend << "\",\"policy\":\"" << a.policy
                << "\",\"collapses\":" << r.collapses << ",\"max_error\":" << r.max_error
                << ",\"stop_reason\":\"" << genmesh::to_string(r.stop_reason) << "\"," << json_counts(report)
                << ",\"seconds\":" << seconds << "}\n";
    } else {
      std::cout << a.files[0] << " -> " << a.files[1] << ": " << soup.num_faces() << " -> " << report.faces
                << " faces, " << r.collapses << " collapses, max error " << r.max_error << ", stopped: "
                << genmesh::to_string(r.stop_reason) << ", " << seconds << " s\n";
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
// others), "simplify" (quadric edge collapse to a quarter of the faces,
// polygons triangulated first). Later algorithms (remeshing) add theirs here.
const std::vector<std::string> demo_steps{"build", "ops", "subdiv", "simplify"};

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
  if (step == "simplify") genmesh::simplify(mesh, {.target_ratio = 0.25, .triangulate = true});
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

} // namespace

int main(int argc, char** argv) {
  try {
    Args a = parse(argc, argv);
    if (a.command == "demo") return cmd_demo(a);
    if (a.command == "convert") return cmd_convert(a);
    if (a.command == "subdivide") return cmd_subdivide(a);
    if (a.command == "simplify") return cmd_simplify(a);
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
