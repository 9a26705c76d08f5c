#pragma once
// A contact law's keys in a JSON object of the single-contact driver (`sqdem contact`, a
// curve's `law`), read through the law registry (law_input.hpp, law_registry.hpp): the keys
// the driver reads itself ("type", ...) are set aside, every message names the key path.

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/probe/json_input.hpp"

namespace sqdem::probe {

class JsonLawInput final : public LawInput {
 public:
  /// `object` must outlive the input; `where` is its key path ("curves[0].law"); `ownKeys` the
  /// driver's keys in it, which the law does not see.
  JsonLawInput(const json& object, std::string where, std::vector<std::string_view> ownKeys)
      : object_(object), where_(std::move(where)), ownKeys_(std::move(ownKeys)) {}

  bool has(std::string_view key) const override { return object_.contains(key); }
  double number(std::string_view key) const override { return probe::number(object_, std::string(key), where_); }
  bool flag(std::string_view key) const override {
    const json& v = object_.at(key);
    if (!v.is_boolean()) fail(key, "must be true or false");
    return v.get<bool>();
  }
  std::unique_ptr<LawInput> child(std::string_view key) const override {
    const json& v = object_.at(key);
    if (!v.is_object()) fail(key, "must be an object");
    return std::make_unique<JsonLawInput>(v, where_ + "." + std::string(key), std::vector<std::string_view>{});
  }
  std::vector<std::string> keys() const override {
    std::vector<std::string> out;
    for (const auto& [key, value] : object_.items()) {
      if (std::find(ownKeys_.begin(), ownKeys_.end(), key) == ownKeys_.end()) out.push_back(key);
    }
    return out;
  }
  std::string ownKeys() const override { return joinKeys(ownKeys_); }

 protected:
  void raise(std::string_view key, const std::string& message) const override {
    throw InputError(where_ + ": " + (key.empty() ? "" : "'" + std::string(key) + "' ") + message);
  }

 private:
  const json& object_;
  std::string where_;
  std::vector<std::string_view> ownKeys_;
};

}  // namespace sqdem::probe
