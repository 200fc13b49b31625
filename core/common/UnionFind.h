#pragma once
/// @file UnionFind.h
/// @brief Disjoint sets over 0..n-1 with path halving; the root of a set is its smallest
/// element, so component numbering by first element is deterministic.
#include <algorithm>
#include <numeric>
#include <vector>

namespace geolattice {

/// @class UnionFind
/// @brief unite() and find() in near-constant amortised time.
class UnionFind {
public:
  explicit UnionFind(int n) : parent_(static_cast<size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }

  int find(int v) {
    while (parent_[v] != v) {
      parent_[v] = parent_[parent_[v]];
      v = parent_[v];
    }
    return v;
  }

  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) {
      parent_[std::max(a, b)] = std::min(a, b);
    }
  }

  /// Labels 0..count-1 per element, numbered in order of each set's smallest element.
  int labels(std::vector<int>& label) {
    const int n = static_cast<int>(parent_.size());
    label.assign(n, -1);
    int count = 0;
    for (int v = 0; v < n; ++v) {
      const int r = find(v);
      label[v] = r == v ? count++ : label[r];
    }
    return count;
  }

private:
  std::vector<int> parent_;
};

}  // namespace geolattice
