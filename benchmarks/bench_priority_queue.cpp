// Mutable priority queues on the edge-collapse access pattern: genmesh's
// Mutable_priority_queue (indexed 4-ary heap) against Boost.Heap's mutable
// heaps and CGAL's Modifiable_priority_queue.
//
//   build-bench/benchmarks/genmesh_benchmarks --benchmark_filter=PriorityQueue
//       --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
//       --benchmark_report_aggregates_only=true
//
// The pattern (what a simplifier does): 1M keys with random costs are pushed;
// then, until 10% remain: pop the top, erase 6 keys near it (the edges the
// collapse removes), give 10 live keys near it new random costs (the edges
// whose cost changes; some rise, some fall). "Near" is a random offset within
// ±2048 of the popped key, like the index locality of a mesh's neighbours.
// Every queue sees the same operation stream (the stream depends on the popped
// keys only, and all queues pop the same sequence: the checksum counter says
// so). Boost.Heap's heaps are max-heaps: they get the reversed order.
#include <genmesh/priority_queue.h>

#include <CGAL/Modifiable_priority_queue.h>

#include <boost/heap/d_ary_heap.hpp>
#include <boost/heap/fibonacci_heap.hpp>
#include <boost/heap/pairing_heap.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

namespace {

constexpr std::size_t key_count = 1'000'000;

const std::vector<double>& initial_costs() {
  static const std::vector<double> costs = [] {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> c(key_count);
    for (double& x : c) x = u(rng);
    return c;
  }();
  return costs;
}

// (priority, key) ordered by priority then key: the same total order for all.
struct Item {
  double cost;
  std::size_t key;
};
struct Item_greater {  // Boost.Heap max-heap → min by (cost, key)
  bool operator()(const Item& a, const Item& b) const {
    return a.cost > b.cost || (a.cost == b.cost && a.key > b.key);
  }
};

// The uniform interface the driver uses.
struct Genmesh_queue {
  genmesh::Mutable_priority_queue<double> q{key_count};
  void push(std::size_t k, double c) { q.push(k, c); }
  void update(std::size_t k, double c) { q.update(k, c); }
  void erase(std::size_t k) { q.erase(k); }
  std::size_t pop() { return q.pop(); }
  std::size_t size() const { return q.size(); }
};

template <class Heap>
struct Boost_queue {
  Heap heap;
  std::vector<typename Heap::handle_type> handle = std::vector<typename Heap::handle_type>(key_count);
  std::vector<char> in = std::vector<char>(key_count, 0);
  void push(std::size_t k, double c) {
    handle[k] = heap.push(Item{c, k});
    in[k] = 1;
  }
  void update(std::size_t k, double c) {
    if (in[k]) heap.update(handle[k], Item{c, k});
    else push(k, c);
  }
  void erase(std::size_t k) {
    if (!in[k]) return;
    heap.erase(handle[k]);
    in[k] = 0;
  }
  std::size_t pop() {
    const std::size_t k = heap.top().key;
    heap.pop();
    in[k] = 0;
    return k;
  }
  std::size_t size() const { return heap.size(); }
};

// CGAL's queue holds keys; the comparator reads the costs from an array (as
// CGAL's edge-collapse does with its edge data).
struct Key_less {
  const std::vector<double>* cost;
  bool operator()(std::size_t a, std::size_t b) const {
    const double ca = (*cost)[a], cb = (*cost)[b];
    return ca < cb || (ca == cb && a < b);
  }
};
template <CGAL::Heap_type type>
struct Cgal_queue {
  std::vector<double> cost = std::vector<double>(key_count);
  CGAL::Modifiable_priority_queue<std::size_t, Key_less, boost::identity_property_map, type> q{
      key_count, Key_less{&cost}, boost::identity_property_map{}};
  std::size_t n = 0;
  void push(std::size_t k, double c) {
    cost[k] = c;
    q.push(k);
    ++n;
  }
  void update(std::size_t k, double c) {
    if (!q.contains(k)) return push(k, c);
    cost[k] = c;
    q.update(k);
  }
  void erase(std::size_t k) {
    if (!q.contains(k)) return;
    q.erase(k);
    --n;
  }
  std::size_t pop() {
    const std::size_t k = q.top();
    q.pop();
    --n;
    return k;
  }
  std::size_t size() const { return n; }
};

// Builds the queue and runs the collapse loop; returns a checksum of the pops.
template <class Q>
std::uint64_t collapse_pattern(Q& q) {
  const std::vector<double>& costs = initial_costs();
  for (std::size_t k = 0; k < key_count; ++k) q.push(k, costs[k]);
  std::vector<char> alive(key_count, 1);
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto near = [&](std::size_t k) {
    const std::int64_t j = static_cast<std::int64_t>(k) + static_cast<std::int64_t>(rng() % 4097) - 2048;
    return static_cast<std::size_t>(std::clamp<std::int64_t>(j, 0, key_count - 1));
  };
  std::uint64_t checksum = 0;
  while (q.size() > key_count / 10) {
    const std::size_t k = q.pop();
    alive[k] = 0;
    checksum = checksum * 1000003u + k;
    for (int i = 0; i < 6; ++i) {
      const std::size_t n = near(k);
      q.erase(n);
      alive[n] = 0;
    }
    for (int i = 0; i < 10; ++i) {
      const std::size_t n = near(k);
      const double c = u(rng);
      if (alive[n]) q.update(n, c);
    }
  }
  return checksum;
}

template <class Q>
void BM_PriorityQueue(benchmark::State& state) {
  std::uint64_t checksum = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto q = std::make_unique<Q>();
    state.ResumeTiming();
    checksum = collapse_pattern(*q);
    benchmark::DoNotOptimize(checksum);
    state.PauseTiming();
    q.reset();
    state.ResumeTiming();
  }
  state.counters["checksum_low"] = static_cast<double>(checksum % 1000000);
}

using Boost_dary4 = boost::heap::d_ary_heap<Item, boost::heap::arity<4>, boost::heap::mutable_<true>,
                                            boost::heap::compare<Item_greater>>;
using Boost_pairing = boost::heap::pairing_heap<Item, boost::heap::compare<Item_greater>>;
using Boost_fibonacci = boost::heap::fibonacci_heap<Item, boost::heap::compare<Item_greater>>;

BENCHMARK_TEMPLATE(BM_PriorityQueue, Genmesh_queue)->Name("PriorityQueue/genmesh_4ary")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_PriorityQueue, Cgal_queue<CGAL::CGAL_BOOST_PENDING_MUTABLE_QUEUE>)
    ->Name("PriorityQueue/cgal_mutable_queue")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_PriorityQueue, Cgal_queue<CGAL::CGAL_BOOST_PAIRING_HEAP>)
    ->Name("PriorityQueue/cgal_pairing_heap")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_PriorityQueue, Boost_queue<Boost_dary4>)
    ->Name("PriorityQueue/boost_d_ary_4_mutable")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_PriorityQueue, Boost_queue<Boost_pairing>)
    ->Name("PriorityQueue/boost_pairing")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_PriorityQueue, Boost_queue<Boost_fibonacci>)
    ->Name("PriorityQueue/boost_fibonacci")
    ->Unit(benchmark::kMillisecond);

} // namespace
