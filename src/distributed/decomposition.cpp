#include "sqdem/distributed/decomposition.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace sqdem {
namespace {

/// A box being cut and the ranks [first, first + count) it is shared by.
struct Part {
  SubDomain box;
  int first, count;
};

/// Bisection steps per cut: the cut is then within 2^-52 of its interval of the exact one.
constexpr int bisectionSteps = 52;

}  // namespace

SubDomain wholeBox(const Domain& box) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  SubDomain whole{box.lo, box.hi};
  for (int d = 0; d < 3; ++d) {
    if (!box.periodic[d]) whole.lo(d) = -inf, whole.hi(d) = inf;
  }
  return whole;
}

std::vector<SubDomain> bisect(const Domain& box, std::span<const Vec3> points, std::span<const double> costs, int ranks,
                              const Communicator& communicator) {
  if (ranks < 1) throw std::invalid_argument("bisect: at least one rank");
  if (points.size() != costs.size()) throw std::invalid_argument("bisect: a cost per point");
  std::vector<Part> parts{{wholeBox(box), 0, ranks}};
  std::vector<std::size_t> partOf(points.size(), 0);
  while (std::any_of(parts.begin(), parts.end(), [](const Part& p) { return p.count > 1; })) {
    const std::size_t n = parts.size();
    // Each part's cut direction (its longest edge within the box) and the interval searched:
    // the edge, widened to the points beyond it along an open direction.
    std::vector<int> axis(n);
    std::vector<double> from(n), to(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3 lo = parts[k].box.lo.cwiseMax(box.lo), hi = parts[k].box.hi.cwiseMin(box.hi);
      (hi - lo).maxCoeff(&axis[k]);
      from[k] = lo(axis[k]);
      to[k] = hi(axis[k]);
    }
    std::vector<double> low(from), high(to);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::size_t k = partOf[i];
      low[k] = std::min(low[k], points[i](axis[k]));
      high[k] = std::max(high[k], points[i](axis[k]));
    }
    communicator.min(low);
    communicator.max(high);
    // The cost each part holds, and the share its lower side must get.
    std::vector<ExactSum> total(n);
    for (std::size_t i = 0; i < points.size(); ++i) total[partOf[i]].add(costs[i]);
    communicator.sum(total);
    std::vector<double> target(n);
    for (std::size_t k = 0; k < n; ++k) target[k] = total[k].value() * (parts[k].count / 2) / parts[k].count;
    // Bisection: the least coordinate (to 2^-52 of the interval) with at least the target below it.
    std::vector<double> a(low), b(high);
    for (int step = 0; step < bisectionSteps; ++step) {
      std::vector<double> trial(n);
      for (std::size_t k = 0; k < n; ++k) trial[k] = 0.5 * (a[k] + b[k]);
      std::vector<ExactSum> below(n);
      for (std::size_t i = 0; i < points.size(); ++i) {
        const std::size_t k = partOf[i];
        if (points[i](axis[k]) < trial[k]) below[k].add(costs[i]);
      }
      communicator.sum(below);
      for (std::size_t k = 0; k < n; ++k) (below[k].value() < target[k] ? a[k] : b[k]) = trial[k];
    }
    std::vector<Part> next;
    std::vector<std::size_t> lowerOf(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Part& p = parts[k];
      lowerOf[k] = next.size();
      if (p.count == 1) {
        next.push_back(p);
        continue;
      }
      // A part without cost is cut in the middle of its edge.
      const double cut = total[k].value() > 0.0 ? b[k] : 0.5 * (from[k] + to[k]);
      Part lower = p, upper = p;
      lower.box.hi(axis[k]) = upper.box.lo(axis[k]) = cut;
      lower.count = p.count / 2;
      upper.first = p.first + lower.count;
      upper.count = p.count - lower.count;
      next.push_back(lower);
      next.push_back(upper);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::size_t k = partOf[i];
      partOf[i] = lowerOf[k] + (parts[k].count > 1 && !(points[i](axis[k]) < next[lowerOf[k]].box.hi(axis[k])) ? 1 : 0);
    }
    parts = std::move(next);
  }
  std::vector<SubDomain> result(ranks);
  for (const Part& p : parts) result[p.first] = p.box;
  return result;
}

int ownerOf(const std::vector<SubDomain>& parts, const Vec3& x) {
  for (std::size_t r = 0; r < parts.size(); ++r) {
    if (parts[r].owns(x)) return static_cast<int>(r);
  }
  throw std::logic_error("ownerOf: a centre outside every sub-domain (not wrapped into the box?)");
}

}  // namespace sqdem
