// genmesh — the command-line program: run genmesh on files, and its demo.
//
//   genmesh info FILE      [--backend B] [--json]   counts and topology
//   genmesh check FILE     [--backend B] [--json] [--repair]
//                                                   full validity report
//   genmesh convert IN OUT [--backend B] [--json] [--binary] [--repair]
//   genmesh subdivide IN OUT --scheme S --levels N [--boundary smooth|fixed]
//                          [--creases FILE] [--backend B] [--json]
//   genmesh simplify IN OUT (--faces N | --ratio R | --error E) [--features DEG]
//                          [--policy quadric|probabilistic|lindstrom-turk|length]
//                          [--boundary preserve|lock|free] [--attributes W|NAME=W,...]
//                          [--attribute-metric gh98|hoppe]
//                          [--backend B] [--json]
//   genmesh remesh IN OUT  [--edge-length L | --relative R] [--iterations N]
//                          [--features DEG] [--adaptive MIN MAX ERR]
//                          [--flips valence|delaunay] [--backend B] [--json]
//   genmesh demo           [--json]                 every backend on built-in meshes
//   genmesh measure A [B]  [--backend B] [--json] [--samples N]
//                          quality and self-intersections of A (and B), with B
//                          the two-way Hausdorff / RMS distance
//   (--backend halfedge|surface-mesh|incidence; check --backend incidence also
//   names the fins, misoriented edges and bow-ties of a non-manifold input)
//
// Exit codes (docs/cli.md): 0 ok; 1 the input mesh is invalid (info/check
// report it on stdout, convert/subdivide name the file on stderr); 2 bad
// input or usage (message on stderr, naming the file and line or byte);
// 3 refused because it would not fit (subdivide's size prediction, out of
// memory); 128+N killed by signal N (INT, TERM, HUP remove the output's
// temporary first). `--json` prints one line per record; `seconds` is
// the algorithm alone (building the mesh and checking it), file IO excluded.
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/local_operations.h>
#include <genmesh/simplification.h>
#include <genmesh/measures.h>
#include <genmesh/remeshing.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>
#include <genmesh/validity.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <exception>
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
#include <string_view>
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
constexpr int exit_too_large = 3;

// What the program is doing, for an error that would otherwise name no file
// (out of memory, a library exception): "reading X", "subdividing X", ...
// An exception leaving a stage keeps it as failed_stage (the innermost one):
// unwinding restores current_stage before main's handler could read it.
std::string current_stage;
std::string failed_stage;
struct Stage {
  std::string saved;
  int exceptions = std::uncaught_exceptions();
  explicit Stage(std::string s) : saved(std::exchange(current_stage, std::move(s))) {}
  ~Stage() {
    if (std::uncaught_exceptions() > exceptions && failed_stage.empty()) failed_stage = current_stage;
    current_stage = std::move(saved);
  }
};

// The refusal of work that would not fit (exit 3).
struct too_large_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Messages are printed at most this long: a hostile input must not give a
// megabyte of error text.
std::string bounded(std::string s, std::size_t max = 2000) {
  if (s.size() > max) {
    const std::size_t more = s.size() - max;
    s.resize(max);
    s += "... (" + std::to_string(more) + " more characters)";
  }
  return s;
}

struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* usage_text =
    "usage: genmesh <command> [options]\n"
    "  info FILE          counts and topology of a mesh\n"
    "  check FILE         validity report (soup problems, halfedge invariants)\n"
    "  convert IN OUT     read IN, build a valid mesh, write OUT (format from extension)\n"
    "                     with the per-vertex attributes OUT's format can hold\n"
    "  subdivide IN OUT   subdivide IN, write OUT\n"
    "  simplify IN OUT    simplify IN by edge collapses, write OUT\n"
    "  remesh IN OUT      isotropic remeshing of IN, write OUT\n"
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
    "  --max-file-size S  largest input file read (default 8G; suffixes K M G T)\n"
    "  --max-memory S     subdivide: largest predicted memory (default: half of RAM)\n"
    "  --faces N | --ratio R | --error E   simplify: face target, face ratio, or max error\n"
    "                     (a distance, relative to the bounding-box diagonal)\n"
    "  --policy P         simplify: quadric|probabilistic|lindstrom-turk|length (default quadric)\n"
    "                     --boundary for simplify: preserve|lock|free (default preserve)\n"
    "  --attributes W | NAME=W[,NAME=W...]   simplify (quadric policy): the input's per-vertex\n"
    "                     attributes (PLY vertex properties, COFF/NOFF/STOFF extras, OBJ\n"
    "                     vt/vn/colours) in the\n"
    "                     quadrics, every one at weight W or each named one at its W; the\n"
    "                     output gets the survivors' optimal values\n"
    "  --attribute-metric M   simplify --attributes: gh98 (Garland-Heckbert 1998, default)\n"
    "                     or hoppe (Hoppe 1999: plane distance plus interpolation error)\n"
    "  --features DEG     simplify: edges whose faces meet at DEG degrees or more are feature\n"
    "                     lines: collapses run along them, never across; corners stay\n"
    "                     remesh: edges sharper than DEG degrees are kept as feature lines\n"
    "  --samples N        measure: face samples per direction (default max(10 x faces, 100000));\n"
    "                     remesh, simplify: for the Hausdorff figure (default 100000)\n"
    "  --edge-length L | --relative R   remesh: target edge length, absolute or times the\n"
    "                     input's mean edge length (default --relative 1)\n"
    "  --iterations N     remesh: rounds (default 5)\n"
    "  --adaptive MIN MAX ERR   remesh: curvature-adapted lengths in [MIN, MAX], chord error ERR\n"
    "  --flips F          remesh: valence|delaunay (default valence)\n"
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
  std::uint64_t max_file_size = genmesh::detail::io::default_max_file_size;
  std::optional<std::uint64_t> max_memory;
  // simplify
  std::optional<std::size_t> faces;
  std::optional<double> ratio, error;
  std::string policy = "quadric";
  std::optional<double> features;  // simplify --features DEG
  // simplify --attributes: (name, weight); the name "" stands for every attribute
  std::vector<std::pair<std::string, double>> attribute_weights;
  std::string attribute_metric = "gh98"; // simplify --attribute-metric: gh98 (Attribute_quadrics) | hoppe (Hoppe_quadrics)
  bool boundary_given = false;
  std::size_t samples = 0;  // measure --samples
  // remesh (and --features)
  std::optional<double> edge_length, relative;
  std::optional<int> iterations;
  std::optional<std::array<double, 3>> adaptive;
  std::string flips = "valence";
};

// "123", "64K", "1.5G" (powers of 1024) -> bytes; nullopt if malformed.
std::optional<std::uint64_t> parse_size(const std::string& v) {
  if (v.empty() || v.size() > 32) return std::nullopt;
  double x = 0;
  auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (ec != std::errc() || !(x >= 0) || ptr == v.data()) return std::nullopt;
  std::string_view unit(ptr, static_cast<std::size_t>(v.data() + v.size() - ptr));
  double scale = 1;
  if (unit == "K" || unit == "k") scale = 1024.0;
  else if (unit == "M") scale = 1024.0 * 1024;
  else if (unit == "G") scale = 1024.0 * 1024 * 1024;
  else if (unit == "T") scale = 1024.0 * 1024 * 1024 * 1024;
  else if (!unit.empty()) return std::nullopt;
  const double bytes = x * scale;
  if (!(bytes < 1.8e19)) return std::nullopt;
  return static_cast<std::uint64_t>(bytes);
}

// A number option's value, or a usage error naming the option.
double number_option(const std::string& option, const std::string& v, double lo, double hi) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (v.empty() || used != v.size() || !(x >= lo && x <= hi))
    throw usage_error(option + " takes a number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                      ", got '" + v + "'");
  return x;
}

// simplify --attributes: "W" (every attribute at weight W) or
// "NAME=W[,NAME=W...]"; a weight of 0 carries an attribute without using it.
void parse_attribute_weights(const std::string& spec, std::vector<std::pair<std::string, double>>& out) {
  if (spec.find('=') == std::string::npos) {
    out.emplace_back("", number_option("--attributes", spec, 0, 1e300));
    return;
  }
  std::size_t b = 0;
  for (;;) {
    const std::size_t e = std::min(spec.find(',', b), spec.size());
    const std::string item = spec.substr(b, e - b);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw usage_error("--attributes takes W or NAME=W[,NAME=W...], got '" + bounded(spec, 80) + "'");
    out.emplace_back(item.substr(0, eq), number_option("--attributes " + item.substr(0, eq), item.substr(eq + 1), 0, 1e300));
    if (e == spec.size()) break;
    b = e + 1;
  }
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
        throw usage_error("unknown backend '" + bounded(a.backend, 40) + "' (halfedge|surface-mesh|incidence)");
    } else if (s == "--faces" || s == "--ratio" || s == "--error" || s == "--policy" || s == "--features") {
      if (i + 1 >= argc) throw usage_error(s + " needs a value");
      const std::string v = argv[++i];
      if (s == "--faces") a.faces = static_cast<std::size_t>(number_option(s, v, 0, 4e9));
      else if (s == "--ratio") a.ratio = number_option(s, v, 0, 1);
      else if (s == "--error") a.error = number_option(s, v, 0, 1e300);
      else if (s == "--policy") a.policy = v;
      else a.features = number_option(s, v, 0, 180);
    } else if (s == "--attributes") {
      if (i + 1 >= argc) throw usage_error("--attributes needs a value: W or NAME=W[,NAME=W...]");
      parse_attribute_weights(argv[++i], a.attribute_weights);
    } else if (s == "--attribute-metric") {
      if (i + 1 >= argc) throw usage_error("--attribute-metric needs a value: gh98|hoppe");
      a.attribute_metric = argv[++i];
    } else if (s == "--scheme" || s == "--levels" || s == "--boundary" || s == "--creases" ||
               s == "--max-file-size" || s == "--max-memory") {
      if (i + 1 >= argc) throw usage_error(s + " needs a value");
      const std::string v = argv[++i];
      if (s == "--scheme") a.scheme = v;
      else if (s == "--boundary") {
        a.boundary = v;
        a.boundary_given = true;
      }
      else if (s == "--creases") {
        if (v.empty()) throw usage_error("--creases needs a file name, got ''");
        a.creases = v;
      } else if (s == "--max-file-size" || s == "--max-memory") {
        const auto bytes = parse_size(v);
        if (!bytes) throw usage_error(s + " takes a size such as 500M or 8G, got '" + bounded(v, 40) + "'");
        if (s == "--max-file-size") a.max_file_size = *bytes;
        else a.max_memory = *bytes;
      } else {
        int levels = -1;
        auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), levels);
        if (v.empty() || ec != std::errc() || ptr != v.data() + v.size() || levels < 0 || levels > 12)
          throw usage_error("--levels takes a whole number from 0 to 12, got '" + bounded(v, 40) + "'");
        a.levels = levels;
      }
    } else if (s == "--edge-length" || s == "--relative" || s == "--iterations" || s == "--flips") {
      if (i + 1 >= argc) throw usage_error(s + " needs a value");
      const std::string v = argv[++i];
      if (s == "--edge-length") a.edge_length = number_option(s, v, 1e-300, 1e300);
      else if (s == "--relative") a.relative = number_option(s, v, 1e-300, 1e300);
      else if (s == "--flips") a.flips = v;
      else {
        int n = -1;
        auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
        if (v.empty() || ec != std::errc() || ptr != v.data() + v.size() || n < 0 || n > 1000)
          throw usage_error("--iterations takes a whole number from 0 to 1000, got '" + bounded(v, 40) + "'");
        a.iterations = n;
      }
    } else if (s == "--adaptive") {
      if (i + 3 >= argc) throw usage_error("--adaptive needs three values: MIN MAX ERR");
      std::array<double, 3> x{};
      for (int k = 0; k < 3; ++k) x[static_cast<std::size_t>(k)] = number_option(s, argv[++i], 1e-300, 1e300);
      if (x[0] > x[1]) throw usage_error("--adaptive MIN MAX ERR needs MIN <= MAX");
      a.adaptive = x;
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
      throw usage_error("unknown option '" + bounded(s, 40) + "'");
    } else {
      a.files.push_back(s);
    }
  }
  const std::map<std::string, std::size_t> files_needed{
      {"info", 1}, {"check", 1}, {"convert", 2}, {"subdivide", 2}, {"simplify", 2}, {"remesh", 2}, {"demo", 0}};
  if (a.command == "measure") {
    if (a.files.size() != 1 && a.files.size() != 2)
      throw usage_error("'measure' takes 1 or 2 file arguments, got " + std::to_string(a.files.size()));
    return a;
  }
  auto it = files_needed.find(a.command);
  if (it == files_needed.end()) throw usage_error("unknown command '" + bounded(a.command, 40) + "'");
  if (a.files.size() != it->second)
    throw usage_error("'" + a.command + "' takes " + std::to_string(it->second) + " file argument" +
                      (it->second == 1 ? "" : "s") + ", got " + std::to_string(a.files.size()));
  if (a.command == "subdivide") {
    static const std::vector<std::string> schemes{"loop", "catmull-clark", "sqrt3",
                                                  "doo-sabin", "butterfly", "midpoint"};
    if (a.scheme.empty()) throw usage_error("subdivide needs --scheme");
    if (std::find(schemes.begin(), schemes.end(), a.scheme) == schemes.end())
      throw usage_error("unknown scheme '" + bounded(a.scheme, 40) +
                        "' (loop|catmull-clark|sqrt3|doo-sabin|butterfly|midpoint)");
    if (a.boundary != "smooth" && a.boundary != "fixed")
      throw usage_error("unknown boundary rule '" + bounded(a.boundary, 40) + "' (smooth|fixed)");
    if (!a.creases.empty() && a.scheme != "loop" && a.scheme != "catmull-clark")
      throw usage_error("--creases applies to loop and catmull-clark only");
  }
  if (a.command == "simplify") {
    if (!a.faces && !a.ratio && !a.error) throw usage_error("simplify needs --faces, --ratio or --error");
    if (a.policy != "quadric" && a.policy != "probabilistic" && a.policy != "length" && a.policy != "lindstrom-turk")
      throw usage_error("unknown policy '" + a.policy + "' (quadric|probabilistic|lindstrom-turk|length)");
    if (!a.attribute_weights.empty() && a.policy != "quadric")
      throw usage_error("--attributes works with --policy quadric only");
    if (a.attribute_metric != "gh98" && a.attribute_metric != "hoppe")
      throw usage_error("unknown attribute metric '" + bounded(a.attribute_metric, 40) + "' (gh98|hoppe)");
    if (!a.boundary_given) a.boundary = "preserve";
    if (a.boundary != "preserve" && a.boundary != "lock" && a.boundary != "free")
      throw usage_error("unknown boundary mode '" + a.boundary + "' (preserve|lock|free)");
  }
  if (a.command == "remesh") {
    if (a.edge_length && a.relative) throw usage_error("remesh takes --edge-length or --relative, not both");
    if (a.flips != "valence" && a.flips != "delaunay")
      throw usage_error("unknown flip rule '" + bounded(a.flips, 40) + "' (valence|delaunay)");
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

// A JSON number (17 digits), or null when x is not finite.
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  std::ostringstream o;
  o.precision(17);
  o << x;
  return o.str();
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

// Reads a command's input (the file named in every error, the size bounded).
genmesh::Polygon_soup read_input(const Args& a, const std::string& file) {
  Stage stage("reading " + file);
  return genmesh::read_soup(file, {.max_file_size = a.max_file_size});
}

// With --repair, a soup with per-vertex attributes is repaired here rather
// than in build_mesh, so that a split vertex's copies get its attributes.
void repair_keeping_attributes(const Args& a, genmesh::Polygon_soup& soup) {
  if (a.repair && !soup.vertex_attributes.empty()) genmesh::repair_soup(soup); // nothing when the soup is fine
}

// A note on stderr naming the attributes the output's format has no place for.
void note_unstored_attributes(const std::string& out, std::span<const genmesh::Soup_attribute> channels) {
  const genmesh::File_format format = genmesh::output_format(out);
  std::string lost;
  for (const auto& c : channels)
    if (!genmesh::format_stores(format, c)) lost += (lost.empty() ? "" : ", ") + c.name;
  if (!lost.empty())
    std::cerr << "genmesh: note: " << out << " has no place for the per-vertex attribute(s) " << bounded(lost, 200)
              << "; written without them\n";
}

// build_mesh() refused the soup (not a 2-manifold, or --repair could not make
// one): exit 1, naming the file, as info and check do for the same input.
int report_unbuildable(const std::string& file, const genmesh::invalid_input& e) {
  std::cerr << "genmesh: " << file << ": not a valid oriented 2-manifold polygon mesh: " << bounded(e.what())
            << "\n(run 'genmesh check " << file << "' for the full report, or add --repair)\n";
  return exit_invalid;
}

// Prints why the soup cannot become a halfedge mesh (exit_invalid).
int report_refused_soup(const Args& a, const genmesh::Polygon_soup& soup, const genmesh::Soup_report& soup_report,
                        double seconds) {
  const std::string& file = a.files[0];
  if (a.json) {
    std::cout << "{\"command\":\"" << a.command << "\",\"file\":\"" << json_escape(file)
              << "\",\"backend\":\"" << a.backend << "\",\"valid\":false,\"manifold\":false"
              << ",\"problems\":\"" << json_escape(genmesh::to_string(soup_report))
              << "\",\"seconds\":" << seconds << "}\n";
  } else {
    std::cout << file << ": not a valid oriented 2-manifold polygon mesh\n" << genmesh::to_string(soup_report);
    if (a.backend == "incidence") {
      // The incidence mesh holds what a halfedge mesh cannot: load the soup
      // as it is and name the fins, misoriented edges and bow-ties.
      Incidence_mesh m;
      try {
        m.load_soup(soup);
        std::cout << "incidence mesh (" << m.n_vertices() << " vertices, " << m.n_edges() << " edges, "
                  << m.n_faces() << " faces): " << genmesh::to_string(m.manifold_report());
      } catch (const genmesh::invalid_input& e) {
        // A face that visits a point twice: no incidence matrix holds it.
        std::cout << "incidence mesh: not loaded: " << bounded(e.what()) << "\n";
      }
    }
    std::cout << "(run with --repair to fix what can be fixed)\n";
  }
  return exit_invalid;
}

int cmd_info_or_check(const Args& a) {
  const std::string& file = a.files[0];
  genmesh::Polygon_soup soup = read_input(a, file);
  Stage stage("checking " + file);

  // The soup is checked first (inside build_mesh, on the edge table the
  // build uses): a halfedge mesh cannot hold what a bad soup says.
  const auto t0 = std::chrono::steady_clock::now();
  return with_backend(a.backend, [&](auto& mesh) {
    genmesh::Build_report build;
    try {
      build = genmesh::build_mesh(soup, mesh, {.repair = a.repair, .throw_on_refusal = false});
    } catch (const genmesh::invalid_input& e) {
      // Repair was asked for and could not make a valid mesh: the input is invalid.
      std::cout << file << ": " << bounded(e.what()) << "\n";
      return exit_invalid;
    }
    if (!build.built) return report_refused_soup(a, soup, build.soup, seconds_since(t0));
    soup = genmesh::Polygon_soup{}; // the mesh holds it all now
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
  genmesh::Polygon_soup soup = read_input(a, a.files[0]);
  repair_keeping_attributes(a, soup);
  const auto t0 = std::chrono::steady_clock::now();
  return with_backend(a.backend, [&](auto& mesh) {
    Stage stage("building the mesh of " + a.files[0]);
    genmesh::Build_report build;
    try {
      build = genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    } catch (const genmesh::invalid_input& e) {
      return report_unbuildable(a.files[0], e);
    }
    // The mesh holds it all now but the attributes (vertex i of the mesh is point i).
    const std::vector<genmesh::Soup_attribute> attributes = std::move(soup.vertex_attributes);
    soup = genmesh::Polygon_soup{};
    genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    const double seconds = seconds_since(t0);
    if (!report.ok()) {
      std::cout << a.files[0] << ": " << genmesh::to_string(report);
      return exit_invalid;
    }
    Stage writing("writing " + a.files[1]);
    genmesh::write_mesh(a.files[1], mesh, attributes, {.binary = a.binary});
    note_unstored_attributes(a.files[1], attributes);
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
// indices, sharpness a number >= 0 or "inf"; '#' starts a comment; LF, CRLF
// or CR line ends. Every error names the file and the line: malformed
// numbers, NaN or negative sharpness, u = v, a pair given twice, and (against
// the input soup) a pair that is not an edge. The file is read as mesh files
// are: a regular file or pipe of bounded size (a directory or /dev/zero is
// refused).
std::vector<genmesh::Crease> read_creases(const std::string& path, const genmesh::Polygon_soup& soup,
                                          std::uint64_t max_size) {
  namespace io = genmesh::detail::io;
  const io::File_content file = io::read_whole_file(path, max_size);
  io::Text_cursor in(file);
  std::vector<genmesh::Crease> creases;
  std::vector<std::uint64_t> lines;
  while (in.next_content_line()) {
    const std::int64_t u = in.read_int("first vertex index");
    const std::int64_t v = in.read_int("second vertex index");
    const double sharpness = in.read_double("sharpness");
    if (!in.at_eol_or_comment()) in.fail("expected 'u v sharpness', found more: " + io::quote(in.token()));
    for (std::int64_t x : {u, v})
      if (x < 0 || x >= static_cast<std::int64_t>(soup.num_points()))
        in.fail("vertex index " + std::to_string(x) + " out of range (" + std::to_string(soup.num_points()) +
                " vertices in the input)");
    if (u == v) in.fail("the two vertex indices are equal (" + std::to_string(u) + ")");
    if (std::isnan(sharpness) || sharpness < 0)
      in.fail("the sharpness must be a number >= 0 or inf, not " + std::string(std::isnan(sharpness) ? "NaN" : "negative"));
    creases.push_back({static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v), sharpness});
    lines.push_back(in.line());
    in.next_line();
  }
  // A pair given twice (either order) is an error, not "the last one wins".
  const auto key = [](const genmesh::Crease& c) {
    return (std::uint64_t(std::min(c.a, c.b)) << 32) | std::max(c.a, c.b);
  };
  std::vector<std::uint32_t> order(creases.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    return std::pair(key(creases[x]), x) < std::pair(key(creases[y]), y);
  });
  for (std::size_t i = 1; i < order.size(); ++i)
    if (key(creases[order[i]]) == key(creases[order[i - 1]]))
      throw genmesh::io_error(path,
                              "the edge (" + std::to_string(creases[order[i]].a) + ", " +
                                  std::to_string(creases[order[i]].b) + ") is given twice (first on line " +
                                  std::to_string(lines[order[i - 1]]) + ")",
                              lines[order[i]]);
  // Every pair must be an edge of the input.
  std::vector<std::uint64_t> edges;
  if (!creases.empty()) {
    edges.reserve(soup.indices.size());
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      const auto c = soup.face(f);
      for (std::size_t k = 0; k < c.size(); ++k)
        edges.push_back(key({c[k], c[(k + 1) % c.size()], 0}));
    }
    std::sort(edges.begin(), edges.end());
  }
  for (std::size_t i = 0; i < creases.size(); ++i)
    if (!std::binary_search(edges.begin(), edges.end(), key(creases[i])))
      throw genmesh::io_error(path,
                              "(" + std::to_string(creases[i].a) + ", " + std::to_string(creases[i].b) +
                                  ") is not an edge of the input mesh",
                              lines[i]);
  return creases;
}

// Progress on a terminal, from the visitor's on_step hook.
struct Subdivide_progress : genmesh::Mutation_visitor {
  const char* scheme = "";
  bool show = false;
  void on_step(std::string_view, std::size_t done, std::size_t total) {
    if (!show) return;
    std::fprintf(stderr, "\r%s: %zu/%zu levels", scheme, done, total);
    if (done == total) std::fprintf(stderr, "\n");
  }
};

// One call of the chosen scheme for every level (the library reserves the
// last level's size once and carries the creases from level to level in the
// crease map); creases is genmesh::Default_map or a crease map of mesh. The
// options name Creases: clang before 17 deduces no aggregate's arguments.
template <class Mesh, class Creases>
genmesh::Subdivision_result subdivide_all(Mesh& mesh, const Args& a, const Creases& creases,
                                          Subdivide_progress& progress) {
  const auto boundary = a.boundary == "fixed" ? genmesh::Boundary_rule::fixed : genmesh::Boundary_rule::smooth;
  const int levels = a.levels;
  if (a.scheme == "loop")
    return genmesh::loop_subdivision(
        mesh, genmesh::Loop_options<Creases>{.iterations = levels, .boundary = boundary, .crease_map = creases}, progress);
  if (a.scheme == "catmull-clark")
    return genmesh::catmull_clark_subdivision(
        mesh, genmesh::Catmull_clark_options<Creases>{.iterations = levels, .boundary = boundary, .crease_map = creases},
        progress);
  if (a.scheme == "sqrt3")
    return genmesh::sqrt3_subdivision(mesh, {.iterations = levels, .boundary = boundary}, progress);
  if (a.scheme == "doo-sabin") return genmesh::doo_sabin_subdivision(mesh, {.iterations = levels}, progress);
  if (a.scheme == "butterfly") return genmesh::butterfly_subdivision(mesh, {.iterations = levels}, progress);
  return genmesh::midpoint_subdivision(mesh, {.iterations = levels}, progress);
}

// ---- subdivide: will it fit? --------------------------------------------------

// Counts of a mesh at one level: vertices, edges, faces, Σ face degrees
// (halfedges inside faces), triangles, border edges.
struct Level_counts {
  double v = 0, e = 0, f = 0, h = 0, f3 = 0, b = 0;
};

// The input's counts, from the soup: O(corners · log).
Level_counts soup_counts(const genmesh::Polygon_soup& soup) {
  Level_counts c;
  c.v = static_cast<double>(soup.num_points());
  c.f = static_cast<double>(soup.num_faces());
  c.h = static_cast<double>(soup.indices.size());
  std::vector<std::uint64_t> keys;
  keys.reserve(soup.indices.size());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto k = soup.face(f);
    if (k.size() == 3) c.f3 += 1;
    for (std::size_t i = 0; i < k.size(); ++i) {
      const std::uint32_t x = k[i], y = k[(i + 1) % k.size()];
      keys.push_back((std::uint64_t(std::min(x, y)) << 32) | std::max(x, y));
    }
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    c.e += 1;
    if (j - i == 1) c.b += 1;
    i = j;
  }
  return c;
}

// One level of `scheme` (docs/subdivision.md's table): exact on closed
// meshes for every scheme and on borders for Loop, butterfly, Catmull-Clark
// and midpoint; √3 counts its border refinement every second level, and
// Doo-Sabin's closed counts bound its border case from above.
Level_counts next_level(const Level_counts& c, const std::string& scheme, int level) {
  Level_counts n;
  if (scheme == "loop" || scheme == "butterfly") {
    n = {c.v + c.e, 2 * c.e + 3 * c.f, 4 * c.f, 12 * c.f, 4 * c.f, 2 * c.b};
  } else if (scheme == "catmull-clark") {
    n = {c.v + c.e + c.f, 2 * c.e + c.h, c.h, 4 * c.h, 0, 2 * c.b};
  } else if (scheme == "midpoint") {
    const double other = c.f - c.f3, other_h = c.h - 3 * c.f3;
    n = {c.v + c.e + other, 2 * c.e + c.h, 4 * c.f3 + other_h, 12 * c.f3 + 4 * other_h, 4 * c.f3, 2 * c.b};
  } else if (scheme == "sqrt3") {
    const bool refine_border = level % 2 == 1;
    n.f = 3 * c.f + (refine_border ? 2 * c.b : 0);
    n.b = refine_border ? 3 * c.b : c.b;
    n.v = c.v + c.f + (refine_border ? c.b : 0);
    n.e = (3 * n.f + n.b) / 2;
    n.h = 3 * n.f;
    n.f3 = n.f;
  } else { // doo-sabin
    n = {c.h, 2 * c.h, c.f + c.e + c.v, c.h + 6 * c.e, 0, 0};
    n.f3 = 0;
  }
  return n;
}

// Peak memory of the whole program at the last level (write_mesh writes
// from the mesh, no output copy): bytes per element fitted to the peak RSS
// of every scheme on each backend, separately for the schemes refined in
// place (Loop, butterfly, Catmull-Clark, midpoint on triangles) and those
// that rebuild the mesh from a soup each level (√3, Doo-Sabin, midpoint on
// polygons), each a few per cent above every measurement (docs/cli.md
// "Limits").
double predicted_bytes(const Level_counts& c, const std::string& backend, bool in_place) {
  const double base = 5e6; // the program, the input
  if (backend == "incidence")
    return base + (in_place ? 40 * c.v + 60 * c.e + 150 * c.f : 90 * c.v + 140 * c.e + 50 * c.f);
  return base + (in_place ? 40 * c.v + 40 * c.e + 12 * c.f : 90 * c.v + 50 * c.e + 50 * c.f);
}

std::uint64_t physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? std::uint64_t(pages) * std::uint64_t(size) : std::uint64_t{8} << 30;
}

// Predicts the counts of every level and the memory of the last, and refuses
// (too_large_error, exit 3) with those figures when they exceed the 32-bit
// indices of the meshes or the memory limit (--max-memory, default half of
// the physical memory). O(input) and done before any work starts.
void check_subdivision_fits(const genmesh::Polygon_soup& soup, const Args& a) {
  Level_counts c = soup_counts(soup);
  // A triangle scheme on other faces refuses at once (exit 2, naming the face).
  if ((a.scheme == "loop" || a.scheme == "butterfly" || a.scheme == "sqrt3") && c.f3 != c.f) return;
  const std::uint64_t limit = a.max_memory ? *a.max_memory : physical_memory() / 2;
  const bool in_place = a.scheme == "loop" || a.scheme == "butterfly" || a.scheme == "catmull-clark" ||
                        (a.scheme == "midpoint" && c.f3 == c.f);
  std::ostringstream levels;
  for (int level = 0; level < a.levels; ++level) {
    c = next_level(c, a.scheme, level);
    levels << "\n  level " << level + 1 << ": " << std::llround(c.v) << " vertices, " << std::llround(c.e)
           << " edges, " << std::llround(c.f) << " faces";
    const double bytes = predicted_bytes(c, a.backend, in_place);
    const bool too_many = 2 * c.e >= 4294967295.0 || c.v >= 4294967295.0 || c.h >= 4294967295.0;
    if (too_many || bytes > static_cast<double>(limit)) {
      throw too_large_error(
          a.files[0] + ": " + a.scheme + " x" + std::to_string(a.levels) + " would not fit: " +
          (too_many ? std::string("level ") + std::to_string(level + 1) +
                          " exceeds the 32-bit element indices of the meshes"
                    : "level " + std::to_string(level + 1) + " needs about " +
                          genmesh::detail::io::human_bytes(static_cast<std::uint64_t>(bytes)) +
                          " of memory on the " + a.backend + " backend, over the limit of " +
                          genmesh::detail::io::human_bytes(limit) +
                          (a.max_memory ? " (--max-memory)" : " (half of the physical memory; raise it with --max-memory)")) +
          "; predicted counts:" + levels.str());
    }
  }
}

int cmd_subdivide(const Args& a) {
  genmesh::Polygon_soup soup = read_input(a, a.files[0]);
  check_subdivision_fits(soup, a);
  std::vector<genmesh::Crease> creases;
  if (!a.creases.empty()) {
    Stage stage("reading " + a.creases);
    creases = read_creases(a.creases, soup, a.max_file_size);
  }
  Subdivide_progress progress;
  progress.scheme = a.scheme.c_str();
  progress.show = !a.json && isatty(STDERR_FILENO);
  return with_backend(a.backend, [&](auto& mesh) {
    try {
      Stage stage("building the mesh of " + a.files[0]);
      genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    } catch (const genmesh::invalid_input& e) {
      return report_unbuildable(a.files[0], e);
    }
    soup = genmesh::Polygon_soup{}; // the mesh holds it all now
    Stage stage("subdividing " + a.files[0]);
    genmesh::Subdivision_result result;
    double seconds = 0;
    try {
    if (creases.empty()) {
      const auto t0 = std::chrono::steady_clock::now();
      result = subdivide_all(mesh, a, genmesh::Default_map{}, progress);
      seconds = seconds_since(t0);
    } else {
      auto crease_map = [&] {
        try {
          return genmesh::crease_map(mesh, std::span<const genmesh::Crease>(creases));
        } catch (const genmesh::invalid_input& e) {
          throw genmesh::io_error(a.creases, e.what());
        }
      }();
      const auto t0 = std::chrono::steady_clock::now();
      result = subdivide_all(mesh, a, crease_map, progress);
      seconds = seconds_since(t0);
    }
    } catch (const genmesh::invalid_input& e) {
      // The scheme refused the mesh ("face 4 has 4 sides"): name the file.
      throw genmesh::io_error(a.files[0], a.scheme + " subdivision refused it: " + bounded(e.what()));
    }
    genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    Stage writing("writing " + a.files[1]);
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
genmesh::Simplification_result simplify_with(Mesh& mesh, const Args& a, bool progress, Policy policy = {}) {
  genmesh::Simplification_options<Policy> o;
  o.policy = std::move(policy);
  o.target_faces = a.faces;
  o.target_ratio = a.ratio;
  if (a.error) {
    o.max_error = *a.error;
    o.max_error_relative = true;
  }
  o.border = a.boundary == "lock"   ? genmesh::Border_mode::lock
             : a.boundary == "free" ? genmesh::Border_mode::free
                                    : genmesh::Border_mode::preserve;
  o.feature_angle = a.features;
  if (!progress) return genmesh::simplify(mesh, o);
  struct Progress : genmesh::Mutation_visitor {
    void on_step(std::string_view, std::size_t done, std::size_t total) {
      std::fprintf(stderr, "\rsimplify: %zu of %zu faces removed   ", done, total);
    }
  };
  const auto r = genmesh::simplify(mesh, o, Progress{});
  std::fprintf(stderr, "\n");
  return r;
}

// The input's per-vertex attributes on the mesh built from it (one vertex
// property map each, dynamic width) and the weight --attributes gives each
// (0: carried to the output, not in the quadrics).
template <class Mesh>
struct Cli_attributes {
  using Map = decltype(genmesh::scratch_property<Eigen::VectorXd>(genmesh::vertex_index, std::declval<Mesh&>()));
  std::vector<const genmesh::Soup_attribute*> channels;
  std::vector<Map> maps;
  std::vector<double> weights;

  Cli_attributes(const genmesh::Polygon_soup& soup, Mesh& mesh, const Args& a) {
    for (const auto& [name, w] : a.attribute_weights)
      if (!name.empty() && !soup.vertex_attribute(name)) {
        std::string have;
        for (const auto& c : soup.vertex_attributes) have += (have.empty() ? "" : ", ") + c.name;
        throw genmesh::io_error(a.files[0], "--attributes names '" + bounded(name, 40) + "', which the file does not have (" +
                                                (have.empty() ? std::string("it has no per-vertex attributes")
                                                              : "its attributes: " + have) + ")");
      }
    for (const auto& c : soup.vertex_attributes) {
      double w = 0;
      for (const auto& [name, weight] : a.attribute_weights)
        if (name.empty() || name == c.name) w = weight;
      channels.push_back(&c);
      maps.push_back(genmesh::scratch_property<Eigen::VectorXd>(genmesh::vertex_index, mesh));
      genmesh::read_vertex_attribute(c, mesh, maps.back());
      weights.push_back(w);
    }
  }

  // The quadric policy over the weighted ones. An integer colour (0..255)
  // counts in units of full scale, as a float colour in [0, 1] does.
  // N: the bound of Attribute_quadrics<Mesh, N> (inline quadrics when 3 +
  // weighted_width() fits).
  template <int N = Eigen::Dynamic>
  genmesh::Attribute_quadrics<Mesh, N> policy() const {
    return fill<genmesh::Attribute_quadrics<Mesh, N>>();
  }
  // Hoppe's 1999 metric over the same attributes (N: the values' bound).
  template <int N = Eigen::Dynamic>
  genmesh::Hoppe_quadrics<Mesh, N> hoppe_policy() const {
    return fill<genmesh::Hoppe_quadrics<Mesh, N>>();
  }
  template <class Policy>
  Policy fill() const {
    Policy q;
    for (std::size_t k = 0; k < channels.size(); ++k) {
      if (weights[k] <= 0) continue;
      const bool byte_colour = channels[k]->name == "color" && channels[k]->type != genmesh::Scalar_type::float32 &&
                               channels[k]->type != genmesh::Scalar_type::float64;
      q.attributes.push_back(genmesh::vertex_attribute(maps[k], byte_colour ? weights[k] / 255.0 : weights[k],
                                                       channels[k]->name));
    }
    return q;
  }

  // Values per vertex of the attributes in the quadrics.
  std::size_t weighted_width() const {
    std::size_t w = 0;
    for (std::size_t k = 0; k < channels.size(); ++k)
      if (weights[k] > 0) w += channels[k]->width();
    return w;
  }

  // The mesh's soup with the attributes' current values.
  genmesh::Polygon_soup soup(const Mesh& mesh) const {
    genmesh::Polygon_soup out = genmesh::to_soup(mesh);
    for (std::size_t k = 0; k < channels.size(); ++k)
      out.vertex_attributes.push_back(
          genmesh::make_soup_attribute(mesh, maps[k], channels[k]->name, channels[k]->components, channels[k]->type));
    return out;
  }

  // "[{"name":"color","width":3,"weight":0.2},...]"
  std::string json() const {
    std::string j = "[";
    for (std::size_t k = 0; k < channels.size(); ++k) {
      std::ostringstream w;
      w << weights[k];
      j += std::string(k ? "," : "") + "{\"name\":\"" + json_escape(channels[k]->name) +
           "\",\"width\":" + std::to_string(channels[k]->width()) + ",\"weight\":" + w.str() + "}";
    }
    return j + "]";
  }
};

int cmd_simplify(const Args& a) {
  genmesh::Polygon_soup soup = read_input(a, a.files[0]);
  const bool progress = !a.json && isatty(STDERR_FILENO);
  repair_keeping_attributes(a, soup);
  return with_backend(a.backend, [&](auto& mesh) {
    using Mesh = std::remove_reference_t<decltype(mesh)>;
    try {
      genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    } catch (const genmesh::invalid_input& e) {
      return report_unbuildable(a.files[0], e);
    }
    const Cli_attributes<Mesh> attributes(soup, mesh, a);
    Mesh input; // the Hausdorff distance's reference
    genmesh::build_mesh(genmesh::to_soup(mesh), input);
    const auto t0 = std::chrono::steady_clock::now();
    genmesh::Simplification_result r;
    try {
      if (a.policy == "probabilistic") r = simplify_with<genmesh::Probabilistic_quadrics>(mesh, a, progress);
      else if (a.policy == "length") r = simplify_with<genmesh::Edge_length>(mesh, a, progress);
      else if (a.policy == "lindstrom-turk") r = simplify_with<genmesh::Lindstrom_turk>(mesh, a, progress);
      // Up to 5 values (an RGBA colour; a colour and texture coordinates) the
      // quadrics are stored inline, in 7 × 7 or 8 × 8 matrices (a larger bound
      // than needed costs memory: docs/benchmarks.md).
      else if (const std::size_t w = attributes.weighted_width(); w > 0 && a.attribute_metric == "hoppe")
        r = w <= 4 ? simplify_with(mesh, a, progress, attributes.template hoppe_policy<4>())
            : w == 5 ? simplify_with(mesh, a, progress, attributes.template hoppe_policy<5>())
                     : simplify_with(mesh, a, progress, attributes.hoppe_policy());
      else if (w > 0 && w <= 4)
        r = simplify_with(mesh, a, progress, attributes.template policy<7>());
      else if (w == 5) r = simplify_with(mesh, a, progress, attributes.template policy<8>());
      else if (w > 5) r = simplify_with(mesh, a, progress, attributes.policy());
      else r = simplify_with<genmesh::Plane_quadrics>(mesh, a, progress);
    } catch (const genmesh::invalid_input& e) {
      // simplify refused the mesh ("face 0 is not a triangle"): name the file (issue 14).
      throw genmesh::io_error(a.files[0], "simplify refused it: " + bounded(e.what()));
    }
    const double seconds = seconds_since(t0);
    genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    // The figures a simplified mesh is judged by, as remesh reports them:
    // triangle quality, self-intersecting pairs, and the Hausdorff distance
    // to the input (100 000 samples each way unless --samples N).
    const auto q = genmesh::triangle_quality(mesh);
    const std::size_t intersecting = genmesh::self_intersections(mesh).size();
    const double diag = genmesh::diagonal(input);
    genmesh::Hausdorff_options ho;
    ho.samples = a.samples ? a.samples : 100'000;
    const auto h = genmesh::hausdorff_distance(mesh, input, ho);
    const double hausdorff = diag > 0 ? h.hausdorff / diag : std::nan("");
    if (attributes.channels.empty()) {
      genmesh::write_mesh(a.files[1], mesh, {.binary = a.binary});
    } else {
      const genmesh::Polygon_soup out = attributes.soup(mesh);
      genmesh::write_soup(a.files[1], out, {.binary = a.binary});
      note_unstored_attributes(a.files[1], out.vertex_attributes);
    }
    if (a.json) {
      std::cout << "{\"command\":\"simplify\",\"file\":\"" << json_escape(a.files[0]) << "\",\"output\":\""
                << json_escape(a.files[1]) << "\",\"backend\":\"" << a.backend << "\",\"policy\":\"" << a.policy
                << "\",\"attributes\":" << attributes.json() << ",\"attribute_metric\":\"" << a.attribute_metric
                << "\",\"collapses\":" << r.collapses
                << ",\"max_error\":" << r.max_error << ",\"stop_reason\":\"" << genmesh::to_string(r.stop_reason)
                << "\"," << json_counts(report) << ",\"min_angle\":" << json_number(q.min_angle)
                << ",\"angles_below_30\":" << json_number(q.angles_below_30)
                << ",\"valence6_share\":" << json_number(q.valence6_share)
                << ",\"self_intersections\":" << intersecting << ",\"hausdorff\":" << json_number(hausdorff)
                << ",\"seconds\":" << seconds << "}\n";
    } else {
      std::cout << a.files[0] << " -> " << a.files[1] << ": " << soup.num_faces() << " -> " << report.faces
                << " faces, " << r.collapses << " collapses, max error " << r.max_error << ", stopped: "
                << genmesh::to_string(r.stop_reason) << ", " << seconds << " s\n";
      std::printf("  min angle %.2f deg, angles below 30 deg %.3f %%, interior valence 6 %.1f %%,"
                  " %zu self-intersecting pairs, Hausdorff %.3g of the diagonal\n",
                  q.min_angle, 100 * q.angles_below_30, 100 * q.valence6_share, intersecting, hausdorff);
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
// polygons triangulated first), "remesh" (three rounds of isotropic
// remeshing at the mean edge length, edges sharper than 45° kept as
// features, polygons triangulated first).
const std::vector<std::string> demo_steps{"build", "ops", "subdiv", "simplify", "remesh"};

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
  if (step == "remesh") genmesh::isotropic_remeshing(mesh, {.iterations = 3, .feature_angle = 45});
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
  for (const auto& f : a.files) soups.push_back(read_input(a, f));
  return with_backend(a.backend, [&](auto& first) {
    using Mesh = std::remove_reference_t<decltype(first)>;
    std::vector<Mesh> meshes(soups.size());
    for (std::size_t i = 0; i < soups.size(); ++i) {
      try {
        genmesh::build_mesh(soups[i], meshes[i]);
      } catch (const genmesh::invalid_input& e) {
        return report_unbuildable(a.files[i], e);   // exit 1, as the other commands (issue 14)
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
      genmesh::Hausdorff_options o;
      o.samples = a.samples;
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

// ---- remesh ----------------------------------------------------------------

// Progress on a terminal: the round being done.
struct Remesh_progress : genmesh::Mutation_visitor {
  bool show = false;
  void on_step(std::string_view, std::size_t done, std::size_t total) {
    if (show) std::fprintf(stderr, "\rremesh: round %zu / %zu   ", done, total);
  }
};

int cmd_remesh(const Args& a) {
  genmesh::Polygon_soup soup = read_input(a, a.files[0]);
  genmesh::Remeshing_options o;
  o.target_edge_length = a.edge_length;
  if (a.relative) o.relative_edge_length = *a.relative;
  if (a.iterations) o.iterations = *a.iterations;
  if (a.features) o.feature_angle = *a.features;
  if (a.adaptive) o.adaptive = genmesh::Adaptive_sizing{(*a.adaptive)[0], (*a.adaptive)[1], (*a.adaptive)[2]};
  o.flips = a.flips == "delaunay" ? genmesh::Flips::delaunay : genmesh::Flips::valence;
  Remesh_progress progress;
  progress.show = !a.json && isatty(STDERR_FILENO);
  return with_backend(a.backend, [&](auto& mesh) {
    using Mesh = std::remove_reference_t<decltype(mesh)>;
    try {
      genmesh::build_mesh(soup, mesh, {.repair = a.repair});
    } catch (const genmesh::invalid_input& e) {
      return report_unbuildable(a.files[0], e);
    }
    Mesh input;
    genmesh::build_mesh(genmesh::to_soup(mesh), input);
    genmesh::Remeshing_result r;
    double seconds = 0;
    {
      Stage stage("remeshing " + a.files[0]);
      const auto t0 = std::chrono::steady_clock::now();
      r = genmesh::isotropic_remeshing(mesh, o, progress);
      seconds = seconds_since(t0);
    }
    if (progress.show) std::fprintf(stderr, "\n");
    const genmesh::Mesh_report report = genmesh::check_mesh(mesh);
    const auto q = genmesh::triangle_quality(mesh);
    const double diag = genmesh::diagonal(input);
    // 100 000 face samples each way (plus every vertex and edge midpoint):
    // enough for the figure, and bounded on large outputs (--samples N).
    genmesh::Hausdorff_options ho;
    ho.samples = a.samples ? a.samples : 100'000;
    const auto h = genmesh::hausdorff_distance(mesh, input, ho);
    const double hausdorff = diag > 0 ? h.hausdorff / diag : std::nan("");
    genmesh::write_mesh(a.files[1], mesh, {.binary = a.binary});
    if (a.json) {
      std::cout << "{\"command\":\"remesh\",\"file\":\"" << json_escape(a.files[0]) << "\",\"output\":\""
                << json_escape(a.files[1]) << "\",\"backend\":\"" << a.backend << "\",\"flips\":\"" << a.flips
                << "\",\"target_edge_length\":" << json_number(r.target_edge_length)
                << ",\"iterations\":" << r.iterations << ",\"splits\":" << r.splits
                << ",\"collapses\":" << r.collapses << ",\"flips_done\":" << r.flips << "," << json_counts(report)
                << ",\"min_angle\":" << json_number(q.min_angle)
                << ",\"angles_below_30\":" << json_number(q.angles_below_30)
                << ",\"valence6_share\":" << json_number(q.valence6_share)
                << ",\"hausdorff\":" << json_number(hausdorff) << ",\"seconds\":" << seconds << "}\n";
    } else {
      std::printf("%s -> %s: %zu -> %zu faces, L = %g, %d rounds (%zu splits, %zu collapses, %zu flips), %g s\n"
                  "  min angle %.2f deg, angles below 30 deg %.3f %%, interior valence 6 %.1f %%,"
                  " Hausdorff %.3g of the diagonal\n",
                  a.files[0].c_str(), a.files[1].c_str(), soup.num_faces(), std::size_t(report.faces),
                  r.target_edge_length, r.iterations, r.splits, r.collapses, r.flips, seconds, q.min_angle,
                  100 * q.angles_below_30, 100 * q.valence6_share, hausdorff);
    }
    return report.ok() ? exit_ok : exit_invalid;
  });
}

} // namespace

// SIGINT, SIGTERM, SIGHUP: remove the output's temporary (an existing output
// is untouched: it is replaced only by the final rename), then die of the
// same signal so the caller sees it (exit status 128 + N in a shell).
extern "C" void on_terminating_signal(int sig) {
  genmesh::remove_pending_temporaries();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void install_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_terminating_signal;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    // A signal the caller ignores (nohup, a background job) stays ignored.
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(sig, &sa, nullptr);
  }
}

// "genmesh: <stage>: <message>" for errors that do not name their file.
std::string in_stage(const std::string& message) {
  const std::string& stage = current_stage.empty() ? failed_stage : current_stage;
  return stage.empty() ? message : stage + ": " + message;
}

int main(int argc, char** argv) {
  install_signal_handlers();
  try {
    Args a = parse(argc, argv);
    if (a.command == "demo") return cmd_demo(a);
    if (a.command == "convert") return cmd_convert(a);
    if (a.command == "subdivide") return cmd_subdivide(a);
    if (a.command == "simplify") return cmd_simplify(a);
    if (a.command == "remesh") return cmd_remesh(a);
    if (a.command == "measure") return cmd_measure(a);
    return cmd_info_or_check(a);
  } catch (const usage_error& e) {
    std::cerr << "genmesh: " << bounded(e.what()) << "\n" << usage_text;
    return exit_bad_input;
  } catch (const too_large_error& e) {
    std::cerr << "genmesh: " << bounded(e.what()) << "\n";
    return exit_too_large;
  } catch (const genmesh::io_error& e) {
    std::cerr << "genmesh: " << bounded(e.what()) << "\n";
    return exit_bad_input;
  } catch (const genmesh::invalid_input& e) {
    std::cerr << "genmesh: " << bounded(in_stage(e.what())) << "\n";
    return exit_bad_input;
  } catch (const std::bad_alloc&) {
    std::cerr << "genmesh: " << bounded(in_stage("out of memory")) << "\n";
    return exit_too_large;
  } catch (const std::exception& e) {
    std::cerr << "genmesh: " << bounded(in_stage(std::string("error: ") + e.what())) << "\n";
    return exit_bad_input;
  }
}
