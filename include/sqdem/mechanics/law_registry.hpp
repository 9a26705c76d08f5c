#pragma once
// The normal contact laws by name: one registry for the scene loader (`interactions[k].normal`),
// the engine (contact_model.hpp holds the chosen law) and the single-contact driver
// (`sqdem contact`, its `law.type`). Each entry reads and validates the law's own keys from a
// LawInput; the law is then a value of NormalLaw, evaluated by static dispatch (std::visit).
//
//   name                 component               seed, equations                  history
//   elliptic_hertz       HertzLaw                004 Eqs. 1-2, 11-14              -
//     + roughness {sigma, asperity_count}: GreenwoodWilliamsonLaw, 004 Eqs. 29-36  -
//   volume_sphere_hertz  HertzLaw on the volume-equivalent spheres (no curvatures)  -
//   becker_kamlah        BeckerKamlahLaw         002 Eqs. 1-54                    largest overlap
//     + surface_energy: JKR on its elastic contact, Thornton-Ning style            + attached
//   haervig_jkr          HaervigJkrLaw           001 Eqs. 7-10, 24                -
//   elliptic_jkr         EllipticJkrLaw          004 Eqs. 19-28, 001 Eq. 24       attached
//     + roughness: RoughJkrLaw, Eq. 29 with elliptic JKR asperities                 -
//   nan_adhesive         NanAdhesiveLaw          000 Eqs. 1-67                    attached, alpha_max
//   jamari               JamariLaw               004 Eqs. 41-46 + elastic unloading  largest overlap
//   true_gap             TrueGapLaw              half-space contact of the true gap   (rungs kept
//                                                (docs/contact_laws.md)               per contact)

#include <optional>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "sqdem/mechanics/becker_kamlah.hpp"
#include "sqdem/mechanics/haervig.hpp"
#include "sqdem/mechanics/hertz_law.hpp"
#include "sqdem/mechanics/jamari.hpp"
#include "sqdem/mechanics/jkr_elliptic.hpp"
#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/mechanics/nan_adhesive.hpp"
#include "sqdem/mechanics/roughness_gw.hpp"
#include "sqdem/mechanics/true_gap_law.hpp"

namespace sqdem {

using NormalLaw = std::variant<HertzLaw, GreenwoodWilliamsonLaw, BeckerKamlahLaw, HaervigJkrLaw, EllipticJkrLaw,
                               RoughJkrLaw, NanAdhesiveLaw, JamariLaw, TrueGapLaw>;

/// Whether a law holds contacts by adhesion.
enum class Adhesion : std::uint8_t { Never, WithSurfaceEnergy, Always };

/// What a registered law is, for the messages that name the laws able to do something.
struct LawTraits {
  Adhesion adhesion = Adhesion::Never;
  bool plastic = false;       ///< it yields (YieldingLaw)
  bool storesEnergy = false;  ///< it states its stored energy (StoredEnergyLaw), when not adhesive
};
template <class L>
constexpr LawTraits traitsOf(Adhesion adhesion) {
  return {adhesion, YieldingLaw<L>, StoredEnergyLaw<L>};
}

struct NormalLawEntry {
  std::string_view name;
  bool curvatures;  ///< uses the detector's curvatures (else the volume-equivalent spheres)
  std::span<const std::string_view> keys;  ///< the law's own keys
  NormalLaw (*read)(const LawInput& in, const PairElasticity& pair);
  LawTraits traits;
};

std::span<const NormalLawEntry> normalLaws();
/// The names of the registered laws `pick` chooses, as "a, b or c" (for messages).
std::string lawNames(bool (*pick)(const NormalLawEntry&));
/// The entry named `name`; `in.fail(key, ...)` listing the names when there is none, and after
/// them `alsoAllowed`: the laws the caller takes outside the registry.
const NormalLawEntry& normalLaw(std::string_view name, const LawInput& in, std::string_view key,
                                std::span<const std::string_view> alsoAllowed = {});
/// The law of `entry` from `in`: every key present must be the source's or the law's (a key of
/// another law is named as such), then the law validates its values.
NormalLaw readNormalLaw(const NormalLawEntry& entry, const LawInput& in, const PairElasticity& pair);

/// Whether the law holds contacts by adhesion (AdhesiveLaw of normal_law.hpp).
inline bool adhesive(const NormalLaw& law) {
  return std::visit([](const auto& l) {
    if constexpr (AdhesiveLaw<std::decay_t<decltype(l)>>) {
      return l.adhesive();
    } else {
      return false;
    }
  }, law);
}

/// std::invalid_argument when the law's parameters admit no contact like `c` (CheckedLaw).
inline void checkContact(const NormalLaw& law, const NormalContact& c) {
  std::visit([&](const auto& l) {
    if constexpr (CheckedLaw<std::decay_t<decltype(l)>>) l.check(c);
  }, law);
}

/// Where a plastic law first yields at this contact (YieldingLaw); none for the others.
inline std::optional<YieldPoint> yieldPoint(const NormalLaw& law, const NormalContact& c) {
  return std::visit([&](const auto& l) -> std::optional<YieldPoint> {
    if constexpr (YieldingLaw<std::decay_t<decltype(l)>>) {
      return l.yieldPoint(c);
    } else {
      return std::nullopt;
    }
  }, law);
}

/// The law's own constants at this contact (ReportingLaw); the Hertz factors e^2, gamma, beta
/// for a law without its own.
inline std::vector<LawConstant> lawConstants(const NormalLaw& law, const NormalContact& c) {
  return std::visit([&](const auto& l) -> std::vector<LawConstant> {
    if constexpr (ReportingLaw<std::decay_t<decltype(l)>>) {
      return l.constants(c);
    } else {
      return {{"e2", c.factors.e2}, {"gamma", c.factors.gamma}, {"beta", c.factors.beta}};
    }
  }, law);
}

/// A law's response through its own history type, kept in a contact's NormalHistory slot.
template <NormalLawComponent Law>
NormalResponse normalResponse(const Law& law, const NormalContact& c, double overlap, NormalHistory& slot) {
  auto h = slot.load<typename Law::History>();
  const NormalResponse r = law.force(c, overlap, h);
  slot.store(h);
  return r;
}
inline NormalResponse normalResponse(const NormalLaw& law, const NormalContact& c, double overlap, NormalHistory& slot) {
  return std::visit([&](const auto& l) { return normalResponse(l, c, overlap, slot); }, law);
}

/// range(history) of normal_law.hpp (m).
template <NormalLawComponent Law>
double normalRange(const Law& law, const NormalHistory& slot) {
  return law.range(slot.load<typename Law::History>());
}
inline double normalRange(const NormalLaw& law, const NormalHistory& slot) {
  return std::visit([&](const auto& l) { return normalRange(l, slot); }, law);
}

/// Whether the law states its contacts' stored energy (StoredEnergyLaw): the energy ledger
/// needs it of every law in a scene.
inline bool storesEnergy(const NormalLaw& law) {
  return std::visit([](const auto& l) {
    if constexpr (StoredEnergyLaw<std::decay_t<decltype(l)>>) {
      return l.storesEnergy();
    } else {
      return false;
    }
  }, law);
}

/// The stored energy (J) of a contact whose law just gave `force` (N) at this overlap; 0 for a
/// law that does not state it.
template <NormalLawComponent Law>
double storedEnergy(const Law& law, const NormalContact& c, double overlap, const NormalHistory& slot, double force) {
  if constexpr (StoredEnergyLaw<Law>) {
    return law.storedEnergy(c, overlap, slot.load<typename Law::History>(), force);
  } else {
    return 0.0;
  }
}

/// reach(E*, R) of normal_law.hpp (m); throws std::invalid_argument when the law admits no
/// contact of relative radius R.
inline double normalReach(const NormalLaw& law, double effectiveModulus, double R) {
  return std::visit([&](const auto& l) { return l.reach(effectiveModulus, R); }, law);
}

}  // namespace sqdem
