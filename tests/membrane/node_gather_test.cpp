// The vectorised gather of node coordinates into element blocks copies exactly what a
// coordinate-by-coordinate copy would, for every block length (the vector part takes four
// elements at a time, the rest one by one) and for the mesh's last node (whose vector
// read must stop at z).
#include <gtest/gtest.h>

#include <vector>

#include "solver/membrane/node_gather.hpp"

using namespace rbcal::solver;

TEST(NodeGather, CopiesEachNodesCoordinatesIntoTheColumns) {
  constexpr int kBlock = 16;
  std::vector<Vec3> x;
  for (int m = 0; m < 11; ++m) x.emplace_back(1.0 + m, -0.5 * m, 100.0 + 0.25 * m);
  // Repeats, the first and the last node, in no particular order.
  const std::vector<int> nodes = {10, 3, 0, 7, 10, 5, 1, 9, 2, 8, 4, 6, 0, 10, 3};
  for (int n = 0; n <= static_cast<int>(nodes.size()); ++n) {
    alignas(64) double columns[3][kBlock] = {};
    gather_nodes_to_columns<kBlock>(x, n, [&](int i) { return nodes[i]; }, columns);
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(columns[d][i], x[nodes[i]][d]) << "block length " << n << ", element " << i << ", coordinate " << d;
    for (int i = n; i < kBlock; ++i)
      for (int d = 0; d < 3; ++d) EXPECT_EQ(columns[d][i], 0.0) << "written past the block length " << n;
  }
}
