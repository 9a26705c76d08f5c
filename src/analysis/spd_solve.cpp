#include "sqdem/analysis/spd_solve.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <algorithm>

namespace sqdem {

void SpdRows::endRow() {
  // Sorted columns, each once (Eigen's compressed storage).
  const std::int64_t begin = start_.back(), end = static_cast<std::int64_t>(column_.size());
  for (std::int64_t i = begin + 1; i < end; ++i) {
    for (std::int64_t j = i; j > begin && column_[j - 1] > column_[j]; --j) {
      std::swap(column_[j - 1], column_[j]);
      std::swap(value_[j - 1], value_[j]);
    }
  }
  std::int64_t kept = begin;
  for (std::int64_t i = begin; i < end; ++i) {
    if (kept > begin && column_[kept - 1] == column_[i]) {
      value_[kept - 1] += value_[i];
    } else {
      column_[kept] = column_[i];
      value_[kept++] = value_[i];
    }
  }
  column_.resize(kept);
  value_.resize(kept);
  start_.push_back(kept);
}

void SpdRows::reserve(std::size_t rows, std::size_t entries) {
  start_.reserve(rows + 1);
  column_.reserve(entries);
  value_.reserve(entries);
}

SpdSolution solveSpd(const SpdRows& A, const std::vector<double>& b, const std::vector<double>& guess, double tolerance,
                     long maxIterations) {
  const std::int64_t n = A.rows();
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, std::int64_t>;
  // A view of the rows (the solver binds a Ref to it: no copy).
  const Eigen::Map<const Matrix> matrix(n, n, static_cast<std::int64_t>(A.value().size()), A.start().data(), A.column().data(),
                                        A.value().data());
  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(tolerance);
  cg.setMaxIterations(maxIterations);
  cg.compute(matrix);
  const Eigen::VectorXd x = cg.solveWithGuess(Eigen::Map<const Eigen::VectorXd>(b.data(), n), Eigen::Map<const Eigen::VectorXd>(guess.data(), n));
  return {std::vector<double>(x.data(), x.data() + n), static_cast<long>(cg.iterations()), cg.info() == Eigen::Success};
}

}  // namespace sqdem
