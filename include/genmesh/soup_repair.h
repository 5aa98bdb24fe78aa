// genmesh/soup_repair.h — repair_soup(soup): make a polygon soup buildable.
//
// repair_soup(soup) removes degenerate, duplicate and out-of-range faces,
// drops the faces beyond the first two on a fin edge, reorients every
// orientable connected component consistently and splits non-manifold
// vertices, saying what it changed; what it cannot fix (a Möbius strip, a NaN
// point) it reports.
#pragma once

#include <genmesh/detail/validity/dense_index.h>
#include <genmesh/detail/validity/soup_edges.h>
#include <genmesh/detail/validity/union_find.h>
#include <genmesh/polygon_soup.h>
#include <genmesh/soup_check.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace genmesh {

// ---------------------------------------------------------------------------
// Soup repair
// ---------------------------------------------------------------------------

/// What repair_soup() may change. Every step is on by default.
struct Soup_repair_options {
  bool remove_out_of_range_faces = true;
  bool remove_degenerate_faces = true;  ///< after merging consecutive repeated corners
  bool remove_duplicate_faces = true;   ///< keeps the first of faces with equal corner sets
  bool remove_fin_faces = true;         ///< keeps the two lowest-numbered faces of a fin edge
  bool reorient = true;                 ///< per component, to the orientation most faces have
  bool split_non_manifold_vertices = true; ///< one new point per extra fan, appended
};

/// What repair_soup() changed (in counts and words) and what is left.
struct Soup_repair_report {
  std::size_t merged_corners = 0;        ///< consecutive repeated corners merged
  std::size_t removed_out_of_range_faces = 0;
  std::size_t removed_degenerate_faces = 0;
  std::size_t removed_duplicate_faces = 0;
  std::size_t removed_fin_faces = 0;
  std::size_t reoriented_faces = 0;
  std::size_t unorientable_components = 0; ///< left as they were (e.g. a Möbius strip)
  std::size_t split_vertices = 0;          ///< non-manifold vertices split
  std::size_t added_points = 0;            ///< new points appended by the splits
  /// For each face of the repaired soup, its index in the input soup.
  std::vector<std::size_t> face_origin;
  /// For each point appended by a split, the point it copies.
  std::vector<std::size_t> point_origin;
  /// One sentence per change, in the order made, naming input faces and points.
  std::vector<std::string> changes;
  /// check_soup() of the repaired soup.
  Soup_report after;

  bool changed() const noexcept {
    return merged_corners + removed_out_of_range_faces + removed_degenerate_faces + removed_duplicate_faces +
               removed_fin_faces + reoriented_faces + added_points >
           0;
  }
  /// The repaired soup passes check_soup().
  bool ok() const noexcept { return after.ok(); }
};

inline std::string to_string(const Soup_repair_report& r) {
  std::ostringstream s;
  if (!r.changed()) s << "repair: nothing changed\n";
  for (const auto& c : r.changes) s << "repair: " << c << "\n";
  if (!r.ok()) s << "repair could not fix:\n" << to_string(r.after);
  return s.str();
}

namespace detail::soup_repair {

/// What every pass of repair_soup() works on: the soup, the options, the
/// report, and for each current face its input index (origin) and whether
/// it stays (keep, applied by compact()).
struct Repair {
  Polygon_soup& soup;
  const Soup_repair_options& opt;
  Soup_repair_report& rep;
  std::vector<std::size_t> origin;
  std::vector<char> keep;

  /// Rebuilds the soup from the kept faces.
  void compact() {
    Polygon_soup out;
    out.points = std::move(soup.points);
    out.vertex_attributes = std::move(soup.vertex_attributes);
    std::vector<std::size_t> o;
    for (std::size_t f = 0; f < soup.num_faces(); ++f)
      if (keep[f]) {
        out.add_face(soup.face(f));
        o.push_back(origin[f]);
      }
    soup = std::move(out);
    origin = std::move(o);
    keep.assign(soup.num_faces(), 1);
  }
};

/// Pass 1: faces with a corner out of range are removed, consecutive
/// repeated corners merged, faces left with fewer than three distinct
/// corners (or a repeated one) removed (as opt allows).
inline void remove_bad_faces(Repair& r) {
  Polygon_soup& soup = r.soup;
  Soup_repair_report& rep = r.rep;
  std::vector<std::size_t>& origin = r.origin;
  std::vector<char>& keep = r.keep;
  const Soup_repair_options& opt = r.opt;
  Polygon_soup out; // its points and attributes are the soup's, moved over at the end
  std::vector<Polygon_soup::Index> c;
  std::vector<std::size_t> o;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto in = soup.face(f);
    if (!face_in_range(soup, f)) {
      if (opt.remove_out_of_range_faces) {
        ++rep.removed_out_of_range_faces;
        rep.changes.push_back("removed face " + std::to_string(f) + " (a corner is out of range)");
        continue;
      }
      out.add_face(in);
      o.push_back(f);
      continue;
    }
    c.assign(in.begin(), in.end());
    if (opt.remove_degenerate_faces) {
      std::vector<Polygon_soup::Index> m;
      for (std::size_t k = 0; k < c.size(); ++k)
        if (m.empty() || m.back() != c[k]) m.push_back(c[k]);
      while (m.size() > 1 && m.front() == m.back()) m.pop_back();
      if (m.size() != c.size()) {
        rep.merged_corners += c.size() - m.size();
        rep.changes.push_back("face " + std::to_string(f) + ": merged " + std::to_string(c.size() - m.size()) +
                              " repeated consecutive corner(s)");
      }
      c = std::move(m);
      if (c.size() < 3 || face_has_repeat(c)) {
        ++rep.removed_degenerate_faces;
        rep.changes.push_back("removed degenerate face " + std::to_string(f) + " (" +
                              (c.size() < 3 ? "fewer than 3 distinct corners" : "a corner repeats") + ")");
        continue;
      }
    }
    out.add_face(c);
    o.push_back(f);
  }
  out.points = std::move(soup.points);
  out.vertex_attributes = std::move(soup.vertex_attributes);
  soup = std::move(out);
  origin = std::move(o);
  keep.assign(soup.num_faces(), 1);
}

/// Pass 2: every face whose corner set equals an earlier face's is removed.
inline void remove_duplicate_faces(Repair& r) {
  Polygon_soup& soup = r.soup;
  Soup_repair_report& rep = r.rep;
  std::vector<std::size_t>& origin = r.origin;
  std::vector<char>& keep = r.keep;
  Soup_edges e = soup_edges(soup);
  for (auto [f, g] : duplicate_faces(soup, e)) {
    keep[f] = 0;
    ++rep.removed_duplicate_faces;
    rep.changes.push_back("removed face " + std::to_string(origin[f]) + " (same corners as face " +
                          std::to_string(origin[g]) + ")");
  }
  r.compact();
}

/// Pass 3: on an edge of three or more faces, the two lowest-numbered faces
/// stay.
inline void remove_fin_faces(Repair& r) {
  Polygon_soup& soup = r.soup;
  Soup_repair_report& rep = r.rep;
  std::vector<std::size_t>& origin = r.origin;
  std::vector<char>& keep = r.keep;
  Soup_edges e = soup_edges(soup);
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g) {
    std::uint32_t b = e.group_begin[g], end = e.group_begin[g + 1];
    if (end - b <= 2) continue;
    std::vector<std::uint32_t> fs;
    for (std::uint32_t i = b; i < end; ++i)
      if (keep[e.halves[i].face]) fs.push_back(e.halves[i].face);
    std::sort(fs.begin(), fs.end());
    for (std::size_t k = 2; k < fs.size(); ++k) {
      keep[fs[k]] = 0;
      ++rep.removed_fin_faces;
      rep.changes.push_back("removed face " + std::to_string(origin[fs[k]]) + " (third or later face on edge (" +
                            std::to_string(e.halves[b].lo) + ", " + std::to_string(e.halves[b].hi) + "))");
    }
  }
  r.compact();
}

/// Pass 4: per component (faces joined across two-face edges), the minority
/// orientation is flipped; an unorientable component is left as it was.
inline void reorient(Repair& r) {
  Polygon_soup& soup = r.soup;
  Soup_repair_report& rep = r.rep;
  std::vector<std::size_t>& origin = r.origin;
  Soup_edges e = soup_edges(soup);
  const std::size_t n = soup.num_faces();
  // Face adjacency (CSR) with "same direction" flags.
  std::vector<std::uint32_t> deg(n + 1, 0);
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g)
    if (e.group_begin[g + 1] - e.group_begin[g] == 2) {
      ++deg[e.halves[e.group_begin[g]].face + 1];
      ++deg[e.halves[e.group_begin[g] + 1].face + 1];
    }
  for (std::size_t f = 0; f < n; ++f) deg[f + 1] += deg[f];
  std::vector<std::pair<std::uint32_t, bool>> adj(deg[n]);
  std::vector<std::uint32_t> fill(deg.begin(), deg.end() - 1);
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g)
    if (e.group_begin[g + 1] - e.group_begin[g] == 2) {
      const Soup_half& x = e.halves[e.group_begin[g]];
      const Soup_half& y = e.halves[e.group_begin[g] + 1];
      bool same = x.forward == y.forward;
      adj[fill[x.face]++] = {y.face, same};
      adj[fill[y.face]++] = {x.face, same};
    }
  std::vector<int> flip(n, -1);
  std::vector<std::uint32_t> queue;
  for (std::size_t s = 0; s < n; ++s) {
    if (flip[s] != -1) continue;
    queue.assign(1, static_cast<std::uint32_t>(s));
    flip[s] = 0;
    bool orientable = true;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      std::uint32_t f = queue[q];
      for (std::uint32_t k = deg[f]; k < deg[f + 1]; ++k) {
        auto [g, same] = adj[k];
        int want = flip[f] ^ (same ? 1 : 0);
        if (flip[g] == -1) {
          flip[g] = want;
          queue.push_back(g);
        } else if (flip[g] != want) {
          orientable = false;
        }
      }
    }
    if (!orientable) {
      ++rep.unorientable_components;
      std::size_t first = *std::min_element(queue.begin(), queue.end());
      rep.changes.push_back("left the component of face " + std::to_string(origin[first]) + " (" +
                            std::to_string(queue.size()) + " faces) as it was: it is not orientable");
      for (auto f : queue) flip[f] = 0;
      continue;
    }
    // Flip the minority; on a tie keep the component's first face as it is.
    std::size_t ones = 0;
    for (auto f : queue) ones += flip[f] == 1;
    bool invert = 2 * ones > queue.size();
    for (auto f : queue) flip[f] ^= invert ? 1 : 0;
  }
  for (std::size_t f = 0; f < n; ++f)
    if (flip[f] == 1) {
      auto c = soup.face(f);
      std::reverse(c.begin() + 1, c.end()); // keeps the first corner
      ++rep.reoriented_faces;
      rep.changes.push_back("reversed the orientation of face " + std::to_string(origin[f]));
    }
}

/// Pass 5: each fan of a vertex beyond the one holding its lowest corner
/// gets a new point (a copy of the vertex's, attribute values included).
inline void split_non_manifold_vertices(Repair& r) {
  Polygon_soup& soup = r.soup;
  Soup_repair_report& rep = r.rep;
  std::vector<std::size_t>& origin = r.origin;
  Soup_edges e = soup_edges(soup);
  Union_find uf = soup_fans(soup, e);
  const std::size_t np = soup.num_points();
  // The fan holding a vertex's lowest corner keeps the vertex.
  std::vector<std::uint32_t> first_root(np, k_null);
  std::vector<std::uint32_t> new_point(soup.indices.size(), k_null); // per root corner
  std::vector<std::uint32_t> extra(np, 0);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (!e.usable[f]) continue;
    for (std::uint32_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c) {
      std::uint32_t v = soup.indices[c], root = uf.find(c);
      if (first_root[v] == k_null) first_root[v] = root;
      if (root == first_root[v]) continue;
      if (new_point[root] == k_null) {
        new_point[root] = soup.add_point(Eigen::Vector3d(soup.points[v]));
        for (Soup_attribute& a : soup.vertex_attributes) // the copy's attributes too
          std::copy_n(a.values.begin() + static_cast<std::ptrdiff_t>(v * a.width()), a.width(),
                      a.values.begin() + static_cast<std::ptrdiff_t>(new_point[root] * a.width()));
        rep.point_origin.push_back(v);
        ++rep.added_points;
        if (extra[v]++ == 0) ++rep.split_vertices;
        rep.changes.push_back("split vertex " + std::to_string(v) + ": a further fan (with face " +
                              std::to_string(origin[f]) + ") now uses new point " + std::to_string(new_point[root]));
      }
      soup.indices[c] = new_point[root];
    }
  }
}

} // namespace detail::soup_repair

/// Repairs soup in place (see Soup_repair_options); point indices of the
/// input stay valid (new points are appended), faces keep their relative
/// order (report.face_origin maps them back). Non-finite points and
/// unorientable components are reported in `after`, not fixed. Runs the
/// named passes of detail::soup_repair in order.
inline Soup_repair_report repair_soup(Polygon_soup& soup, const Soup_repair_options& opt = {}) {
  using namespace detail::soup_repair;
  Soup_repair_report rep;
  const std::size_t nf = soup.num_faces();
  if (Soup_report before = check_soup(soup); before.ok()) { // nothing to repair
    rep.face_origin.resize(nf);
    std::iota(rep.face_origin.begin(), rep.face_origin.end(), std::size_t{0});
    rep.after = std::move(before);
    return rep;
  }
  Repair c{soup, opt, rep, std::vector<std::size_t>(nf), std::vector<char>(nf, 1)};
  std::iota(c.origin.begin(), c.origin.end(), std::size_t{0});
  remove_bad_faces(c);
  if (opt.remove_duplicate_faces) remove_duplicate_faces(c);
  if (opt.remove_fin_faces) remove_fin_faces(c);
  if (opt.reorient && soup.num_faces() > 0) reorient(c);
  if (opt.split_non_manifold_vertices) split_non_manifold_vertices(c);
  rep.face_origin = std::move(c.origin);
  rep.after = check_soup(soup);
  return rep;
}

} // namespace genmesh
