// `sqdem sticking-velocity`: critical velocities of a sphere hitting a wall (000 Eqs. 73-79).

#include "sqdem/mechanics/sticking_velocity.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "commands.hpp"

namespace sqdem::cli {
namespace {

struct Option {
  double StickingVelocityInput::*field;
  const char* help;
  bool (*allowed)(double);
};

const std::map<std::string, Option>& options() {
  static const std::map<std::string, Option> table{
      {"--radius", {&StickingVelocityInput::radius, "particle radius R (m), > 0", [](double v) { return v > 0; }}},
      {"--density", {&StickingVelocityInput::density, "particle density (kg/m^3), > 0", [](double v) { return v > 0; }}},
      {"--youngs-modulus", {&StickingVelocityInput::youngs, "particle Young's modulus (Pa), > 0", [](double v) { return v > 0; }}},
      {"--poisson-ratio", {&StickingVelocityInput::poisson, "particle Poisson ratio, in (-1, 0.5)", [](double v) { return v > -1 && v < 0.5; }}},
      {"--wall-youngs-modulus", {&StickingVelocityInput::wallYoungs, "wall Young's modulus (Pa), > 0", [](double v) { return v > 0; }}},
      {"--wall-poisson-ratio", {&StickingVelocityInput::wallPoisson, "wall Poisson ratio, in (-1, 0.5)", [](double v) { return v > -1 && v < 0.5; }}},
      {"--surface-energy", {&StickingVelocityInput::surfaceEnergy, "surface energy Gamma (J/m^2), > 0", [](double v) { return v > 0; }}},
      {"--yield-pressure", {&StickingVelocityInput::yieldPressure, "yield contact pressure p_y (Pa), > 0", [](double v) { return v > 0; }}},
  };
  return table;
}

std::string optionList() {
  std::string list;
  for (const auto& [name, option] : options()) list += "\n  " + name + "  " + option.help;
  return list;
}

}  // namespace

int stickingVelocity(const Arguments& args) {
  StickingVelocityInput input;
  std::map<std::string, bool> seen;
  for (std::size_t i = 0; i < args.size(); i += 2) {
    const auto it = options().find(args[i]);
    if (it == options().end()) {
      throw std::invalid_argument("unknown option '" + args[i] + "'; all of these are required:" + optionList());
    }
    if (i + 1 >= args.size()) throw std::invalid_argument("option " + args[i] + " needs a value");
    std::size_t used = 0;
    double value = NAN;
    try {
      value = std::stod(args[i + 1], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != args[i + 1].size() || !std::isfinite(value) || !it->second.allowed(value)) {
      throw std::invalid_argument("option " + args[i] + " = '" + args[i + 1] + "': expected " + it->second.help);
    }
    input.*(it->second.field) = value;
    seen[args[i]] = true;
  }
  for (const auto& [name, option] : options()) {
    if (!seen[name]) throw std::invalid_argument("missing option " + name + " (" + option.help + ")");
  }
  const StickingVelocities v = stickingVelocities(input);
  const nlohmann::ordered_json out{{"V_s", v.Vs}, {"V_y0", v.Vy0}, {"V_y", v.Vy}, {"V_ys", v.Vys}};
  std::printf("%s\n", out.dump().c_str());
  return 0;
}

}  // namespace sqdem::cli
