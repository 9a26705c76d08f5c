#include "sqdem/interaction/contact_store.hpp"

#include "sqdem/math/permutation.hpp"

#include <type_traits>
#include <utility>

namespace sqdem {
namespace {

/// The value of a fresh contact for each array's element type.
template <typename T>
T fresh() {
  if constexpr (std::is_same_v<T, ContactStatus>) {
    return ContactStatus::Separated;
  } else if constexpr (std::is_same_v<T, Vec3>) {
    return Vec3::Zero();
  } else {
    return T{};
  }
}

template <typename Array>
using Element = typename std::decay_t<Array>::value_type;

}  // namespace

void ContactStore::reserve(std::size_t n) {
  forEachArray(*this, [&](auto& array) {
    if (keeps(&array)) array.reserve(n);
  });
}

void ContactStore::add(std::uint32_t bodyA, std::uint32_t bodyB, const Vec3& bShift, std::uint32_t bFeature) {
  const std::size_t k = size();
  forEachArray(*this, [&](auto& array) {
    if (keeps(&array)) array.push_back(fresh<Element<decltype(array)>>());
  });
  a[k] = bodyA;
  b[k] = bodyB;
  shift[k] = bShift;
  feature[k] = bFeature;
  normal[k] = Vec3::UnitZ();
}

void ContactStore::reset(std::size_t k) {
  std::apply([&](auto... member) {
    ((keeps(&(this->*member)) ? void((this->*member)[k] = fresh<Element<decltype(this->*member)>>()) : void()), ...);
  }, stateArrays);
  normal[k] = Vec3::UnitZ();
}

void ContactStore::carryOver(std::size_t k, const ContactStore& other, std::size_t from) {
  std::apply([&](auto... member) {
    ((keeps(&(this->*member)) && other.keeps(&(other.*member)) ? void((this->*member)[k] = (other.*member)[from])
                                                               : void()),
     ...);
  }, stateArrays);
}

void ContactStore::permute(const std::vector<std::uint32_t>& order) {
  forEachArray(*this, [&](auto& array) {
    if (keeps(&array)) sqdem::permute(array, order);
  });
}

void ContactStore::exchangeBodies(std::size_t k) {
  std::swap(a[k], b[k]);
  const Vec3 s = shift[k];
  shift[k] = -s;
  std::swap(localA[k], localB[k]);
  normal[k] = -normal[k];
  point[k] -= s;
  spring[k] = -spring[k];  // the rolling displacement is symmetric in A and B (001 Eq. 20)
  force[k] = -force[k];
  if (withRolling) moment[k] = -moment[k];
}

}  // namespace sqdem
