// genmesh/priority_queue.h — a mutable priority queue keyed by dense element indices.
//
// Simplification orders edges by cost, remeshing splits the longest edges
// first and collapses the shortest: both pop the best element, then change
// the priorities of a few neighbours (raise or lower), drop some (erased by
// the operation) and add new ones. Mutable_priority_queue does exactly that
// on keys that are dense std::size_t indices (an index map's values):
//
//   genmesh::Mutable_priority_queue<double> q(index_bound(edge_index, g));
//   for (auto e : edges(g)) q.push(get(eidx, e), cost(e));
//   while (!q.empty()) { std::size_t e = q.pop(); ...; q.update(n, new_cost); q.erase(gone); }
//
// Guarantees: push, update, erase and pop are O(log n); top, contains and
// size are O(1); nothing is allocated per operation (storage grows only with
// the key bound and the largest size reached). The order is total and
// deterministic: smallest first by Compare, and equal priorities pop in
// increasing key order, so every backend pops the same sequence.
//
// Implementation: an indexed 4-ary heap (entries {priority, key} in one
// array, a key → heap position array, moves instead of swaps while sifting;
// where the priorities are floating point and the order refines <, the
// smallest child is found without a branch per comparison; push_unordered
// and heapify build a queue bottom-up; set_near_size keeps only the smallest
// priorities in the heap and the rest unordered beside it, in the same
// storage, so that a big queue sifts within a heap that stays in cache).
// Chosen by measurement against Boost.Heap's mutable heaps (d_ary_heap with
// mutable_<true>, pairing_heap, fibonacci_heap) and CGAL's
// Modifiable_priority_queue (its default boost::mutable_queue and its
// pairing-heap variant) on the edge-collapse access pattern — 1M keys with
// random costs; pop, erase 6 and update 10 neighbours until 10% remain.
// Boost.Heap's mutable heaps allocate a node per push (a std::list node for
// d_ary_heap, a tree node for pairing/fibonacci) and took 4.0-5.3x the CPU
// time; CGAL's default mutable_queue (a binary heap of keys that reads the
// priority through its comparator, no allocation per operation) was the
// closest at 2.9x. Own code won clearly, so own code it is (figures and
// command in docs/benchmarks.md, "Mutable priority queue").
#pragma once

#include <genmesh/detail/memory/huge_pages.h>
#include <genmesh/detail/prefetch.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <functional>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace genmesh {

/// A min-priority queue over keys in [0, key_bound) whose priorities can be
/// raised, lowered or erased. Smallest first by Compare; equal priorities
/// pop in increasing key order — unless Compare orders (priority, key)
/// pairs itself, as compare(pa, ka, pb, kb) (a strict total order: a caller
/// whose ties go by something derived from the key, which then need not be
/// stored in the priority). Keys and heap positions are stored as Index
/// (std::uint32_t halves the key → position array and may shrink the heap
/// entries; then keys and sizes must stay below its maximum). Arity: the
/// heap's (4 by default; a larger one makes a big heap shallower, fewer
/// cache misses per sift, at more comparisons per level).
template <class Priority, class Compare = std::less<Priority>, std::unsigned_integral Index = std::size_t,
          std::size_t Arity = 4>
class Mutable_priority_queue {
 public:
  using priority_type = Priority;
  using key_type = std::size_t;
  using size_type = std::size_t;

  /// An empty queue for keys below key_bound (it grows when a larger key is
  /// pushed or updated, see grow()).
  explicit Mutable_priority_queue(std::size_t key_bound = 0, Compare compare = {})
      : compare_(std::move(compare)), position_(key_bound, absent) {}

  /// Allows keys below key_bound without further allocation (never shrinks).
  void grow(std::size_t key_bound) {
    if (key_bound > position_.size()) position_.resize(key_bound, absent);
  }

  /// Reserves room for n queued entries at once.
  void reserve(std::size_t n) {
    if constexpr (select_children) {
      if (n > heap_.size()) grow_slots(n);
    } else {
      heap_.reserve(n);
    }
  }

  /// With floating priorities ordered by < (Compare refines <, see
  /// best_child): lets heapify() keep only about the n smallest priorities in
  /// the heap and the others unordered beside it (the far part, in the same
  /// storage), moved in, the next smallest few at a time, when the heap runs
  /// low. A big queue whose costliest entries rarely pop then sifts within a
  /// heap that stays in cache. The pops are the same (the order is total and
  /// every far priority is at or above every heap priority), and so are the
  /// costs of all the rest; only heapify() bands, and only when the queue is
  /// well above n (0, the default: never). A NaN priority waits in the far
  /// part until only NaN and infinite ones are left there.
  void set_near_size(std::size_t n) {
    static_assert(select_children, "set_near_size: floating priorities ordered by <");
    near_size_ = n;
  }

  /// The current key bound.
  std::size_t key_bound() const { return position_.size(); }

  /// Whether key is queued (false for any key at or above key_bound()).
  bool contains(std::size_t key) const { return key < position_.size() && position_[key] != absent; }

  /// Queues key with priority p. Precondition: !contains(key). A key at or
  /// above key_bound() grows the bound (amortized, doubling).
  void push(std::size_t key, Priority p) {
    assert(!contains(key));
    if (key >= position_.size()) grow_for(key);
    if (pushed_far(key, p)) return;
    near_push(Entry{std::move(p), static_cast<Index>(key)});
    sift_up(near_ - 1);
  }

  /// Queues key with priority p without restoring the order: for filling
  /// a queue with many keys at once, then heapify() before any other call
  /// (top, pop, update, erase). Precondition: !contains(key).
  void push_unordered(std::size_t key, Priority p) {
    assert(!contains(key));
    if (key >= position_.size()) grow_for(key);
    if (pushed_far(key, p)) return;
    near_push(Entry{std::move(p), static_cast<Index>(key)});
  }
  /// Restores the order after push_unordered (Floyd's construction: O(n),
  /// sifting down from the last parent to the root). The pops that follow
  /// are the same as after push() (the order is total).
  void heapify() {
    if constexpr (select_children) {
      if (near_size_ > 0 && !banded_ && near_ > 4 * near_size_) {
        // A band: the entries at or above the sampled priority go far.
        banded_ = true;
        band_ = band_above(0, near_, near_size_);
        if (banded_) {
        std::size_t k = 0;
        for (std::size_t i = 0; i < near_; ++i) {
          if (!(heap_[i].priority < band_)) continue;
          std::swap(heap_[i], heap_[k]);
          ++k;
        }
        // heap_[k, near_) becomes the far part: moved to the storage's end.
        std::size_t to = heap_.size();
        for (std::size_t i = near_; i-- > k;) heap_[--to] = heap_[i];
        far_ = to;
        near_ = k;
        for (std::size_t i = 0; i < near_; ++i) position_[heap_[i].key] = static_cast<Index>(i);
        for (std::size_t i = far_; i < heap_.size(); ++i) position_[heap_[i].key] = static_cast<Index>(i);
        if (near_ < 2) refill();
        }
      }
    }
    const std::size_t n = near_;
    if (n < 2) return;
    for (std::size_t i = (n - 2) / arity + 1; i-- > 0;) sift_down(i);
  }

  /// Queues key with priority p, or moves it to priority p (up or down) if
  /// it is queued already.
  void update(std::size_t key, Priority p) {
    if (!contains(key)) {
      push(key, std::move(p));
      return;
    }
    const std::size_t i = position_[key];
    if constexpr (select_children) {
     if (banded_) {
      const bool near = p < band_;
      if (i >= far_) {
        if (!near) {
          heap_[i].priority = std::move(p);
          return;
        }
        far_remove(i, key);
        near_push(Entry{std::move(p), static_cast<Index>(key)});
        sift_up(near_ - 1);
        return;
      }
      if (!near) {
        remove_at(i);
        far_add(Entry{std::move(p), static_cast<Index>(key)});
        if (near_ < 2) refill();
        return;
      }
     }
    }
    heap_[i].priority = std::move(p);
    // Against the parent, not the old priority: with a keyed Compare the
    // order of an unchanged priority may have moved.
    restore(i);
  }

  /// Removes key; does nothing when key is not queued.
  [[gnu::always_inline]] void erase(std::size_t key) {
    if (!contains(key)) return;
    const std::size_t i = position_[key];
    if constexpr (select_children) {
      if (banded_ && i >= far_) {
        far_remove(i, key);
        return;
      }
    }
    remove_at(i);
    if constexpr (select_children)
      if (banded_ && near_ < 2) refill();
  }

  /// The key with the smallest priority. Precondition: !empty().
  std::size_t top() const {
    assert(!empty());
    return heap_.front().key;
  }
  /// The key that pops after top() if the queue does not change meanwhile
  /// (the smallest of the root's children). Precondition: size() >= 2.
  std::size_t second() const {
    assert(size() >= 2);
    return heap_[best_child(1, std::min(arity + 1, near_))].key;
  }
  /// Its priority. Precondition: !empty().
  const Priority& top_priority() const {
    assert(!empty());
    return heap_.front().priority;
  }
  /// The priority of a queued key. Precondition: contains(key).
  const Priority& priority(std::size_t key) const {
    assert(contains(key));
    return heap_[position_[key]].priority;
  }

  /// Removes the top key and returns it. Precondition: !empty().
  std::size_t pop() {
    assert(!empty());
    const std::size_t key = heap_.front().key;
    remove_at(0);
    if constexpr (select_children)
      if (banded_ && near_ < 2) refill();
    return key;
  }

  bool empty() const { return near_ == 0; } // the far part is empty too then
  std::size_t size() const { return near_ + (heap_.size() - far_); }

  /// Hints that key's position will be read soon (a cache prefetch; no
  /// effect on the queue). With prefetch_entry (its entry, once the
  /// position is in cache), lets a caller about to update many scattered
  /// keys overlap their cache misses.
  void prefetch(std::size_t key) const {
    if (key < position_.size()) detail::prefetch(&position_[key]);
  }
  void prefetch_entry(std::size_t key) const {
    if (contains(key)) detail::prefetch(&heap_[position_[key]]);
  }

  /// Empties the queue, keeping the key bound and the storage.
  void clear() {
    for (std::size_t i = 0; i < near_; ++i) position_[heap_[i].key] = absent;
    for (std::size_t i = far_; i < heap_.size(); ++i) position_[heap_[i].key] = absent;
    near_ = 0;
    if constexpr (!select_children) heap_.clear();
    far_ = heap_.size();
    banded_ = false;
  }

 private:
  static constexpr std::size_t arity = Arity;
  static_assert(Arity >= 2);
  static constexpr Index absent = std::numeric_limits<Index>::max();

  struct Entry {
    Priority priority;
    Index key;
  };

  // The total order: by priority, ties by key (or Compare's own, keyed).
  bool before(const Priority& pa, std::size_t ka, const Priority& pb, std::size_t kb) const {
    if constexpr (std::is_invocable_r_v<bool, const Compare&, const Priority&, std::size_t, const Priority&,
                                        std::size_t>) {
      return compare_(pa, ka, pb, kb);
    } else {
      if (compare_(pa, pb)) return true;
      if (compare_(pb, pa)) return false;
      return ka < kb;
    }
  }
  bool before(const Entry& a, const Entry& b) const { return before(a.priority, a.key, b.priority, b.key); }

  // Whether the order refines < on the priorities (Compare is std::less, or
  // says so: `static constexpr bool refines_less = true`, for a keyed
  // Compare whose key only breaks ties): then best_child compares floating
  // priorities without a branch.
  static constexpr bool refines_less = [] {
    if constexpr (std::is_same_v<Compare, std::less<Priority>>) return true;
    else if constexpr (requires { Compare::refines_less; }) return static_cast<bool>(Compare::refines_less);
    else return false;
  }();
  static constexpr bool select_children = refines_less && std::is_floating_point_v<Priority>;

  // The entry of [first, end) (end > first) that goes first. Which child
  // wins is a coin toss, so a branch per comparison mispredicted about every
  // other one (~9 a pop on the 208k armadillo). With select_children the
  // smallest priority is found with selects instead, and the full order
  // (Compare's tie break, which may read elsewhere) asked only among
  // children tied at it.
  [[gnu::always_inline]] std::size_t best_child(std::size_t first, std::size_t end) const {
    if constexpr (select_children) {
#if defined(__SSE2__)
      if constexpr (std::is_same_v<Priority, float> && sizeof(Entry) == 8 && Arity == 8) {
        if (end - first == 8) {
          // The eight priorities in two registers (the keys shuffled out),
          // their minimum in every lane, and a bit per child at it.
          const float* f = &heap_[first].priority;
          const __m128 e0 = _mm_loadu_ps(f), e1 = _mm_loadu_ps(f + 4), e2 = _mm_loadu_ps(f + 8),
                       e3 = _mm_loadu_ps(f + 12);
          const __m128 lo = _mm_shuffle_ps(e0, e1, _MM_SHUFFLE(2, 0, 2, 0)),
                       hi = _mm_shuffle_ps(e2, e3, _MM_SHUFFLE(2, 0, 2, 0));
          __m128 m = _mm_min_ps(lo, hi);
          m = _mm_min_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
          m = _mm_min_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
          const unsigned at = static_cast<unsigned>(_mm_movemask_ps(_mm_cmpeq_ps(lo, m))) |
                              static_cast<unsigned>(_mm_movemask_ps(_mm_cmpeq_ps(hi, m))) << 4;
          // No bit: a NaN priority made the minimum NaN in every lane (the
          // selects below take NaN as they come, and never index past end).
          if (at != 0) [[likely]] {
            std::size_t best = first + static_cast<std::size_t>(std::countr_zero(at));
            if ((at & (at - 1)) == 0) [[likely]] return best;
            for (unsigned rest = at & (at - 1); rest != 0; rest &= rest - 1) {
              const std::size_t c = first + static_cast<std::size_t>(std::countr_zero(rest));
              if (before(heap_[c], heap_[best])) best = c;
            }
            return best;
          }
        }
      }
#endif
      std::size_t best = first;
      Priority low = heap_[first].priority;
      bool tie = false;
      for (std::size_t c = first + 1; c < end; ++c) {
        const Priority p = heap_[c].priority;
        const bool lower = p < low, same = p == low;
        tie = (tie | same) & !static_cast<bool>(lower);
        const std::size_t m = std::size_t{0} - static_cast<std::size_t>(lower);
        best = (c & m) | (best & ~m);
        low = lower ? p : low;
      }
      if (!tie) [[likely]] return best;
      for (std::size_t c = best + 1; c < end; ++c)
        if (heap_[c].priority == low && before(heap_[c], heap_[best])) best = c;
      return best;
    } else {
      std::size_t best = first;
      for (std::size_t c = first + 1; c < end; ++c)
        if (before(heap_[c], heap_[best])) best = c;
      return best;
    }
  }

  void grow_for(std::size_t key) {
    std::size_t bound = std::max<std::size_t>(position_.size() * 2, 16);
    while (bound <= key) bound *= 2;
    position_.resize(bound, absent);
  }

  void remove_at(std::size_t i) {
    position_[heap_[i].key] = absent;
    const std::size_t last = --near_;
    if (i != last) {
      heap_[i] = std::move(heap_[last]);
      position_[heap_[i].key] = static_cast<Index>(i);
    }
    if constexpr (!select_children) { // no far part: the storage is the heap
      heap_.pop_back();
      far_ = near_;
    }
    if (i != last) restore(i);
  }

  // Storage of n slots (n > heap_.size()), the far part kept at its end.
  [[gnu::noinline]] void grow_slots(std::size_t n) {
    const std::size_t old = heap_.size(), far = old - far_;
    heap_.resize(n);
    for (std::size_t i = 0; i < far; ++i) {
      heap_[n - 1 - i] = std::move(heap_[old - 1 - i]);
      position_[heap_[n - 1 - i].key] = static_cast<Index>(n - 1 - i);
    }
    far_ = n - far;
  }
  void near_push(Entry e) {
    position_[e.key] = static_cast<Index>(near_);
    if constexpr (select_children) {
      if (near_ == far_) grow_slots(std::max<std::size_t>(16, 2 * heap_.size()));
      heap_[near_++] = std::move(e);
    } else { // no far part: the storage is the heap (Priority need not be default-constructible)
      heap_.push_back(std::move(e));
      far_ = ++near_;
    }
  }
  void far_add(Entry e) {
    if (near_ == far_) grow_slots(std::max<std::size_t>(16, 2 * heap_.size()));
    position_[e.key] = static_cast<Index>(--far_);
    heap_[far_] = std::move(e);
  }
  // Queues key in the far part where a band is set and p is at or above
  // it (push and push_unordered); false otherwise (p untouched).
  bool pushed_far(std::size_t key, Priority& p) {
    if constexpr (select_children) {
      if (banded_ && !(p < band_)) {
        far_add(Entry{std::move(p), static_cast<Index>(key)});
        if (near_ < 2) refill();
        return true;
      }
    }
    return false;
  }
  // Takes the far entry of `key` out of slot i (key given: reading it from
  // the slot was a cache miss the removal waited for).
  void far_remove(std::size_t i, std::size_t key) {
    position_[key] = absent;
    if (i != far_) {
      heap_[i] = std::move(heap_[far_]);
      position_[heap_[i].key] = static_cast<Index>(i);
    }
    ++far_;
  }

  // A band for the entries heap_[first, end): a priority about `want` of
  // them are below (from a sample), made a bound that at least one is below.
  // Clears banded_ instead where the sample's is not finite (only NaN and
  // infinite priorities left, or nearly).
  Priority band_above(std::size_t first, std::size_t end, std::size_t want) {
    constexpr std::size_t samples = 256;
    const std::size_t n = end - first, step = std::max<std::size_t>(1, n / samples);
    std::array<Priority, samples> s;
    std::size_t m = 0;
    for (std::size_t i = first; i < end && m < samples; i += step) s[m++] = heap_[i].priority;
    const std::size_t r = std::min(m - 1, want * m / n);
    std::nth_element(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(r), s.begin() + static_cast<std::ptrdiff_t>(m),
                     [](Priority a, Priority b) { return a < b || (a == a && b != b); }); // NaN last
    const Priority b = s[r];
    if (!std::isfinite(b)) {
      banded_ = false;
      return b;
    }
    return std::nextafter(b, std::numeric_limits<Priority>::infinity());
  }

  // Moves the far entries below a new band into the heap (which holds fewer
  // than two), until it holds two or the far part is empty; heap_ then
  // ordered again.
  [[gnu::noinline]] void refill() {
    while (near_ < 2 && far_ < heap_.size()) {
      const std::size_t end = heap_.size();
      band_ = band_above(far_, end, near_size_);
      // Moved down to the heap's end (never above their slots: near_ <= far_).
      auto take = [&](std::size_t i) {
        position_[heap_[i].key] = static_cast<Index>(near_);
        heap_[near_++] = std::move(heap_[i]);
      };
      if (!banded_) {
        for (std::size_t i = far_; i < end; ++i) take(i);
        far_ = end;
      } else {
        // The far entries below the band gathered at the far part's start
        // (in order of the slots), then moved down to the heap's end.
        std::size_t k = far_;
        for (std::size_t i = far_; i < end; ++i) {
          if (!(heap_[i].priority < band_)) continue;
          if (i != k) {
            std::swap(heap_[i], heap_[k]);
            position_[heap_[i].key] = static_cast<Index>(i);
          }
          ++k;
        }
        for (std::size_t i = far_; i < k; ++i) take(i);
        far_ = k;
      }
      const std::size_t n = near_;
      if (n >= 2)
        for (std::size_t i = (n - 2) / arity + 1; i-- > 0;) sift_down(i);
    }
  }

  // Puts the entry at i, whose priority changed, where it belongs: up if it
  // now goes before its parent, else down.
  void restore(std::size_t i) {
    if (i > 0 && before(heap_[i], heap_[(i - 1) / arity])) sift_up(i);
    else sift_down(i);
  }

  // Both sifts move the entry into a hole instead of swapping at each level.
  void sift_up(std::size_t i) {
    Entry moving = std::move(heap_[i]);
    while (i > 0) {
      const std::size_t parent = (i - 1) / arity;
      if (!before(moving, heap_[parent])) break;
      heap_[i] = std::move(heap_[parent]);
      position_[heap_[i].key] = static_cast<Index>(i);
      i = parent;
    }
    position_[moving.key] = static_cast<Index>(i);
    heap_[i] = std::move(moving);
  }

  void sift_down(std::size_t i) {
    const std::size_t n = near_;
    Entry moving = std::move(heap_[i]);
    for (;;) {
      const std::size_t first = i * arity + 1;
      if (first >= n) break;
      const std::size_t best = first + arity <= n ? best_child(first, first + arity) : best_child(first, n);
      if (!before(heap_[best], moving)) break;
      heap_[i] = std::move(heap_[best]);
      position_[heap_[i].key] = static_cast<Index>(i);
      i = best;
    }
    position_[moving.key] = static_cast<Index>(i);
    heap_[i] = std::move(moving);
  }

  [[no_unique_address]] Compare compare_;
  // heap_[0, near_) is the heap; with a band, heap_[far_, heap_.size()) the
  // far entries, unordered (far_ >= near_; the slots between are free).
  // A far entry's position is its slot, so position_[key] >= far_ tells it.
  detail::huge_page_vector<Entry> heap_; // big ones on huge pages (memory/huge_pages.h)
  detail::huge_page_vector<Index> position_;  // key → slot in heap_, or absent
  std::size_t near_ = 0, far_ = 0;
  std::size_t near_size_ = 0; // set_near_size's n; 0: no band
  bool banded_ = false;
  std::conditional_t<select_children, Priority, bool> band_{}; // with banded_: the heap holds the priorities below it, the far part the others
};

} // namespace genmesh
