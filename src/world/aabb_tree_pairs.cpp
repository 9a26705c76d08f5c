// Candidate pairs from FCL's dynamic AABB tree (neighbour_list.hpp). Each particle is a sphere of
// its bounding radius + skin/2; the tree reports pairs whose boxes overlap and the sphere test
// keeps those closer than the skin. The result is sorted, so it does not depend on the tree's
// traversal order.
#include <algorithm>
#include <cstdint>
#include <memory>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision_object.h>

#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {
namespace {

struct Search {
  const ParticleCloud& cloud;
  double skin;
  std::vector<CandidatePair> found;
};

std::uint32_t indexOf(const fcl::CollisionObjectd* o) {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(o->getUserData()));
}

bool considerPair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  Search& s = *static_cast<Search*>(data);
  const std::uint32_t i = indexOf(o1), j = indexOf(o2);
  if (i != j && withinSkin(s.cloud, i, j, candidateDistanceSquared(s.cloud, i, j), s.skin)) s.found.push_back(oriented(s.cloud, i, j));
  return false;  // keep going
}

}  // namespace

std::vector<CandidatePair> aabbTreePairs(const ParticleCloud& cloud, double skin) {
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

  Search search{cloud, skin, {}};
  tree.collide(&search, considerPair);
  std::sort(search.found.begin(), search.found.end(),
            [](const CandidatePair& x, const CandidatePair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  return std::move(search.found);
}

}  // namespace sqdem
