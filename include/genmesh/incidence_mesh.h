// genmesh/incidence_mesh.h — the sparse-incidence backend: Incidence_mesh<Point>.
//
// What it is: a polygon mesh stored as its two signed incidence matrices,
//   d0 (E × V): row e holds −1 at the edge's source and +1 at its target;
//   d1 (F × E): row f holds +1 at each edge f runs along, −1 at each edge it
//               runs against;
// plus the vertex positions. Both are Eigen sparse matrices, each kept twice
// (row-major and its transpose row-major) so that every query reads rows
// only. No next, prev, opposite or face array exists: a halfedge is
// (edge, side), h = 2e + side, side 0 running along the edge (source →
// target as in d0); opposite(h) = h ^ 1 and edge(h) = h / 2 are arithmetic,
// and next, prev, face, target, halfedge(v), halfedge(f) are derived from the
// matrices on each call, in O(local degree). The E-row matrices d0 and d1ᵀ
// keep row e at entries [2e, 2e + 2), and d1 row f at [4f, 4f + 4) (home
// slots, see detail::Incidence_rows) while every row fits, so target(),
// face() and next() read short rows without the outer index. Two derived helpers make the derivation cheap and are
// kept up to date by every edit: per halfedge a 16-bit turn record (where
// next(h) and prev(h) sit in its face's d1 row and their signs, and the
// slots of face(h) and target(h) in edge(h)'s d1ᵀ and d0 rows), so a query
// reads the column it needs and no value array, and next() does not search
// the face's row; per vertex the number of its edges with fewer than two
// faces, so halfedge(v) does not scan an interior vertex's edges.
//
// Guarantees:
// - It models HalfedgeGraph, HalfedgeListGraph, VertexListGraph,
//   EdgeListGraph, FaceGraph and FaceListGraph (checked by static_asserts at
//   the bottom), with genmesh's own index types as descriptors, so the
//   numbering semantics are Halfedge_mesh's: element allocation is
//   Halfedge_mesh's (= CGAL::Surface_mesh's): removal marks and pushes onto a
//   LIFO free list per element kind, adding reuses the most recently freed
//   index (recycling on), else appends; iteration by increasing index.
// - build_mesh(soup, g) (through genmesh_native_link_soup) and every local
//   operation (genmesh_native_<op> in <genmesh/detail/incidence/operations.h>)
//   create and remove elements in the same order, with the same edge
//   directions and returned descriptors, as on Halfedge_mesh: the same
//   operation sequence gives the same to_soup() and the same edge numbering.
// - In-place subdivision appends a whole level in one call
//   (genmesh_native_relink → relink(): every row written in one pass, the
//   elements numbered as the local operations would number them).
// - Local edits cost O(local degree) amortized: rows live in Eigen's
//   uncompressed storage with per-row slack; a row that outgrows its slot
//   moves to the end of the buffer with twice the room, and the buffer is
//   compacted when its abandoned slots exceed half of the live ones.
// - It holds non-manifold input: from_soup()/load_soup() accept fins (edges
//   in three or more faces), bow-tie vertices and inconsistently oriented
//   neighbours; manifold_report() lists them by the fans-and-fins rule, and
//   halfedge queries touching them throw genmesh::invalid_input naming the
//   element.
//
// Limits:
// - halfedge(v) and halfedge(f) are canonical, not remembered: halfedge(v)
//   is v's incoming border halfedge if it has one, else the incoming halfedge
//   of its lowest-numbered edge; halfedge(f) is f's side along its
//   lowest-numbered edge. Halfedge_mesh remembers whatever its last edit set, so generic
//   code that starts at halfedge(v) or halfedge(f) (bevel_vertex,
//   bevel_face, erase_vertex) numbers its new elements from another start.
// - Not a MutableHalfedgeGraph (no set_next): generic code that edits
//   pointers does not compile on it; the local operations are native.
// - A face must not visit a vertex twice (the loaders refuse such faces; the
//   native operations refuse where the generic ones would make one, and where
//   they would pinch a vertex into two border gaps: see
//   detail/incidence/operations.h).
// - next() reads h's turn record, one d1ᵀ column and one d1 column: O(1);
//   faces edited by the low-level calls below since the last
//   update_face_orders() fall back to scanning d0 rows (O(d) per next), and
//   faces of more than 16 sides to target(h)'s d0ᵀ row (O(degree(target))
//   per next, so a million-sided face walks in a million steps).
//   Measured (benchmarks/bench_incidence.cpp, table in docs/benchmarks.md):
//   next() 6–7× slower than Halfedge_mesh, face(opposite(h)) 3×, around a
//   face 8–9×, around a vertex 7–9× in cache and 10× on an 89k-triangle mesh
//   (four arrays per step against one record), local operations 8–16×; 140
//   bytes per triangle against 66.
// - Local operations need a manifold mesh; on a mesh loaded with
//   non-manifold elements they refuse (predicates false, operations empty).
// - collect_garbage() rebuilds all four matrices: O(mesh), not O(garbage).
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/elements/compaction.h>
#include <genmesh/detail/elements/mesh_functions.h>
#include <genmesh/detail/memory/huge_pages.h>
#include <genmesh/elements.h>
#include <genmesh/exceptions.h>
#include <genmesh/mesh_properties.h>
#include <genmesh/point_traits.h>
#include <genmesh/polygon_soup.h>
#include <genmesh/property_maps.h>
#include <genmesh/soup_to_mesh.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace genmesh {

namespace detail {

/// The rows of one signed sparse matrix, held in an
/// Eigen::SparseMatrix<signed char, RowMajor, int> in uncompressed mode.
/// Eigen reads row r as [outer[r], outer[r] + nnz[r]); this class owns the
/// rest of the layout: each row has a slot of cap[r] entries starting at
/// outer[r] (slots need not be in row order), entries of a row are sorted by
/// column (so the matrix is a valid Eigen matrix for reading: iteration,
/// products, coeff), a full row moves to the end of the buffer with doubled
/// room, the buffer grows by doubling, and abandoned slots are compacted
/// away once they exceed half of the live slots. Eigen's own insert() would shift
/// every later row, O(non-zeros), which is why it is not used.
///
/// Home slots: a store made with a home width K (the mesh uses K = 2 for its
/// E-row matrices d0 and d1ᵀ, whose rows hold an edge's two ends and, on a
/// manifold mesh, at most two faces) keeps row r at [K r, K r + K) for as
/// long as no row needs more than K entries, with the values past a row's
/// end zero. While homed() holds, a reader finds row r at K r without
/// reading the outer index or the non-zero count (home_cols(), home_vals()),
/// which saves two dependent loads per derived next(), face() or target();
/// cols() and vals() skip the outer index too. The first row to outgrow K
/// turns the store into the general layout above (fins of a non-manifold
/// load do so for d1ᵀ, a pentagon for d1); a copy or assign() homes the rows
/// again when they fit.
class Incidence_rows {
public:
  using Matrix = Eigen::SparseMatrix<signed char, Eigen::RowMajor, int>;

  Incidence_rows() { reset(); }
  /// A store with home slots of `home_width` entries, a power of two (see above).
  explicit Incidence_rows(int home_width) : home_(home_width), shift_(std::countr_zero(unsigned(home_width))) {
    if (home_width <= 0 || !std::has_single_bit(unsigned(home_width)))
      throw invalid_input("Incidence_rows: the home width must be a power of two");
    reset();
  }
  Incidence_rows(const Incidence_rows& o) : m_(o.m_), home_(o.home_), shift_(o.shift_) {
    relayout_after_copy();
  }
  // Eigen 3.4's SparseMatrix has no move constructor (a "move" would copy
  // into compressed form): swap instead.
  Incidence_rows(Incidence_rows&& o) noexcept
      : cap_(std::move(o.cap_)), tail_(o.tail_), garbage_(o.garbage_), home_(o.home_), shift_(o.shift_),
        homed_(o.homed_) {
    m_.swap(o.m_);
    o.reset();
  }
  Incidence_rows& operator=(const Incidence_rows& o) {
    if (this != &o) {
      m_ = o.m_;
      home_ = o.home_;
      shift_ = o.shift_;
      relayout_after_copy();
    }
    return *this;
  }
  Incidence_rows& operator=(Incidence_rows&& o) noexcept {
    if (this != &o) {
      m_.swap(o.m_);
      cap_.swap(o.cap_);
      std::swap(tail_, o.tail_);
      std::swap(garbage_, o.garbage_);
      std::swap(home_, o.home_);
      std::swap(shift_, o.shift_);
      std::swap(homed_, o.homed_);
      o.reset();
    }
    return *this;
  }
  ~Incidence_rows() = default;

  /// Back to no rows and an empty buffer (homed if the store has a home width).
  void reset() {
    m_ = Matrix(1, 1);
    m_.uncompress();
    m_.innerNonZeroPtr()[0] = 0;
    m_.outerIndexPtr()[0] = 0;
    cap_.assign(1, 0);
    tail_ = 0;
    garbage_ = 0;
    m_.data().resize(0);
    homed_ = false;
    if (home_ > 0) home_rows_(0);
  }

  /// Every row sits in its home slot (see above).
  [[nodiscard]] bool homed() const { return homed_; }
  /// The home width K (0: none).
  [[nodiscard]] int home_width() const { return home_; }
  /// Row r's columns and values at its home slot, K entries, the values past
  /// the row's end zero. Only while homed().
  [[nodiscard]] const int* home_cols(std::uint32_t r) const {
    return m_.innerIndexPtr() + (std::size_t(r) << shift_);
  }
  [[nodiscard]] const signed char* home_vals(std::uint32_t r) const {
    return m_.valuePtr() + (std::size_t(r) << shift_);
  }

  /// Room for rows [0, rows) and columns [0, cols) (doubling).
  void reserve_shape(std::size_t rows, std::size_t cols) {
    const auto r0 = static_cast<std::size_t>(m_.rows()), c0 = static_cast<std::size_t>(m_.cols());
    if (rows <= r0 && cols <= c0) return;
    const std::size_t r = rows <= r0 ? r0 : std::max(rows, 2 * r0);
    const std::size_t c = cols <= c0 ? c0 : std::max(cols, 2 * c0);
    m_.conservativeResize(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c));
    cap_.resize(r, 0);
    if (homed_ && r > r0) home_rows_(r0);
  }
  /// Room for `extra` more entries in the buffer.
  void reserve_entries(std::size_t entries) {
    if (static_cast<std::size_t>(m_.data().allocatedSize()) < entries) {
      const auto used = m_.data().size();
      m_.data().resize(static_cast<Eigen::Index>(entries));
      m_.data().resize(used);
    }
  }

  [[nodiscard]] int size(std::uint32_t r) const { return m_.innerNonZeroPtr()[r]; }
  /// Row r's first column and value (homed: at K r, no outer index read).
  [[nodiscard]] const int* cols(std::uint32_t r) const { return m_.innerIndexPtr() + start_(r); }
  [[nodiscard]] const signed char* vals(std::uint32_t r) const { return m_.valuePtr() + start_(r); }
  [[nodiscard]] std::span<const int> row_cols(std::uint32_t r) const {
    return {cols(r), static_cast<std::size_t>(size(r))};
  }

  /// The column of row r that holds `value` (never 0), -1 if none. Homed,
  /// the row's K home entries are scanned without reading its count (the
  /// values past its end are zero).
  [[nodiscard]] int column_of(std::uint32_t r, signed char value) const {
    const int n = homed_ ? home_ : size(r);
    const int* c = cols(r);
    const signed char* s = vals(r);
    for (int k = 0; k < n; ++k)
      if (s[k] == value) return c[k];
    return -1;
  }

  /// The value at (r, c), 0 if absent.
  [[nodiscard]] signed char at(std::uint32_t r, int c) const {
    const int n = size(r);
    const int* cs = cols(r);
    for (int k = 0; k < n; ++k)
      if (cs[k] == c) return vals(r)[k];
    return 0;
  }

  /// Makes sure row r has a slot of at least n entries (moves it if not).
  void ensure_room(std::uint32_t r, int n) {
    if (cap_[r] >= n) return;
    relocate(r, std::max(n, 2 * cap_[r]));
  }

  /// Sets (r, c) to v (inserted in column order if absent).
  void set(std::uint32_t r, int c, signed char v) {
    int n = size(r);
    int* cs = m_.innerIndexPtr() + m_.outerIndexPtr()[r];
    signed char* vs = m_.valuePtr() + m_.outerIndexPtr()[r];
    int k = 0;
    while (k < n && cs[k] < c) ++k;
    if (k < n && cs[k] == c) {
      vs[k] = v;
      return;
    }
    if (n == cap_[r]) {
      homed_ = false; // the general layout from here on
      relocate(r, std::max(2, 2 * n));
      cs = m_.innerIndexPtr() + m_.outerIndexPtr()[r];
      vs = m_.valuePtr() + m_.outerIndexPtr()[r];
    }
    for (int j = n; j > k; --j) {
      cs[j] = cs[j - 1];
      vs[j] = vs[j - 1];
    }
    cs[k] = c;
    vs[k] = v;
    m_.innerNonZeroPtr()[r] = n + 1;
  }
  /// Removes (r, c) if present.
  void erase(std::uint32_t r, int c) {
    const int n = size(r);
    int* cs = m_.innerIndexPtr() + m_.outerIndexPtr()[r];
    signed char* vs = m_.valuePtr() + m_.outerIndexPtr()[r];
    int k = 0;
    while (k < n && cs[k] != c) ++k;
    if (k == n) return;
    for (int j = k + 1; j < n; ++j) {
      cs[j - 1] = cs[j];
      vs[j - 1] = vs[j];
    }
    vs[n - 1] = 0; // past the row's end: zero (see home slots)
    m_.innerNonZeroPtr()[r] = n - 1;
  }
  void clear_row(std::uint32_t r) {
    std::fill_n(m_.valuePtr() + m_.outerIndexPtr()[r], size(r), static_cast<signed char>(0));
    m_.innerNonZeroPtr()[r] = 0;
  }

  /// Replaces the whole layout by rows given in compressed form (begin has
  /// rows + 1 offsets into cols/vals, each row sorted by column). Slots are
  /// exactly as large as the rows.
  void assign(std::size_t rows, std::size_t ncols, const std::vector<std::uint32_t>& begin,
              const std::vector<int>& cols, const std::vector<signed char>& vals) {
    reset();
    bool fits = home_ > 0;
    for (std::size_t r = 0; fits && r < rows; ++r) fits = begin[r + 1] - begin[r] <= std::uint32_t(home_);
    if (!fits) homed_ = false;
    reserve_shape(std::max<std::size_t>(rows, 1), std::max<std::size_t>(ncols, 1));
    if (homed_) {
      for (std::size_t r = 0; r < rows; ++r) {
        const std::size_t at = std::size_t(home_) * r;
        std::copy(cols.begin() + begin[r], cols.begin() + begin[r + 1], m_.innerIndexPtr() + at);
        std::copy(vals.begin() + begin[r], vals.begin() + begin[r + 1], m_.valuePtr() + at);
        m_.innerNonZeroPtr()[r] = static_cast<int>(begin[r + 1] - begin[r]);
      }
      return;
    }
    const std::size_t nnz = cols.size();
    m_.data().resize(static_cast<Eigen::Index>(nnz));
    std::copy(cols.begin(), cols.end(), m_.innerIndexPtr());
    std::copy(vals.begin(), vals.end(), m_.valuePtr());
    for (std::size_t r = 0; r < rows; ++r) {
      m_.outerIndexPtr()[r] = static_cast<int>(begin[r]);
      m_.innerNonZeroPtr()[r] = static_cast<int>(begin[r + 1] - begin[r]);
      cap_[r] = m_.innerNonZeroPtr()[r];
    }
    for (std::size_t r = rows; r < cap_.size(); ++r) {
      m_.outerIndexPtr()[r] = static_cast<int>(nnz);
      m_.innerNonZeroPtr()[r] = 0;
      cap_[r] = 0;
    }
    tail_ = nnz;
  }

  /// A compressed copy of rows [0, rows) × columns [0, cols) as ints.
  [[nodiscard]] Eigen::SparseMatrix<int, Eigen::RowMajor> compressed(std::size_t rows, std::size_t ncols) const {
    Eigen::SparseMatrix<int, Eigen::RowMajor> out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(ncols));
    std::size_t nnz = 0;
    for (std::size_t r = 0; r < rows; ++r) nnz += static_cast<std::size_t>(size(static_cast<std::uint32_t>(r)));
    out.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    int k = 0;
    for (std::size_t r = 0; r < rows; ++r) {
      out.outerIndexPtr()[r] = k;
      const auto rr = static_cast<std::uint32_t>(r);
      for (int j = 0; j < size(rr); ++j, ++k) {
        out.innerIndexPtr()[k] = cols(rr)[j];
        out.valuePtr()[k] = vals(rr)[j];
      }
    }
    out.outerIndexPtr()[rows] = k;
    return out;
  }

  /// How many times abandoned slots were compacted away (for tests).
  [[nodiscard]] std::size_t compactions() const { return compactions_; }

  /// The Eigen matrix as stored (uncompressed; rows and columns are capacities).
  [[nodiscard]] const Matrix& matrix() const { return m_; }

  /// Bytes held: the entry buffer (4-byte column + 1-byte value per entry
  /// allocated), the outer index, non-zero counts and slot capacities.
  [[nodiscard]] std::size_t memory_bytes() const {
    return static_cast<std::size_t>(m_.data().allocatedSize()) * (sizeof(int) + sizeof(signed char)) +
           static_cast<std::size_t>(m_.rows()) * (2 * sizeof(int)) + sizeof(int) + cap_.capacity() * sizeof(int);
  }

private:
  [[nodiscard]] std::size_t start_(std::uint32_t r) const {
    return homed_ ? std::size_t(r) << shift_ : static_cast<std::size_t>(m_.outerIndexPtr()[r]);
  }

  // Moves row r to a new slot of `room` entries at the end of the buffer.
  void relocate(std::uint32_t r, int room) {
    // Abandoned slots are at most the live slots' size (each row doubles), so
    // compact when they pass half of it: the buffer stays below 1.5× the live
    // slots, and each compaction is paid for by the insertions that grew rows.
    if (garbage_ > 1024 && 2 * garbage_ > tail_ - garbage_) compact();
    homed_ = false;
    const int n = size(r);
    const std::size_t start = tail_;
    const std::size_t need = start + static_cast<std::size_t>(room);
    if (static_cast<std::size_t>(m_.data().allocatedSize()) < need)
      m_.data().resize(static_cast<Eigen::Index>(need), 1.0); // doubling
    else
      m_.data().resize(static_cast<Eigen::Index>(need));
    const int old = m_.outerIndexPtr()[r];
    std::copy_n(m_.innerIndexPtr() + old, n, m_.innerIndexPtr() + start);
    std::copy_n(m_.valuePtr() + old, n, m_.valuePtr() + start);
    garbage_ += static_cast<std::size_t>(cap_[r]);
    m_.outerIndexPtr()[r] = static_cast<int>(start);
    cap_[r] = room;
    tail_ = need;
  }

  // Lays every slot out again in row order, dropping abandoned slots.
  void compact() {
    const std::size_t rows = cap_.size();
    std::vector<int> ci;
    std::vector<signed char> cv;
    ci.reserve(tail_ - garbage_);
    cv.reserve(tail_ - garbage_);
    std::vector<int> start(rows);
    for (std::size_t r = 0; r < rows; ++r) {
      const auto rr = static_cast<std::uint32_t>(r);
      start[r] = static_cast<int>(ci.size());
      ci.insert(ci.end(), cols(rr), cols(rr) + size(rr));
      cv.insert(cv.end(), vals(rr), vals(rr) + size(rr));
      ci.resize(ci.size() + static_cast<std::size_t>(cap_[r] - size(rr)), 0);
      cv.resize(cv.size() + static_cast<std::size_t>(cap_[r] - size(rr)), 0);
    }
    std::copy(ci.begin(), ci.end(), m_.innerIndexPtr());
    std::copy(cv.begin(), cv.end(), m_.valuePtr());
    for (std::size_t r = 0; r < rows; ++r) m_.outerIndexPtr()[r] = start[r];
    tail_ = ci.size();
    garbage_ = 0;
    ++compactions_;
    m_.data().resize(static_cast<Eigen::Index>(tail_));
  }

  // Eigen's copy assignment gives a compressed matrix laid out in row order;
  // a copy is homed again when its rows fit (assign() decides).
  void relayout_after_copy() {
    if (m_.isCompressed()) m_.uncompress();
    cap_.assign(static_cast<std::size_t>(m_.rows()), 0);
    for (Eigen::Index r = 0; r < m_.rows(); ++r) cap_[static_cast<std::size_t>(r)] = m_.innerNonZeroPtr()[r];
    tail_ = static_cast<std::size_t>(m_.data().size());
    garbage_ = 0;
    homed_ = false;
    if (home_ == 0) return;
    const std::size_t rows = cap_.size();
    std::vector<std::uint32_t> begin(rows + 1, 0);
    for (std::size_t r = 0; r < rows; ++r) begin[r + 1] = begin[r] + static_cast<std::uint32_t>(cap_[r]);
    std::vector<int> cols(m_.innerIndexPtr(), m_.innerIndexPtr() + tail_);
    std::vector<signed char> vals(m_.valuePtr(), m_.valuePtr() + tail_);
    for (std::size_t r = 0; r < rows; ++r) // compressed rows may not start at begin[r]
      for (std::uint32_t k = 0; k < begin[r + 1] - begin[r]; ++k) {
        cols[begin[r] + k] = m_.innerIndexPtr()[m_.outerIndexPtr()[r] + static_cast<int>(k)];
        vals[begin[r] + k] = m_.valuePtr()[m_.outerIndexPtr()[r] + static_cast<int>(k)];
      }
    const auto ncols = static_cast<std::size_t>(m_.cols());
    assign(rows, ncols, begin, cols, vals);
  }

  // Gives rows [from, rows()) their home slots: the buffer covers K × rows(),
  // each new row starts empty at K r with zero values.
  void home_rows_(std::size_t from) {
    const std::size_t rows = static_cast<std::size_t>(m_.rows()), k = static_cast<std::size_t>(home_);
    const auto old = static_cast<std::size_t>(m_.data().size());
    m_.data().resize(static_cast<Eigen::Index>(k * rows));
    std::fill(m_.valuePtr() + std::min(old, k * from), m_.valuePtr() + k * rows, static_cast<signed char>(0));
    std::fill(m_.innerIndexPtr() + std::min(old, k * from), m_.innerIndexPtr() + k * rows, 0);
    for (std::size_t r = from; r < rows; ++r) {
      m_.outerIndexPtr()[r] = static_cast<int>(k * r);
      m_.innerNonZeroPtr()[r] = 0;
      cap_[r] = home_;
    }
    tail_ = k * rows;
    homed_ = true;
  }

  Matrix m_;
  std::vector<int> cap_;
  std::size_t tail_ = 0;    // first free entry of the buffer
  std::size_t garbage_ = 0; // entries in abandoned slots
  std::size_t compactions_ = 0;
  int home_ = 0;       // home width K, 0 for none
  int shift_ = 0;      // K = 1 << shift_
  bool homed_ = false; // every row at K r (see home slots)
};

} // namespace detail

namespace detail {

/// What an Incidence_vertex_row_iterator yields for each edge of a vertex.
enum class Row_walk { out_edges, in_edges, adjacent_vertices };

/// Walks the edges of a vertex v in its d0ᵀ row (row order, which is not
/// rotation order) and yields each as Boost wants it: the edge oriented
/// away from v (out_edges), towards v (in_edges), or its other end
/// (adjacent_vertices). Needs no halfedge walk, so it works on non-manifold
/// vertices too. Invalidated by any edit of the mesh.
template <class Mesh, Row_walk W>
class Incidence_vertex_row_iterator {
public:
  using value_type = std::conditional_t<W == Row_walk::adjacent_vertices, Vertex_index, Edge_index>;
  using reference = value_type;
  using pointer = void;
  using difference_type = std::ptrdiff_t;
  using iterator_category = std::forward_iterator_tag;
  using iterator_concept = std::forward_iterator_tag;

  Incidence_vertex_row_iterator() = default;
  Incidence_vertex_row_iterator(const Mesh* m, const int* col, const signed char* sign)
      : m_(m), col_(col), sign_(sign) {}

  value_type operator*() const {
    // d0ᵀ holds +1 where v is the edge's target: side 0 then enters v.
    const Halfedge_index in(2u * static_cast<std::uint32_t>(*col_) + (*sign_ > 0 ? 0u : 1u));
    if constexpr (W == Row_walk::in_edges) return Edge_index(in);
    else if constexpr (W == Row_walk::out_edges) return Edge_index(Halfedge_index(in.idx() ^ 1u));
    else return m_->source(in);
  }
  Incidence_vertex_row_iterator& operator++() {
    ++col_;
    ++sign_;
    return *this;
  }
  Incidence_vertex_row_iterator operator++(int) {
    Incidence_vertex_row_iterator t = *this;
    ++*this;
    return t;
  }
  friend bool operator==(const Incidence_vertex_row_iterator& a, const Incidence_vertex_row_iterator& b) {
    return a.col_ == b.col_;
  }

private:
  const Mesh* m_ = nullptr;
  const int* col_ = nullptr;
  const signed char* sign_ = nullptr;
};

} // namespace detail

/// The vertex point map of an Incidence_mesh (a boost lvalue property map).
template <class P>
struct Incidence_point_map {
  using key_type = Vertex_index;
  using value_type = P;
  using reference = P&;
  using category = boost::lvalue_property_map_tag;
  detail::huge_page_vector<P>* points = nullptr;
  P& operator[](Vertex_index v) const { return (*points)[v.idx()]; }
  friend P& get(const Incidence_point_map& m, Vertex_index v) { return m[v]; }
  friend void put(const Incidence_point_map& m, Vertex_index v, const P& p) { m[v] = p; }
};

/// What is not a 2-manifold in an Incidence_mesh, by the fans-and-fins rule:
/// an edge is manifold when it bounds at most two faces, running it in
/// opposite directions; a vertex when its faces form one fan (they are
/// connected through the edges at the vertex). Elements are listed by
/// increasing index.
struct Incidence_manifold_report {
  std::vector<Edge_index> fin_edges;            ///< edges in three or more faces
  std::vector<Edge_index> misoriented_edges;    ///< edges whose two faces run the same way along them
  std::vector<Vertex_index> non_manifold_vertices; ///< vertices whose faces form several fans (bow-ties)
  [[nodiscard]] bool ok() const {
    return fin_edges.empty() && misoriented_edges.empty() && non_manifold_vertices.empty();
  }
};

/// One line per problem kind, naming the elements.
inline std::string to_string(const Incidence_manifold_report& r) {
  std::string s;
  auto list = [&](const char* what, const auto& v) {
    if (v.empty()) return;
    s += what;
    for (const auto& x : v) s += ' ' + std::to_string(x.idx());
    s += '\n';
  };
  list("edges in three or more faces:", r.fin_edges);
  list("edges whose two faces run the same way:", r.misoriented_edges);
  list("vertices whose faces form several fans:", r.non_manifold_vertices);
  return s.empty() ? "manifold\n" : s;
}

/// genmesh's sparse-incidence mesh; see the top of this header.
template <class P = Eigen::Vector3d>
class Incidence_mesh : public Mesh_properties<Vertex_index, Halfedge_index, Edge_index, Face_index> {
public:
  using Point = P;
  using size_type = std::size_t;

  static constexpr Vertex_index null_vertex() { return {}; }
  static constexpr Halfedge_index null_halfedge() { return {}; }
  static constexpr Edge_index null_edge() { return {}; }
  static constexpr Face_index null_face() { return {}; }

  Incidence_mesh() = default;

  /// Loads any soup of polygons with distinct corners, manifold or not (see
  /// load_soup()).
  [[nodiscard]] static Incidence_mesh from_soup(const Polygon_soup& soup) {
    Incidence_mesh m;
    m.load_soup(soup);
    return m;
  }

  /// Replaces the mesh by soup: point i is vertex i, face j is face j, edges
  /// are numbered in the order of their first use (face by face, corner by
  /// corner) and directed as that first use, as build_mesh() numbers them.
  /// Fins, bow-ties and inconsistent orientation are accepted (see
  /// manifold_report()). Throws invalid_input, leaving the mesh unchanged,
  /// for a face with fewer than three corners, a repeated corner or a point
  /// index out of range.
  void load_soup(const Polygon_soup& soup) {
    const std::size_t np = soup.num_points(), nf = soup.num_faces();
    // seen[p] = 1 + the last face that visited p: one pass finds a repeated
    // corner in any face size (a pairwise test is quadratic in it).
    std::vector<std::uint32_t> seen(np, 0);
    for (std::size_t f = 0; f < nf; ++f) {
      const auto c = soup.face(f);
      if (c.size() < 3) throw invalid_input("Incidence_mesh::load_soup: face " + std::to_string(f) + " has fewer than three corners");
      const auto stamp = static_cast<std::uint32_t>(f + 1);
      for (std::size_t i = 0; i < c.size(); ++i) {
        if (c[i] >= np)
          throw invalid_input("Incidence_mesh::load_soup: face " + std::to_string(f) + " uses point " +
                              std::to_string(c[i]) + ", out of range");
        if (seen[c[i]] == stamp)
          throw invalid_input("Incidence_mesh::load_soup: face " + std::to_string(f) + " visits point " +
                              std::to_string(c[i]) + " twice");
        seen[c[i]] = stamp;
      }
    }
    std::unordered_map<std::uint64_t, std::uint32_t> edge_of;
    edge_of.reserve(soup.indices.size());
    std::vector<std::uint32_t> corner_edge(soup.indices.size());
    std::vector<signed char> corner_sign(soup.indices.size());
    std::vector<std::uint32_t> ends; // source, target per edge
    for (std::size_t f = 0; f < nf; ++f) {
      const std::uint32_t b = soup.offsets[f], e = soup.offsets[f + 1];
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t u = soup.indices[c], v = soup.indices[c + 1 == e ? b : c + 1];
        const std::uint64_t key = (std::uint64_t(std::min(u, v)) << 32) | std::max(u, v);
        auto [it, fresh] = edge_of.try_emplace(key, static_cast<std::uint32_t>(ends.size() / 2));
        if (fresh) {
          ends.push_back(u);
          ends.push_back(v);
        }
        corner_edge[c] = it->second;
        corner_sign[c] = ends[2 * it->second] == u ? 1 : -1;
      }
    }
    for_each_container([](auto& c) { c.resize(0); }); // every property value back to its default
    assign_incidences(soup.points, ends, soup.offsets, corner_edge, corner_sign);
    update_manifold_flags_();
  }

  // ---- counts -------------------------------------------------------------

  /// Live (not removed) elements.
  [[nodiscard]] size_type n_vertices() const { return vremoved_.size() - removed_vertices_; }
  [[nodiscard]] size_type n_halfedges() const { return 2 * n_edges(); }
  [[nodiscard]] size_type n_edges() const { return eremoved_.size() - removed_edges_; }
  [[nodiscard]] size_type n_faces() const { return fremoved_.size() - removed_faces_; }
  [[nodiscard]] bool is_empty() const { return n_vertices() == 0; }
  /// Index bounds: live plus removed elements.
  [[nodiscard]] size_type vertices_size() const { return vremoved_.size(); }
  [[nodiscard]] size_type halfedges_size() const { return 2 * eremoved_.size(); }
  [[nodiscard]] size_type edges_size() const { return eremoved_.size(); }
  [[nodiscard]] size_type faces_size() const { return fremoved_.size(); }

  [[nodiscard]] bool is_removed(Vertex_index v) const { return vremoved_[v.idx()]; }
  [[nodiscard]] bool is_removed(Halfedge_index h) const { return eremoved_[h.idx() >> 1]; }
  [[nodiscard]] bool is_removed(Edge_index e) const { return eremoved_[e.idx()]; }
  [[nodiscard]] bool is_removed(Face_index f) const { return fremoved_[f.idx()]; }
  /// Within bounds and not removed.
  [[nodiscard]] bool is_valid(Vertex_index v) const { return v.idx() < vertices_size() && !is_removed(v); }
  [[nodiscard]] bool is_valid(Halfedge_index h) const { return h.idx() < halfedges_size() && !is_removed(h); }
  [[nodiscard]] bool is_valid(Edge_index e) const { return e.idx() < edges_size() && !is_removed(e); }
  [[nodiscard]] bool is_valid(Face_index f) const { return f.idx() < faces_size() && !is_removed(f); }

  // ---- the matrices ---------------------------------------------------------

  /// d0, E × V with E and V the index bounds (removed elements give empty
  /// rows and columns): −1 at each edge's source, +1 at its target. A
  /// compressed copy.
  [[nodiscard]] Eigen::SparseMatrix<int> d0() const {
    return Eigen::SparseMatrix<int>(d0_.compressed(edges_size(), vertices_size()));
  }
  /// d1, F × E: +1 where the face runs along the edge, −1 against. A
  /// compressed copy.
  [[nodiscard]] Eigen::SparseMatrix<int> d1() const {
    return Eigen::SparseMatrix<int>(d1_.compressed(faces_size(), edges_size()));
  }
  /// The stored rows (uncompressed Eigen storage with slack; rows and
  /// columns beyond the index bounds are capacity). For reading.
  [[nodiscard]] const detail::Incidence_rows& d0_rows() const { return d0_; }
  [[nodiscard]] const detail::Incidence_rows& d0t_rows() const { return d0t_; }
  [[nodiscard]] const detail::Incidence_rows& d1_rows() const { return d1_; }
  [[nodiscard]] const detail::Incidence_rows& d1t_rows() const { return d1t_; }

  // ---- connectivity -------------------------------------------------------

  [[nodiscard]] static constexpr Halfedge_index opposite(Halfedge_index h) { return Halfedge_index(h.idx() ^ 1u); }
  [[nodiscard]] static constexpr Edge_index edge(Halfedge_index h) { return Edge_index(h); }
  [[nodiscard]] static constexpr Halfedge_index halfedge(Edge_index e) { return e.halfedge(); }
  [[nodiscard]] static constexpr Halfedge_index halfedge(Edge_index e, unsigned i) {
    return Halfedge_index((e.idx() << 1) + i);
  }

  /// The vertex h points to (d0's +1 for side 0, −1 for side 1); null for an
  /// edge whose ends are not set.
  [[nodiscard]] Vertex_index target(Halfedge_index h) const {
    const std::uint32_t e = h.idx() >> 1;
    const std::uint16_t turn = turns_[h.idx()];
    if (turn != no_turn_) return Vertex_index(static_cast<std::uint32_t>(d0_.cols(e)[(turn >> target_slot_bit_) & 1u]));
    const int c = d0_.column_of(e, (h.idx() & 1u) ? -1 : 1);
    return c < 0 ? Vertex_index() : Vertex_index(static_cast<std::uint32_t>(c));
  }
  [[nodiscard]] Vertex_index source(Halfedge_index h) const { return target(opposite(h)); }

  /// The face on h's side (d1ᵀ row of edge(h) with h's sign), null on the
  /// border. Throws invalid_input on an edge that is not manifold.
  [[nodiscard]] Face_index face(Halfedge_index h) const {
    const std::uint32_t e = h.idx() >> 1;
    if (!manifold_ && bad_edge_[e]) throw_edge_(e, "face");
    const std::uint16_t turn = turns_[h.idx()];
    if (turn != no_turn_) return Face_index(static_cast<std::uint32_t>(d1t_.cols(e)[(turn >> face_slot_bit_) & 1u]));
    const int c = d1t_.column_of(e, (h.idx() & 1u) ? -1 : 1);
    return c < 0 ? Face_index() : Face_index(static_cast<std::uint32_t>(c));
  }

  /// The halfedge after h in its face (the one of face(h) leaving target(h)),
  /// or, on the border, the border halfedge leaving target(h). Inside a face:
  /// the entry of f's d1 row at the successor position h's turn record
  /// keeps, directed as the record says (its sign in f); on a face without
  /// records, the edge other than edge(h) in f's d1 row whose d0 row holds
  /// target(h).
  [[nodiscard]] Halfedge_index next(Halfedge_index h) const {
    const std::uint16_t turn = turns_[h.idx()];
    if (turn != no_turn_) return turn_side_(h, turn, turn & 15u, (turn >> next_side_bit_) & 1u);
    const Face_index f = face(h);
    if (f.is_valid()) return side_at_(f, target(h), h);
    return border_leaving_(target(h), h);
  }

  /// The halfedge before h in its face, or on the border the border halfedge
  /// entering source(h).
  [[nodiscard]] Halfedge_index prev(Halfedge_index h) const {
    const std::uint16_t turn = turns_[h.idx()];
    if (turn != no_turn_) return turn_side_(h, turn, (turn >> 4) & 15u, (turn >> prev_side_bit_) & 1u);
    const Face_index f = face(h);
    if (f.is_valid()) return side_at_(f, source(h), h);
    return border_entering_(source(h), h);
  }

  /// A halfedge targeting v: its incoming border halfedge if v is on the
  /// border, else the incoming halfedge of its lowest-numbered edge; null if
  /// v is isolated. Throws invalid_input on a non-manifold vertex.
  [[nodiscard]] Halfedge_index halfedge(Vertex_index v) const {
    if (!manifold_ && bad_vertex_[v.idx()]) throw_vertex_(v.idx(), "halfedge");
    const int n = d0t_.size(v.idx());
    if (n == 0) return {};
    const int* c = d0t_.cols(v.idx());
    const signed char* s = d0t_.vals(v.idx());
    if (manifold_ && border_edges_[v.idx()] == 0) // interior: no edge to look at
      return Halfedge_index(2u * static_cast<std::uint32_t>(c[0]) + (s[0] > 0 ? 0u : 1u));
    for (int k = 0; k < n; ++k) {
      if (d1t_.size(static_cast<std::uint32_t>(c[k])) == 2) continue; // faces on both sides
      const Halfedge_index in(2u * static_cast<std::uint32_t>(c[k]) + (s[k] > 0 ? 0u : 1u));
      if (!face(in).is_valid()) return in;
    }
    return Halfedge_index(2u * static_cast<std::uint32_t>(c[0]) + (s[0] > 0 ? 0u : 1u));
  }
  /// The side of f along its lowest-numbered edge (the first entry of its d1
  /// row), null for a face with no side: O(1).
  [[nodiscard]] Halfedge_index halfedge(Face_index f) const {
    if (d1_.size(f.idx()) == 0) return {};
    return side_at_position_(f, 0);
  }
  /// The side of f targeting f's lowest-numbered vertex (null for a face
  /// with no side): where triangulate_face() fans from, as the generic
  /// operation does. O(degree).
  [[nodiscard]] Halfedge_index lowest_corner(Face_index f) const {
    const int n = d1_.size(f.idx());
    const int* c = d1_.cols(f.idx());
    const signed char* s = d1_.vals(f.idx());
    Halfedge_index best;
    Vertex_index low;
    for (int k = 0; k < n; ++k) {
      const Halfedge_index x(2u * static_cast<std::uint32_t>(c[k]) + (s[k] > 0 ? 0u : 1u));
      const Vertex_index t = target(x);
      if (!best.is_valid() || t < low) {
        best = x;
        low = t;
      }
    }
    return best;
  }
  /// The halfedge from u to v, or null.
  [[nodiscard]] Halfedge_index halfedge(Vertex_index u, Vertex_index v) const {
    const int n = d0t_.size(v.idx());
    const int* c = d0t_.cols(v.idx());
    const signed char* s = d0t_.vals(v.idx());
    for (int k = 0; k < n; ++k) {
      const Halfedge_index in(2u * static_cast<std::uint32_t>(c[k]) + (s[k] > 0 ? 0u : 1u));
      if (source(in) == u) return in;
    }
    return {};
  }

  using Out_edge_iterator = detail::Incidence_vertex_row_iterator<Incidence_mesh, detail::Row_walk::out_edges>;
  using In_edge_iterator = detail::Incidence_vertex_row_iterator<Incidence_mesh, detail::Row_walk::in_edges>;
  using Adjacent_vertex_iterator =
      detail::Incidence_vertex_row_iterator<Incidence_mesh, detail::Row_walk::adjacent_vertices>;
  /// The edges at v oriented away from v (Boost out_edges), in d0ᵀ row
  /// order, not rotation order; also on a non-manifold vertex.
  [[nodiscard]] Range<Out_edge_iterator> out_edges(Vertex_index v) const { return vertex_row_<Out_edge_iterator>(v); }
  /// The edges at v oriented towards v (Boost in_edges), in d0ᵀ row order.
  [[nodiscard]] Range<In_edge_iterator> in_edges(Vertex_index v) const { return vertex_row_<In_edge_iterator>(v); }
  /// The other ends of v's edges (Boost adjacent_vertices), in d0ᵀ row order.
  [[nodiscard]] Range<Adjacent_vertex_iterator> adjacent_vertices(Vertex_index v) const {
    return vertex_row_<Adjacent_vertex_iterator>(v);
  }

  /// Number of edges at v (a d0ᵀ row length): O(1).
  [[nodiscard]] size_type degree(Vertex_index v) const { return static_cast<size_type>(d0t_.size(v.idx())); }
  /// Number of sides of f (a d1 row length): O(1).
  [[nodiscard]] size_type degree(Face_index f) const { return static_cast<size_type>(d1_.size(f.idx())); }
  /// face(h) is null.
  [[nodiscard]] bool is_border(Halfedge_index h) const { return !face(h).is_valid(); }
  /// Fewer than two faces at e.
  [[nodiscard]] bool is_border(Edge_index e) const { return d1t_.size(e.idx()) < 2; }
  /// v is isolated or has an incoming border halfedge.
  [[nodiscard]] bool is_border(Vertex_index v) const {
    const Halfedge_index h = halfedge(v);
    return !h.is_valid() || is_border(h);
  }
  [[nodiscard]] bool is_isolated(Vertex_index v) const { return d0t_.size(v.idx()) == 0; }

  // ---- manifoldness -------------------------------------------------------

  /// No fin, no misoriented edge, no vertex with several fans.
  [[nodiscard]] bool is_manifold() const { return manifold_; }
  /// The offending elements (see Incidence_manifold_report). O(mesh).
  [[nodiscard]] Incidence_manifold_report manifold_report() const {
    Incidence_manifold_report r;
    for (std::uint32_t e = 0; e < edges_size(); ++e) {
      if (eremoved_[e]) continue;
      const int n = d1t_.size(e);
      if (n > 2) r.fin_edges.emplace_back(e);
      else if (n == 2 && d1t_.vals(e)[0] == d1t_.vals(e)[1]) r.misoriented_edges.emplace_back(e);
    }
    for (std::uint32_t v = 0; v < vertices_size(); ++v)
      if (!vremoved_[v] && fans_(v) > 1) r.non_manifold_vertices.emplace_back(v);
    return r;
  }
  /// The vertices of face f in order (following its signed edges), valid on
  /// any face, manifold or not.
  [[nodiscard]] std::vector<Vertex_index> face_vertices(Face_index f) const {
    std::vector<Vertex_index> out;
    const int n = d1_.size(f.idx());
    if (n == 0) return out;
    const int* c = d1_.cols(f.idx());
    const signed char* s = d1_.vals(f.idx());
    auto from = [&](int k) {
      return source(Halfedge_index(2u * static_cast<std::uint32_t>(c[k]) + (s[k] > 0 ? 0u : 1u)));
    };
    auto to = [&](int k) {
      return target(Halfedge_index(2u * static_cast<std::uint32_t>(c[k]) + (s[k] > 0 ? 0u : 1u)));
    };
    // Start at the side leaving the lowest vertex, as lowest_corner() does.
    int k = 0;
    for (int j = 1; j < n; ++j)
      if (to(j) < to(k)) k = j;
    for (int step = 0; step < n; ++step) {
      out.push_back(to(k));
      int nk = -1;
      for (int j = 0; j < n; ++j)
        if (from(j) == to(k)) nk = j;
      if (nk < 0) throw invalid_input("Incidence_mesh: face " + std::to_string(f.idx()) + " is not a closed cycle");
      k = nk;
    }
    return out;
  }
  /// The polygon soup of the mesh read from d1 directly (vertices and faces
  /// in index order, each face rotated to its lowest vertex): works on
  /// non-manifold meshes too; build_mesh(polygon_soup(), halfedge_mesh)
  /// then refuses or repairs as for any soup.
  [[nodiscard]] Polygon_soup polygon_soup() const {
    Polygon_soup s;
    std::vector<std::uint32_t> num(vertices_size(), 0);
    for (std::uint32_t v = 0; v < vertices_size(); ++v)
      if (!vremoved_[v]) {
        num[v] = static_cast<std::uint32_t>(s.points.size());
        s.points.push_back(to_eigen(points_[v]));
      }
    std::vector<std::uint32_t> c;
    for (std::uint32_t f = 0; f < faces_size(); ++f) {
      if (fremoved_[f]) continue;
      c.clear();
      for (const auto v : face_vertices(Face_index(f))) c.push_back(num[v.idx()]);
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      s.add_face(c);
    }
    return s;
  }

  // ---- adding and removing ------------------------------------------------

  /// A new isolated vertex (recycled if possible), at the default point.
  Vertex_index add_vertex() { return add_vertex(detail::default_point<P>()); }
  Vertex_index add_vertex(const Point& p) {
    if (recycle_ && !vfree_.empty()) {
      const std::uint32_t i = vfree_.back();
      vfree_.pop_back();
      --removed_vertices_;
      vremoved_[i] = false;
      points_[i] = p;
      d0t_.clear_row(i);
      border_edges_[i] = 0;
      vprops_.reset(i);
      return Vertex_index(i);
    }
    const auto i = static_cast<std::uint32_t>(vremoved_.size());
    check_room_(i);
    vremoved_.push_back(false);
    points_.push_back(p);
    border_edges_.push_back(0);
    vprops_.push_back();
    d0t_.reserve_shape(i + 1, 1);
    d0_.reserve_shape(1, i + 1);
    if (!manifold_) bad_vertex_.push_back(false);
    return Vertex_index(i);
  }
  /// A new edge (recycled if possible) with no ends yet (set them with
  /// set_edge_vertices()).
  Edge_index add_edge() { return allocate_edge_(); }
  /// A new edge (recycled if possible) from u to v: halfedge(e, 0) goes
  /// u → v. u and v must be distinct live vertices.
  Edge_index add_edge(Vertex_index u, Vertex_index v) {
    const Edge_index e = allocate_edge_();
    set_edge_vertices(e, u, v);
    return e;
  }
  /// A new face (recycled if possible) with no side; add_side() gives it sides.
  Face_index add_face() {
    if (recycle_ && !ffree_.empty()) {
      const std::uint32_t i = ffree_.back();
      ffree_.pop_back();
      --removed_faces_;
      fremoved_[i] = false;
      d1_.clear_row(i);
      touch_face_(i);
      fprops_.reset(i);
      return Face_index(i);
    }
    const auto i = static_cast<std::uint32_t>(fremoved_.size());
    check_room_(i);
    fremoved_.push_back(false);
    face_state_.push_back(order_dirty_);
    dirty_.push_back(i);
    fprops_.push_back();
    d1_.reserve_shape(i + 1, 1);
    d1t_.reserve_shape(1, i + 1);
    return Face_index(i);
  }
  /// Marks v removed and frees its index; its remaining incidences are dropped.
  void remove_vertex(Vertex_index v) {
    const std::uint32_t i = v.idx();
    touch_vertex_faces_(i);
    for (int k = 0; k < d0t_.size(i); ++k) {
      const auto e = static_cast<std::uint32_t>(d0t_.cols(i)[k]);
      unhook_border_(e);
      d0_.erase(e, static_cast<int>(i));
      hook_border_(e);
    }
    border_edges_[i] = 0;
    d0t_.clear_row(i);
    vremoved_[i] = true;
    ++removed_vertices_;
    garbage_ = true;
    vfree_.push_back(i);
  }
  /// Marks e removed and frees its index; drops its incidences (its ends'
  /// and faces' rows lose it).
  void remove_edge(Edge_index e) {
    const std::uint32_t i = e.idx();
    touch_edge_faces_(i);
    unhook_border_(i);
    for (int k = 0; k < d0_.size(i); ++k) d0t_.erase(static_cast<std::uint32_t>(d0_.cols(i)[k]), static_cast<int>(i));
    for (int k = 0; k < d1t_.size(i); ++k) d1_.erase(static_cast<std::uint32_t>(d1t_.cols(i)[k]), static_cast<int>(i));
    d0_.clear_row(i);
    d1t_.clear_row(i);
    eremoved_[i] = true;
    ++removed_edges_;
    garbage_ = true;
    efree_.push_back(i);
  }
  /// Marks f removed and frees its index; its sides become border.
  void remove_face(Face_index f) {
    const std::uint32_t i = f.idx();
    for (int k = 0; k < d1_.size(i); ++k) // f's sides lose their records, the faces beside it their slots
      touch_edge_faces_(static_cast<std::uint32_t>(d1_.cols(i)[k]));
    for (int k = 0; k < d1_.size(i); ++k) {
      const auto e = static_cast<std::uint32_t>(d1_.cols(i)[k]);
      unhook_border_(e);
      d1t_.erase(e, static_cast<int>(i));
      hook_border_(e);
    }
    d1_.clear_row(i);
    face_state_[i] = order_unknown_; // not in the dirty list's sense: touch_face_() on reuse
    fremoved_[i] = true;
    ++removed_faces_;
    garbage_ = true;
    ffree_.push_back(i);
  }

  // ---- low-level incidence edits (keep nothing else consistent) -----------

  /// Edge e now goes from u to v (halfedge(e, 0) targets v).
  void set_edge_vertices(Edge_index e, Vertex_index u, Vertex_index v) {
    const std::uint32_t i = e.idx();
    touch_edge_faces_(i);
    unhook_border_(i);
    for (int k = 0; k < d0_.size(i); ++k) d0t_.erase(static_cast<std::uint32_t>(d0_.cols(i)[k]), static_cast<int>(i));
    d0_.clear_row(i);
    d0_.ensure_room(i, 2);
    d0_.set(i, static_cast<int>(u.idx()), -1);
    d0_.set(i, static_cast<int>(v.idx()), 1);
    d0t_.set(u.idx(), static_cast<int>(i), -1);
    d0t_.set(v.idx(), static_cast<int>(i), 1);
    hook_border_(i);
  }
  /// h now goes from u to v.
  void set_halfedge_vertices(Halfedge_index h, Vertex_index u, Vertex_index v) {
    if (h.idx() & 1u) set_edge_vertices(edge(h), v, u);
    else set_edge_vertices(edge(h), u, v);
  }
  /// Every incidence of vertex `from` moves to `to` (edge directions kept).
  void move_incidences(Vertex_index from, Vertex_index to) {
    const std::uint32_t a = from.idx(), b = to.idx();
    touch_vertex_faces_(a);
    for (int k = 0; k < d0t_.size(a); ++k) {
      const auto e = static_cast<std::uint32_t>(d0t_.cols(a)[k]);
      const signed char s = d0t_.vals(a)[k];
      unhook_border_(e);
      d0_.erase(e, static_cast<int>(a));
      d0_.set(e, static_cast<int>(b), s);
      d0t_.set(b, static_cast<int>(e), s);
      hook_border_(e);
    }
    d0t_.clear_row(a);
  }
  /// Exchanges the incidences of p and q (not their points).
  void swap_incidences(Vertex_index p, Vertex_index q) {
    touch_vertex_faces_(p.idx());
    touch_vertex_faces_(q.idx());
    std::vector<std::pair<int, signed char>> ep, eq;
    for (int k = 0; k < d0t_.size(p.idx()); ++k) ep.emplace_back(d0t_.cols(p.idx())[k], d0t_.vals(p.idx())[k]);
    for (int k = 0; k < d0t_.size(q.idx()); ++k) eq.emplace_back(d0t_.cols(q.idx())[k], d0t_.vals(q.idx())[k]);
    for (auto [e, s] : ep) d0_.erase(static_cast<std::uint32_t>(e), static_cast<int>(p.idx()));
    for (auto [e, s] : eq) d0_.erase(static_cast<std::uint32_t>(e), static_cast<int>(q.idx()));
    for (auto [e, s] : ep) d0_.set(static_cast<std::uint32_t>(e), static_cast<int>(q.idx()), s);
    for (auto [e, s] : eq) d0_.set(static_cast<std::uint32_t>(e), static_cast<int>(p.idx()), s);
    d0t_.clear_row(p.idx());
    d0t_.clear_row(q.idx());
    for (auto [e, s] : eq) d0t_.set(p.idx(), e, s);
    for (auto [e, s] : ep) d0t_.set(q.idx(), e, s);
    std::swap(border_edges_[p.idx()], border_edges_[q.idx()]); // whole rows swapped
  }
  /// h becomes a side of f (f runs along h).
  void add_side(Face_index f, Halfedge_index h) {
    const signed char s = (h.idx() & 1u) ? -1 : 1;
    const int e = static_cast<int>(h.idx() >> 1);
    touch_face_(f.idx());
    touch_edge_faces_(static_cast<std::uint32_t>(e)); // the other face's slot in e's d1ᵀ row may move
    turns_[h.idx()] = no_turn_;
    d1_.set(f.idx(), e, s);
    d1t_.ensure_room(static_cast<std::uint32_t>(e), 2);
    unhook_border_(static_cast<std::uint32_t>(e));
    d1t_.set(static_cast<std::uint32_t>(e), static_cast<int>(f.idx()), s);
    hook_border_(static_cast<std::uint32_t>(e));
  }
  /// h is no longer a side of f.
  void remove_side(Face_index f, Halfedge_index h) {
    const int e = static_cast<int>(h.idx() >> 1);
    touch_edge_faces_(static_cast<std::uint32_t>(e)); // f and the other face, whose slot may move
    d1_.erase(f.idx(), e);
    unhook_border_(static_cast<std::uint32_t>(e));
    d1t_.erase(static_cast<std::uint32_t>(e), static_cast<int>(f.idx()));
    hook_border_(static_cast<std::uint32_t>(e));
  }

  /// Recomputes the cyclic order of every face edited since the last call
  /// (see next()). Every native operation calls it on return; after
  /// low-level incidence edits, next() and prev() on the edited faces stay
  /// correct but take the slow path until it is called. O(edited sides).
  void update_face_orders() {
    for (const std::uint32_t f : dirty_)
      if (face_state_[f] == order_dirty_) record_face_order_(f);
    dirty_.clear();
  }

  // ---- allocation policy ---------------------------------------------------

  /// Some element was removed since the mesh was built or cleared.
  [[nodiscard]] bool has_garbage() const { return garbage_; }
  /// Whether add_* reuses removed indices (default true).
  void set_recycle_garbage(bool b) { recycle_ = b; }
  [[nodiscard]] bool does_recycle_garbage() const { return recycle_; }

  /// Drops removed elements and renumbers the survivors (see
  /// Garbage_order: stable by default, or exactly as
  /// CGAL::Surface_mesh::collect_garbage() does), rebuilding the matrices
  /// compacted; returns the old -> new maps (identity if there was no
  /// garbage). Defined in <genmesh/detail/incidence/garbage.h>.
  Garbage_collection_maps collect_garbage(Garbage_order order = Garbage_order::stable);

  /// Renumbers the live elements in any order: vertex i becomes vmap[i],
  /// edge i emap[i], face i fmap[i] (removed elements: the null index); each
  /// map must send the live elements one to one onto [0, live count)
  /// (checked: invalid_input, the mesh unchanged). Edges keep their
  /// direction; every property follows; the garbage is dropped; the matrices
  /// are rebuilt as collect_garbage() rebuilds them. genmesh::renumber
  /// (<genmesh/renumbering.h>) calls it. In <genmesh/detail/incidence/garbage.h>.
  void renumber(std::span<const std::uint32_t> vmap, std::span<const std::uint32_t> emap,
                std::span<const std::uint32_t> fmap);

  /// Capacity for nv vertices, ne edges and nf faces.
  void reserve(size_type nv, size_type ne, size_type nf) {
    points_.reserve(nv);
    border_edges_.reserve(nv);
    vremoved_.reserve(nv);
    eremoved_.reserve(ne);
    fremoved_.reserve(nf);
    face_state_.reserve(nf);
    turns_.reserve(2 * ne);
    d0_.reserve_shape(ne, nv);
    d0t_.reserve_shape(nv, ne);
    d1_.reserve_shape(nf, ne);
    d1t_.reserve_shape(ne, nf);
    d0_.reserve_entries(2 * ne);
    d0t_.reserve_entries(2 * ne);
    vprops_.reserve(nv);
    hprops_.reserve(2 * ne);
    eprops_.reserve(ne);
    fprops_.reserve(nf);
  }

  /// Back to an empty, manifold mesh with recycling on.
  void clear() { *this = Incidence_mesh(); }

  /// Bytes held by all arrays (capacities), points included.
  [[nodiscard]] size_type memory_bytes() const {
    auto bits = [](const std::vector<bool>& b) { return (b.capacity() + 7) / 8; };
    return points_.capacity() * sizeof(P) + d0_.memory_bytes() + d0t_.memory_bytes() + d1_.memory_bytes() +
           d1t_.memory_bytes() + bits(vremoved_) + bits(eremoved_) + bits(fremoved_) +
           (vfree_.capacity() + efree_.capacity() + ffree_.capacity()) * sizeof(std::uint32_t) +
           bits(bad_vertex_) + bits(bad_edge_) + face_state_.capacity() + turns_.capacity() * sizeof(std::uint16_t) +
           (dirty_.capacity() + border_edges_.capacity()) * sizeof(std::uint32_t) + properties_memory_bytes();
  }

  // ---- ranges -------------------------------------------------------------

  [[nodiscard]] Range<Vertex_iterator> vertices() const {
    return detail::live_range<Vertex_iterator>(vertices_size(), n_vertices(), vremoved_, garbage_);
  }
  [[nodiscard]] Range<Halfedge_iterator> halfedges() const {
    return detail::live_range<Halfedge_iterator>(halfedges_size(), n_halfedges(), eremoved_, garbage_);
  }
  [[nodiscard]] Range<Edge_iterator> edges() const {
    return detail::live_range<Edge_iterator>(edges_size(), n_edges(), eremoved_, garbage_);
  }
  [[nodiscard]] Range<Face_iterator> faces() const {
    return detail::live_range<Face_iterator>(faces_size(), n_faces(), fremoved_, garbage_);
  }

  // ---- points -------------------------------------------------------------

  Point& point(Vertex_index v) { return points_[v.idx()]; }
  const Point& point(Vertex_index v) const { return points_[v.idx()]; }
  /// The positions as a boost lvalue property map (valid while the mesh
  /// lives and is not moved from).
  [[nodiscard]] Incidence_point_map<P> points() const {
    return {const_cast<detail::huge_page_vector<P>*>(&points_)};
  }
  /// The positions as one array by vertex index (removed vertices' slots
  /// included), valid until a vertex is added or the garbage is collected.
  [[nodiscard]] std::span<const Point> point_array() const { return {points_.data(), points_.size()}; }

  // ---- bulk building (genmesh_native_link_soup, load_soup) ----------------

  /// Replaces everything: points (Eigen vectors, or already P); edge i from ends[2i] to ends[2i+1]; face f
  /// with sides corner_edge[c] (sign corner_sign[c]) for c in
  /// [offsets[f], offsets[f+1]). No check.
  template <class Points>
  void assign_incidences(const Points& pts, const std::vector<std::uint32_t>& ends, const std::vector<std::uint32_t>& offsets,
               const std::vector<std::uint32_t>& corner_edge, const std::vector<signed char>& corner_sign) {
    Incidence_mesh m;
    const std::size_t np = pts.size(), ne = ends.size() / 2, nf = offsets.size() - 1, nc = corner_edge.size();
    m.points_.reserve(np);
    for (const auto& p : pts) {
      if constexpr (std::is_convertible_v<decltype(p), const P&>) m.points_.push_back(p);
      else m.points_.push_back(from_eigen<P>(p));
    }
    m.vremoved_.assign(np, false);
    m.eremoved_.assign(ne, false);
    m.fremoved_.assign(nf, false);
    // d0: rows of two, sorted by vertex.
    {
      std::vector<std::uint32_t> begin(ne + 1);
      std::vector<int> cols(2 * ne);
      std::vector<signed char> vals(2 * ne);
      for (std::size_t e = 0; e < ne; ++e) {
        begin[e] = static_cast<std::uint32_t>(2 * e);
        const std::uint32_t u = ends[2 * e], v = ends[2 * e + 1];
        const bool lo_first = u < v;
        cols[2 * e] = static_cast<int>(lo_first ? u : v);
        vals[2 * e] = lo_first ? -1 : 1;
        cols[2 * e + 1] = static_cast<int>(lo_first ? v : u);
        vals[2 * e + 1] = lo_first ? 1 : -1;
      }
      begin[ne] = static_cast<std::uint32_t>(2 * ne);
      m.d0_.assign(ne, np, begin, cols, vals);
      transpose_into_(begin, cols, vals, ne, np, m.d0t_);
    }
    // d1: face rows sorted by edge.
    {
      std::vector<std::uint32_t> begin(offsets.begin(), offsets.end());
      std::vector<int> cols(nc);
      std::vector<signed char> vals(nc);
      std::vector<std::pair<int, signed char>> row;
      for (std::size_t f = 0; f < nf; ++f) {
        row.clear();
        for (std::uint32_t c = offsets[f]; c < offsets[f + 1]; ++c)
          row.emplace_back(static_cast<int>(corner_edge[c]), corner_sign[c]);
        std::sort(row.begin(), row.end());
        for (std::size_t k = 0; k < row.size(); ++k) {
          cols[offsets[f] + k] = row[k].first;
          vals[offsets[f] + k] = row[k].second;
        }
      }
      m.d1_.assign(nf, ne, begin, cols, vals);
      transpose_into_(begin, cols, vals, nf, ne, m.d1t_);
    }
    m.border_edges_.assign(np, 0);
    for (std::uint32_t e = 0; e < ne; ++e) m.hook_border_(e);
    m.turns_.assign(2 * ne, no_turn_);
    m.face_state_.assign(nf, order_dirty_);
    for (std::size_t f = 0; f < nf; ++f) m.record_face_order_(static_cast<std::uint32_t>(f));
    // The properties stay (their handles too), sized to the new elements.
    static_cast<Mesh_properties&>(m) = std::move(static_cast<Mesh_properties&>(*this));
    *this = std::move(m);
    vprops_.resize(np);
    hprops_.resize(2 * ne);
    eprops_.resize(ne);
    fprops_.resize(nf);
  }

  /// The bulk append of in-place subdivision (genmesh_native_relink): the
  /// mesh becomes nv vertices (the old ones, then new ones at the default
  /// point), edges e = 0, 1, … from ends[2e] to ends[2e+1] and faces
  /// f = 0, 1, … with the sides sides[offsets[f] .. offsets[f+1]) in cycle
  /// order (2e: along edge e, 2e+1: against it). The old elements keep their
  /// indices and property values, the new ones get the next indices and
  /// default values, exactly as the same elements appended one by one on a
  /// mesh without removed elements; all four matrices are written in one pass
  /// (assign_incidences) instead of row edits per element. Preconditions (not
  /// checked): no removed elements; at least as many vertices, edges and faces
  /// as before; a valid manifold result with distinct corners per face.
  void relink(std::size_t nv, const std::vector<std::uint32_t>& ends, const std::vector<std::uint32_t>& offsets,
              const std::vector<std::uint32_t>& sides) {
    detail::huge_page_vector<P> pts = std::move(points_);
    pts.resize(nv, detail::default_point<P>());
    std::vector<std::uint32_t> corner_edge(sides.size());
    std::vector<signed char> corner_sign(sides.size());
    for (std::size_t c = 0; c < sides.size(); ++c) {
      corner_edge[c] = sides[c] >> 1;
      corner_sign[c] = (sides[c] & 1u) ? -1 : 1;
    }
    const bool recycle = recycle_, manifold = manifold_;
    assign_incidences(pts, ends, offsets, corner_edge, corner_sign);
    recycle_ = recycle;
    if (!manifold) update_manifold_flags_(); // a fresh mesh assumes a manifold one
  }

private:
  static void transpose_into_(const std::vector<std::uint32_t>& begin, const std::vector<int>& cols,
                              const std::vector<signed char>& vals, std::size_t rows, std::size_t ncols,
                              detail::Incidence_rows& out) {
    std::vector<std::uint32_t> tb(ncols + 1, 0);
    for (int c : cols) ++tb[static_cast<std::size_t>(c) + 1];
    for (std::size_t c = 0; c < ncols; ++c) tb[c + 1] += tb[c];
    std::vector<int> tc(cols.size());
    std::vector<signed char> tv(cols.size());
    std::vector<std::uint32_t> fill(tb.begin(), tb.end() - 1);
    for (std::size_t r = 0; r < rows; ++r)
      for (std::uint32_t k = begin[r]; k < begin[r + 1]; ++k) {
        const std::uint32_t at = fill[static_cast<std::size_t>(cols[k])]++;
        tc[at] = static_cast<int>(r);
        tv[at] = vals[k];
      }
    out.assign(ncols, rows, tb, tc, tv);
  }

  Edge_index allocate_edge_() {
    if (recycle_ && !efree_.empty()) {
      const std::uint32_t i = efree_.back();
      efree_.pop_back();
      --removed_edges_;
      eremoved_[i] = false;
      d0_.clear_row(i);
      d1t_.clear_row(i);
      turns_[2 * std::size_t(i)] = turns_[2 * std::size_t(i) + 1] = no_turn_;
      eprops_.reset(i);
      hprops_.reset(2 * std::size_t(i));
      hprops_.reset(2 * std::size_t(i) + 1);
      return Edge_index(i);
    }
    const auto i = static_cast<std::uint32_t>(eremoved_.size());
    check_room_(2 * std::size_t(i) + 1);
    eremoved_.push_back(false);
    turns_.push_back(no_turn_);
    turns_.push_back(no_turn_);
    eprops_.push_back();
    hprops_.push_back();
    hprops_.push_back();
    d0_.reserve_shape(i + 1, 1);
    d0t_.reserve_shape(1, i + 1);
    d1_.reserve_shape(1, i + 1);
    d1t_.reserve_shape(i + 1, 1);
    if (!manifold_) bad_edge_.push_back(false);
    return Edge_index(i);
  }

  // ---- border counts: halfedge(v) without a scan on interior vertices ------
  // border_edges_[v] counts v's edges with fewer than two faces. Every edit
  // of an edge's d0 or d1ᵀ row unhooks the edge before and hooks it after.
  void hook_border_(std::uint32_t e) {
    if (d1t_.size(e) >= 2) return;
    for (int k = 0; k < d0_.size(e); ++k) ++border_edges_[static_cast<std::size_t>(d0_.cols(e)[k])];
  }
  void unhook_border_(std::uint32_t e) {
    if (d1t_.size(e) >= 2) return;
    for (int k = 0; k < d0_.size(e); ++k) --border_edges_[static_cast<std::size_t>(d0_.cols(e)[k])];
  }

  // ---- face orders: next() in one lookup -------------------------------------
  // For a face f of 2..16 sides that is a closed directed cycle on a
  // manifold mesh, each side h records in turns_[h] where to read its
  // answers in the rows: the positions of next(h) and prev(h) in f's d1 row
  // and their signs there, the slot of f in edge(h)'s d1ᵀ row and the slot
  // of target(h) in its d0 row (see next_side_bit_). With it next(h) reads
  // one d1ᵀ column and one d1 column, face(h) and target(h) one column each,
  // and no value array. A record depends on f's row, its edges' d0 rows and
  // their d1ᵀ rows, so every edit that changes those touches f first (an
  // edit of an edge's d1ᵀ row touches every face at the edge), which clears
  // the records of f's sides (add_side() clears the joining side's,
  // remove_face() its sides'), and update_face_orders() records them again;
  // until then the queries derive from the rows. face_state_[f]:
  // order_dirty_ (f is in dirty_), order_known_, order_unknown_ (too large,
  // not a cycle, removed, or a non-manifold mesh: its sides keep no record).
  static constexpr std::uint8_t order_dirty_ = 0, order_known_ = 1, order_unknown_ = 2;
  // A record: bits 0-3 the position of next(h) in f's d1 row, 4-7 that of
  // prev(h), then the sides of next(h) and prev(h) (their signs in f), the
  // slot of f in edge(h)'s d1ᵀ row and the slot of target(h) in its d0 row.
  static constexpr unsigned next_side_bit_ = 8, prev_side_bit_ = 9, face_slot_bit_ = 10, target_slot_bit_ = 11;
  static constexpr std::uint16_t no_turn_ = 0xFFFF;

  // The side of face(h) at position k of its d1 row, on side `side`.
  Halfedge_index turn_side_(Halfedge_index h, std::uint16_t turn, unsigned k, unsigned side) const {
    const std::uint32_t e = h.idx() >> 1;
    const auto f = static_cast<std::uint32_t>(d1t_.cols(e)[(turn >> face_slot_bit_) & 1u]);
    return Halfedge_index(2u * static_cast<std::uint32_t>(d1_.cols(f)[k]) + side);
  }

  void touch_face_(std::uint32_t f) {
    if (face_state_[f] != order_dirty_) {
      face_state_[f] = order_dirty_;
      dirty_.push_back(f);
      forget_turns_(f);
    }
  }
  void forget_turns_(std::uint32_t f) {
    const int n = d1_.size(f);
    for (int k = 0; k < n; ++k) turns_[side_at_position_(Face_index(f), k).idx()] = no_turn_;
  }
  // Computes f's order and records it in its sides' turns_ (or marks f
  // order_unknown_).
  void record_face_order_(std::uint32_t f) {
    const std::uint64_t w = manifold_ ? face_order_(f) : slow_order_;
    const int n = d1_.size(f);
    // Slots: f in each side's d1ᵀ row, the side's target in its d0 row (both
    // rows of at most two entries, or no record).
    std::uint16_t slots[16] = {};
    bool recordable = w != slow_order_;
    for (int k = 0; recordable && k < n; ++k) {
      const Halfedge_index hk = side_at_position_(Face_index(f), k);
      const std::uint32_t e = hk.idx() >> 1;
      const int nf = d1t_.size(e);
      const int fs = nf > 0 && d1t_.cols(e)[0] == static_cast<int>(f) ? 0 : 1;
      const signed char want = (hk.idx() & 1u) ? -1 : 1;
      recordable = nf <= 2 && fs < nf && d0_.size(e) == 2;
      const int ts = recordable && d0_.vals(e)[0] == want ? 0 : 1;
      slots[k] = static_cast<std::uint16_t>((fs << face_slot_bit_) | (ts << target_slot_bit_));
    }
    if (!recordable) {
      face_state_[f] = order_unknown_;
      forget_turns_(f);
      return;
    }
    for (int k = 0; k < n; ++k) turns_[side_at_position_(Face_index(f), k).idx()] = slots[k];
    for (int k = 0; k < n; ++k) {
      const auto next_k = static_cast<unsigned>((w >> (4 * k)) & 15u);
      const Halfedge_index hk = side_at_position_(Face_index(f), k),
                           hn = side_at_position_(Face_index(f), static_cast<int>(next_k));
      turns_[hk.idx()] |= static_cast<std::uint16_t>(next_k | ((hn.idx() & 1u) << next_side_bit_));
      turns_[hn.idx()] |= static_cast<std::uint16_t>((unsigned(k) << 4) | ((hk.idx() & 1u) << prev_side_bit_));
    }
    face_state_[f] = order_known_;
  }
  void touch_edge_faces_(std::uint32_t e) {
    for (int k = 0; k < d1t_.size(e); ++k) touch_face_(static_cast<std::uint32_t>(d1t_.cols(e)[k]));
  }
  void touch_vertex_faces_(std::uint32_t v) {
    for (int k = 0; k < d0t_.size(v); ++k) touch_edge_faces_(static_cast<std::uint32_t>(d0t_.cols(v)[k]));
  }
  // The side at position k of f's d1 row, directed by its sign.
  Halfedge_index side_at_position_(Face_index f, int k) const {
    return Halfedge_index(2u * static_cast<std::uint32_t>(d1_.cols(f.idx())[k]) +
                          static_cast<std::uint32_t>(d1_.vals(f.idx())[k] < 0));
  }
  // The successor of each position of f's d1 row, 4 bits each (see turns_),
  // or slow_order_.
  static constexpr std::uint64_t slow_order_ = ~std::uint64_t(0);
  std::uint64_t face_order_(std::uint32_t f) const {
    const int n = d1_.size(f);
    if (n < 2 || n > 16) return slow_order_;
    const Face_index fi(f);
    std::uint64_t w = 0;
    for (int k = 0; k < n; ++k) {
      const Halfedge_index hk = side_at_position_(fi, k);
      const Vertex_index t = target(hk);
      if (!t.is_valid() || d0_.size(hk.idx() >> 1) != 2) return slow_order_;
      int j = 0; // the first other side through t, as side_at_() finds it
      for (; j < n; ++j) {
        if (j == k) continue;
        const auto c = static_cast<std::uint32_t>(d1_.cols(f)[j]);
        if (d0_.size(c) != 2) return slow_order_;
        if (d0_.cols(c)[0] == static_cast<int>(t.idx()) || d0_.cols(c)[1] == static_cast<int>(t.idx())) break;
      }
      if (j == n || source(side_at_position_(fi, j)) != t) return slow_order_;
      w |= std::uint64_t(j) << (4 * k);
    }
    int k = 0; // one cycle through all n positions
    for (int step = 1; step <= n; ++step) {
      k = static_cast<int>((w >> (4 * k)) & 15u);
      if ((k == 0) != (step == n)) return slow_order_;
    }
    return w;
  }

  // The side of face f at vertex v other than h's: the edge of f's d1 row,
  // other than edge(h), whose d0 row holds v; directed by its sign in f.
  // (Scanning f's few edges and reading their two-entry d0 rows touches
  // less memory than merging f's row with v's d0ᵀ row.)
  Halfedge_index side_at_(Face_index f, Vertex_index v, Halfedge_index h) const {
    const int e = static_cast<int>(h.idx() >> 1);
    const int vi = static_cast<int>(v.idx());
    const int nf = d1_.size(f.idx());
    if (nf > large_face_ && d0t_.size(v.idx()) < nf) return side_at_large_(f, v, e);
    const int* cf = d1_.cols(f.idx());
    for (int i = 0; i < nf; ++i) {
      const auto c = static_cast<std::uint32_t>(cf[i]);
      if (cf[i] == e) continue;
      const int* d = d0_.cols(c);
      if (d[0] == vi || d[1] == vi)
        return Halfedge_index(2u * c + (d1_.vals(f.idx())[i] > 0 ? 0u : 1u));
    }
    throw_cycle_(f.idx(), v.idx());
  }
  // side_at_() on a face of more than large_face_ sides: v's edges (d0ᵀ row)
  // other than e whose d1ᵀ row holds f, the lowest-numbered one (the first
  // in f's sorted d1 row, as the scan finds it), signed by its d1ᵀ entry.
  // O(degree(v) · faces per edge), not O(face size): a 1M-sided face costs
  // what a triangle costs.
  static constexpr int large_face_ = 16;
  Halfedge_index side_at_large_(Face_index f, Vertex_index v, int e) const {
    const int fi = static_cast<int>(f.idx());
    const int nv = d0t_.size(v.idx());
    const int* cv = d0t_.cols(v.idx());
    for (int k = 0; k < nv; ++k) { // sorted by edge: the first hit is the lowest
      const auto c = static_cast<std::uint32_t>(cv[k]);
      if (cv[k] == e) continue;
      const signed char sign = d1t_.at(c, fi);
      if (sign != 0) return Halfedge_index(2u * c + (sign > 0 ? 0u : 1u));
    }
    throw_cycle_(f.idx(), v.idx());
  }
  [[noreturn]] static void throw_cycle_(std::uint32_t f, std::uint32_t v) {
    throw invalid_input("Incidence_mesh: face " + std::to_string(f) + " does not continue at vertex " +
                        std::to_string(v));
  }

  // The border halfedge leaving t (h is the border halfedge entering t).
  Halfedge_index border_leaving_(Vertex_index t, Halfedge_index h) const {
    if (!manifold_ && bad_vertex_[t.idx()]) throw_vertex_(t.idx(), "next");
    const int n = d0t_.size(t.idx());
    const int* c = d0t_.cols(t.idx());
    const signed char* s = d0t_.vals(t.idx());
    for (int k = 0; k < n; ++k) {
      const Halfedge_index out(2u * static_cast<std::uint32_t>(c[k]) + (s[k] < 0 ? 0u : 1u));
      if (out != opposite(h) && !face(out).is_valid()) return out;
    }
    return opposite(h); // an isolated edge turns back
  }
  // The border halfedge entering s (h is the border halfedge leaving s).
  Halfedge_index border_entering_(Vertex_index s0, Halfedge_index h) const {
    if (!manifold_ && bad_vertex_[s0.idx()]) throw_vertex_(s0.idx(), "prev");
    const int n = d0t_.size(s0.idx());
    const int* c = d0t_.cols(s0.idx());
    const signed char* s = d0t_.vals(s0.idx());
    for (int k = 0; k < n; ++k) {
      const Halfedge_index in(2u * static_cast<std::uint32_t>(c[k]) + (s[k] > 0 ? 0u : 1u));
      if (in != opposite(h) && !face(in).is_valid()) return in;
    }
    return opposite(h);
  }

  // Number of fans of faces around v (faces linked through v's edges).
  int fans_(std::uint32_t v) const {
    std::vector<std::uint32_t> fs;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
    for (int k = 0; k < d0t_.size(v); ++k) {
      const auto e = static_cast<std::uint32_t>(d0t_.cols(v)[k]);
      const int n = d1t_.size(e);
      for (int j = 0; j < n; ++j) {
        fs.push_back(static_cast<std::uint32_t>(d1t_.cols(e)[j]));
        if (j > 0) links.emplace_back(static_cast<std::uint32_t>(d1t_.cols(e)[0]), static_cast<std::uint32_t>(d1t_.cols(e)[j]));
      }
    }
    std::sort(fs.begin(), fs.end());
    fs.erase(std::unique(fs.begin(), fs.end()), fs.end());
    std::vector<std::size_t> parent(fs.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
    auto find = [&](std::size_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    auto at = [&](std::uint32_t f) {
      return static_cast<std::size_t>(std::lower_bound(fs.begin(), fs.end(), f) - fs.begin());
    };
    int comps = static_cast<int>(fs.size());
    for (auto [a, b] : links) {
      const std::size_t x = find(at(a)), y = find(at(b));
      if (x != y) {
        parent[x] = y;
        --comps;
      }
    }
    return comps;
  }

  // collect_garbage and renumber: rebuild the matrices with the survivors
  // at their new indices; `any_order`: the maps may reorder (properties
  // permuted, not compacted in place). hmap: the halfedges' map, from emap
  // (detail::halfedge_compaction_map).
  void reassemble_(std::span<const std::uint32_t> vmap, std::span<const std::uint32_t> emap,
                   std::span<const std::uint32_t> hmap, std::span<const std::uint32_t> fmap, bool any_order);

  void update_manifold_flags_() {
    const Incidence_manifold_report r = manifold_report();
    manifold_ = r.ok();
    bad_edge_.clear();
    bad_vertex_.clear();
    if (manifold_) return;
    // Records are for manifold meshes only: queries on a non-manifold one go
    // the checked way.
    std::fill(turns_.begin(), turns_.end(), no_turn_);
    std::fill(face_state_.begin(), face_state_.end(), order_unknown_);
    bad_edge_.assign(edges_size(), false);
    bad_vertex_.assign(vertices_size(), false);
    for (auto e : r.fin_edges) bad_edge_[e.idx()] = true;
    for (auto e : r.misoriented_edges) bad_edge_[e.idx()] = true;
    for (auto v : r.non_manifold_vertices) bad_vertex_[v.idx()] = true;
  }

  [[noreturn]] void throw_edge_(std::uint32_t e, const char* query) const {
    throw invalid_input(std::string("Incidence_mesh::") + query + ": edge " + std::to_string(e) +
                        (d1t_.size(e) > 2 ? " is in " + std::to_string(d1t_.size(e)) + " faces (a fin)"
                                          : std::string(" has two faces running the same way along it")) +
                        "; halfedge queries need a manifold edge");
  }
  [[noreturn]] void throw_vertex_(std::uint32_t v, const char* query) const {
    throw invalid_input(std::string("Incidence_mesh::") + query + ": vertex " + std::to_string(v) +
                        " is not manifold (its faces form several fans); halfedge queries need a manifold vertex");
  }
  static void check_room_(std::size_t i) {
    if (i + 2 >= std::size_t(Vertex_index::invalid_value) || i + 2 >= std::size_t(std::numeric_limits<int>::max()))
      throw invalid_input("Incidence_mesh: too many elements");
  }

  detail::huge_page_vector<P> points_; // big ones on huge pages (memory/huge_pages.h)
  detail::Incidence_rows d0_{2};  // E × V, rows homed (two ends)
  detail::Incidence_rows d0t_;    // V × E
  detail::Incidence_rows d1_{4};  // F × E, rows homed while faces have at most 4 sides
  detail::Incidence_rows d1t_{2}; // E × F, rows homed while manifold
  std::vector<bool> vremoved_, eremoved_, fremoved_;
  template <class It>
  Range<It> vertex_row_(Vertex_index v) const {
    const int n = d0t_.size(v.idx());
    const int* c = d0t_.cols(v.idx());
    const signed char* sg = d0t_.vals(v.idx());
    return {It(this, c, sg), It(this, c + n, sg + n), static_cast<std::size_t>(n)};
  }

  std::vector<std::uint32_t> vfree_, efree_, ffree_; // LIFO free lists
  std::size_t removed_vertices_ = 0, removed_edges_ = 0, removed_faces_ = 0;
  bool garbage_ = false;
  bool recycle_ = true;
  bool manifold_ = true;
  std::vector<bool> bad_edge_, bad_vertex_; // empty while manifold_
  std::vector<std::uint8_t> face_state_; // per face, see record_face_order_()
  std::vector<std::uint16_t> turns_;     // per halfedge, see record_face_order_()
  std::vector<std::uint32_t> dirty_;     // faces with face_state_ order_dirty_
  std::vector<std::uint32_t> border_edges_; // per vertex, see hook_border_()
};

namespace detail {
template <>
inline constexpr bool is_genmesh_mesh<Incidence_mesh> = true; // the shared BGL functions, property maps included
} // namespace detail

} // namespace genmesh

// ---------------------------------------------------------------------------
// boost::graph_traits
// ---------------------------------------------------------------------------

namespace boost {

template <class P>
struct graph_traits<genmesh::Incidence_mesh<P>> : genmesh::detail::Mesh_graph_traits<P> {
  using in_edge_iterator = typename genmesh::Incidence_mesh<P>::In_edge_iterator;
  using out_edge_iterator = typename genmesh::Incidence_mesh<P>::Out_edge_iterator;
  using adjacency_iterator = typename genmesh::Incidence_mesh<P>::Adjacent_vertex_iterator;
};

template <class P>
struct graph_traits<const genmesh::Incidence_mesh<P>> : graph_traits<genmesh::Incidence_mesh<P>> {};

} // namespace boost

// ---------------------------------------------------------------------------
// CGAL BGL free functions (found by ADL through Incidence_mesh)
// ---------------------------------------------------------------------------

namespace genmesh {

// What only Incidence_mesh has; the rest: <genmesh/detail/elements/mesh_functions.h>.

/// A new edge with no ends yet (set them with g.set_edge_vertices(e, u, v)).
template <class P>
Edge_index add_edge(Incidence_mesh<P>& m) {
  return m.add_edge();
}

/// Replaces g by soup (see Incidence_mesh::load_soup): non-manifold soups load.
template <class P>
void load_soup(const Polygon_soup& soup, Incidence_mesh<P>& g) {
  g.load_soup(soup);
}

/// detail::link_soup()'s contract on Incidence_mesh (build_mesh() and the
/// subdivision schemes build through it): same vertex, edge and face order,
/// same edge directions as on Halfedge_mesh. g must be empty.
template <class P>
std::size_t genmesh_native_link_soup(const Polygon_soup& s, const std::vector<std::uint32_t>& twin,
                                     const std::vector<std::uint32_t>& /*border_out*/, std::size_t ne,
                                     Incidence_mesh<P>& g, std::vector<std::uint32_t>* corner_edge = nullptr) {
  const std::size_t nf = s.num_faces(), nc = s.indices.size();
  std::vector<std::uint32_t> ends;
  ends.reserve(2 * ne);
  std::vector<std::uint32_t> ce(nc, detail::k_null);
  std::vector<signed char> sign(nc, 0);
  std::size_t border = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t first = s.offsets[f], last = s.offsets[f + 1] - 1;
    for (std::uint32_t c = first; c <= last; ++c) {
      if (twin[c] == detail::k_null) ++border;
      if (ce[c] != detail::k_null) continue;
      const auto e = static_cast<std::uint32_t>(ends.size() / 2);
      ends.push_back(s.indices[c]);
      ends.push_back(s.indices[c == last ? first : c + 1]);
      ce[c] = e;
      sign[c] = 1;
      if (twin[c] != detail::k_null) {
        ce[twin[c]] = e;
        sign[twin[c]] = -1;
      }
    }
  }
  g.assign_incidences(s.points, ends, s.offsets, ce, sign);
  if (corner_edge) *corner_edge = std::move(ce);
  return border;
}

/// The bulk append of in-place subdivision on Incidence_mesh (found by ADL:
/// detail::subdivision::Has_native_relink; see Incidence_mesh::relink and
/// docs/concepts.md). A backend without set_next cannot be linked by the
/// generic bulk path, so it takes the level's result in incidence form.
template <class P>
void genmesh_native_relink(Incidence_mesh<P>& g, std::size_t nv, const std::vector<std::uint32_t>& ends,
                           const std::vector<std::uint32_t>& offsets, const std::vector<std::uint32_t>& sides) {
  g.relink(nv, ends, offsets, sides);
}

// The claims of this header, checked where it is compiled.
static_assert(HalfedgeListGraph<Incidence_mesh<>> && VertexListGraph<Incidence_mesh<>> &&
              EdgeListGraph<Incidence_mesh<>> && FaceListGraph<Incidence_mesh<>>);
static_assert(!MutableHalfedgeGraph<Incidence_mesh<>>);
static_assert(HasVertexPoints<Incidence_mesh<>> && HasIndexMap<Incidence_mesh<>, vertex_index_t> &&
              HasIndexMap<Incidence_mesh<>, halfedge_index_t> && HasIndexMap<Incidence_mesh<>, edge_index_t> &&
              HasIndexMap<Incidence_mesh<>, face_index_t>);
static_assert(detail::Has_native_link_soup<Incidence_mesh<>> && detail::Soup_buildable<Incidence_mesh<>>);

} // namespace genmesh

#include <genmesh/detail/incidence/garbage.h>
#include <genmesh/detail/incidence/operations.h>
