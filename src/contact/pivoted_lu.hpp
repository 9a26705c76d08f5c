#pragma once
// Gaussian elimination with partial pivoting of a small fixed-size system: the detector's 4 x 4
// Newton step. Hand-written although Eigen offers PartialPivLU: Eigen's fixed-size 4 x 4 path
// runs its general-size kernel and also forms the L1 norm for an rcond estimate the detector
// never asks for (13 % of an ellipsoid bed's instructions); this is the same algorithm with the
// loops fixed at compile time.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <utility>

namespace sqdem::detail {

template <int N>
class PivotedLu {
 public:
  using Matrix = Eigen::Matrix<double, N, N>;
  using Vector = Eigen::Matrix<double, N, 1>;

  /// P m = L U, L unit lower triangular; a zero pivot leaves its column unscaled (and the
  /// factorisation not wellConditioned).
  explicit PivotedLu(const Matrix& m) : lu_(m) {
    for (int k = 0; k < N; ++k) {
      int pivot = k;
      for (int i = k + 1; i < N; ++i) {
        if (std::abs(lu_(i, k)) > std::abs(lu_(pivot, k))) pivot = i;
      }
      swaps_[k] = pivot;
      if (pivot != k) lu_.row(k).swap(lu_.row(pivot));
      const double diagonal = lu_(k, k);
      if (diagonal == 0.0) continue;
      for (int i = k + 1; i < N; ++i) {
        lu_(i, k) /= diagonal;
        for (int j = k + 1; j < N; ++j) lu_(i, j) -= lu_(i, k) * lu_(k, j);
      }
    }
  }

  /// Whether the smallest |pivot| exceeds ratio times the largest (a cheap conditioning test).
  bool wellConditioned(double ratio) const {
    const Vector pivots = lu_.diagonal().cwiseAbs();
    return pivots.minCoeff() > ratio * pivots.maxCoeff();
  }

  Vector solve(Vector x) const {
    for (int k = 0; k < N; ++k) std::swap(x(k), x(swaps_[k]));
    for (int i = 1; i < N; ++i) {
      for (int j = 0; j < i; ++j) x(i) -= lu_(i, j) * x(j);
    }
    for (int i = N - 1; i >= 0; --i) {
      for (int j = i + 1; j < N; ++j) x(i) -= lu_(i, j) * x(j);
      x(i) /= lu_(i, i);
    }
    return x;
  }

 private:
  Matrix lu_;
  std::array<int, N> swaps_{};
};

}  // namespace sqdem::detail
