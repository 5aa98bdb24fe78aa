// genmesh/measures.h — the numbers a user judges a mesh by: Hausdorff and
// RMS distance between two surfaces, self-intersections, triangle quality.
//
// hausdorff_distance samples surface A (points on the faces, spread by area,
// plus every vertex and every edge midpoint) and measures each sample's
// distance to surface B with an Aabb_tree (<genmesh/aabb_tree.h>), as Metro
// (Cignoni et al. 1998) and MeshLab do; the symmetric version does it both
// ways. It is an under-estimate of the true Hausdorff distance that tightens
// with the sample count; with a given seed it is deterministic.
//
// self_intersections follows CGAL's PMP::self_intersections exactly (same
// pairs): two faces sharing a vertex or an edge intersect only if they
// overlap beyond it, every decision is an exact predicate, and a degenerate
// (zero-area) face is reported as the pair (f, f).
//
// triangle_quality reports angles, aspect ratios, valences and edge lengths.
//
// Bad input: a NaN or infinite coordinate makes hausdorff_distance and
// self_intersections throw genmesh::invalid_input naming a face;
// hausdorff_distance refuses an empty surface; self_intersections of an empty
// mesh is empty; triangle_quality of an empty mesh has zero counts and NaN
// statistics.
#pragma once

#include <genmesh/aabb_tree.h>
#include <genmesh/concepts.h>
#include <genmesh/exceptions.h>
#include <genmesh/geometry.h>
#include <genmesh/property_maps.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace genmesh {

/// How hausdorff_distance samples a surface.
struct Hausdorff_options {
  /// Points sampled on the faces of the sampled surface, spread in
  /// proportion to area (each face gets ⌊n·area/total⌋ and one more with the
  /// probability of the remainder). 0: use samples_per_area instead.
  std::size_t samples = 0;
  /// Face samples per unit area, used when samples == 0. If both are 0:
  /// max(10 × faces, 100'000) face samples.
  double samples_per_area = 0;
  /// Also measure at every vertex and at every edge midpoint.
  bool vertices = true;
  bool edge_midpoints = true;
  /// The random sequence (std::mt19937_64) behind the face samples.
  std::uint64_t seed = 0;
  /// Called now and then with (samples done, samples in all); may be empty.
  std::function<void(std::size_t, std::size_t)> progress = {};
};

/// Distances from the samples of one surface to another.
struct Distance_result {
  double max = 0;   ///< the (one-sided) Hausdorff distance
  double mean = 0;  ///< mean over the samples
  double rms = 0;   ///< root mean square over the samples
  std::size_t samples = 0;
};

/// Both ways between A and B.
struct Hausdorff_result {
  Distance_result a_to_b, b_to_a;
  double hausdorff = 0;  ///< max(a_to_b.max, b_to_a.max)
  double mean = 0;       ///< max of the two means (Metro's convention)
  double rms = 0;        ///< max of the two RMS
};

namespace detail::measures {

inline double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

template <FaceGraph G, class PointMap>
void check_face_finite(face_descriptor_t<G> f, const G& g, const PointMap& pm, const char* who) {
  const auto h0 = halfedge(f, g);
  auto h = h0;
  do {
    if (!point(target(h, g), g, pm).allFinite()) {
      std::string id;
      if constexpr (HasIndexMap<G, face_index_t>) id = " " + std::to_string(get(get(face_index, g), f));
      throw invalid_input(std::string(who) + ": face" + id + " has a NaN or infinite coordinate");
    }
    h = next(h, g);
  } while (h != h0);
}

// Distances from the samples of a to the surface indexed by tree; samples
// visited in a spatially coherent order, each query bounded by the previous
// distance plus the step since (a valid upper bound on the new distance).
template <class G, class PointMap, class Tree>
Distance_result sample_distances(const G& a, const PointMap& pm, const Tree& tree,
                                 const Hausdorff_options& o) {
  if (tree.empty()) throw invalid_input("hausdorff_distance: the surface measured against is empty");
  // Triangles of a (fans from the lowest-index corner).
  struct Tri {
    Eigen::Vector3d p[3];
    double area;
  };
  std::vector<Tri> tris;
  double total = 0;
  for (const auto f : faces(a)) {
    check_face_finite(f, a, pm, "hausdorff_distance");
    const auto h0 = detail::geom::canonical_halfedge(f, a);
    const Eigen::Vector3d p0 = point(target(h0, a), a, pm);
    auto h = next(h0, a);
    Eigen::Vector3d pp = point(target(h, a), a, pm);
    for (h = next(h, a); h != h0; h = next(h, a)) {
      const Eigen::Vector3d pc = point(target(h, a), a, pm);
      const double ar = 0.5 * triangle_normal(p0, pp, pc).norm();
      tris.push_back({{p0, pp, pc}, ar});
      total += ar;
      pp = pc;
    }
  }
  if (tris.empty()) throw invalid_input("hausdorff_distance: the sampled surface is empty");
  std::size_t n = o.samples;
  if (n == 0 && o.samples_per_area > 0) n = static_cast<std::size_t>(std::ceil(o.samples_per_area * total));
  if (n == 0 && o.samples_per_area <= 0) n = std::max<std::size_t>(10 * tris.size(), 100'000);

  Distance_result r;
  double sum = 0, sum2 = 0;
  Eigen::Vector3d prev_q(0, 0, 0);
  double prev_d = std::numeric_limits<double>::infinity();
  auto measure = [&](const Eigen::Vector3d& q) {
    double bound = std::numeric_limits<double>::infinity();
    if (std::isfinite(prev_d)) {
      const double b = prev_d + (q - prev_q).norm();
      bound = b * b * (1 + 1e-9) + 1e-300;
    }
    auto c = tree.closest_point(q, bound);
    if (!(c.squared_distance < bound)) c = tree.closest_point(q);
    const double d = std::sqrt(c.squared_distance);
    prev_q = q;
    prev_d = d;
    r.max = std::max(r.max, d);
    sum += d;
    sum2 += d * d;
    ++r.samples;
  };

  std::mt19937_64 rng(o.seed);
  const std::size_t report_every = 1 << 16;
  std::size_t done = 0;
  for (const Tri& t : tris) {
    const double want = total > 0 ? static_cast<double>(n) * t.area / total : 0.0;
    std::size_t k = static_cast<std::size_t>(want);
    if (uniform01(rng) < want - static_cast<double>(k)) ++k;
    for (std::size_t i = 0; i < k; ++i) {
      const double s = std::sqrt(uniform01(rng)), u = uniform01(rng);
      measure((1 - s) * t.p[0] + s * (1 - u) * t.p[1] + s * u * t.p[2]);
      if (o.progress && ++done % report_every == 0) o.progress(done, n);
    }
  }
  if (o.vertices)
    for (const auto v : vertices(a))
      if (halfedge(v, a) != boost::graph_traits<G>::null_halfedge()) measure(point(v, a, pm));
  if (o.edge_midpoints)
    for (const auto e : edges(a)) {
      const auto h = halfedge(e, a);
      measure(0.5 * (point(source(h, a), a, pm) + point(target(h, a), a, pm)));
    }
  if (o.progress) o.progress(n, n);
  r.mean = sum / static_cast<double>(r.samples);
  r.rms = std::sqrt(sum2 / static_cast<double>(r.samples));
  return r;
}

} // namespace detail::measures

/// one_sided_hausdorff(a, b, options): distances from samples of a to b (see
/// the header comment). Throws invalid_input if a or b has no face or a
/// coordinate is not finite.
inline constexpr struct One_sided_hausdorff_fn {
  template <FaceListGraph A, FaceListGraph B>
    requires EdgeListGraph<A> && VertexListGraph<A>
  Distance_result operator()(const A& a, const B& b, const Hausdorff_options& o = {}) const {
    const Aabb_tree<B> tree(b);
    if (tree.skipped_faces())
      throw invalid_input("hausdorff_distance: a face of the second surface has a NaN or infinite coordinate");
    return detail::measures::sample_distances(a, get(vertex_point, a), tree, o);
  }
} one_sided_hausdorff{};

/// hausdorff_distance(a, b, options): both ways (see the header comment).
inline constexpr struct Hausdorff_distance_fn {
  template <FaceListGraph A, FaceListGraph B>
    requires EdgeListGraph<A> && VertexListGraph<A> && EdgeListGraph<B> && VertexListGraph<B>
  Hausdorff_result operator()(const A& a, const B& b, const Hausdorff_options& o = {}) const {
    Hausdorff_result r;
    r.a_to_b = one_sided_hausdorff(a, b, o);
    Hausdorff_options ob = o;
    ob.seed = o.seed + 1;
    r.b_to_a = one_sided_hausdorff(b, a, ob);
    r.hausdorff = std::max(r.a_to_b.max, r.b_to_a.max);
    r.mean = std::max(r.a_to_b.mean, r.b_to_a.mean);
    r.rms = std::max(r.a_to_b.rms, r.b_to_a.rms);
    return r;
  }
} hausdorff_distance{};

namespace detail::measures {

// Runs the self-intersection test over g's faces; calls report(f, g) for
// every intersecting pair (f, f for a degenerate face); stops when report
// returns false.
template <FaceListGraph G, class Report>
void for_each_self_intersection(const G& g, Report&& report) {
  using Face = face_descriptor_t<G>;
  using Vertex = vertex_descriptor_t<G>;
  const auto pm = get(vertex_point, g);
  for (const auto f : faces(g)) {
    if (degree(f, g) != 3) {
      std::string id;
      if constexpr (HasIndexMap<G, face_index_t>) id = " " + std::to_string(get(get(face_index, g), f));
      throw invalid_input("self_intersections: face" + id + " is not a triangle (triangulate first)");
    }
    check_face_finite(f, g, pm, "self_intersections");
  }
  const Aabb_tree<G> tree(g, pm);
  const std::size_t n = tree.triangle_count();
  std::vector<char> degenerate(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = tree.triangle_points(i);
    degenerate[i] = collinear(p[0], p[1], p[2]);
  }
  // Degenerate faces first, in face order (as CGAL reports them first).
  std::vector<Face> degenerate_faces;
  for (std::size_t i = 0; i < n; ++i)
    if (degenerate[i]) degenerate_faces.push_back(tree.triangle_face(i));
  std::sort(degenerate_faces.begin(), degenerate_faces.end());
  for (const Face f : degenerate_faces)
    if (!report(f, f)) return;
  tree.for_each_overlapping_pair([&](std::size_t i, std::size_t j) {
    if (degenerate[i] || degenerate[j]) return true;
    const Mesh_triangle<Vertex> ti{tree.triangle_points(i), tree.triangle_corners(i)};
    const Mesh_triangle<Vertex> tj{tree.triangle_points(j), tree.triangle_corners(j)};
    return !faces_intersect(ti, tj) || report(tree.triangle_face(i), tree.triangle_face(j));
  });
}

} // namespace detail::measures

/// self_intersections(g): the pairs of faces of the triangle mesh g that
/// intersect (see the header comment), each pair (f, h) with f <= h, sorted.
/// Throws invalid_input on a non-triangle face or a non-finite coordinate.
inline constexpr struct Self_intersections_fn {
  template <FaceListGraph G>
  std::vector<std::pair<face_descriptor_t<G>, face_descriptor_t<G>>> operator()(const G& g) const {
    std::vector<std::pair<face_descriptor_t<G>, face_descriptor_t<G>>> out;
    detail::measures::for_each_self_intersection(g, [&](auto f, auto h) {
      out.emplace_back(std::min(f, h), std::max(f, h));
      return true;
    });
    std::sort(out.begin(), out.end());
    return out;
  }
} self_intersections{};

/// does_self_intersect(g): whether self_intersections(g) is not empty
/// (stops at the first pair found).
inline constexpr struct Does_self_intersect_fn {
  template <FaceListGraph G>
  bool operator()(const G& g) const {
    bool found = false;
    detail::measures::for_each_self_intersection(g, [&](auto, auto) {
      found = true;
      return false;
    });
    return found;
  }
} does_self_intersect{};

/// Options of triangle_quality().
struct Quality_options {
  /// The edge length the mesh aims at (a remeshing target); 0: none, the
  /// relative edge-length numbers are then relative to the mean.
  double target_edge_length = 0;
};

/// What triangle_quality() reports. Angles in degrees.
struct Triangle_quality {
  std::size_t vertices = 0, faces = 0, edges = 0, border_edges = 0;
  std::size_t triangles = 0;          ///< faces of degree 3
  std::size_t degenerate_faces = 0;   ///< faces of zero area
  double min_angle = NAN, max_angle = NAN, mean_angle = NAN;  ///< over every corner of every face
  double angles_below_30 = NAN;       ///< share of corners with an angle below 30°
  /// Aspect ratio of the non-degenerate triangles: circumradius / (2 ·
  /// inradius), 1 for the equilateral triangle, growing without bound.
  double min_aspect_ratio = NAN, max_aspect_ratio = NAN, mean_aspect_ratio = NAN;
  std::vector<std::size_t> valence_histogram;  ///< [k] = vertices with k edges
  std::size_t interior_vertices = 0, border_vertices = 0;
  double valence6_share = NAN;        ///< interior vertices of valence 6 / interior vertices
  double border_valence4_share = NAN; ///< border vertices of valence 4 / border vertices
  double edge_length_min = NAN, edge_length_max = NAN;
  double edge_length_mean = NAN, edge_length_deviation = NAN;  ///< standard deviation
  double reference_edge_length = NAN; ///< the target, or the mean without one
  double relative_edge_length_mean = NAN;       ///< mean / reference
  double relative_edge_length_deviation = NAN;  ///< deviation / reference
};

/// triangle_quality(g, options): see Triangle_quality. Works on any
/// polygon mesh (aspect ratios only over its triangles).
inline constexpr struct Triangle_quality_fn {
  template <class G>
    requires FaceListGraph<G> && EdgeListGraph<G> && VertexListGraph<G>
  Triangle_quality operator()(const G& g, const Quality_options& o = {}) const {
    const auto pm = get(vertex_point, g);
    Triangle_quality q;
    const double deg = 180.0 / std::numbers::pi;
    double angle_sum = 0, aspect_sum = 0;
    std::size_t corners = 0, below30 = 0, aspects = 0;
    double amin = INFINITY, amax = -INFINITY, rmin = INFINITY, rmax = -INFINITY;
    for (const auto f : faces(g)) {
      ++q.faces;
      const auto h0 = halfedge(f, g);
      auto h = h0;
      do {
        const double a = corner_angle(h, g, pm) * deg;
        amin = std::min(amin, a), amax = std::max(amax, a);
        angle_sum += a;
        below30 += a < 30.0;
        ++corners;
        h = next(h, g);
      } while (h != h0);
      if (face_area(f, g, pm) == 0) ++q.degenerate_faces;
      if (degree(f, g) == 3) {
        ++q.triangles;
        const Eigen::Vector3d a = point(target(h0, g), g, pm), b = point(target(next(h0, g), g), g, pm),
                              c = point(source(h0, g), g, pm);
        const double ratio = triangle_aspect_ratio(a, b, c);
        if (std::isfinite(ratio)) {
          rmin = std::min(rmin, ratio), rmax = std::max(rmax, ratio);
          aspect_sum += ratio;
          ++aspects;
        }
      }
    }
    if (corners) {
      q.min_angle = amin, q.max_angle = amax, q.mean_angle = angle_sum / corners;
      q.angles_below_30 = static_cast<double>(below30) / corners;
    }
    if (aspects) q.min_aspect_ratio = rmin, q.max_aspect_ratio = rmax, q.mean_aspect_ratio = aspect_sum / aspects;

    std::size_t v6 = 0, b4 = 0;
    for (const auto v : vertices(g)) {
      ++q.vertices;
      std::size_t valence = 0;
      bool border = false;
      const auto h0 = halfedge(v, g);
      if (h0 != boost::graph_traits<G>::null_halfedge()) {
        auto h = h0;
        do {
          ++valence;
          if (face(h, g) == boost::graph_traits<G>::null_face()) border = true;
          h = opposite(next(h, g), g);
        } while (h != h0);
      }
      if (q.valence_histogram.size() <= valence) q.valence_histogram.resize(valence + 1);
      ++q.valence_histogram[valence];
      if (border) ++q.border_vertices, b4 += valence == 4;
      else ++q.interior_vertices, v6 += valence == 6;
    }
    if (q.interior_vertices) q.valence6_share = static_cast<double>(v6) / q.interior_vertices;
    if (q.border_vertices) q.border_valence4_share = static_cast<double>(b4) / q.border_vertices;

    double lsum = 0, lsum2 = 0, lmin = INFINITY, lmax = -INFINITY;
    for (const auto e : edges(g)) {
      ++q.edges;
      const auto h = halfedge(e, g);
      if (face(h, g) == boost::graph_traits<G>::null_face() ||
          face(opposite(h, g), g) == boost::graph_traits<G>::null_face())
        ++q.border_edges;
      const double l = edge_length(h, g, pm);
      lsum += l, lsum2 += l * l;
      lmin = std::min(lmin, l), lmax = std::max(lmax, l);
    }
    if (q.edges) {
      const double n = static_cast<double>(q.edges);
      q.edge_length_min = lmin, q.edge_length_max = lmax;
      q.edge_length_mean = lsum / n;
      q.edge_length_deviation = std::sqrt(std::max(0.0, lsum2 / n - q.edge_length_mean * q.edge_length_mean));
      q.reference_edge_length = o.target_edge_length > 0 ? o.target_edge_length : q.edge_length_mean;
      q.relative_edge_length_mean = q.edge_length_mean / q.reference_edge_length;
      q.relative_edge_length_deviation = q.edge_length_deviation / q.reference_edge_length;
    }
    return q;
  }
} triangle_quality{};

} // namespace genmesh
