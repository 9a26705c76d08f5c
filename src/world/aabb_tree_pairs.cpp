// Candidate pairs from FCL's dynamic AABB tree (neighbour_list.hpp). Each particle is a sphere of
// its bounding radius + skin/2; the tree reports pairs whose boxes overlap and the sphere test
// keeps those closer than the skin. Periodic images: a particle within reach of a periodic face
// is queried again at each image position it has there. The result is sorted, so it does not
// depend on the tree's traversal order.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision_object.h>

#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {
namespace {

struct Found {
  CandidatePair pair;
  double distanceSquared;
};

struct Search {
  const ParticleCloud& cloud;
  double skin;
  std::uint32_t query = 0;        ///< the queried particle, for image queries
  Vec3 shift = Vec3::Zero();      ///< the queried image is at position[query] + shift
  std::vector<Found> found;

  /// Records i seen from j at position[i] + s, oriented by id.
  void consider(std::uint32_t i, std::uint32_t j, const Vec3& s) {
    if (i == j) return;
    const double d2 = candidateDistanceSquared(cloud, j, i, s);
    if (withinSkin(cloud, j, i, d2, skin)) found.push_back({oriented(cloud, j, i, s), d2});
  }
};

std::uint32_t indexOf(const fcl::CollisionObjectd* o) {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(o->getUserData()));
}

bool selfPair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  static_cast<Search*>(data)->consider(indexOf(o1), indexOf(o2), Vec3::Zero());
  return false;  // keep going
}

bool imagePair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  Search& s = *static_cast<Search*>(data);
  // One of the two is the image (it carries the queried index); the other is a tree member.
  s.consider(s.query, indexOf(o1) == s.query ? indexOf(o2) : indexOf(o1), s.shift);
  return false;
}

}  // namespace

std::vector<CandidatePair> aabbTreePairs(const Domain& domain, const ParticleCloud& cloud, double skin) {
  const std::vector<Vec3>& position = cloud.position;
  const std::vector<double>& radius = cloud.radius;
  const std::size_t n = position.size();
  if (n < 2) return {};
  std::vector<std::shared_ptr<fcl::Sphered>> spheres;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  std::vector<fcl::CollisionObjectd*> registered;
  objects.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    fcl::Transform3d pose = fcl::Transform3d::Identity();
    pose.translation() = position[i];
    spheres.push_back(std::make_shared<fcl::Sphered>(radius[i] + 0.5 * skin));
    auto& o = objects.emplace_back(std::make_unique<fcl::CollisionObjectd>(spheres.back(), pose));
    o->setUserData(reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
    registered.push_back(o.get());
  }
  fcl::DynamicAABBTreeCollisionManagerd tree;
  tree.registerObjects(registered);
  tree.setup();

  Search search{cloud, skin};
  tree.collide(&search, selfPair);

  const double maxRadius = *std::max_element(radius.begin(), radius.end());
  const Vec3 L = domain.length();
  for (std::uint32_t i = 0; i < n; ++i) {
    // Image offsets per direction: 0, and +-L where the particle is within reach of a face.
    const double margin = radius[i] + maxRadius + skin;
    std::array<std::array<double, 3>, 3> options{};
    std::array<int, 3> count{};
    for (int d = 0; d < 3; ++d) {
      options[d][count[d]++] = 0.0;
      if (!domain.periodic[d]) continue;
      if (position[i](d) - domain.lo(d) < margin) options[d][count[d]++] = L(d);
      if (domain.hi(d) - position[i](d) < margin) options[d][count[d]++] = -L(d);
    }
    for (int x = 0; x < count[0]; ++x) {
      for (int y = 0; y < count[1]; ++y) {
        for (int z = 0; z < count[2]; ++z) {
          if (x == 0 && y == 0 && z == 0) continue;
          search.query = i;
          search.shift = Vec3(options[0][x], options[1][y], options[2][z]);
          fcl::Transform3d pose = fcl::Transform3d::Identity();
          pose.translation() = position[i] + search.shift;
          fcl::CollisionObjectd image(spheres[i], pose);
          image.setUserData(reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
          tree.collide(&image, &search, imagePair);
        }
      }
    }
  }

  // Each pair once, the nearest image where a narrow box offers several.
  std::vector<Found>& f = search.found;
  std::sort(f.begin(), f.end(), [](const Found& x, const Found& y) {
    if (x.pair.a != y.pair.a) return x.pair.a < y.pair.a;
    if (x.pair.b != y.pair.b) return x.pair.b < y.pair.b;
    return x.distanceSquared < y.distanceSquared;
  });
  std::vector<CandidatePair> pairs;
  pairs.reserve(f.size());
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (k > 0 && f[k].pair.a == f[k - 1].pair.a && f[k].pair.b == f[k - 1].pair.b) continue;
    pairs.push_back(f[k].pair);
  }
  return pairs;
}

}  // namespace sqdem
