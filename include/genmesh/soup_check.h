// genmesh/soup_check.h — check_soup(soup): what would stop a polygon soup
// from becoming a halfedge mesh.
//
// check_soup(soup) finds what would stop a polygon soup from becoming a
// halfedge mesh: degenerate faces, indices out of range, non-finite points,
// duplicate faces, edges shared by three or more faces (fins), edges used in
// the same direction by two faces (inconsistent orientation) and vertices
// whose faces form several fans (bow-ties); zero-area faces and isolated
// points are reported but do not fail the check.
//
// Guarantees: linear time up to sorts of small per-vertex edge buckets, in
// named passes (detail::soup_check) over one shared edge table
// (detail::soup_edges). Limits: geometry is checked only for non-finite
// points and zero-area faces; self-intersections are not looked for.
#pragma once

#include <genmesh/detail/validity/soup_edges.h>
#include <genmesh/detail/validity/union_find.h>
#include <genmesh/geometry.h>
#include <genmesh/polygon_soup.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace genmesh {

// ---------------------------------------------------------------------------
// Soup check
// ---------------------------------------------------------------------------

/// What a polygon-soup problem is about.
enum class Soup_problem_kind {
  index_out_of_range,   ///< error: a corner names no point
  degenerate_face,      ///< error: fewer than 3 corners, or a corner repeated
  non_finite_point,     ///< error: a coordinate is NaN or infinite
  duplicate_face,       ///< error: two faces with the same set of corners
  non_manifold_edge,    ///< error: an edge shared by three or more faces (a fin)
  inconsistent_orientation, ///< error: two faces use an edge in the same direction
  non_manifold_vertex,  ///< error: the faces around a vertex form several fans (a bow-tie)
  zero_area_face,       ///< warning: the face's vector area is (nearly) zero
  isolated_point,       ///< info: a point no face uses
};

inline const char* to_string(Soup_problem_kind k) {
  switch (k) {
    case Soup_problem_kind::index_out_of_range: return "index_out_of_range";
    case Soup_problem_kind::degenerate_face: return "degenerate_face";
    case Soup_problem_kind::non_finite_point: return "non_finite_point";
    case Soup_problem_kind::duplicate_face: return "duplicate_face";
    case Soup_problem_kind::non_manifold_edge: return "non_manifold_edge";
    case Soup_problem_kind::inconsistent_orientation: return "inconsistent_orientation";
    case Soup_problem_kind::non_manifold_vertex: return "non_manifold_vertex";
    case Soup_problem_kind::zero_area_face: return "zero_area_face";
    case Soup_problem_kind::isolated_point: return "isolated_point";
  }
  return "unknown";
}

/// Whether a soup problem stops a halfedge mesh from being built.
inline bool is_error(Soup_problem_kind k) {
  return k != Soup_problem_kind::zero_area_face && k != Soup_problem_kind::isolated_point;
}

/// One soup problem: `element` names it ("face 4", "edge (2, 7)", "vertex 3",
/// "point 9"); `faces` and `vertices` list the soup indices involved.
struct Soup_problem {
  Soup_problem_kind kind;
  std::string element;
  std::string message;
  std::vector<std::size_t> faces;
  std::vector<std::size_t> vertices;
};

/// What check_soup() found. Counts cover every problem; `problems` keeps the
/// first max_problems of them (errors and warnings; isolated points are only
/// counted).
struct Soup_report {
  std::size_t points = 0, faces = 0;
  std::size_t out_of_range_faces = 0;
  std::size_t degenerate_faces = 0;
  std::size_t non_finite_points = 0;
  std::size_t duplicate_faces = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t inconsistent_edges = 0;
  std::size_t non_manifold_vertices = 0;
  std::size_t zero_area_faces = 0;
  std::size_t isolated_points = 0;
  std::size_t border_edges = 0; ///< edges used by exactly one face
  std::size_t edges = 0;        ///< undirected edges of the non-degenerate faces

  std::vector<Soup_problem> problems;
  std::size_t problem_count = 0;
  static constexpr std::size_t max_problems = 100;

  std::size_t errors() const noexcept {
    return out_of_range_faces + degenerate_faces + non_finite_points + duplicate_faces + non_manifold_edges +
           inconsistent_edges + non_manifold_vertices;
  }
  /// No error (warnings and isolated points allowed): a halfedge mesh can be built.
  bool ok() const noexcept { return errors() == 0; }
};

inline std::string to_string(const Soup_report& r) {
  std::ostringstream s;
  s << (r.ok() ? "soup ok" : "soup NOT ok") << ": " << r.points << " points, " << r.faces << " faces, " << r.edges
    << " edges (" << r.border_edges << " border)\n";
  auto line = [&](const char* what, std::size_t n) {
    if (n) s << what << ": " << n << "\n";
  };
  line("faces with an index out of range", r.out_of_range_faces);
  line("degenerate faces", r.degenerate_faces);
  line("non-finite points", r.non_finite_points);
  line("duplicate faces", r.duplicate_faces);
  line("non-manifold edges (fins)", r.non_manifold_edges);
  line("inconsistently oriented edges", r.inconsistent_edges);
  line("non-manifold vertices (bow-ties)", r.non_manifold_vertices);
  line("zero-area faces (warning)", r.zero_area_faces);
  line("isolated points (info)", r.isolated_points);
  for (const auto& p : r.problems)
    s << p.element << ": " << to_string(p.kind) << (is_error(p.kind) ? "" : " (warning)") << ": " << p.message << "\n";
  if (r.problem_count > r.problems.size())
    s << "... and " << (r.problem_count - r.problems.size()) << " more problems\n";
  return s.str();
}

namespace detail {

/// "a, b, c" — at most `max_items` of them, then "... (N more)": a message
/// stays short however large the face or the fin (the problem's own vectors
/// keep every index).
inline std::string list(const std::vector<std::size_t>& v, std::size_t max_items = 10) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < max_items; ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  if (v.size() > max_items) s += ", ... (" + std::to_string(v.size() - max_items) + " more)";
  return s;
}

} // namespace detail

namespace detail::soup_check {

/// Records one soup problem (counted always, kept up to max_problems).
struct Problem_sink {
  Soup_report& r;
  void operator()(Soup_problem_kind kind, std::string element, std::string msg, std::vector<std::size_t> faces,
                  std::vector<std::size_t> verts) const {
    ++r.problem_count;
    if (r.problems.size() < Soup_report::max_problems)
      r.problems.push_back({kind, std::move(element), std::move(msg), std::move(faces), std::move(verts)});
  }
};

/// Points with a NaN or infinite coordinate.
inline void check_points(const Polygon_soup& soup, Soup_report& r, const Problem_sink& add) {
  for (std::size_t p = 0; p < soup.num_points(); ++p)
    if (!soup.points[p].allFinite()) {
      ++r.non_finite_points;
      add(Soup_problem_kind::non_finite_point, "point " + std::to_string(p), "has a NaN or infinite coordinate", {},
          {p});
    }
}

/// Faces with an index out of range, fewer than three corners or a repeated corner.
inline void check_faces(const Polygon_soup& soup, Soup_report& r, const Problem_sink& add) {
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto c = soup.face(f);
    if (!face_in_range(soup, f)) {
      ++r.out_of_range_faces;
      std::size_t bad = 0;
      for (auto i : c)
        if (i >= soup.num_points()) bad = i;
      add(Soup_problem_kind::index_out_of_range, "face " + std::to_string(f),
          "corner " + std::to_string(bad) + " is out of range (" + std::to_string(soup.num_points()) + " points)",
          {f}, {});
    } else if (c.size() < 3) {
      ++r.degenerate_faces;
      add(Soup_problem_kind::degenerate_face, "face " + std::to_string(f),
          "has " + std::to_string(c.size()) + " corners (< 3)", {f}, {});
    } else if (face_has_repeat(c)) {
      ++r.degenerate_faces;
      std::vector<std::size_t> vs(c.begin(), c.end());
      add(Soup_problem_kind::degenerate_face, "face " + std::to_string(f),
          "repeats a corner (corners " + list(vs) + ")", {f}, vs);
    }
  }
}

/// Faces with the same corner set as an earlier face.
inline void check_duplicates(const Polygon_soup& soup, const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  for (auto [f, g] : duplicate_faces(soup, e)) {
    ++r.duplicate_faces;
    add(Soup_problem_kind::duplicate_face, "face " + std::to_string(f),
        "has the same corners as face " + std::to_string(g), {g, f}, {});
  }
}

/// Per undirected edge: border (one face), inconsistent orientation (two
/// faces, same direction) or fin (three or more faces).
inline void check_edge_groups(const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g) {
    std::uint32_t b = e.group_begin[g], end = e.group_begin[g + 1];
    ++r.edges;
    const Soup_half& x = e.halves[b];
    if (end - b == 1) {
      ++r.border_edges;
    } else if (end - b == 2) {
      const Soup_half& y = e.halves[b + 1];
      if (x.forward == y.forward) {
        ++r.inconsistent_edges;
        std::uint32_t from = x.forward ? x.lo : x.hi, to = x.forward ? x.hi : x.lo;
        add(Soup_problem_kind::inconsistent_orientation,
            "edge (" + std::to_string(x.lo) + ", " + std::to_string(x.hi) + ")",
            "faces " + std::to_string(x.face) + " and " + std::to_string(y.face) + " both use it as " +
                std::to_string(from) + "→" + std::to_string(to) + " (one of them is flipped, or they duplicate)",
            {x.face, y.face}, {x.lo, x.hi});
      }
    } else {
      ++r.non_manifold_edges;
      std::vector<std::size_t> fs;
      for (std::uint32_t i = b; i < end; ++i) fs.push_back(e.halves[i].face);
      add(Soup_problem_kind::non_manifold_edge, "edge (" + std::to_string(x.lo) + ", " + std::to_string(x.hi) + ")",
          "is shared by " + std::to_string(end - b) + " faces (" + list(fs) + "); at most 2 are allowed", fs,
          {x.lo, x.hi});
    }
  }
}

/// Vertices whose faces form several fans (bow-ties), and isolated points
/// (used by no face; points used only by unusable faces count as used).
inline void check_fans(const Polygon_soup& soup, const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  std::vector<std::uint32_t> fans(soup.num_points(), 0);
  std::vector<char> used(soup.num_points(), 0);
  {
    Union_find uf = soup_fans(soup, e);
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      if (!e.usable[f]) continue;
      for (std::uint32_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c) {
        used[soup.indices[c]] = 1;
        if (uf.find(c) == c) ++fans[soup.indices[c]];
      }
    }
  }
  for (std::size_t v = 0; v < soup.num_points(); ++v) {
    if (fans[v] > 1) {
      ++r.non_manifold_vertices;
      add(Soup_problem_kind::non_manifold_vertex, "vertex " + std::to_string(v),
          "its faces form " + std::to_string(fans[v]) + " fans that meet only at this vertex (bow-tie)", {}, {v});
    }
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    if (!e.usable[f])
      for (auto i : soup.face(f))
        if (i < soup.num_points()) used[i] = 1;
  for (std::size_t v = 0; v < soup.num_points(); ++v) r.isolated_points += !used[v];
}

/// Zero-area faces (a warning): the vector area (geometry.h's
/// polygon_normal) against the longest edge squared.
inline void check_zero_area(const Polygon_soup& soup, const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  std::vector<Eigen::Vector3d> corners;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (!e.usable[f]) continue;
    auto c = soup.face(f);
    corners.clear();
    double longest = 0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      corners.push_back(soup.points[c[k]]);
      longest = std::max(longest, (soup.points[c[(k + 1) % c.size()]] - soup.points[c[k]]).squaredNorm());
    }
    if (!(0.5 * polygon_normal(corners).norm() > 1e-12 * longest)) {
      ++r.zero_area_faces;
      add(Soup_problem_kind::zero_area_face, "face " + std::to_string(f), "has zero area", {f}, {});
    }
  }
}

} // namespace detail::soup_check

/// check_soup() on the edge table e = detail::soup_edges(soup) the caller
/// already built (build_mesh() builds one and shares it with the linking).
inline Soup_report check_soup(const Polygon_soup& soup, const detail::Soup_edges& e) {
  using namespace detail::soup_check;
  Soup_report r;
  r.points = soup.num_points();
  r.faces = soup.num_faces();
  const Problem_sink add{r};
  check_points(soup, r, add);
  check_faces(soup, r, add);
  check_duplicates(soup, e, r, add);
  check_edge_groups(e, r, add);
  check_fans(soup, e, r, add);
  check_zero_area(soup, e, r, add);
  return r;
}

/// Checks a polygon soup before a halfedge mesh is built from it; see the
/// header comment for what is looked for. Linear time up to small sorts.
inline Soup_report check_soup(const Polygon_soup& soup) { return check_soup(soup, detail::soup_edges(soup)); }

} // namespace genmesh
