// genmesh/simplification/attribute_quadrics.h — the quadric policy of
// genmesh::simplify that respects per-vertex attributes (colours, texture
// coordinates, normals, ...).
//
// Garland & Heckbert, "Simplifying surfaces with color and texture using
// quadric error metrics" (IEEE Visualization 1998): each vertex is a point of
// R^(3+k), its position followed by its k attribute values, each times its
// weight; a triangle contributes the squared distance to its plane in that
// space (the 2-plane through its three lifted corners). A collapse goes to
// the point of R^(3+k) minimizing the summed quadric: a position and the
// attribute values of the survivor, which simplify() writes back into the
// attributes' property maps. So an edge across a colour or UV seam costs
// what the seam would lose, and the survivor gets the values that fit its
// neighbourhood best.
// (Hoppe's 1999 metric is a variant of this one with a smaller matrix; the
// minimizer is the same for k ≤ 3 up to the weighting of the geometric term.)
//
// The attributes are vertex property maps, each with a weight (any number of
// them, of any value type genmesh::Attribute_traits knows: a number, an
// Eigen vector, std::array, std::vector, a point type):
//
//   auto colour = genmesh::scratch_property<Eigen::Vector3d>(genmesh::vertex_index, mesh);  // or the user's map
//   auto uv = ...;                                                         // a map of std::array<double, 2>
//   genmesh::simplify(mesh, genmesh::Simplification_options<genmesh::Attribute_quadrics<Mesh>>{
//       .target_ratio = 0.1,
//       .policy = {.attributes = {genmesh::vertex_attribute(colour, 0.1), genmesh::vertex_attribute(uv, 1.0)}}});
//
// Attribute_quadrics<G, N> with N ≥ 3 + the number of values stores the
// quadrics inline (no allocation per evaluation) and gives the same results
// to the bit as the heap-stored default Attribute_quadrics<G>.
//
// Before the first collapse every vertex's values are read; after each
// collapse the survivor's optimal values are written back into each writable
// map (the removed vertex's entries are left as they were). The cost is the
// squared distance in R^(3+k): geometric distance squared plus (weight ×
// attribute deviation) squared, so a weight says how many model units one
// unit of the attribute is worth. With no attributes this is Plane_quadrics
// without its fallback to the segment's minimizer. Deterministic across
// backends as the other policies (values read by vertex index, corners in
// canonical order, sums in face order): the same maps' contents give the
// same mesh and the same values on every backend.
#pragma once

#include <genmesh/attribute_traits.h>
#include <genmesh/concepts.h>
#include <genmesh/exceptions.h>
#include <genmesh/geometry.h>
#include <genmesh/property_maps.h>
#include <genmesh/simplification/quadric.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

/// A quadric over R^n: Q(v) = vᵀAv + 2bᵀv + c, A symmetric n × n. The
/// default (n = 0) is the zero quadric of any dimension. MaxDimension bounds
/// n at compile time: the matrices are then stored inline (no allocation);
/// Eigen::Dynamic (Generalized_quadric) stores them on the heap. The same
/// Eigen code runs on both, with the same results (tested).
template <int MaxDimension = Eigen::Dynamic>
struct Basic_generalized_quadric {
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, MaxDimension, MaxDimension>;
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, MaxDimension, 1>;
  Matrix a;
  Vector b;
  double c = 0;

  Eigen::Index dimension() const { return b.size(); }

  friend Basic_generalized_quadric operator+(const Basic_generalized_quadric& x, const Basic_generalized_quadric& y) {
    if (x.dimension() == 0) return y;
    if (y.dimension() == 0) return x;
    return {x.a + y.a, x.b + y.b, x.c + y.c};
  }

  /// Q(v), clamped at 0.
  double operator()(const Vector& v) const {
    if (dimension() == 0) return 0.0;
    const double r = v.dot(a * v) + 2 * b.dot(v) + c;
    return r > 0 ? r : 0.0;
  }

  /// The quadric of the 2-plane through p, q, r in R^n (Garland & Heckbert
  /// 1998, with orthonormal e₁, e₂ spanning it), times w; zero when they are
  /// collinear.
  static Basic_generalized_quadric plane_through(const Vector& p, const Vector& q, const Vector& r, double w) {
    const Eigen::Index n = p.size();
    Basic_generalized_quadric g{Matrix::Zero(n, n), Vector::Zero(n), 0.0};
    Vector e1 = q - p;
    const double l1 = e1.norm();
    if (!(l1 > 0)) return g;
    e1 /= l1;
    Vector e2 = r - p;
    e2 -= e1.dot(e2) * e1;
    const double l2 = e2.norm();
    if (!(l2 > 0)) return g;
    e2 /= l2;
    const double p1 = p.dot(e1), p2 = p.dot(e2);
    g.a = w * (Matrix::Identity(n, n) - e1 * e1.transpose() - e2 * e2.transpose());
    g.b = w * (p1 * e1 + p2 * e2 - p);
    g.c = w * (p.squaredNorm() - p1 * p1 - p2 * p2);
    return g;
  }
};

/// The quadric of Attribute_quadrics<G> (heap-stored, any dimension).
using Generalized_quadric = Basic_generalized_quadric<>;

/// One attribute of Attribute_quadrics: how to read (and write back) a
/// vertex's values, and their weight. Made by vertex_attribute(map, weight).
template <class Vertex>
struct Vertex_attribute {
  /// Names the attribute in error messages.
  std::string name = "attribute";
  /// Model units per unit of each value (> 0, finite).
  double weight = 1.0;
  /// Replaces `out` with the vertex's values.
  std::function<void(const Vertex&, std::vector<double>& out)> read = {};
  /// Stores `n` values as the vertex's (empty: the map is read-only, nothing
  /// is written back).
  std::function<void(const Vertex&, const double* values, std::size_t n)> write = {};
};

/// An attribute of Attribute_quadrics from a vertex property map: keyed by
/// vertex descriptor, its value an Attribute_value (<genmesh/attribute_traits.h>:
/// a number, an Eigen vector, std::array, std::vector, a point type). A
/// writable map receives each survivor's optimal values; a read-only one is
/// only read. The map is copied (property maps are handles).
template <class Map>
  requires Attribute_value<typename boost::property_traits<Map>::value_type>
Vertex_attribute<typename boost::property_traits<Map>::key_type> vertex_attribute(Map map, double weight = 1.0,
                                                                                  std::string name = "attribute") {
  using Key = typename boost::property_traits<Map>::key_type;
  using T = typename boost::property_traits<Map>::value_type;
  using Traits = Attribute_traits<T>;
  Vertex_attribute<Key> a{std::move(name), weight, {}, {}};
  a.read = [map](const Key& v, std::vector<double>& out) {
    const T& x = get(map, v);
    out.resize(Traits::width(x));
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = Traits::get(x, i);
  };
  if constexpr (std::is_convertible_v<typename boost::property_traits<Map>::category,
                                      boost::writable_property_map_tag>) {
    a.write = [map, label = a.name](const Key& v, const double* values, std::size_t n) {
      T x = get(map, v);
      if (!Traits::assign(x, values, n))
        throw invalid_input("simplify: attribute '" + label + "' cannot hold " + std::to_string(n) + " values");
      put(map, v, x);
    };
  }
  return a;
}

namespace detail::simplification {
// What Attribute_quadrics::start() reads from the mesh.
template <class Vertex>
struct Attribute_state {
  std::size_t dimension = 0;            // values per vertex, all attributes
  std::vector<double> weight;           // per value
  std::vector<std::size_t> offset;      // per attribute, then the dimension
  std::vector<double> values;           // weighted values, by vertex index × dimension
  std::vector<Vertex> vertex;           // by vertex index
};
} // namespace detail::simplification

/// Garland–Heckbert 1998 quadrics over position and the values of
/// `attributes` (vertex property maps with weights: see the top of this
/// header). simplify() reads every vertex's values before the first collapse
/// and writes the survivor's optimal values into each writable map after
/// every collapse. G is the mesh type (the maps are keyed by its vertex
/// descriptor).
///
/// MaxDimension (Eigen::Dynamic by default): with a number N ≥ 3 + the total
/// number of attribute values (a colour: 6; colour and texture coordinates:
/// 8), the per-vertex quadrics and every evaluation's matrices are stored
/// inline — no allocation per evaluation, and the same results to the bit as
/// with Eigen::Dynamic; start() refuses attributes that do not fit.
template <class G, int MaxDimension = Eigen::Dynamic>
struct Attribute_quadrics {
  using Vertex = vertex_descriptor_t<G>;
  /// The attributes, each a map and a weight: vertex_attribute(map, weight).
  std::vector<Vertex_attribute<Vertex>> attributes = {};
  /// Weight each triangle's quadric by its area (in R^3).
  bool area_weighted = false;
  /// The optimal point is refused (the best of the ends and the midpoint
  /// taken instead) when A's LU pivots fall below this times the largest.
  double conditioning = 1e-9;
  /// The optimal position may be at most this many edge lengths from the midpoint.
  double max_distance_factor = 2.0;
  /// Filled by start() (simplify calls it): leave it alone.
  detail::simplification::Attribute_state<Vertex> state = {};

  /// The per-vertex quadric (inline storage when MaxDimension is a number).
  using Vertex_data = Basic_generalized_quadric<MaxDimension>;

  /// Values per vertex, all attributes together (known after start()).
  std::size_t dimension() const { return state.dimension; }

  /// Reads every vertex's values (simplify calls it once, before face()).
  /// Throws genmesh::invalid_input naming the attribute and the vertex on a
  /// weight that is not positive and finite, a non-finite value, an empty
  /// value, or a vertex whose value has another width than the first vertex's.
  void start(const G& g) {
    auto& s = state;
    s = {};
    const auto vindex = get(vertex_index, g);
    const std::size_t vb = index_bound(vertex_index, g);
    s.vertex.resize(vb);
    std::vector<std::size_t> live;
    for (const Vertex v : vertices(g)) {
      const auto i = static_cast<std::size_t>(get(vindex, v));
      s.vertex[i] = v;
      live.push_back(i);
    }
    std::vector<double> x;
    std::vector<std::size_t> width(attributes.size(), 0);
    for (std::size_t k = 0; k < attributes.size(); ++k) {
      const auto& a = attributes[k];
      if (!(a.weight > 0) || !std::isfinite(a.weight))
        throw invalid_input("simplify: attribute '" + a.name + "' has weight " + std::to_string(a.weight) +
                            " (a positive finite number is needed)");
      if (!a.read) throw invalid_input("simplify: attribute '" + a.name + "' has no read function");
      if (live.empty()) continue;
      a.read(s.vertex[live.front()], x);
      if (x.empty())
        throw invalid_input("simplify: attribute '" + a.name + "' has no values at vertex " +
                            std::to_string(live.front()));
      width[k] = x.size();
    }
    s.offset.push_back(0);
    for (std::size_t k = 0; k < attributes.size(); ++k) {
      s.offset.push_back(s.offset.back() + width[k]);
      s.weight.insert(s.weight.end(), width[k], attributes[k].weight);
    }
    s.dimension = s.offset.back();
    if (MaxDimension != Eigen::Dynamic && 3 + s.dimension > static_cast<std::size_t>(MaxDimension))
      throw invalid_input("simplify: the attributes have " + std::to_string(s.dimension) +
                          " values per vertex; Attribute_quadrics<G, " + std::to_string(MaxDimension) +
                          "> holds at most " + std::to_string(MaxDimension - 3) +
                          " (use a larger bound or Eigen::Dynamic)");
    s.values.assign(vb * s.dimension, 0.0);
    for (std::size_t k = 0; k < attributes.size(); ++k) {
      const auto& a = attributes[k];
      for (const std::size_t i : live) {
        a.read(s.vertex[i], x);
        if (x.size() != width[k])
          throw invalid_input("simplify: attribute '" + a.name + "' has " + std::to_string(x.size()) +
                              " values at vertex " + std::to_string(i) + " but " + std::to_string(width[k]) +
                              " at vertex " + std::to_string(live.front()));
        for (std::size_t j = 0; j < x.size(); ++j) {
          if (!std::isfinite(x[j]))
            throw invalid_input("simplify: attribute '" + a.name + "' has a non-finite value at vertex " +
                                std::to_string(i));
          s.values[i * s.dimension + s.offset[k] + j] = a.weight * x[j];
        }
      }
    }
  }

  /// A triangle's contribution (corners with their vertex indices, so that
  /// the attributes can be read).
  Vertex_data face(std::size_t ia, const Eigen::Vector3d& a, std::size_t ib, const Eigen::Vector3d& b, std::size_t ic,
               const Eigen::Vector3d& c) const {
    const double w = area_weighted ? 0.5 * triangle_normal(a, b, c).norm() : 1.0;
    return Vertex_data::plane_through(lift(ia, a), lift(ib, b), lift(ic, c), w);
  }

  /// The border quadric of Plane_quadrics, on the geometric coordinates.
  Vertex_data border(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double weight) const {
    const Quadric q = detail::simplification::border_plane(a, b, c, weight, area_weighted);
    const Eigen::Index n = 3 + static_cast<Eigen::Index>(dimension());
    Vertex_data g{Vertex_data::Matrix::Zero(n, n), Vertex_data::Vector::Zero(n), q.c};
    g.a.template topLeftCorner<3, 3>() << q.a00, q.a01, q.a02, q.a01, q.a11, q.a12, q.a02, q.a12, q.a22;
    g.b.template head<3>() << q.b0, q.b1, q.b2;
    return g;
  }

  Placement place(const Vertex_data& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    if (q.dimension() == 0) return {0.0, 0.5 * (a + b)};
    Eigen::FullPivLU<typename Vertex_data::Matrix> lu(q.a);
    lu.setThreshold(conditioning);
    if (lu.isInvertible()) {
      const typename Vertex_data::Vector v = lu.solve(-q.b);
      const Eigen::Vector3d x = v.template head<3>();
      const double limit = max_distance_factor * max_distance_factor * (b - a).squaredNorm();
      if (v.allFinite() && (x - 0.5 * (a + b)).squaredNorm() <= limit) return {q(v), x};
    }
    Placement r = fixed(q, a, b, a);
    const Placement pb = fixed(q, a, b, b);
    if (pb.cost < r.cost) r = pb;
    const Placement pm = fixed(q, a, b, 0.5 * (a + b));
    if (pm.cost < r.cost) r = pm;
    return r;
  }

  /// The cost at position x with the best attribute values there.
  Placement fixed(const Vertex_data& q, const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d& x) const {
    if (q.dimension() == 0) return {0.0, x};
    return {q(best_at(q, x)), x};
  }

  /// After a collapse: the survivor's values, the minimizer at its position,
  /// written to each writable map.
  void collapsed(std::size_t survivor, const Vertex_data& q, const Eigen::Vector3d& x) const {
    if (dimension() == 0 || q.dimension() == 0) return;
    const typename Vertex_data::Vector v = best_at(q, x);
    std::vector<double> values;
    for (std::size_t k = 0; k < attributes.size(); ++k) {
      if (!attributes[k].write) continue;
      const std::size_t o = state.offset[k], n = state.offset[k + 1] - o;
      values.resize(n);
      for (std::size_t i = 0; i < n; ++i) values[i] = v[3 + static_cast<Eigen::Index>(o + i)] / state.weight[o + i];
      attributes[k].write(state.vertex[survivor], values.data(), n);
    }
  }

 private:
  // (x, weight · values of vertex v).
  typename Vertex_data::Vector lift(std::size_t v, const Eigen::Vector3d& x) const {
    const std::size_t k = dimension();
    typename Vertex_data::Vector r(3 + static_cast<Eigen::Index>(k));
    r.template head<3>() = x;
    for (std::size_t i = 0; i < k; ++i) r[3 + static_cast<Eigen::Index>(i)] = state.values[v * k + i];
    return r;
  }

  // (x, s) with s minimizing Q(x, ·): A_ss s = −(A_sx x + b_s). A_ss is
  // positive semi-definite; a tiny multiple of its trace on the diagonal
  // makes it definite where a vertex's faces do not constrain a value.
  static typename Vertex_data::Vector best_at(const Vertex_data& q, const Eigen::Vector3d& x) {
    const Eigen::Index n = q.dimension(), k = n - 3;
    typename Vertex_data::Vector v(n);
    v.template head<3>() = x;
    if (k == 0) return v;
    typename Vertex_data::Matrix ass = q.a.bottomRightCorner(k, k);
    const double tiny = 1e-12 * std::max(ass.trace(), std::numeric_limits<double>::min());
    ass.diagonal().array() += tiny;
    const typename Vertex_data::Vector rhs = -(q.a.bottomLeftCorner(k, 3) * x + q.b.tail(k));
    v.tail(k) = ass.ldlt().solve(rhs);
    return v;
  }
};

} // namespace genmesh
