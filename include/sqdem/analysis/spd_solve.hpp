#pragma once
// The symmetric positive-definite system of the electronic network (a conductance per contact),
// assembled row by row in compressed form (no triplet list) and solved by Eigen's conjugate
// gradients with its diagonal preconditioner. Eigen's headers stay in spd_solve.cpp. (The pore
// voxels' seven-point systems have a solver of their own: voxel_operator.hpp.)

#include <cstdint>
#include <vector>

namespace sqdem {

/// A sparse symmetric matrix, row by row: add a row's entries (any order, repeated columns
/// summed), then endRow.
class SpdRows {
 public:
  void add(std::int64_t column, double value) {
    column_.push_back(column);
    value_.push_back(value);
  }
  void endRow();
  void reserve(std::size_t rows, std::size_t entries);
  std::int64_t rows() const { return static_cast<std::int64_t>(start_.size()) - 1; }

  const std::vector<std::int64_t>& start() const { return start_; }
  const std::vector<std::int64_t>& column() const { return column_; }
  const std::vector<double>& value() const { return value_; }

 private:
  std::vector<std::int64_t> start_{0}, column_;
  std::vector<double> value_;
};

struct SpdSolution {
  std::vector<double> x;
  long iterations = 0;
  bool converged = false;  ///< the tolerance reached within maxIterations
};

/// Solves A x = b from `guess` to the relative residual |r| / |b| <= tolerance, in at most
/// maxIterations iterations.
SpdSolution solveSpd(const SpdRows& A, const std::vector<double>& b, const std::vector<double>& guess, double tolerance,
                     long maxIterations);

}  // namespace sqdem
