// The shared layer under every algorithm: the mutable priority queue,
// scratch properties on every backend, the typed dynamic properties of
// genmesh's meshes, the LocalOperations concept.
#include "backends.h"

#include <genmesh/adaptors/openmesh.h>
#include <genmesh/generators.h>
#include <genmesh/local_operations.h>
#include <genmesh/priority_queue.h>
#include <genmesh/properties.h>
#include <genmesh/soup_to_mesh.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <type_traits>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

// ---------------------------------------------------------------------------
// Mutable_priority_queue against a reference: std::set of (priority, key)
// ordered the same way (smallest priority, ties by increasing key).

template <class Compare>
struct Reference_queue {
  struct Less {
    Compare c;
    bool operator()(const std::pair<int, std::size_t>& a, const std::pair<int, std::size_t>& b) const {
      if (c(a.first, b.first)) return true;
      if (c(b.first, a.first)) return false;
      return a.second < b.second;
    }
  };
  std::set<std::pair<int, std::size_t>, Less> set;
  std::map<std::size_t, int> priority;

  bool contains(std::size_t k) const { return priority.count(k) != 0; }
  void update(std::size_t k, int p) {
    erase(k);
    set.insert({p, k});
    priority[k] = p;
  }
  void erase(std::size_t k) {
    auto it = priority.find(k);
    if (it == priority.end()) return;
    set.erase({it->second, k});
    priority.erase(it);
  }
  std::size_t top() const { return set.begin()->second; }
  int top_priority() const { return set.begin()->first; }
  std::size_t pop() {
    const std::size_t k = top();
    erase(k);
    return k;
  }
};

// Random operation sequences; priorities from a small range, so ties are
// frequent and the key order of equal priorities is exercised.
template <class Compare>
void run_random_sequence(unsigned seed, std::size_t key_bound, int priority_range, int steps) {
  std::mt19937 rng(seed);
  genmesh::Mutable_priority_queue<int, Compare> q(key_bound);
  Reference_queue<Compare> ref;
  const auto key = [&] { return static_cast<std::size_t>(rng() % (key_bound + key_bound / 4 + 1)); };
  const auto prio = [&] { return static_cast<int>(rng() % static_cast<unsigned>(priority_range)); };
  for (int s = 0; s < steps; ++s) {
    switch (rng() % 7) {
      case 0:
      case 1: {  // push (a key may be above the initial bound: the queue grows)
        const std::size_t k = key();
        if (!q.contains(k)) {
          const int p = prio();
          q.push(k, p);
          ref.update(k, p);
        }
        break;
      }
      case 2:
      case 3: {  // update: insert, raise or lower
        const std::size_t k = key();
        const int p = prio();
        q.update(k, p);
        ref.update(k, p);
        break;
      }
      case 4: {  // erase, present or not
        const std::size_t k = key();
        q.erase(k);
        ref.erase(k);
        break;
      }
      case 5:
      case 6:
        if (!ref.set.empty()) {
          ASSERT_FALSE(q.empty());
          ASSERT_EQ(q.top(), ref.top()) << "step " << s;
          ASSERT_EQ(q.top_priority(), ref.top_priority());
          ASSERT_EQ(q.pop(), ref.pop());
        }
        break;
    }
    ASSERT_EQ(q.size(), ref.set.size());
    ASSERT_EQ(q.empty(), ref.set.empty());
    if (s % 97 == 0) {
      for (std::size_t k = 0; k < key_bound + key_bound / 4 + 2; ++k) {
        ASSERT_EQ(q.contains(k), ref.contains(k)) << "key " << k;
        if (ref.contains(k)) {
          ASSERT_EQ(q.priority(k), ref.priority.at(k));
        }
      }
    }
  }
  // Drain: the whole remaining order agrees.
  while (!ref.set.empty()) ASSERT_EQ(q.pop(), ref.pop());
  EXPECT_TRUE(q.empty());
}

TEST(PriorityQueue, RandomSequencesMatchReference) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    run_random_sequence<std::less<int>>(seed, 64, 8, 3000);         // many ties
    run_random_sequence<std::less<int>>(seed + 100, 1000, 1 << 20, 3000);
  }
}

TEST(PriorityQueue, RandomSequencesWithGreaterCompare) {
  for (unsigned seed = 1; seed <= 10; ++seed) run_random_sequence<std::greater<int>>(seed, 100, 5, 3000);
}

TEST(PriorityQueue, EqualPrioritiesPopInIncreasingKeyOrder) {
  genmesh::Mutable_priority_queue<double> q(10);
  for (std::size_t k : {7u, 3u, 9u, 0u, 5u}) q.push(k, 1.0);
  q.push(8, 0.5);
  q.update(2, 1.0);
  q.update(8, 1.0);  // raised into the tie
  std::vector<std::size_t> order;
  while (!q.empty()) order.push_back(q.pop());
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 2, 3, 5, 7, 8, 9}));
}

// A keyed Compare orders (priority, key) pairs itself (here: ties by a
// rank derived from the key, as simplify's vertex pairs), with 32-bit keys.
TEST(PriorityQueue, KeyedCompareBreaksTiesAnd32BitKeys) {
  const std::vector<int> rank{4, 0, 3, 1, 2, 5};  // by key
  struct By_rank {
    const std::vector<int>* rank;
    bool operator()(double a, std::size_t ka, double b, std::size_t kb) const {
      if (a < b) return true;
      if (b < a) return false;
      return (*rank)[ka] < (*rank)[kb];
    }
  };
  genmesh::Mutable_priority_queue<double, By_rank, std::uint32_t> q(6, By_rank{&rank});
  for (std::size_t k = 0; k < 6; ++k) q.push(k, 1.0);
  q.update(5, 0.5);  // lowered out of the tie: first
  q.update(1, 2.0);  // raised out of it: last
  q.update(1, 1.0);  // back into it: its rank (0) puts it first of the ties
  std::vector<std::size_t> order;
  while (!q.empty()) order.push_back(q.pop());
  EXPECT_EQ(order, (std::vector<std::size_t>{5, 1, 3, 4, 2, 0}));
}

// Float priorities in an 8-ary heap with 32-bit keys, as simplify's queue:
// the children are picked by their priorities alone (SSE2 for full groups
// of eight, selects for the last group) and by the full order among ties.
// Priorities from a few values (ties in most groups, and -0.0 tied with
// +0.0), ties by a rank derived from the key (a keyed Compare that says it
// refines <) or by the key (std::less); second() checked too.
struct Float_by_rank {
  static constexpr bool refines_less = true;
  const std::vector<std::uint32_t>* rank;
  bool operator()(float a, std::size_t ka, float b, std::size_t kb) const {
    if (a < b) return true;
    if (b < a) return false;
    return (*rank)[ka] < (*rank)[kb];
  }
};

template <class Compare>
void run_random_float_sequence(unsigned seed, std::size_t key_bound, int values, int steps) {
  std::mt19937 rng(seed);
  std::vector<std::uint32_t> rank(key_bound);
  for (std::size_t k = 0; k < key_bound; ++k) rank[k] = static_cast<std::uint32_t>(k);
  std::shuffle(rank.begin(), rank.end(), rng);
  auto order = [&](float a, std::size_t ka, float b, std::size_t kb) {
    if (a < b) return true;
    if (b < a) return false;
    if constexpr (std::is_same_v<Compare, Float_by_rank>) return rank[ka] < rank[kb];
    else return ka < kb;
  };
  auto make = [&] {
    if constexpr (std::is_same_v<Compare, Float_by_rank>)
      return genmesh::Mutable_priority_queue<float, Compare, std::uint32_t, 8>(key_bound, Compare{&rank});
    else
      return genmesh::Mutable_priority_queue<float, Compare, std::uint32_t, 8>(key_bound);
  };
  auto q = make();
  std::map<std::size_t, float> ref;
  auto ref_sorted = [&] {
    std::vector<std::pair<float, std::size_t>> v;
    for (const auto& [k, p] : ref) v.push_back({p, k});
    std::sort(v.begin(), v.end(), [&](const auto& x, const auto& y) { return order(x.first, x.second, y.first, y.second); });
    return v;
  };
  const auto prio = [&] {
    const unsigned v = rng() % static_cast<unsigned>(values);
    return v == 0 ? ((rng() & 1) ? -0.0f : 0.0f) : static_cast<float>(v) * 0.25f;
  };
  for (int s = 0; s < steps; ++s) {
    const std::size_t k = rng() % key_bound;
    switch (rng() % 6) {
      case 0:
      case 1:
      case 2: {
        const float p = prio();
        q.update(k, p);
        ref[k] = p;
        break;
      }
      case 3:
        q.erase(k);
        ref.erase(k);
        break;
      default:
        if (!ref.empty()) {
          const auto v = ref_sorted();
          if (v.size() >= 2) {
            ASSERT_EQ(q.second(), v[1].second) << "step " << s;
          }
          ASSERT_EQ(q.pop(), v[0].second) << "step " << s;
          ref.erase(v[0].second);
        }
        break;
    }
    ASSERT_EQ(q.size(), ref.size());
  }
  for (const auto& [p, k] : ref_sorted()) ASSERT_EQ(q.pop(), k);
  EXPECT_TRUE(q.empty());
}

TEST(PriorityQueue, FloatPrioritiesInAnEightAryHeapMatchReference) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    run_random_float_sequence<Float_by_rank>(seed, 600, 5, 4000);        // many ties
    run_random_float_sequence<Float_by_rank>(seed + 50, 600, 1000, 4000);
    run_random_float_sequence<std::less<float>>(seed + 100, 600, 5, 4000);
    run_random_float_sequence<std::less<float>>(seed + 150, 600, 1000, 4000);
  }
}

// NaN priorities (a cost that overflowed) have no place in the order, but
// the queue must stay sound: every key pops exactly once, none twice, and
// the children's selection never reads past a group (its SSE2 minimum is
// NaN in every lane when a NaN meets it first).
TEST(PriorityQueue, NaNPrioritiesPopEveryKeyOnce) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 rng(seed);
    const std::size_t n = 700;
    std::vector<std::uint32_t> rank(n);
    for (std::size_t k = 0; k < n; ++k) rank[k] = static_cast<std::uint32_t>(k);
    genmesh::Mutable_priority_queue<float, Float_by_rank, std::uint32_t, 8> q(n, Float_by_rank{&rank});
    std::set<std::size_t> in;
    for (int s = 0; s < 3000; ++s) {
      const std::size_t k = rng() % n;
      const float p = rng() % 3 == 0 ? nan : static_cast<float>(rng() % 9);
      if (rng() % 4 == 0) {
        q.erase(k);
        in.erase(k);
      } else {
        q.update(k, p);
        in.insert(k);
      }
      if (s % 7 == 0 && !q.empty()) {
        const std::size_t top = q.pop();
        ASSERT_EQ(in.erase(top), 1u) << "seed " << seed << " step " << s;
      }
      ASSERT_EQ(q.size(), in.size());
    }
    while (!q.empty()) ASSERT_EQ(in.erase(q.pop()), 1u) << "seed " << seed;
    EXPECT_TRUE(in.empty());
  }
}

// With set_near_size the heap holds only the smallest priorities and the
// rest wait unordered (simplify keeps ~16k of its edges so): the same keys
// pop in the same order as without, with ties, infinities, raised and
// lowered priorities, erases and pushes across the band, and the far part
// moved in each time the heap runs low (near sizes down to 1).
TEST(PriorityQueue, NearSizePopsAsWithout) {
  const float inf = std::numeric_limits<float>::infinity();
  for (unsigned seed = 1; seed <= 12; ++seed) {
    std::mt19937 rng(seed);
    const std::size_t n = 200 + rng() % 4000;
    std::vector<std::uint32_t> rank(n);
    for (std::size_t k = 0; k < n; ++k) rank[k] = static_cast<std::uint32_t>(k);
    std::shuffle(rank.begin(), rank.end(), rng);
    using Q = genmesh::Mutable_priority_queue<float, Float_by_rank, std::uint32_t, 8>;
    Q plain(n, Float_by_rank{&rank}), banded(n, Float_by_rank{&rank});
    banded.set_near_size(std::size_t{1} << (seed % 7)); // 1 … 64
    banded.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
      if (rng() % 6 == 0) continue;
      const float p = rng() % 50 == 0 ? inf : static_cast<float>(rng() % 64);
      plain.push_unordered(k, p);
      banded.push_unordered(k, p);
    }
    plain.heapify();
    banded.heapify();
    for (int s = 0; !plain.empty(); ++s) {
      ASSERT_EQ(banded.size(), plain.size()) << "seed " << seed << " step " << s;
      ASSERT_EQ(banded.top(), plain.top()) << "seed " << seed << " step " << s;
      if (plain.size() >= 2) {
        ASSERT_EQ(banded.second(), plain.second()) << "seed " << seed << " step " << s;
      }
      ASSERT_EQ(banded.pop(), plain.pop()) << "seed " << seed << " step " << s;
      // Costs that grow as the pops go on, as a simplification's do.
      for (int j = 0; j < (s < 3 * static_cast<int>(n) ? 5 : 0); ++j) {
        const std::size_t k = rng() % n;
        const float p = rng() % 40 == 0 ? inf : static_cast<float>(rng() % 64 + s / 16);
        if (rng() % 4 == 0) {
          plain.erase(k);
          banded.erase(k);
        } else {
          plain.update(k, p);
          banded.update(k, p);
        }
        ASSERT_EQ(banded.contains(k), plain.contains(k));
        if (plain.contains(k)) {
          ASSERT_EQ(banded.priority(k), plain.priority(k));
        }
      }
    }
    EXPECT_TRUE(banded.empty());
    EXPECT_EQ(banded.size(), 0u);
  }
}

// A queue filled with push_unordered and heapify() pops what one filled
// with push() pops (simplify builds its first queue so), and takes updates
// and erases afterwards.
TEST(PriorityQueue, HeapifyPopsAsPushDoes) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    std::mt19937 rng(seed);
    const std::size_t n = 1 + rng() % 3000;
    std::vector<std::uint32_t> rank(n);
    for (std::size_t k = 0; k < n; ++k) rank[k] = static_cast<std::uint32_t>(k);
    std::shuffle(rank.begin(), rank.end(), rng);
    using Q = genmesh::Mutable_priority_queue<float, Float_by_rank, std::uint32_t, 8>;
    Q pushed(n, Float_by_rank{&rank}), built(n, Float_by_rank{&rank});
    for (std::size_t k = 0; k < n; ++k) {
      if (rng() % 5 == 0) continue; // some keys left out
      const float p = static_cast<float>(rng() % 7);
      pushed.push(k, p);
      built.push_unordered(k, p);
    }
    built.heapify();
    ASSERT_EQ(built.size(), pushed.size());
    for (int s = 0; s < 200 && !pushed.empty(); ++s) {
      const std::size_t k = rng() % n;
      const float p = static_cast<float>(rng() % 7);
      if (s % 3 == 0) {
        pushed.erase(k);
        built.erase(k);
      } else {
        pushed.update(k, p);
        built.update(k, p);
      }
      ASSERT_EQ(built.pop(), pushed.pop()) << "seed " << seed << " step " << s;
    }
    while (!pushed.empty()) ASSERT_EQ(built.pop(), pushed.pop());
    EXPECT_TRUE(built.empty());
  }
}

TEST(PriorityQueue, UpdateEraseGrowClear) {
  genmesh::Mutable_priority_queue<int> q;  // key bound 0: push grows it
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.contains(5));
  q.push(5, 10);
  q.push(100, 3);
  EXPECT_GE(q.key_bound(), 101u);
  EXPECT_EQ(q.top(), 100u);
  q.update(5, 1);  // lower
  EXPECT_EQ(q.top(), 5u);
  EXPECT_EQ(q.top_priority(), 1);
  q.update(5, 50);  // raise
  EXPECT_EQ(q.top(), 100u);
  q.erase(100);
  q.erase(100);  // absent: no-op
  q.erase(1u << 30);  // above the bound: no-op
  EXPECT_EQ(q.size(), 1u);
  EXPECT_EQ(q.top(), 5u);
  q.grow(1000);
  EXPECT_EQ(q.key_bound(), 1000u);
  q.push(999, 0);
  q.clear();
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.contains(5));
  EXPECT_FALSE(q.contains(999));
  EXPECT_EQ(q.key_bound(), 1000u);
  q.push(5, 2);  // usable after clear
  EXPECT_EQ(q.pop(), 5u);
}

// A priority that is a class (no default constructor, no std::isfinite):
// the queue needs only its order and moves. (set_near_size's far part, for
// floating priorities only, must not ask more of other types.)
namespace {
struct Cost_and_tag {
  Cost_and_tag(double c, int t) : cost(c), tag(t) {}
  double cost;
  int tag;
  friend bool operator<(const Cost_and_tag& a, const Cost_and_tag& b) {
    return a.cost < b.cost || (a.cost == b.cost && a.tag < b.tag);
  }
};
} // namespace

TEST(PriorityQueue, ClassPrioritiesWithoutDefaultConstructor) {
  static_assert(!std::is_default_constructible_v<Cost_and_tag>);
  genmesh::Mutable_priority_queue<Cost_and_tag> q(8);
  q.reserve(8);
  for (int k = 0; k < 8; ++k) q.push(static_cast<std::size_t>(k), Cost_and_tag{static_cast<double>(k % 3), -k});
  q.update(7, Cost_and_tag{-1.0, 0});
  q.erase(0);
  std::vector<std::size_t> order;
  while (!q.empty()) order.push_back(q.pop());
  // 7 (lowered), then cost 0: 6, 3; cost 1: 4, 1; cost 2: 5, 2 (tag −k: larger k first).
  EXPECT_EQ(order, (std::vector<std::size_t>{7, 6, 3, 4, 1, 5, 2}));
  q.push(2, Cost_and_tag{0.5, 0});
  q.clear();
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.size(), 0u);
}

// No allocation per operation: once the heap reached its largest size, the
// storage does not move while keys are popped, erased and updated.
TEST(PriorityQueue, NoReallocationAfterReserve) {
  genmesh::Mutable_priority_queue<double> q(1000);
  q.reserve(1000);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (std::size_t k = 0; k < 1000; ++k) q.push(k, u(rng));
  const double* first = &q.priority(q.top());
  const std::size_t bound = q.key_bound();
  for (int i = 0; i < 5000; ++i) {
    const std::size_t k = rng() % 1000;
    if (i % 3 == 0) q.erase(k);
    else q.update(k, u(rng));
    if (i % 5 == 0 && !q.empty()) q.pop();
  }
  q.update(0, -1.0);  // make sure the front entry exists
  EXPECT_EQ(&q.priority(q.top()), first);  // heap_ storage never moved
  EXPECT_EQ(q.key_bound(), bound);
}


// ---------------------------------------------------------------------------
// Scratch properties on every backend

template <class G>
class ScratchProperty : public ::testing::Test {};
TYPED_TEST_SUITE(ScratchProperty, genmesh_test::Backends);

template <class G>
G make_mesh(const genmesh::Polygon_soup& soup) {
  G g;
  genmesh::build_mesh(soup, g);
  return g;
}

// Writes f(index) to every element of a range, reads it back, and checks
// get/put and the boost lvalue property map concept.
template <class Tag, class G, class Range>
void check_write_read(G& g, const Range& range) {
  auto m = genmesh::scratch_property<long>(Tag{}, g, -7L);
  using Map = decltype(m);
  using Key = typename boost::property_traits<Map>::key_type;
  BOOST_CONCEPT_ASSERT((boost::LvaluePropertyMapConcept<Map, Key>));
  static_assert(std::is_same_v<decltype(m[std::declval<Key>()]), long&>);
  const auto idx = get(Tag{}, std::as_const(g));
  std::size_t n = 0;
  for (auto d : range) {
    EXPECT_EQ(m[d], -7L);
    put(m, d, static_cast<long>(get(idx, d)) * 3);
    ++n;
  }
  ASSERT_GT(n, 0u);
  const auto copy = m;  // copies share the storage
  for (auto d : range) {
    EXPECT_EQ(get(copy, d), static_cast<long>(get(idx, d)) * 3);
    get(copy, d) += 1;
    EXPECT_EQ(m[d], static_cast<long>(get(idx, d)) * 3 + 1);
  }
}

TYPED_TEST(ScratchProperty, EveryElementKindWritesAndReads) {
  TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(1));
  check_write_read<genmesh::vertex_index_t>(g, vertices(g));
  check_write_read<genmesh::halfedge_index_t>(g, halfedges(g));
  check_write_read<genmesh::edge_index_t>(g, edges(g));
  check_write_read<genmesh::face_index_t>(g, faces(g));
  // On a const graph too (the generic storage).
  const TypeParam& cg = g;
  check_write_read<genmesh::vertex_index_t>(cg, vertices(cg));
  check_write_read<genmesh::face_index_t>(cg, faces(cg));
}

TYPED_TEST(ScratchProperty, BoolIsAnLvalue) {
  TypeParam g = make_mesh<TypeParam>(genmesh::make_cube());
  auto mark = genmesh::scratch_property<bool>(genmesh::face_index, g);
  static_assert(std::is_same_v<decltype(mark[*faces(g).begin()]), bool&>);
  bool& b = mark[*faces(g).begin()];
  b = true;
  std::size_t marked = 0;
  for (auto f : faces(g)) marked += get(mark, f) ? 1 : 0;
  EXPECT_EQ(marked, 1u);
}

// Elements added after the map was made: split every edge and triangulate,
// then the new vertices, halfedges, edges and faces read init and keep what
// is written, and the old ones keep their values.
template <class Tag, class G>
void check_growth(G& g) {
  const auto idx = get(Tag{}, std::as_const(g));
  auto m = genmesh::scratch_property<int>(Tag{}, g, 5);
  auto m_const = genmesh::scratch_property<int>(Tag{}, std::as_const(g), 5);  // generic on every backend
  auto range = [&] {
    if constexpr (std::is_same_v<Tag, genmesh::vertex_index_t>) return vertices(g);
    else if constexpr (std::is_same_v<Tag, genmesh::halfedge_index_t>) return halfedges(g);
    else if constexpr (std::is_same_v<Tag, genmesh::edge_index_t>) return edges(g);
    else return faces(g);
  };
  std::size_t before = 0;
  for (auto d : range()) {
    m[d] = static_cast<int>(get(idx, d));
    m_const[d] = static_cast<int>(get(idx, d)) + 1;
    ++before;
  }
  const std::size_t bound_before = index_bound(Tag{}, g);
  std::vector<genmesh::halfedge_descriptor_t<G>> hs;
  for (auto e : edges(g)) hs.push_back(halfedge(e, g));
  for (auto h : hs) ASSERT_TRUE(genmesh::split_edge_and_triangulate(h, g));
  ASSERT_GT(index_bound(Tag{}, g), bound_before);
  std::size_t fresh = 0, after = 0;
  for (auto d : range()) {
    ++after;
    if (get(idx, d) >= bound_before) {
      ++fresh;
      EXPECT_EQ(m[d], 5);
      EXPECT_EQ(m_const[d], 5);
      m[d] = -static_cast<int>(get(idx, d));
      m_const[d] = -static_cast<int>(get(idx, d)) - 1;
    }
  }
  EXPECT_EQ(fresh, after - before);
  ASSERT_GT(fresh, 0u);
  for (auto d : range()) {
    const int i = static_cast<int>(get(idx, d));
    if (get(idx, d) >= bound_before) {
      EXPECT_EQ(get(m, d), -i);
      EXPECT_EQ(get(m_const, d), -i - 1);
    } else {
      EXPECT_EQ(get(m, d), i);
      EXPECT_EQ(get(m_const, d), i + 1);
    }
  }
}

TYPED_TEST(ScratchProperty, GrowsWithElementsAddedAfterCreation) {
  {
    TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(1));
    check_growth<genmesh::vertex_index_t>(g);
  }
  {
    TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(1));
    check_growth<genmesh::halfedge_index_t>(g);
  }
  {
    TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(1));
    check_growth<genmesh::edge_index_t>(g);
  }
  {
    TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(1));
    check_growth<genmesh::face_index_t>(g);
  }
}

// Natives where the backend's property system grows with the mesh; the
// generic storage elsewhere and on const graphs.
static_assert(genmesh::HasNativeScratchProperty<genmesh_test::Halfedge_mesh, genmesh::vertex_index_t, int>);
static_assert(genmesh::HasNativeScratchProperty<genmesh_test::Incidence_mesh, genmesh::face_index_t, bool>);
static_assert(genmesh::HasNativeScratchProperty<genmesh_test::Surface_mesh, genmesh::edge_index_t, double>);
static_assert(genmesh::HasNativeScratchProperty<genmesh_test::Surface_mesh, genmesh::halfedge_index_t, bool>);
static_assert(!genmesh::HasNativeScratchProperty<const genmesh_test::Halfedge_mesh, genmesh::vertex_index_t, int>);
static_assert(std::is_same_v<decltype(genmesh::scratch_property<int>(genmesh::vertex_index,
                                                                      std::declval<const genmesh_test::Surface_mesh&>())),
                             genmesh::Scratch_property<int, genmesh::vertex_index_t, genmesh_test::Surface_mesh>>);

// A native scratch property lives in the mesh while a copy of it lives, and
// is gone (its memory too) after the last copy.
TYPED_TEST(ScratchProperty, NativeStorageIsReleasedWithTheLastCopy) {
  TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(2));
  const auto count = [&] {
    if constexpr (std::is_same_v<TypeParam, genmesh_test::Surface_mesh>)
      return g.template properties<typename TypeParam::Vertex_index>().size();
    else
      return g.memory_bytes();
  };
  const auto base = count();
  {
    auto m = genmesh::scratch_property<double>(genmesh::vertex_index, g, 1.0);
    auto copy = m;
    {
      auto inner = copy;
      EXPECT_GT(count(), base);
    }
    EXPECT_GT(count(), base);
    m = {};
    EXPECT_GT(count(), base);  // copy still holds it
  }
  EXPECT_EQ(count(), base);
}

// After collect_garbage the native properties follow their elements.
TYPED_TEST(ScratchProperty, NativeValuesFollowGarbageCollection) {
  TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(1));
  auto tag = genmesh::vertex_index;
  auto m = genmesh::scratch_property<int>(tag, g, -1);
  auto pm = get(genmesh::vertex_point, g);
  using P = genmesh::point_t<TypeParam>;
  // Remember each vertex's point in the map (as an id), remove faces around
  // one vertex, collect: every surviving vertex still maps to its id.
  std::vector<Eigen::Vector3d> pts;
  for (auto v : vertices(g)) {
    m[v] = static_cast<int>(pts.size());
    pts.push_back(genmesh::to_eigen(P(get(pm, v))));
  }
  const auto v0 = *vertices(g).begin();
  ASSERT_TRUE(genmesh::collapse_edge(edge(halfedge(v0, g), g), g));
  g.collect_garbage();
  std::size_t n = 0;
  for (auto v : vertices(g)) {
    ASSERT_GE(m[v], 0);
    EXPECT_EQ(genmesh::to_eigen(P(get(pm, v))), pts[static_cast<std::size_t>(m[v])]);
    ++n;
  }
  EXPECT_EQ(n, pts.size() - 1);
}

// ---------------------------------------------------------------------------
// Typed dynamic properties: the same API and behaviour on both genmesh meshes

template <class G>
class MeshProperties : public ::testing::Test {};
using Genmesh_meshes = ::testing::Types<genmesh_test::Halfedge_mesh, genmesh_test::Incidence_mesh>;
TYPED_TEST_SUITE(MeshProperties, Genmesh_meshes);

TYPED_TEST(MeshProperties, AddFindRemoveScoped) {
  using genmesh::Edge_index;
  using genmesh::Vertex_index;
  TypeParam g = make_mesh<TypeParam>(genmesh::make_cube());
  auto w = g.template add_edge_property<double>("e:weight", 1.5);
  for (auto e : edges(g)) EXPECT_EQ(w[e], 1.5);
  w[Edge_index(3)] = 4.0;
  EXPECT_THROW(g.template add_edge_property<double>("e:weight"), genmesh::invalid_input);
  auto found = g.template get_edge_property<double>("e:weight");
  ASSERT_TRUE(found);
  EXPECT_EQ((*found)[Edge_index(3)], 4.0);
  EXPECT_FALSE(g.template get_edge_property<int>("e:weight"));  // wrong type
  EXPECT_FALSE(g.template get_vertex_property<double>("e:weight"));  // wrong kind
  EXPECT_TRUE(g.has_edge_property("e:weight"));
  EXPECT_EQ((g.template property<Edge_index, double>("e:weight")[Edge_index(3)]), 4.0);  // find-or-add finds
  auto names = g.template property_names<Edge_index>();
  EXPECT_NE(std::find(names.begin(), names.end(), "e:weight"), names.end());
  EXPECT_TRUE(g.remove_edge_property(w));
  EXPECT_FALSE(w);
  EXPECT_FALSE(g.has_edge_property("e:weight"));
  EXPECT_FALSE(g.remove_edge_property(w));
  const auto bytes = g.memory_bytes();
  {
    genmesh::Scoped_vertex_property<int> s(g, 3);
    EXPECT_GT(g.memory_bytes(), bytes);
    EXPECT_EQ(s[Vertex_index(0)], 3);
    put(s, Vertex_index(1), 9);
    EXPECT_EQ(get(s, Vertex_index(1)), 9);
    genmesh::Shared_property<genmesh::Face_index, bool> shared(g);
    genmesh::Shared_property<genmesh::Face_index, bool> copy(shared);  // from a non-const lvalue: a copy
    copy[genmesh::Face_index(0)] = true;
    EXPECT_TRUE(shared[genmesh::Face_index(0)]);
  }
  EXPECT_EQ(g.memory_bytes(), bytes);
  // Copies of the mesh copy the properties (found by name in the copy).
  auto id = g.template add_vertex_property<int>("v:id", -1);
  for (auto v : vertices(g)) id[v] = static_cast<int>(v.idx());
  const TypeParam copy = g;
  auto cid = copy.template get_vertex_property<int>("v:id");
  ASSERT_TRUE(cid);
  for (auto v : vertices(copy)) EXPECT_EQ((*cid)[v], static_cast<int>(v.idx()));
}

// Properties follow the elements: added and recycled elements get the
// default; collect_garbage moves values with their elements; both meshes
// (same allocation semantics) agree element for element.
TYPED_TEST(MeshProperties, FollowAddRemoveAndGarbageCollection) {
  using genmesh::Edge_index;
  using genmesh::Face_index;
  using genmesh::Halfedge_index;
  using genmesh::Vertex_index;
  TypeParam g = make_mesh<TypeParam>(genmesh::make_icosphere(1));
  auto vid = g.template add_vertex_property<int>("v:id", -1);
  auto hid = g.template add_halfedge_property<int>("h:id", -1);
  auto eid = g.template add_edge_property<int>("e:id", -1);
  auto fid = g.template add_face_property<int>("f:id", -1);
  for (auto v : vertices(g)) vid[v] = static_cast<int>(v.idx());
  for (auto h : halfedges(g)) hid[h] = static_cast<int>(h.idx());
  for (auto e : edges(g)) eid[e] = static_cast<int>(e.idx());
  for (auto f : faces(g)) fid[f] = static_cast<int>(f.idx());
  // Collapse three edges (removes vertices, edges, faces), then split one:
  // the split recycles removed slots, which must read the defaults.
  for (std::uint32_t e : {0u, 17u, 40u}) {
    if (genmesh::can_collapse_edge(Edge_index(e), g)) {
      ASSERT_TRUE(genmesh::collapse_edge(Edge_index(e), g));
    }
  }
  ASSERT_TRUE(g.has_garbage());
  const auto hnew = genmesh::split_edge_and_triangulate(halfedge(Edge_index(5), g), g);
  ASSERT_TRUE(hnew);
  const Vertex_index vnew = target(*hnew, g);
  EXPECT_EQ(vid[vnew], -1);
  std::size_t defaults = 0;
  for (auto e : edges(g)) defaults += eid[e] == -1 ? 1 : 0;
  EXPECT_EQ(defaults, 3u);  // split_edge_and_triangulate adds three edges
  for (auto h : halfedges(g)) EXPECT_TRUE(hid[h] == -1 || hid[h] == static_cast<int>(h.idx()));
  std::size_t new_faces = 0;
  for (auto f : faces(g)) new_faces += fid[f] == -1 ? 1 : 0;
  EXPECT_EQ(new_faces, 2u);
  // Before collecting, every live element with an id has it at its index.
  std::vector<int> old_v(index_bound(genmesh::vertex_index, g)), old_e(index_bound(genmesh::edge_index, g)),
      old_f(index_bound(genmesh::face_index, g)), old_h(index_bound(genmesh::halfedge_index, g));
  for (auto v : vertices(g)) old_v[v.idx()] = vid[v];
  for (auto h : halfedges(g)) old_h[h.idx()] = hid[h];
  for (auto e : edges(g)) old_e[e.idx()] = eid[e];
  for (auto f : faces(g)) old_f[f.idx()] = fid[f];
  const auto maps = g.collect_garbage();
  EXPECT_FALSE(g.has_garbage());
  for (std::size_t i = 0; i < maps.vertices.size(); ++i)
    if (maps.vertices[i].is_valid()) {
      EXPECT_EQ(vid[maps.vertices[i]], old_v[i]);
    }
  for (std::size_t i = 0; i < maps.halfedges.size(); ++i)
    if (maps.halfedges[i].is_valid()) {
      EXPECT_EQ(hid[maps.halfedges[i]], old_h[i]);
    }
  for (std::size_t i = 0; i < maps.edges.size(); ++i)
    if (maps.edges[i].is_valid()) {
      EXPECT_EQ(eid[maps.edges[i]], old_e[i]);
    }
  for (std::size_t i = 0; i < maps.faces.size(); ++i)
    if (maps.faces[i].is_valid()) {
      EXPECT_EQ(fid[maps.faces[i]], old_f[i]);
    }
  EXPECT_EQ(index_bound(genmesh::vertex_index, g), num_vertices(g));
  // New elements after collection get the default.
  const Vertex_index v = g.add_vertex();
  EXPECT_EQ(vid[v], -1);
}

// Both meshes, the same operations: the same property values everywhere.
TEST(MeshProperties, HalfedgeAndIncidenceMeshesAgree) {
  auto run = [](auto g) {
    auto vid = g.template add_vertex_property<int>("v:id", -1);
    auto eid = g.template add_edge_property<int>("e:id", -1);
    for (auto v : vertices(g)) vid[v] = static_cast<int>(v.idx()) * 10;
    for (auto e : edges(g)) eid[e] = static_cast<int>(e.idx()) * 10;
    for (std::uint32_t e : {2u, 30u, 61u})
      if (genmesh::can_collapse_edge(genmesh::Edge_index(e), g)) (void)genmesh::collapse_edge(genmesh::Edge_index(e), g);
    (void)genmesh::split_edge(halfedge(genmesh::Edge_index(7), g), g);
    g.collect_garbage();
    std::vector<int> out;
    for (auto v : vertices(g)) out.push_back(vid[v]);
    for (auto e : edges(g)) out.push_back(eid[e]);
    return out;
  };
  const auto a = run(make_mesh<genmesh_test::Halfedge_mesh>(genmesh::make_icosphere(1)));
  const auto b = run(make_mesh<genmesh_test::Incidence_mesh>(genmesh::make_icosphere(1)));
  EXPECT_EQ(a, b);
  EXPECT_NE(std::count(a.begin(), a.end(), -1), 0);  // the split's new elements
}

// load_soup replaces the mesh: the properties stay registered, every value
// back to its default, sized to the new elements.
TEST(MeshProperties, IncidenceLoadSoupResetsValues) {
  genmesh_test::Incidence_mesh g = make_mesh<genmesh_test::Incidence_mesh>(genmesh::make_cube());
  auto w = g.add_face_property<int>("f:w", 7);
  for (auto f : faces(g)) w[f] = 1;
  g.load_soup(genmesh::make_icosphere(1));
  ASSERT_TRUE(g.get_face_property<int>("f:w"));
  std::size_t n = 0;
  for (auto f : faces(g)) {
    EXPECT_EQ(w[f], 7);
    ++n;
  }
  EXPECT_EQ(n, 80u);
}


// ---------------------------------------------------------------------------
// The LocalOperations concept

using Polyhedron = CGAL::Polyhedron_3<genmesh_test::Kernel>;
using Polyhedron_with_ids = CGAL::Polyhedron_3<genmesh_test::Kernel, CGAL::Polyhedron_items_with_id_3>;
using Om_poly = OpenMesh::PolyMesh_ArrayKernelT<>;
using Om_tri = OpenMesh::TriMesh_ArrayKernelT<>;

// What algorithms call: every expression of the concept's table through the
// customization point objects themselves. Checked on every model, so the
// concept's rule (generic path or every native hook) and the objects'
// dispatch cannot drift apart.
template <class G>
concept Cpo_local_operations =
    requires(G& g, const G& cg, genmesh::halfedge_descriptor_t<G> h, genmesh::edge_descriptor_t<G> e,
             genmesh::face_descriptor_t<G> f, const std::vector<genmesh::vertex_descriptor_t<G>>& vs) {
      { genmesh::can_flip_edge(h, cg) } -> std::convertible_to<bool>;
      { genmesh::flip_edge(h, g) } -> std::same_as<std::optional<genmesh::halfedge_descriptor_t<G>>>;
      { genmesh::can_split_edge(h, cg) } -> std::convertible_to<bool>;
      { genmesh::split_edge(h, g) } -> std::same_as<std::optional<genmesh::halfedge_descriptor_t<G>>>;
      { genmesh::can_split_edge_and_triangulate(h, cg) } -> std::convertible_to<bool>;
      { genmesh::split_edge_and_triangulate(h, g) } -> std::same_as<std::optional<genmesh::halfedge_descriptor_t<G>>>;
      { genmesh::does_satisfy_link_condition(e, cg) } -> std::convertible_to<bool>;
      { genmesh::can_collapse_edge(e, cg) } -> std::convertible_to<bool>;
      { genmesh::collapse_edge(e, g) } -> std::same_as<std::optional<genmesh::vertex_descriptor_t<G>>>;
      { genmesh::can_split_face(h, h, cg) } -> std::convertible_to<bool>;
      { genmesh::split_face(h, h, g) } -> std::same_as<std::optional<genmesh::halfedge_descriptor_t<G>>>;
      { genmesh::can_join_face(h, cg) } -> std::convertible_to<bool>;
      { genmesh::join_face(h, g) } -> std::same_as<std::optional<genmesh::halfedge_descriptor_t<G>>>;
      { genmesh::can_add_center_vertex(h, cg) } -> std::convertible_to<bool>;
      { genmesh::add_center_vertex(h, g) } -> std::same_as<std::optional<genmesh::halfedge_descriptor_t<G>>>;
      { genmesh::can_triangulate_face(f, cg) } -> std::convertible_to<bool>;
      { genmesh::triangulate_face(f, g) } -> std::convertible_to<bool>;
      { genmesh::euler::can_add_face(vs, cg) } -> std::convertible_to<bool>;
      { genmesh::euler::add_face(vs, g) } -> std::same_as<std::optional<genmesh::face_descriptor_t<G>>>;
      { genmesh::euler::can_remove_face(h, cg) } -> std::convertible_to<bool>;
      { genmesh::euler::remove_face(h, g) } -> std::convertible_to<bool>;
      { genmesh::flip_edge(h, g, std::declval<genmesh::Mutation_visitor&>()) };
      { genmesh::collapse_edge(e, g, std::declval<genmesh::Mutation_visitor&>()) };
    };

template <class G>
constexpr bool models_local_operations() {
  static_assert(genmesh::LocalOperations<G>);
  static_assert(Cpo_local_operations<G>);
  return true;
}
static_assert(models_local_operations<genmesh_test::Halfedge_mesh>());
static_assert(models_local_operations<genmesh_test::Surface_mesh>());
static_assert(models_local_operations<genmesh_test::Incidence_mesh>());
static_assert(models_local_operations<Polyhedron_with_ids>());
static_assert(models_local_operations<Om_poly>());
static_assert(models_local_operations<Om_tri>());
// Incidence_mesh qualifies by its native operations alone (it has no set_next).
static_assert(!genmesh::MutableFaceGraph<genmesh_test::Incidence_mesh>);
static_assert(genmesh::NativeLocalOperations<genmesh_test::Incidence_mesh>);
static_assert(!genmesh::NativeLocalOperations<genmesh_test::Halfedge_mesh>);
// Must not qualify: a const mesh (nothing can change it); a Polyhedron_3
// without ids (a MutableFaceGraph, but triangulate_face needs a vertex
// index map, which it lacks) — and there the objects refuse that call too.
static_assert(!genmesh::LocalOperations<const genmesh_test::Halfedge_mesh>);
static_assert(!genmesh::LocalOperations<const genmesh_test::Incidence_mesh>);
static_assert(genmesh::MutableFaceGraph<Polyhedron> && !genmesh::LocalOperations<Polyhedron>);
static_assert(!Cpo_local_operations<Polyhedron>);
static_assert(!Cpo_local_operations<const genmesh_test::Halfedge_mesh>);

// The scratch property on the adaptors' meshes (the generic storage):
// Polyhedron_3 with ids and OpenMesh, elements added after creation included.
TEST(ScratchPropertyAdaptors, OpenMeshAndPolyhedronWithIds) {
  auto run = [](auto g) {
    genmesh::build_mesh(genmesh::make_icosphere(1), g);
    auto m = genmesh::scratch_property<int>(genmesh::vertex_index, g, 4);
    static_assert(!genmesh::HasNativeScratchProperty<decltype(g), genmesh::vertex_index_t, int>);
    for (auto v : vertices(g)) m[v] = 1;
    std::vector<genmesh::halfedge_descriptor_t<decltype(g)>> hs;
    for (auto e : edges(g)) hs.push_back(halfedge(e, g));
    for (auto h : hs) EXPECT_TRUE(genmesh::split_edge(h, g));
    std::size_t ones = 0, fours = 0;
    for (auto v : vertices(g)) (m[v] == 1 ? ones : fours) += 1;
    EXPECT_EQ(ones, 42u);
    EXPECT_EQ(fours, 120u);
  };
  run(Om_poly{});
  run(Polyhedron_with_ids{});
}

// ---------------------------------------------------------------------------
// Points by vertex index (detail::Point_reader, what simplify reads): the
// mesh's own array where the backend hands it out (HasNativePointArray), a
// copy in double elsewhere; the mesh's points either way.

static_assert(genmesh::HasNativePointArray<genmesh_test::Halfedge_mesh> &&
              genmesh::HasNativePointArray<genmesh_test::Surface_mesh> &&
              genmesh::HasNativePointArray<genmesh_test::Incidence_mesh>);
static_assert(!genmesh::HasNativePointArray<Polyhedron_with_ids> && !genmesh::HasNativePointArray<Om_tri>);

template <class G>
void check_point_reader(G g) {
  genmesh::build_mesh(genmesh::make_icosphere(2), g);
  using P = genmesh::point_t<G>;
  const auto idx = get(genmesh::vertex_index, std::as_const(g));
  auto pm = get(genmesh::vertex_point, g);
  const std::size_t bound = index_bound(genmesh::vertex_index, g);
  genmesh::detail::Point_reader<G> r(g, bound);
  ASSERT_EQ(r.size(), bound);
  for (auto v : vertices(g))
    EXPECT_EQ(Eigen::Vector3d(r[static_cast<std::size_t>(get(idx, v))]), genmesh::to_eigen(P(get(pm, v))));
  // A point written through the map: a native array shows it at once, the
  // copy after set().
  const auto v = *vertices(g).begin();
  const auto i = static_cast<std::size_t>(get(idx, v));
  const Eigen::Vector3d p(0.25, -1.5, 3.0);
  put(pm, v, genmesh::from_eigen<P>(p));
  if constexpr (genmesh::detail::Point_reader<G>::native) {
    EXPECT_EQ(Eigen::Vector3d(r[i]), p);
    EXPECT_EQ(r.address(i), static_cast<const void*>(&get(pm, v)));
  } else {
    EXPECT_NE(Eigen::Vector3d(r[i]), p);
    r.set(i, p);
    EXPECT_EQ(Eigen::Vector3d(r[i]), p);
  }
}

TEST(PointReader, ReadsTheMeshsPointsOnEveryBackend) {
  check_point_reader(genmesh_test::Halfedge_mesh{});
  check_point_reader(genmesh_test::Surface_mesh{});
  check_point_reader(genmesh_test::Incidence_mesh{});
  check_point_reader(Polyhedron_with_ids{});
  check_point_reader(Om_tri{});
}

// ---------------------------------------------------------------------------
// Edges and faces by index (HasNativeDescriptorOfIndex, what simplify uses
// instead of arrays of descriptors): genmesh_native_descriptor(tag, g, i) is
// the descriptor edges(g) / faces(g) yields for index i, with the same
// halfedge.

using genmesh::edge_index_t, genmesh::face_index_t, genmesh::HasNativeDescriptorOfIndex;
static_assert(HasNativeDescriptorOfIndex<genmesh_test::Halfedge_mesh, edge_index_t> &&
              HasNativeDescriptorOfIndex<genmesh_test::Surface_mesh, edge_index_t> &&
              HasNativeDescriptorOfIndex<genmesh_test::Incidence_mesh, edge_index_t>);
static_assert(HasNativeDescriptorOfIndex<genmesh_test::Halfedge_mesh, face_index_t> &&
              HasNativeDescriptorOfIndex<genmesh_test::Surface_mesh, face_index_t> &&
              HasNativeDescriptorOfIndex<genmesh_test::Incidence_mesh, face_index_t> &&
              HasNativeDescriptorOfIndex<Om_tri, face_index_t>);
static_assert(!HasNativeDescriptorOfIndex<Polyhedron_with_ids, edge_index_t> &&
              !HasNativeDescriptorOfIndex<Polyhedron_with_ids, face_index_t> &&
              !HasNativeDescriptorOfIndex<Om_tri, edge_index_t>);

template <class G>
void check_descriptor_of_index(G g) {
  genmesh::build_mesh(genmesh::make_icosphere(2), g);
  // Three edges and two faces gone (their indices stay holes): the others
  // keep theirs.
  ASSERT_TRUE(genmesh::collapse_edge(*std::next(edges(g).begin(), 7), g));
  // Every element's descriptor made from its index is the one the range yields.
  auto check = [&](auto tag, const auto& range) {
    const auto index = get(tag, std::as_const(g));
    for (auto x : range) {
      const auto made = genmesh_native_descriptor(tag, std::as_const(g), static_cast<std::size_t>(get(index, x)));
      EXPECT_EQ(made, x);
      EXPECT_EQ(halfedge(made, g), halfedge(x, g));
    }
  };
  if constexpr (HasNativeDescriptorOfIndex<G, edge_index_t>) check(genmesh::edge_index, edges(g));
  check(genmesh::face_index, faces(g));
}

TEST(DescriptorOfIndex, IsTheDescriptorEdgesAndFacesYield) {
  check_descriptor_of_index(genmesh_test::Halfedge_mesh{});
  check_descriptor_of_index(genmesh_test::Surface_mesh{});
  check_descriptor_of_index(genmesh_test::Incidence_mesh{});
  check_descriptor_of_index(Om_tri{}); // faces only
}

} // namespace
