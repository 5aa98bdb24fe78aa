// genmesh/remeshing/detail/reference_surface.h — the input surface that
// remeshing projects onto: the geometry layer's Aabb_tree
// (<genmesh/aabb_tree.h>) over a snapshot of the input's triangles, built
// once; with a face patch, over the patch's triangles only, so that a vertex
// of the patch never lands on a face outside it.
//
// Queries are bounded: the caller passes the triangle of the vertex's
// previous projection, where the search starts (Aabb_tree::closest_point_from:
// that triangle is tested first, and its distance bounds the descent), or,
// when it has none, a point known to lie on the surface, so the search is
// pruned to the ball through it; the closest point is the global one either way.
// Deterministic: every backend numbers faces and vertices alike, so the tree
// (built in face order, fans from the lowest-index corner) and its answers
// are the same on every backend.
#pragma once

#include <genmesh/aabb_tree.h>
#include <genmesh/concepts.h>
#include <genmesh/geometry.h>
#include <genmesh/polygon_soup.h>
#include <genmesh/property_maps.h>
#include <genmesh/soup_to_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace genmesh::detail::remeshing {

/// The surface a remesher projects onto (see the header comment).
template <class G>
class Reference_surface {
public:
  /// Indexes g's faces; with a non-empty `patch` (by face index), only the
  /// faces it marks, copied as separate triangles (any face subset is then a
  /// valid mesh to index).
  Reference_surface(const G& g, const std::vector<char>& patch) {
    if (patch.empty()) {
      tree_.emplace(g);
      set_slack();
      return;
    }
    Polygon_soup soup;
    auto pm = get(vertex_point, const_cast<G&>(g));
    auto fi = get(face_index, g);
    for (auto f : faces(g)) {
      const std::size_t i = get(fi, f);
      if (i >= patch.size() || !patch[i]) continue;
      const auto first = static_cast<Polygon_soup::Index>(soup.num_points());
      const auto h0 = detail::geom::canonical_halfedge(f, g); // not halfedge(f): backends differ
      auto h = h0;
      do {
        soup.add_point(to_eigen(get(pm, target(h, g))));
        source_vertex_.push_back(static_cast<std::size_t>(get(get(vertex_index, g), target(h, g))));
        h = next(h, g);
      } while (h != h0);
      std::vector<Polygon_soup::Index> corners;
      for (auto k = first; k < soup.num_points(); ++k) corners.push_back(k);
      soup.add_face(corners);
    }
    copy_.emplace();
    genmesh::build_mesh(soup, *copy_);
    tree_.emplace(*copy_);
    set_slack();
  }

  Reference_surface(const Reference_surface&) = delete;
  Reference_surface& operator=(const Reference_surface&) = delete;

  /// Attaches a value to every vertex of the indexed surface, by vertex
  /// index of the g given to the constructor (call before g changes):
  /// project() then interpolates it at the point it returns.
  void attach_vertex_values(const G& g, const std::vector<double>& by_vertex_index) {
    values_.assign(3 * tree_->triangle_count(), 0.0);
    for (std::size_t t = 0; t < tree_->triangle_count(); ++t)
      for (int i = 0; i < 3; ++i)
        values_[3 * t + static_cast<std::size_t>(i)] = by_vertex_index[corner_index(g, t, i)];
  }

  /// For each vertex of the g given to the constructor (by vertex index,
  /// below vertex_bound), the first indexed triangle (in leaf order) that
  /// has it as a corner; npos for a vertex on none (call before g changes).
  /// The start triangles of the first projection: a vertex moved a little
  /// from where it was is nearest to one of its own triangles, or to one
  /// beside them. The same on every backend (the tree is).
  std::vector<std::size_t> corner_triangles(const G& g, std::size_t vertex_bound) const {
    std::vector<std::size_t> out(vertex_bound, npos);
    for (std::size_t t = 0; t < tree_->triangle_count(); ++t)
      for (int i = 0; i < 3; ++i)
        if (std::size_t& o = out[corner_index(g, t, i)]; o == npos) o = t;
    return out;
  }

  /// The point of the surface nearest to q, given `triangle`, the
  /// (leaf-order) triangle of the previous answer or npos, where the search
  /// starts: a vertex moved tangentially is usually still nearest to the
  /// triangle it was on, or to one beside it, whose distance then bounds the
  /// rest of the search; and a point `on` of the surface, read only when
  /// triangle is npos (it bounds the search: the nearest point is no
  /// farther). `triangle` is updated; with attached values, `value` is set
  /// to theirs interpolated at the returned point.
  Eigen::Vector3d project(const Eigen::Vector3d& q, const Eigen::Vector3d& on, std::size_t& triangle,
                          double* value = nullptr) const {
    if (tree_->empty() || !q.allFinite()) return q;
    const double d2 = triangle < triangle_count() ? 0 : (q - on).squaredNorm();
    if (std::isfinite(d2)) {
      // The previous triangle is tested first and bounds the rest.
      const auto c = tree_->closest_point_from(q, bound(triangle, d2), triangle);
      // Nothing that near: face is null_face().
      if (c.face != boost::graph_traits<G>::null_face()) return answer(q, c, triangle, value);
    }
    return answer(q, tree_->closest_point(q), triangle, value);
  }

  /// project(q[i], on[i], triangle[i], value[i]) into out[i] for every i
  /// (spans of one length; value[i] may be null): the same points, with the
  /// tree's searches interleaved (Aabb_tree::closest_points_from).
  void project(std::span<const Eigen::Vector3d> q, std::span<const Eigen::Vector3d> on,
               std::span<std::size_t> triangle, std::span<double* const> value, std::span<Eigen::Vector3d> out) const {
    constexpr std::size_t width = 16;
    std::size_t index[width], m = 0;
    Eigen::Vector3d bq[width];
    double limit[width];
    std::size_t start[width];
    typename Aabb_tree<G>::Closest found[width];
    auto flush = [&] {
      tree_->closest_points_from(std::span<const Eigen::Vector3d>(bq, m), std::span<const double>(limit, m),
                                 std::span<const std::size_t>(start, m),
                                 std::span<typename Aabb_tree<G>::Closest>(found, m));
      for (std::size_t j = 0; j < m; ++j) {
        const std::size_t i = index[j];
        // Nothing within the bound: face is null_face().
        out[i] = found[j].face != boost::graph_traits<G>::null_face()
                     ? answer(q[i], found[j], triangle[i], value[i])
                     : answer(q[i], tree_->closest_point(q[i]), triangle[i], value[i]);
      }
      m = 0;
    };
    for (std::size_t i = 0; i < q.size(); ++i) {
      const double d2 = triangle[i] < triangle_count() ? 0 : (q[i] - on[i]).squaredNorm();
      if (tree_->empty() || !q[i].allFinite() || !std::isfinite(d2)) {
        out[i] = project(q[i], on[i], triangle[i], value[i]);
        continue;
      }
      index[m] = i, bq[m] = q[i], limit[m] = bound(triangle[i], d2), start[m] = triangle[i];
      if (++m == width) flush();
    }
    if (m != 0) flush();
  }

  /// A hint that project() will soon be called with this triangle.
  void prefetch(std::size_t triangle) const { tree_->prefetch_triangle(triangle); }

  /// No previous triangle.
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  bool empty() const { return tree_->empty(); }
  /// The number of indexed triangles (leaf-order indices are below it).
  std::size_t triangle_count() const { return tree_->triangle_count(); }

private:
  // The squared search bound: none from a start triangle (its distance
  // bounds the search as soon as it is tested: the same answer as a bound
  // through the previous point, which lies on it, without reading that
  // point); else through `on`, at squared distance d2 from the query, with a
  // little slack: `on` is a computed point of a triangle, not exactly on it.
  double bound(std::size_t triangle, double d2) const {
    if (triangle < triangle_count()) return std::numeric_limits<double>::infinity();
    const double r = std::sqrt(d2) * (1 + 1e-9) + slack_;
    return r * r;
  }

  // g's vertex index of corner i of indexed triangle t.
  std::size_t corner_index(const G& g, std::size_t t, int i) const {
    const auto c = tree_->triangle_corners(t)[static_cast<std::size_t>(i)];
    return copy_ ? source_vertex_[static_cast<std::size_t>(get(get(vertex_index, *copy_), c))]
                 : static_cast<std::size_t>(get(get(vertex_index, g), c));
  }

  Eigen::Vector3d answer(const Eigen::Vector3d& q, const typename Aabb_tree<G>::Closest& c, std::size_t& triangle,
                         double* value) const {
    triangle = c.triangle;
    if (value && !values_.empty())
      *value = c.barycentric[0] * values_[3 * c.triangle] + c.barycentric[1] * values_[3 * c.triangle + 1] +
               c.barycentric[2] * values_[3 * c.triangle + 2];
    return snap(q, c);
  }

  // A point already on the surface (up to the slack) stays where it is:
  // re-projecting it would only add rounding, and on needle triangles
  // rounding decides which collapses pass their orientation test.
  static Eigen::Vector3d snap(const Eigen::Vector3d& q, const typename Aabb_tree<G>::Closest& c) {
    return c.squared_distance <= 0 ? q : c.point;
  }

  void set_slack() {
    if (!tree_->empty()) slack_ = 1e-12 * tree_->bounding_box().diagonal().norm();
  }

  std::optional<G> copy_;
  std::vector<std::size_t> source_vertex_; // patch: g's vertex index of each vertex of copy_
  std::vector<double> values_;             // attached values, 3 per triangle (leaf order)
  std::optional<Aabb_tree<G>> tree_;
  double slack_ = 0;
};

} // namespace genmesh::detail::remeshing
