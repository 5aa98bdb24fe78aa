// genmesh/detail/halfedge/cycle_iterator.h — Halfedge_mesh's iterators
// around a face and around a vertex (used through <genmesh/halfedge_mesh.h>).
#pragma once

#include <genmesh/elements.h>

#include <cstddef>
#include <iterator>

namespace genmesh {

class Halfedge_connectivity;

namespace detail {

/// Walks a halfedge cycle from an anchor (CGAL's iterator-over-circulator
/// scheme: begin = (anchor, winding 0), end = (anchor, winding 1)).
/// Step provides next(m, h) and value(m, h).
template <class Step>
class Cycle_iterator {
public:
  using value_type = typename Step::value_type;
  using reference = value_type;
  using pointer = void;
  using difference_type = std::ptrdiff_t;
  using iterator_category = std::forward_iterator_tag;
  using iterator_concept = std::forward_iterator_tag;

  Cycle_iterator() = default;
  Cycle_iterator(const Halfedge_connectivity* m, Halfedge_index anchor, int winding)
      : m_(m), pos_(anchor), anchor_(anchor), winding_(anchor.is_valid() ? winding : 1) {}

  value_type operator*() const { return Step::value(*m_, pos_); }
  Cycle_iterator& operator++() {
    pos_ = Step::next(*m_, pos_);
    if (pos_ == anchor_) ++winding_;
    return *this;
  }
  Cycle_iterator operator++(int) {
    Cycle_iterator t = *this;
    ++*this;
    return t;
  }
  friend bool operator==(const Cycle_iterator& a, const Cycle_iterator& b) {
    return a.pos_ == b.pos_ && a.winding_ == b.winding_;
  }

private:
  const Halfedge_connectivity* m_ = nullptr;
  Halfedge_index pos_;
  Halfedge_index anchor_;
  int winding_ = 1;
};

// Steps are templates on the mesh so they can precede Halfedge_connectivity.
struct Step_face {
  using value_type = Halfedge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next(h); }
  template <class M>
  static Halfedge_index value(const M&, Halfedge_index h) { return h; }
};
struct Step_face_vertex {
  using value_type = Vertex_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next(h); }
  template <class M>
  static Vertex_index value(const M& m, Halfedge_index h) { return m.target(h); }
};
struct Step_target {
  using value_type = Halfedge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Halfedge_index value(const M&, Halfedge_index h) { return h; }
};
struct Step_target_vertex {
  using value_type = Vertex_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Vertex_index value(const M& m, Halfedge_index h) { return m.source(h); }
};
struct Step_target_in_edge {
  using value_type = Edge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Edge_index value(const M&, Halfedge_index h) { return Edge_index(h); }
};
struct Step_target_out_edge {
  using value_type = Edge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Edge_index value(const M&, Halfedge_index h) { return Edge_index(Halfedge_index(h.idx() ^ 1u)); }
};
struct Step_target_face {
  using value_type = Face_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Face_index value(const M& m, Halfedge_index h) { return m.face(h); }
};

} // namespace detail
} // namespace genmesh
