// The shared layer under every algorithm: the mutable priority queue.
#include <genmesh/priority_queue.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
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

} // namespace
