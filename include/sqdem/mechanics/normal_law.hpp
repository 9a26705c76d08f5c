#pragma once
// What every normal contact law is (docs/architecture.md, "Layers": a law is a value type): its parameters,
// read and validated once from a LawInput (law_registry.hpp); a History record of its own,
// trivially copyable, whose all-zero bytes are a fresh contact's; and three functions:
//   force(contact, overlap, history)  the rate-independent normal response at this overlap,
//                                      updating the history (damping is added by the pair
//                                      composition, interaction of the world: contact_model.hpp)
//   range(history)                     the largest gap (m) it acts across in this state: 0 for
//                                      touching-only laws, 4 sigma for rough contacts, infinite
//                                      for an attached adhesive contact (it then decides itself
//                                      where it detaches); the pair keeps its history while
//                                      within range, also when the law does not act there
//   reach(E*, R)                       a bound of range() over every state and every contact
//                                      whose relative radii are at most R (m): the candidate
//                                      search and the detector's cut-off reach that far.
// A law may also state the elastic energy its contact stores (StoredEnergyLaw, below): what the
// energy ledger (world/energy_ledger.hpp) needs to tell stored from dissipated work. And it may
// say of itself, each part found where a law has it (below), so that what the engine and the
// single-contact driver ask of a law lives with the law:
//   adhesive()           whether these parameters hold contacts by adhesion (AdhesiveLaw)
//   yieldPoint(contact)  where a plastic law first yields (YieldingLaw)
//   constants(contact)   the law's own constants at a contact, for the driver's report
//                        (ReportingLaw)
//   check(contact)       std::invalid_argument when its parameters admit no contact like
//                        this one (CheckedLaw; the engine sizes its laws by their reach)

#include <array>
#include <string_view>
#include <concepts>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

struct TrueGapRungs;

/// What a normal law sees of a contact.
struct NormalContact {
  RelativeRadii radii;          ///< relative principal radii (m); volume spheres: Ri = Rj = R*
  HertzFactors factors;         ///< elliptic Hertz e^2, gamma, beta, K, D (circle for volume spheres)
  double effectiveModulus = 0;  ///< E* (Pa)
  double radiusSum = 0;         ///< r_IJ = R_vol,A + R_vol,B (m; a wall: 2 R_vol,A), 002 Eq. 54
  const TrueGapRungs* trueGap = nullptr;  ///< the true-gap law's solved rungs (true_gap_law.hpp), none for the others
};

struct NormalResponse {
  double force = 0.0;      ///< rate-independent normal force (N), > 0 repulsive
  double stiffness = 0.0;  ///< S_n (N/m) for the viscous damping (see each law)
  double area = 0.0;       ///< contact area (m^2)
  double pullOff = 0.0;    ///< F_C (N, >= 0) of an adhesive law: Coulomb limit mu |F_n + 2 F_C| (001 Eq. 17)
  bool acting = true;      ///< false: no contact (not yet formed, or detached): no force
  bool valid = true;       ///< false (with acting false): the law's parameters admit no contact here
  bool yielded = false;    ///< loaded past its elastic limit at some time: the contact carries a dent
  const char* regime = "elastic";  ///< branch name, for the single-contact driver
};

template <class L>
concept NormalLawComponent = std::is_trivially_copyable_v<typename L::History> &&
    requires(const L& law, const NormalContact& c, typename L::History& h) {
      { law.force(c, 0.0, h) } -> std::same_as<NormalResponse>;
      { law.range(std::as_const(h)) } -> std::convertible_to<double>;
      { law.reach(0.0, 0.0) } -> std::convertible_to<double>;
    };

/// A law that knows the elastic energy of its contacts: storedEnergy(contact, overlap, history,
/// force) (J) is the work the contact gives back when unloaded from this state (history and
/// force as force() left them), where storesEnergy() says the law's parameters allow the
/// statement (e.g. not for an adhesive variant).
template <class L>
concept StoredEnergyLaw = NormalLawComponent<L> &&
    requires(const L& law, const NormalContact& c, const typename L::History& h) {
      { law.storesEnergy() } -> std::same_as<bool>;
      { law.storedEnergy(c, 0.0, h, 0.0) } -> std::convertible_to<double>;
    };

/// Adhesion: the law pulls (a pull-off force) and holds contacts across gaps until they detach.
template <class L>
concept AdhesiveLaw = requires(const L& law) {
  { law.adhesive() } -> std::same_as<bool>;
};

/// The onset of plastic flow of a contact: overlap (m) and force (N).
struct YieldPoint {
  double overlap = 0.0;
  double force = 0.0;
};
template <class L>
concept YieldingLaw = requires(const L& law, const NormalContact& c) {
  { law.yieldPoint(c) } -> std::same_as<YieldPoint>;
};

/// A named constant of a law at one contact (SI units), in the single-contact driver's report.
struct LawConstant {
  const char* name;
  double value;
};
template <class L>
concept ReportingLaw = requires(const L& law, const NormalContact& c) {
  { law.constants(c) } -> std::same_as<std::vector<LawConstant>>;
};

/// Whether the law's parameters admit this contact: check() throws std::invalid_argument saying
/// why not.
template <class L>
concept CheckedLaw = requires(const L& law, const NormalContact& c) { law.check(c); };

/// A contact's normal-law history record: fixed size, so contact records stay flat and
/// trivially copyable; the law's own History is copied in and out of it.
class NormalHistory {
 public:
  template <class H>
  H load() const {
    static_assert(sizeof(H) <= capacity && std::is_trivially_copyable_v<H>);
    H h;
    std::memcpy(&h, bytes_.data(), sizeof(H));
    return h;
  }
  template <class H>
  void store(const H& h) {
    static_assert(sizeof(H) <= capacity && std::is_trivially_copyable_v<H>);
    std::memcpy(bytes_.data(), &h, sizeof(H));
  }

 private:
  static constexpr std::size_t capacity = 16;
  alignas(8) std::array<std::byte, capacity> bytes_{};
};

}  // namespace sqdem
