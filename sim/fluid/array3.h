// sim/fluid/array3.h — a dense 3-D array of values on the solver grid (cells or faces), x fastest.
// Dense storage: see docs/solver.md for the sizes it handles (128³ on 2 cores, 256³ on a workstation).
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <vector>

namespace fluidsound::sim {

/// Integer grid index or extent (i, j, k), x fastest.
using Index3 = std::array<int, 3>;

template <typename T>
class Array3 {
 public:
  Array3() = default;
  Array3(Index3 size, T value = T{}) : size_(size), data_(count(size), value) {}

  const Index3& size() const { return size_; }
  int ni() const { return size_[0]; }
  int nj() const { return size_[1]; }
  int nk() const { return size_[2]; }
  std::size_t elementCount() const { return data_.size(); }

  T& operator()(int i, int j, int k) { return data_[offset(i, j, k)]; }
  const T& operator()(int i, int j, int k) const { return data_[offset(i, j, k)]; }

  /// Value at (i, j, k) with indices clamped to the array (constant extension outside).
  const T& clamped(int i, int j, int k) const {
    return (*this)(clampIndex(i, size_[0]), clampIndex(j, size_[1]), clampIndex(k, size_[2]));
  }

  bool contains(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < size_[0] && j < size_[1] && k < size_[2];
  }

  void fill(const T& value) { std::fill(data_.begin(), data_.end(), value); }
  T* data() { return data_.data(); }
  const T* data() const { return data_.data(); }
  std::vector<T>& values() { return data_; }
  const std::vector<T>& values() const { return data_; }

  std::size_t offset(int i, int j, int k) const {
    assert(contains(i, j, k));
    return (static_cast<std::size_t>(k) * size_[1] + j) * size_[0] + i;
  }

 private:
  static std::size_t count(Index3 s) {
    return static_cast<std::size_t>(s[0]) * s[1] * s[2];
  }
  static int clampIndex(int i, int n) { return i < 0 ? 0 : (i >= n ? n - 1 : i); }

  Index3 size_{0, 0, 0};
  std::vector<T> data_;
};

using Array3f = Array3<float>;
using Array3d = Array3<double>;

}  // namespace fluidsound::sim
