#include "common/UnionFind.h"

#include <gtest/gtest.h>

using geolattice::UnionFind;

TEST(UnionFind, LabelsComponentsInOrderOfTheirSmallestElement) {
  UnionFind sets(7);
  sets.unite(5, 1);
  sets.unite(3, 6);
  sets.unite(6, 5);
  std::vector<int> label;
  EXPECT_EQ(sets.labels(label), 4);  // {0}, {1,3,5,6}, {2}, {4}
  EXPECT_EQ(label, (std::vector<int>{0, 1, 2, 1, 3, 1, 1}));
  EXPECT_EQ(sets.find(6), 1);
}
