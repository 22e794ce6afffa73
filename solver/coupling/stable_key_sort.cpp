#include "solver/coupling/stable_key_sort.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <utility>

namespace rbcal::solver {

const std::vector<std::uint64_t>& StableKeySort::operator()(const std::vector<std::uint32_t>& key,
                                                            std::uint64_t key_limit) {
  const std::size_t n = key.size();
  if (n > UINT32_MAX) throw std::invalid_argument("stable key sort: more than 2^32 keys");
  if (key_limit > (std::uint64_t{1} << 32)) throw std::invalid_argument("stable key sort: keys wider than 32 bits");
  sorted_.resize(n);
  scratch_.resize(n);
  // A counting sort (one counter per key value) while the values are few against the
  // keys; otherwise passes of at most 11 bits, whose counters stay in the L1 cache.
  constexpr int kMaxDigit = 11;
  if (key_limit <= std::max<std::uint64_t>(std::uint64_t{1} << kMaxDigit, 4 * std::uint64_t{n})) {
    start_.assign(key_limit, 0);
    for (const std::uint32_t k : key) ++start_[k];
    std::uint32_t sum = 0;
    for (std::uint32_t& s : start_) sum += std::exchange(s, sum);
    for (std::size_t i = 0; i < n; ++i) sorted_[start_[key[i]]++] = (std::uint64_t{key[i]} << 32) | i;
    return sorted_;
  }
  const int bits = std::bit_width(key_limit - 1);
  const int passes = (bits + kMaxDigit - 1) / kMaxDigit;
  const int digit = (bits + passes - 1) / passes;  // even digits: fewer counters
  const std::size_t buckets = std::size_t{1} << digit;
  const std::uint32_t mask = static_cast<std::uint32_t>(buckets - 1);
  // The counts of every pass from one read of the keys, then where each digit starts.
  start_.assign(passes * buckets, 0);
  for (const std::uint32_t k : key)
    for (int p = 0; p < passes; ++p) ++start_[p * buckets + ((k >> (p * digit)) & mask)];
  for (int p = 0; p < passes; ++p) {
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < buckets; ++d) sum += std::exchange(start_[p * buckets + d], sum);
  }
  // The first pass reads the keys and writes the records; each later one moves them in
  // order, so records of equal digits keep the order of the pass before.
  std::vector<std::uint64_t>* out = passes % 2 ? &sorted_ : &scratch_;
  for (std::size_t i = 0; i < n; ++i) (*out)[start_[key[i] & mask]++] = (std::uint64_t{key[i]} << 32) | i;
  for (int p = 1; p < passes; ++p) {
    std::vector<std::uint64_t>* in = out;
    out = in == &sorted_ ? &scratch_ : &sorted_;
    std::uint32_t* s = start_.data() + p * buckets;
    for (const std::uint64_t r : *in) (*out)[s[(key_of_record(r) >> (p * digit)) & mask]++] = r;
  }
  return sorted_;
}

}  // namespace rbcal::solver
