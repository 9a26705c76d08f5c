#pragma once
// Where a contact law reads its parameters: an `interactions[k]` entry of a scene file
// (scene/scene_loader.cpp) or the `law` object of a `sqdem contact` input (cli/driven_law.cpp).
// Each law names its keys and validates them once (law_registry.hpp); the source adds its file,
// line and key path to every message.

#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sqdem {

class LawInput {
 public:
  virtual ~LawInput() = default;
  virtual bool has(std::string_view key) const = 0;
  /// The finite number at key (the source reports a missing key or a non-number).
  virtual double number(std::string_view key) const = 0;
  /// true or false at key.
  virtual bool flag(std::string_view key) const = 0;
  /// The mapping at key, itself read as a law input.
  virtual std::unique_ptr<LawInput> child(std::string_view key) const = 0;
  /// The keys present, but for the source's own (an interaction's `materials`, `friction`, ...).
  virtual std::vector<std::string> keys() const = 0;
  /// The source's own keys, for messages ("materials, normal, ...").
  virtual std::string ownKeys() const = 0;
  /// Reports the problem with the value at key (or with the whole input when key is empty): the
  /// source's error, naming its file and key path.
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

  /// A required number > 0; `unit` names the quantity's unit in the message.
  double positive(std::string_view key, const char* unit) const;
  /// The same, `fallback` when absent.
  double positive(std::string_view key, const char* unit, double fallback) const;

 protected:
  /// Throws the source's error for fail().
  virtual void raise(std::string_view key, const std::string& message) const = 0;
};

/// "a, b, c": a list of keys or names for messages.
std::string joinKeys(std::span<const std::string_view> keys);

/// What a law is built with besides its own keys: the pair's elastic constants.
struct PairElasticity {
  double effectiveModulus = 0.0;  ///< E* (Pa), after any reduced_stiffness
  double stiffnessScale = 1.0;    ///< reduced_stiffness E_mod / E (001 Eq. 24), 1 = the real material
  double poissonRatio = 0.0;      ///< mean nu of the two materials (-)
  double yieldStrength = 0.0;     ///< Y (Pa) of the weaker material, 0 when the materials give none

  /// 001 Eq. 24: the surface energy (J/m^2) that keeps the separation energy of gamma under the
  /// reduced stiffness, gamma (E_mod/E)^2/5.
  double reducedSurfaceEnergy(double gamma) const { return gamma * std::pow(stiffnessScale, 0.4); }
};

}  // namespace sqdem
