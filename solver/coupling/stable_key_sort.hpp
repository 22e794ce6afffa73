#pragma once
// A stable sort of 32-bit keys whose cost does not grow with the key range. The membrane
// nodes' keys are lattice indices: a counting sort over the whole lattice (one counter per
// lattice node, cleared and summed at every membrane update) costs more than the nodes
// themselves once the lattice holds many more nodes than the membranes, so there the keys
// go through an LSD radix sort in passes of at most 11 bits instead.
#include <cstdint>
#include <vector>

namespace rbcal::solver {

class StableKeySort {
 public:
  // One record (key << 32) | i per key[i], in ascending key order, equal keys in ascending
  // i. key_limit: every key is below it. The records live until the next call.
  const std::vector<std::uint64_t>& operator()(const std::vector<std::uint32_t>& key, std::uint64_t key_limit);

 private:
  std::vector<std::uint64_t> sorted_, scratch_;
  std::vector<std::uint32_t> start_;
};

inline std::uint32_t key_of_record(std::uint64_t r) { return static_cast<std::uint32_t>(r >> 32); }
inline std::uint32_t index_of_record(std::uint64_t r) { return static_cast<std::uint32_t>(r); }

}  // namespace rbcal::solver
