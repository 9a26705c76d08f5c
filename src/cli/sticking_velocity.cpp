// `sqdem sticking-velocity`: critical velocities of a sphere hitting a wall (000 Eqs. 73-79).

#include "sqdem/mechanics/sticking_velocity.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
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

/// Each option's plausible range: beyond it the inputs are a unit slip, not a particle.
const std::map<std::string, Option>& options() {
  static const std::map<std::string, Option> table{
      {"--radius", {&StickingVelocityInput::radius, "particle radius R (m), in [1e-9, 1]", [](double v) { return v >= 1e-9 && v <= 1.0; }}},
      {"--density", {&StickingVelocityInput::density, "particle density (kg/m^3), in [1, 1e5]", [](double v) { return v >= 1.0 && v <= 1e5; }}},
      {"--youngs-modulus", {&StickingVelocityInput::youngs, "particle Young's modulus (Pa), in [1e3, 1e13]", [](double v) { return v >= 1e3 && v <= 1e13; }}},
      {"--poisson-ratio", {&StickingVelocityInput::poisson, "particle Poisson ratio, in (-1, 0.5)", [](double v) { return v > -1 && v < 0.5; }}},
      {"--wall-youngs-modulus", {&StickingVelocityInput::wallYoungs, "wall Young's modulus (Pa), in [1e3, 1e13]", [](double v) { return v >= 1e3 && v <= 1e13; }}},
      {"--wall-poisson-ratio", {&StickingVelocityInput::wallPoisson, "wall Poisson ratio, in (-1, 0.5)", [](double v) { return v > -1 && v < 0.5; }}},
      {"--work-of-adhesion", {&StickingVelocityInput::workOfAdhesion, "work of adhesion W = 2 gamma (J/m^2; 000's Gamma), in [1e-6, 10]", [](double v) { return v >= 1e-6 && v <= 10.0; }}},
      {"--yield-pressure", {&StickingVelocityInput::yieldPressure, "yield contact pressure p_y (Pa), in [1e3, 1e11]", [](double v) { return v >= 1e3 && v <= 1e11; }}},
  };
  return table;
}

/// A decimal number as written by a person (no hex, no inf/nan, no trailing text).
bool decimal(const std::string& text, double& value) {
  static const std::regex form(R"([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?)");
  if (!std::regex_match(text, form)) return false;
  value = std::strtod(text.c_str(), nullptr);
  return std::isfinite(value);
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
    if (seen[args[i]]) throw std::invalid_argument("option " + args[i] + " is given twice");
    double value = NAN;
    if (!decimal(args[i + 1], value) || !it->second.allowed(value)) {
      throw std::invalid_argument("option " + args[i] + " = '" + args[i + 1] + "': expected " + it->second.help);
    }
    input.*(it->second.field) = value;
    seen[args[i]] = true;
  }
  for (const auto& [name, option] : options()) {
    if (!seen[name]) throw std::invalid_argument("missing option " + name + " (" + option.help + ")");
  }
  StickingVelocities v;
  try {
    v = stickingVelocities(input);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("these options give no valid Nan et al. law (000 Eqs. 28-59): ") + e.what() +
                                "; a higher --yield-pressure or a lower --work-of-adhesion moves the contact out of it");
  }
  const nlohmann::ordered_json out{{"V_s", v.Vs}, {"V_y0", v.Vy0}, {"V_y", v.Vy}, {"V_ys", v.Vys}};
  std::printf("%s\n", out.dump().c_str());
  return 0;
}

}  // namespace sqdem::cli
