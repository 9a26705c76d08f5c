#include "sqdem/mechanics/law_registry.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace sqdem {
namespace {

static_assert(NormalLawComponent<HertzLaw> && NormalLawComponent<GreenwoodWilliamsonLaw> &&
              NormalLawComponent<BeckerKamlahLaw> && NormalLawComponent<HaervigJkrLaw> &&
              NormalLawComponent<EllipticJkrLaw> && NormalLawComponent<RoughJkrLaw> &&
              NormalLawComponent<NanAdhesiveLaw> && NormalLawComponent<JamariLaw> && NormalLawComponent<TrueGapLaw>);

/// Refuses any key of `in` that is not in `allowed` (`what` names whose keys they are).
void allowOnly(const LawInput& in, std::span<const std::string_view> allowed, std::string_view what);

constexpr std::array<std::string_view, 1> hertzKeys{"roughness"};
constexpr std::array<std::string_view, 3> jkrKeys{"surface_energy", "tabulated", "roughness"};
constexpr std::array<std::string_view, 2> roughnessKeys{"sigma", "asperity_count"};

/// The `roughness` mapping: Greenwood-Williamson's sigma_s and N A_n (004 Eqs. 29-36).
RoughContact readRoughness(const LawInput& in) {
  const auto rough = in.child("roughness");
  allowOnly(*rough, roughnessKeys, "roughness");
  return {.asperityCount = rough->positive("asperity_count", "-, N A_n, asperities on the nominal contact area"),
          .sigma = rough->positive("sigma", "m, standard deviation of asperity heights")};
}

/// elliptic_hertz and volume_sphere_hertz: smooth, or Greenwood-Williamson with `roughness`.
NormalLaw readHertz(const LawInput& in, const PairElasticity&) {
  if (!in.has("roughness")) return HertzLaw{};
  return GreenwoodWilliamsonLaw{readRoughness(in)};
}

/// elliptic_jkr: smooth, or Greenwood-Williamson with JKR asperities with `roughness`.
NormalLaw readJkr(const LawInput& in, const PairElasticity& pair) {
  const EllipticJkrLaw smooth = EllipticJkrLaw::read(in, pair);
  if (!in.has("roughness")) return smooth;
  return RoughJkrLaw{readRoughness(in), smooth.surfaceEnergy, smooth.curve};
}

template <class L>
NormalLaw readAs(const LawInput& in, const PairElasticity& pair) {
  return L::read(in, pair);
}

constexpr std::array entries{
    NormalLawEntry{"elliptic_hertz", true, hertzKeys, readHertz, traitsOf<HertzLaw>(Adhesion::Never)},
    NormalLawEntry{"volume_sphere_hertz", false, hertzKeys, readHertz, traitsOf<HertzLaw>(Adhesion::Never)},
    NormalLawEntry{"becker_kamlah", true, BeckerKamlahLaw::keys, readAs<BeckerKamlahLaw>,
                   traitsOf<BeckerKamlahLaw>(Adhesion::WithSurfaceEnergy)},
    NormalLawEntry{"haervig_jkr", true, HaervigJkrLaw::keys, readAs<HaervigJkrLaw>, traitsOf<HaervigJkrLaw>(Adhesion::Always)},
    NormalLawEntry{"elliptic_jkr", true, jkrKeys, readJkr, traitsOf<EllipticJkrLaw>(Adhesion::Always)},
    NormalLawEntry{"nan_adhesive", true, NanAdhesiveLaw::keys, readAs<NanAdhesiveLaw>, traitsOf<NanAdhesiveLaw>(Adhesion::Always)},
    NormalLawEntry{"jamari", true, JamariLaw::keys, readAs<JamariLaw>, traitsOf<JamariLaw>(Adhesion::Never)},
    NormalLawEntry{"true_gap", true, TrueGapLaw::keys, readAs<TrueGapLaw>, traitsOf<TrueGapLaw>(Adhesion::Never)},
};

/// Why a key of some laws is not combined with law `what` (appended to the message).
std::string combinationRefused(std::string_view key, std::string_view what) {
  if (key == "roughness") {
    return "Greenwood-Williamson roughness is built on elastic asperities, Hertz or elliptic JKR; the seeds give no "
           "rough plastic law";
  }
  if (key == "surface_energy") return "an adhesive form of " + std::string(what) + " is not built";
  return {};
}

void allowOnly(const LawInput& in, std::span<const std::string_view> allowed, std::string_view what) {
  for (const std::string& key : in.keys()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::vector<std::string_view> owners;
    for (const NormalLawEntry& e : entries) {
      if (std::find(e.keys.begin(), e.keys.end(), key) != e.keys.end()) owners.push_back(e.name);
    }
    const std::string own = in.ownKeys(), lawKeys = std::string(what) + ": " + (allowed.empty() ? "none" : joinKeys(allowed));
    const std::string reason = owners.empty() ? std::string() : combinationRefused(key, what);
    in.fail(key, "unknown key (allowed: " + (own.empty() ? lawKeys : own + ", and for " + lawKeys) + ")" +
                     (owners.empty() ? "" : "; '" + key + "' is a key of normal: " + joinKeys(owners)) +
                     (reason.empty() ? "" : " (" + reason + ")"));
  }
}

}  // namespace

NormalLaw readNormalLaw(const NormalLawEntry& entry, const LawInput& in, const PairElasticity& pair) {
  allowOnly(in, entry.keys, entry.name);
  return entry.read(in, pair);
}

std::span<const NormalLawEntry> normalLaws() { return entries; }

std::string lawNames(bool (*pick)(const NormalLawEntry&)) {
  std::vector<std::string_view> names;
  for (const NormalLawEntry& e : entries) {
    if (pick(e)) names.push_back(e.name);
  }
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    out += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + std::string(names[k]);
  }
  return out;
}

const NormalLawEntry& normalLaw(std::string_view name, const LawInput& in, std::string_view key,
                                std::span<const std::string_view> alsoAllowed) {
  std::vector<std::string_view> names;
  for (const NormalLawEntry& e : entries) {
    if (e.name == name) return e;
    names.push_back(e.name);
  }
  names.insert(names.end(), alsoAllowed.begin(), alsoAllowed.end());
  in.fail(key, "unknown law '" + std::string(name) + "' (allowed: " + joinKeys(names) + ")");
}

}  // namespace sqdem
