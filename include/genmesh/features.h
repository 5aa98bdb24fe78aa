// genmesh/features.h — sharp (feature) edges and what they make of vertices.
//
// detect_sharp_edges marks the same edges as CGAL's
// PMP::detect_sharp_edges: every border edge, and every interior edge whose
// two faces' normals make an angle of at least angle_deg (0 marks every
// edge, 180 only the border). On triangles the normals are formed exactly
// as CGAL forms them (from the edge vector and each face's third corner) and
// compared without square roots, so the two agree edge for edge; on other
// polygons the faces' face_normal() is used.
//
// classify_vertex sorts a vertex by the feature edges around it (border
// edges always count as feature edges): interior (none), border (two, both
// border edges), feature (two, on a crease), corner (three or more: where
// creases or a crease and the border meet; also one: where a crease ends) —
// the vertices remeshing and simplification must not move.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/geometry.h>
#include <genmesh/property_maps.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/property_map/vector_property_map.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace genmesh {

namespace detail::features {

// Is h or opposite(h) a border halfedge?
template <FaceGraph G>
bool border_edge(halfedge_descriptor_t<G> h, const G& g) {
  const auto null = boost::graph_traits<G>::null_face();
  return face(h, g) == null || face(opposite(h, g), g) == null;
}

// CGAL's internal::is_sharp: n1·n2 ≤ cos(angle)·|n1||n2| without roots.
template <FaceGraph G, class PointMap>
bool is_sharp(halfedge_descriptor_t<G> h, const G& g, PointMap pm, double cos_angle) {
  const auto o = opposite(h, g);
  Eigen::Vector3d n1, n2;
  if (degree(face(h, g), g) == 3 && degree(face(o, g), g) == 3) {
    const Eigen::Vector3d s = point(source(h, g), g, pm);
    const Eigen::Vector3d vc = point(target(h, g), g, pm) - s;
    const Eigen::Vector3d v1 = point(target(next(h, g), g), g, pm) - s;
    const Eigen::Vector3d v2 = point(target(o, g), g, pm) - point(target(next(o, g), g), g, pm);
    n1 = vc.cross(v1);
    n2 = vc.cross(v2);
  } else {
    n1 = face_normal(face(h, g), g, pm);
    n2 = -face_normal(face(o, g), g, pm);
  }
  // Both conventions give n2 the opposite orientation of face(o)'s normal;
  // CGAL compares n1 · n2 with the sign so arranged.
  // Written out (not Eigen's dot) to round in CGAL's order.
  auto dot = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
  };
  const double sp = dot(n1, n2);
  const double sq = cos_angle * cos_angle * dot(n1, n1) * dot(n2, n2);
  if (cos_angle < 0) return sp < 0 && sp * sp >= sq;
  return sp < 0 || sp * sp <= sq;
}

} // namespace detail::features

// The functions below are function objects (see geometry.h): CGAL's
// unqualified detect_sharp_edges(...) calls on genmesh meshes stay CGAL's.

/// detect_sharp_edges(g, angle_deg, is_feature[, pm]): writes, for every
/// edge e, into the writable boolean edge map is_feature whether e is a
/// border edge or its faces' normals make an angle of at least angle_deg
/// degrees. Same edges as CGAL's PMP::detect_sharp_edges on triangle meshes.
inline constexpr struct Detect_sharp_edges_fn {
  template <class G, class EdgeMap, PointMapOf<G> PointMap>
    requires FaceGraph<G> && EdgeListGraph<G>
  void operator()(const G& g, double angle_deg, EdgeMap is_feature, const PointMap& pm) const {
    const double cos_angle = std::cos(angle_deg * std::numbers::pi / 180.0);
    for (const auto e : edges(g)) {
      const auto h = halfedge(e, g);
      const bool sharp = detail::features::border_edge(h, g) || angle_deg == 0 ||
                         (angle_deg != 180 && detail::features::is_sharp(h, g, pm, cos_angle));
      put(is_feature, e, sharp);
    }
  }
  template <class G, class EdgeMap>
    requires FaceGraph<G> && EdgeListGraph<G>
  void operator()(const G& g, double angle_deg, EdgeMap is_feature) const {
    (*this)(g, angle_deg, is_feature, get(vertex_point, g));
  }
} detect_sharp_edges{};

/// The boolean edge map sharp_edges() fills, indexed through g's edge index map.
template <class G>
using Edge_flag_map = boost::vector_property_map<bool, decltype(get(edge_index, std::declval<const G&>()))>;

/// sharp_edges(g, angle_deg): detect_sharp_edges into a new edge map of bool.
inline constexpr struct Sharp_edges_fn {
  template <class G>
    requires FaceGraph<G> && EdgeListGraph<G> && HasIndexMap<G, edge_index_t>
  Edge_flag_map<G> operator()(const G& g, double angle_deg) const {
    Edge_flag_map<G> m(static_cast<unsigned>(index_bound(edge_index, g)), get(edge_index, g));
    detect_sharp_edges(g, angle_deg, m);
    return m;
  }
} sharp_edges{};

/// What the feature edges make of a vertex (see the header comment).
enum class Vertex_kind : std::uint8_t { interior, border, feature, corner };

namespace detail::features {
// (feature edges that are not border edges, border edges) around v.
template <FaceGraph G, class EdgeMap>
std::pair<int, int> count_around(vertex_descriptor_t<G> v, const G& g, const EdgeMap& is_feature) {
  const auto h0 = halfedge(v, g);
  if (h0 == boost::graph_traits<G>::null_halfedge()) return {0, 0};
  int features = 0, border = 0;
  auto h = h0;
  do {
    if (border_edge(h, g)) ++border;
    else if (get(is_feature, edge(h, g))) ++features;
    h = opposite(next(h, g), g);
  } while (h != h0);
  return {features, border};
}
} // namespace detail::features

/// feature_degree(v, g, is_feature): the number of feature edges at v,
/// border edges counted as features.
inline constexpr struct Feature_degree_fn {
  template <FaceGraph G, class EdgeMap>
  int operator()(vertex_descriptor_t<G> v, const G& g, const EdgeMap& is_feature) const {
    const auto [f, b] = detail::features::count_around(v, g, is_feature);
    return f + b;
  }
} feature_degree{};

/// classify_vertex(v, g, is_feature): v's Vertex_kind (see the header comment).
inline constexpr struct Classify_vertex_fn {
  template <FaceGraph G, class EdgeMap>
  Vertex_kind operator()(vertex_descriptor_t<G> v, const G& g, const EdgeMap& is_feature) const {
    const auto [f, b] = detail::features::count_around(v, g, is_feature);
    const int n = f + b;
    if (n == 0) return Vertex_kind::interior;
    if (n == 2) return f == 0 ? Vertex_kind::border : Vertex_kind::feature;
    return Vertex_kind::corner;
  }
} classify_vertex{};

} // namespace genmesh
