#include "solver/coupling/stable_key_sort.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace rbcal::solver;

namespace {

// The indices 0..n-1 in the order std::stable_sort gives them by key.
std::vector<std::uint32_t> reference_order(const std::vector<std::uint32_t>& key) {
  std::vector<std::uint32_t> index(key.size());
  std::iota(index.begin(), index.end(), 0u);
  std::stable_sort(index.begin(), index.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  return index;
}

void expect_stable_sort(const std::vector<std::uint32_t>& key, std::uint64_t key_limit) {
  StableKeySort sort;
  const std::vector<std::uint64_t>& sorted = sort(key, key_limit);
  const std::vector<std::uint32_t> expected = reference_order(key);
  ASSERT_EQ(sorted.size(), key.size());
  for (std::size_t i = 0; i < key.size(); ++i) {
    ASSERT_EQ(index_of_record(sorted[i]), expected[i]) << "position " << i << ", key limit " << key_limit;
    ASSERT_EQ(key_of_record(sorted[i]), key[expected[i]]);
  }
}

}  // namespace

TEST(StableKeySort, EqualsAStableSortForEveryKeyWidth) {
  // 5000 keys: a counting sort up to 20000 key values, beyond that one, two and three radix
  // passes, digits that do and do not divide the key width; and few distinct values (many
  // ties, whose order must follow the index).
  std::mt19937 rng(7);
  for (const std::uint64_t limit : {1ull, 2ull, 100ull, 4096ull, 20000ull, 20001ull, 147456ull, 995328ull, 1ull << 22, 10485760ull,
                                    1ull << 32}) {
    std::uniform_int_distribution<std::uint64_t> pick(0, limit - 1);
    std::vector<std::uint32_t> key(5000);
    for (auto& k : key) k = static_cast<std::uint32_t>(pick(rng));
    expect_stable_sort(key, limit);
  }
}

TEST(StableKeySort, KeepsTiesInIndexOrderAndHandlesEmptyInput) {
  expect_stable_sort({5, 3, 5, 3, 0, 5, 0}, 6);
  expect_stable_sort({}, 10);
}

TEST(StableKeySort, ReusedForAnotherKeyRange) {
  // The scratch of a radix sort must not leak into a later counting sort, or back.
  StableKeySort sort;
  std::mt19937 rng(3);
  for (const std::uint64_t limit : {1ull << 30, 50ull, 1ull << 22, 3000ull}) {
    std::uniform_int_distribution<std::uint64_t> pick(0, limit - 1);
    std::vector<std::uint32_t> key(700);
    for (auto& k : key) k = static_cast<std::uint32_t>(pick(rng));
    const std::vector<std::uint64_t>& sorted = sort(key, limit);
    const std::vector<std::uint32_t> expected = reference_order(key);
    for (std::size_t i = 0; i < key.size(); ++i) ASSERT_EQ(index_of_record(sorted[i]), expected[i]);
  }
}

TEST(StableKeySort, RefusesKeysWiderThan32Bits) {
  StableKeySort sort;
  EXPECT_THROW(sort({1, 2}, (1ull << 32) + 1), std::invalid_argument);
}
