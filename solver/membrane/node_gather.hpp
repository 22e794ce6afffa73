#pragma once
// Copies node coordinates into the column blocks that the membrane's element loops
// vectorise over (the elastic triangles, the bending hinges, the volume's triangles):
// four elements at a time, each node's x y z read as one vector and the four transposed
// into the x, y and z columns. The same values as a copy coordinate by coordinate, with
// a third of the loads and a quarter of the stores.
#include <vector>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

// columns[d][i] = x[node_of(i)][d] for d = 0, 1, 2 and i < n. columns must be aligned to
// 32 bytes (the blocks are alignas(64)).
template <int kBlock, class NodeOf>
inline void gather_nodes_to_columns(const std::vector<Vec3>& x, int n, NodeOf node_of, double (*columns)[kBlock]) {
  int i = 0;
#if defined(__AVX2__)
  const __m256i xyz = _mm256_setr_epi64x(-1, -1, -1, 0);  // the lane past z is not read
  for (; i + 4 <= n; i += 4) {
    const __m256d r0 = _mm256_maskload_pd(x[node_of(i)].data(), xyz);
    const __m256d r1 = _mm256_maskload_pd(x[node_of(i + 1)].data(), xyz);
    const __m256d r2 = _mm256_maskload_pd(x[node_of(i + 2)].data(), xyz);
    const __m256d r3 = _mm256_maskload_pd(x[node_of(i + 3)].data(), xyz);
    const __m256d xz01 = _mm256_unpacklo_pd(r0, r1), y01 = _mm256_unpackhi_pd(r0, r1);
    const __m256d xz23 = _mm256_unpacklo_pd(r2, r3), y23 = _mm256_unpackhi_pd(r2, r3);
    _mm256_store_pd(&columns[0][i], _mm256_permute2f128_pd(xz01, xz23, 0x20));
    _mm256_store_pd(&columns[1][i], _mm256_permute2f128_pd(y01, y23, 0x20));
    _mm256_store_pd(&columns[2][i], _mm256_permute2f128_pd(xz01, xz23, 0x31));
  }
#endif
  for (; i < n; ++i) {
    const Vec3& p = x[node_of(i)];
    for (int d = 0; d < 3; ++d) columns[d][i] = p[d];
  }
}

}  // namespace rbcal::solver
