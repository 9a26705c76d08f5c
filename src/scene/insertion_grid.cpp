#include "insertion_grid.hpp"

#include <cassert>

namespace sqdem::detail {

InsertionGrid::InsertionGrid(const Domain& domain, double reach, std::size_t expectedCentres)
    : lo_(domain.lo), periodic_(domain.periodic) {
  const Vec3 length = domain.length();
  // 1e-12 L: the margin over the rounding of binning and separations (insertion_grid.hpp).
  const Vec3 width = (reach + 1e-12 * length.array()).matrix();
  // A head per cell: bound the cells by the centres (a tall box of small particles, say).
  const double maxCells = 4.0 * static_cast<double>(expectedCentres) + 4096.0;
  Vec3 n;
  for (double grow = 1.0;; grow *= 1.25) {
    for (int d = 0; d < 3; ++d) n(d) = std::max(1.0, std::floor(length(d) / (grow * width(d))));
    if (n.prod() <= maxCells) break;
  }
  for (int d = 0; d < 3; ++d) {
    n_[d] = static_cast<int>(n(d));
    cell_(d) = length(d) / n(d);
  }
  head_.assign(static_cast<std::size_t>(n.prod()), -1);
}

void InsertionGrid::add(std::uint32_t i, const Vec3& x) {
  assert(i == next_.size());
  const std::size_t c = (static_cast<std::size_t>(cellOf(x, 0)) * n_[1] + cellOf(x, 1)) * n_[2] + cellOf(x, 2);
  next_.push_back(head_[c]);
  head_[c] = static_cast<std::int32_t>(i);
}

}  // namespace sqdem::detail
