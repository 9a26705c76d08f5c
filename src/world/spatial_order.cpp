#include "sqdem/world/spatial_order.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <numeric>

namespace sqdem {

std::vector<std::uint32_t> hilbertOrder(const std::vector<Vec3>& points) {
  using Kernel = CGAL::Simple_cartesian<double>;
  std::vector<Kernel::Point_3> cgalPoints;
  cgalPoints.reserve(points.size());
  for (const Vec3& x : points) cgalPoints.emplace_back(x.x(), x.y(), x.z());
  std::vector<std::size_t> order(points.size());  // the property map's key type
  std::iota(order.begin(), order.end(), std::size_t{0});
  using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(cgalPoints)),
                     CGAL::Hilbert_sort_median_policy());
  return {order.begin(), order.end()};
}

}  // namespace sqdem
