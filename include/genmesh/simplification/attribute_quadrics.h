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
// Hoppe_quadrics (below) is Hoppe's 1999 metric over the same attributes:
// plain plane distance plus each value's deviation from its face's linear
// interpolation, with a smaller quadric and a 3 × 3 solve.
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

// Reads every live vertex's values of `attributes` into `s` (weighted),
// checking weights, widths and finiteness. max_values < 0: no bound; else
// more values per vertex than that are refused, naming the policy type
// `bound_name` in the message.
template <class G, class Vertex>
void read_attributes(const std::vector<Vertex_attribute<Vertex>>& attributes, const G& g, Attribute_state<Vertex>& s,
                     int max_values, const std::string& bound_name) {
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
  if (max_values >= 0 && s.dimension > static_cast<std::size_t>(max_values))
    throw invalid_input("simplify: the attributes have " + std::to_string(s.dimension) + " values per vertex; " +
                        bound_name + " holds at most " + std::to_string(max_values) +
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

// Writes the survivor's weighted values (s.dimension of them at `weighted`),
// unweighted, into each writable attribute's map.
template <class Vertex>
void write_attributes(const std::vector<Vertex_attribute<Vertex>>& attributes, const Attribute_state<Vertex>& s,
                      std::size_t survivor, const double* weighted) {
  std::vector<double> values;
  for (std::size_t k = 0; k < attributes.size(); ++k) {
    if (!attributes[k].write) continue;
    const std::size_t o = s.offset[k], n = s.offset[k + 1] - o;
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = weighted[o + i] / s.weight[o + i];
    attributes[k].write(s.vertex[survivor], values.data(), n);
  }
}
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
    detail::simplification::read_attributes(attributes, g, state, MaxDimension == Eigen::Dynamic ? -1 : MaxDimension - 3,
                                            "Attribute_quadrics<G, " + std::to_string(MaxDimension) + ">");
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
    return detail::simplification::best_of_ends_and_midpoint(
        [&](const Eigen::Vector3d& x) { return fixed(q, a, b, x); }, a, b);
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
    detail::simplification::write_attributes(attributes, state, survivor, v.data() + 3);
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

/// Hoppe's quadric over position x ∈ R^3 and k weighted attribute values
/// s ∈ R^k ("New quadric metric for simplifying meshes with appearance
/// attributes", IEEE Visualization 1999): Q(x, s) = xᵀAx + 2xᵀPs + α sᵀs +
/// 2bₓᵀx + 2bₛᵀs + c. Of the (3+k)² matrix of Garland–Heckbert 1998 it
/// keeps A (3 × 3), P (3 × k) and a multiple α of the identity: 11 + 4k
/// numbers instead of (3+k)(4+k)/2 + 4 (k = 3: 23 instead of 25; k = 8:
/// 43 instead of 71). MaxValues bounds k at compile time (inline storage).
template <int MaxValues = Eigen::Dynamic>
struct Basic_hoppe_quadric {
  using Values = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, MaxValues, 1>;
  using Gradients = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, MaxValues>;
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Gradients p;                                 // x–s coupling, 3 × k
  Eigen::Vector3d bx = Eigen::Vector3d::Zero();
  Values bs;                                   // k
  double alpha = 0, c = 0;
  bool empty = true;                           // the zero quadric of any k

  friend Basic_hoppe_quadric operator+(const Basic_hoppe_quadric& x, const Basic_hoppe_quadric& y) {
    if (x.empty) return y;
    if (y.empty) return x;
    return {x.a + y.a, x.p + y.p, x.bx + y.bx, x.bs + y.bs, x.alpha + y.alpha, x.c + y.c, false};
  }

  /// Q(x, s), clamped at 0.
  double operator()(const Eigen::Vector3d& x, const Values& s) const {
    if (empty) return 0.0;
    const double r = x.dot(a * x) + 2 * x.dot(p * s) + alpha * s.squaredNorm() + 2 * bx.dot(x) + 2 * bs.dot(s) + c;
    return r > 0 ? r : 0.0;
  }

  /// The values minimizing Q(x, ·): s = −(Pᵀx + bₛ)/α (zero when no face
  /// constrains them, α = 0).
  Values best_values(const Eigen::Vector3d& x) const {
    if (!(alpha > 0)) return Values::Zero(bs.size());
    return -(p.transpose() * x + bs) / alpha;
  }
};

/// The quadric of Hoppe_quadrics<G> (heap-stored, any number of values).
using Hoppe_quadric = Basic_hoppe_quadric<>;

/// Hoppe 1999 quadrics over position and the values of `attributes` (vertex
/// property maps with weights, as Attribute_quadrics): a face contributes
/// the squared distance of a point to its plane plus, for each value, the
/// squared difference between the value and the face's linear interpolation
/// of its corners' values at that point (a gradient in the face's plane).
/// Against Attribute_quadrics (Garland–Heckbert 1998) the geometric error is
/// the plain distance to the face's plane whatever the attributes' weights
/// (the 1998 metric measures distance in R^(3+k), so a heavily weighted
/// attribute tilts the geometry), the quadric is smaller (see
/// Basic_hoppe_quadric), and the optimal point needs only a 3 × 3 solve
/// (the values follow from the position). Same interface, same guarantees
/// (determinism, values written back to writable maps).
///
/// MaxValues (Eigen::Dynamic by default): with a number k ≥ the total
/// number of attribute values, quadrics are stored inline, with the same
/// results to the bit; start() refuses attributes that do not fit.
template <class G, int MaxValues = Eigen::Dynamic>
struct Hoppe_quadrics {
  using Vertex = vertex_descriptor_t<G>;
  /// The attributes, each a map and a weight: vertex_attribute(map, weight).
  std::vector<Vertex_attribute<Vertex>> attributes = {};
  /// Weight each triangle's quadric by its area.
  bool area_weighted = false;
  /// The optimal point is refused (the best of the ends and the midpoint
  /// taken instead) when the 3 × 3 system's LU pivots fall below this times
  /// the largest.
  double conditioning = 1e-9;
  /// The optimal position may be at most this many edge lengths from the midpoint.
  double max_distance_factor = 2.0;
  /// Filled by start() (simplify calls it): leave it alone.
  detail::simplification::Attribute_state<Vertex> state = {};

  using Vertex_data = Basic_hoppe_quadric<MaxValues>;
  using Values = typename Vertex_data::Values;

  /// Values per vertex, all attributes together (known after start()).
  std::size_t dimension() const { return state.dimension; }

  /// Reads every vertex's values; refusals as Attribute_quadrics::start.
  void start(const G& g) {
    detail::simplification::read_attributes(attributes, g, state, MaxValues == Eigen::Dynamic ? -1 : MaxValues,
                                            "Hoppe_quadrics<G, " + std::to_string(MaxValues) + ">");
  }

  /// A triangle's contribution (corners with their vertex indices).
  Vertex_data face(std::size_t ia, const Eigen::Vector3d& a, std::size_t ib, const Eigen::Vector3d& b, std::size_t ic,
                   const Eigen::Vector3d& c) const {
    const auto k = static_cast<Eigen::Index>(dimension());
    Vertex_data q{Eigen::Matrix3d::Zero(), Vertex_data::Gradients::Zero(3, k), Eigen::Vector3d::Zero(),
                  Values::Zero(k), 0.0, 0.0, false};
    const Eigen::Vector3d n2 = triangle_normal(a, b, c);
    const double len = n2.norm();
    if (!(len > 0)) return q; // a degenerate face constrains nothing
    const Eigen::Vector3d n = n2 / len;
    const double w = area_weighted ? 0.5 * len : 1.0;
    const double d = -n.dot(a);
    q.a = w * n * n.transpose();
    q.bx = w * d * n;
    q.c = w * d * d;
    q.alpha = w;
    // Each value's gradient g in the face's plane and offset e: g·x + e
    // interpolates the corners' values, g·n = 0.
    Eigen::Matrix3d m;
    m.row(0) = (b - a).transpose();
    m.row(1) = (c - a).transpose();
    m.row(2) = n.transpose();
    const Eigen::Matrix3d inv = m.inverse();
    const double* va = &state.values[ia * dimension()];
    const double* vb = &state.values[ib * dimension()];
    const double* vc = &state.values[ic * dimension()];
    for (Eigen::Index j = 0; j < k; ++j) {
      const Eigen::Vector3d g = inv * Eigen::Vector3d(vb[j] - va[j], vc[j] - va[j], 0.0);
      const double e = va[j] - g.dot(a);
      q.a += w * g * g.transpose();
      q.p.col(j) = -w * g;
      q.bx += w * e * g;
      q.bs[j] = -w * e;
      q.c += w * e * e;
    }
    return q;
  }

  /// The border quadric of Plane_quadrics, on the position only.
  Vertex_data border(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double weight) const {
    const Quadric q = detail::simplification::border_plane(a, b, c, weight, area_weighted);
    const auto k = static_cast<Eigen::Index>(dimension());
    Vertex_data g{Eigen::Matrix3d::Zero(), Vertex_data::Gradients::Zero(3, k), Eigen::Vector3d(q.b0, q.b1, q.b2),
                  Values::Zero(k), 0.0, q.c, false};
    g.a << q.a00, q.a01, q.a02, q.a01, q.a11, q.a12, q.a02, q.a12, q.a22;
    return g;
  }

  /// The optimal position: (A − PPᵀ/α) x = −bₓ + P bₛ/α (the values
  /// eliminated), refused as Attribute_quadrics refuses its solution.
  Placement place(const Vertex_data& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    if (q.empty) return {0.0, 0.5 * (a + b)};
    Eigen::Matrix3d m = q.a;
    Eigen::Vector3d rhs = -q.bx;
    if (q.alpha > 0) {
      m -= q.p * q.p.transpose() / q.alpha;
      rhs += q.p * q.bs / q.alpha;
    }
    Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
    lu.setThreshold(conditioning);
    if (lu.isInvertible()) {
      const Eigen::Vector3d x = lu.solve(rhs);
      const double limit = max_distance_factor * max_distance_factor * (b - a).squaredNorm();
      if (x.allFinite() && (x - 0.5 * (a + b)).squaredNorm() <= limit) return {q(x, q.best_values(x)), x};
    }
    return detail::simplification::best_of_ends_and_midpoint(
        [&](const Eigen::Vector3d& x) { return fixed(q, a, b, x); }, a, b);
  }

  /// The cost at position x with the best values there.
  Placement fixed(const Vertex_data& q, const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d& x) const {
    if (q.empty) return {0.0, x};
    return {q(x, q.best_values(x)), x};
  }

  /// After a collapse: the survivor's best values at its position, written
  /// to each writable map.
  void collapsed(std::size_t survivor, const Vertex_data& q, const Eigen::Vector3d& x) const {
    if (dimension() == 0 || q.empty || !(q.alpha > 0)) return;
    const Values s = q.best_values(x);
    detail::simplification::write_attributes(attributes, state, survivor, s.data());
  }
};

} // namespace genmesh
