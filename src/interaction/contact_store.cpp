#include "sqdem/interaction/contact_store.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>

#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/math/permutation.hpp"

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

void ContactStore::add(const ContactKey& key, std::uint32_t slotA, std::uint32_t slotB, const Vec3& wallImageOffset) {
  const std::size_t k = size();
  forEachArray(*this, [&](auto& array) {
    if (keeps(&array)) array.push_back(fresh<Element<decltype(array)>>());
  });
  idA[k] = static_cast<std::uint32_t>(key.pair >> 32);
  idB[k] = static_cast<std::uint32_t>(key.pair);
  feature[k] = key.feature;
  a[k] = slotA;
  b[k] = slotB;
  wallImage[k] = wallImageOffset;
  normal[k] = Vec3::UnitZ();
}

std::size_t ContactStore::intactBonds() const {
  return static_cast<std::size_t>(std::ranges::count_if(bond, [](const BondRecord& b) { return b.intact(); }));
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
  if (withBonds && other.withBonds) bond[k] = other.bond[from];
}

void ContactStore::permute(const std::vector<std::uint32_t>& order) {
  forEachArray(*this, [&](auto& array) {
    if (keeps(&array)) sqdem::permute(array, order);
  });
}

void ContactStore::write(std::size_t k, CheckpointWriter& out) const {
  forEachArray(*this, [&](const auto& array) {
    if (keeps(&array)) out.put(array[k]);
  });
}

void ContactStore::read(CheckpointReader& in) {
  forEachArray(*this, [&](auto& array) {
    if (!keeps(&array)) return;
    Element<decltype(array)> value;
    in.get(value);
    array.push_back(value);
  });
}

void ContactStore::writeArrays(CheckpointWriter& out) const {
  for (const bool flag : {withRolling, withCurvatureCache, withTrueGap, withEnergy, withBonds}) out.put(static_cast<std::uint8_t>(flag));
  forEachArray(*this, [&](const auto& array) { out.putVector(array); });
}

ContactStore ContactStore::readArrays(CheckpointReader& in, const ContactStore& layout) {
  ContactStore s;
  for (bool* flag : {&s.withRolling, &s.withCurvatureCache, &s.withTrueGap, &s.withEnergy, &s.withBonds}) {
    std::uint8_t value = 0;
    in.get(value);
    requireIntact(value <= 1, "optional contact arrays");
    *flag = value == 1;
  }
  requireIntact(s.sameOptionalArrays(layout), "optional contact arrays");
  const std::uint64_t anyLength = ~std::uint64_t{0};  // bounded by the bytes left
  std::uint64_t count = 0;
  bool first = true;
  forEachArray(s, [&](auto& array) {
    if (!s.keeps(&array)) {
      in.getVector(array, 0);
      return;
    }
    in.getVector(array, first ? anyLength : count);
    if (first) count = array.size(), first = false;
    requireIntact(array.size() == count, "contact array length");
  });
  return s;
}

}  // namespace sqdem
