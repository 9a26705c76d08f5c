#include "sqdem/analysis/voxel_image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sqdem {

double VoxelImage::porosity() const {
  if (pore.empty()) return 0.0;
  return static_cast<double>(std::count(pore.begin(), pore.end(), std::uint8_t{1})) / static_cast<double>(pore.size());
}

VoxelImage voxelise(std::span<const PlacedShape> particles, const Vec3& lo, const Vec3& hi, const std::array<bool, 3>& periodic,
                    int voxelsAlongLongest) {
  const Vec3 length = hi - lo;
  if (!(length.minCoeff() > 0.0)) throw std::invalid_argument("voxelise: the box's high corner must lie above its low corner on every axis");
  if (voxelsAlongLongest < 1) throw std::invalid_argument("voxelise: at least one voxel along the longest edge");
  VoxelImage image;
  image.origin = lo;
  const double edge = length.maxCoeff() / voxelsAlongLongest;
  for (int d = 0; d < 3; ++d) {
    image.size[d] = std::max(1, static_cast<int>(std::lround(length[d] / edge)));
    image.voxel[d] = length[d] / image.size[d];
  }
  image.pore.assign(image.count(), 1);
  const Vec3& h = image.voxel;
  const auto wrap = [&](int n, int d) { return ((n % image.size[d]) + image.size[d]) % image.size[d]; };
  for (const PlacedShape& p : particles) {
    const double reach = p.shape->boundingRadius();
    const Mat3 toBody = p.orientation.toRotationMatrix().transpose();
    // The voxels whose centres may lie inside: those within the bounding sphere's box.
    std::array<int, 3> first{}, last{};
    for (int d = 0; d < 3; ++d) {
      first[d] = static_cast<int>(std::floor((p.centre[d] - reach - lo[d]) / h[d] - 0.5));
      last[d] = static_cast<int>(std::ceil((p.centre[d] + reach - lo[d]) / h[d] - 0.5));
      if (!periodic[d]) {  // along a periodic axis the voxels beyond the box are the images of those in it
        first[d] = std::max(first[d], 0);
        last[d] = std::min(last[d], image.size[d] - 1);
      }
    }
    for (int k = first[2]; k <= last[2]; ++k) {
      for (int j = first[1]; j <= last[1]; ++j) {
        for (int i = first[0]; i <= last[0]; ++i) {
          const Vec3 centre = lo + h.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
          if (p.shape->gauge(toBody * (centre - p.centre)) >= 1.0) continue;
          image.pore[image.index(wrap(i, 0), wrap(j, 1), wrap(k, 2))] = 0;
        }
      }
    }
  }
  return image;
}

}  // namespace sqdem
