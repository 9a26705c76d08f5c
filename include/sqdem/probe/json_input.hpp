#pragma once
// JSON input helpers shared by the sub-commands that read a JSON description: typed look-ups
// whose errors name the object and key, and the particle (shape + pose) object.

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem::probe {

using nlohmann::json;

/// Bad input; the message names where ("particles[1]", "curves[0].law") and the key.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parsed JSON of a file, or of standard input for "-".
json readJsonInput(const std::string& path);

/// A required finite number.
double number(const json& object, const std::string& key, const std::string& where);
/// An optional finite number with a default.
double number(const json& object, const std::string& key, const std::string& where, double fallback);
/// A required array of N finite numbers.
template <int N>
Eigen::Matrix<double, N, 1> vector(const json& object, const std::string& key, const std::string& where);
/// A required string that must be one of the allowed values.
std::string choice(const json& object, const std::string& key, const std::string& where,
                   std::initializer_list<const char*> allowed, const char* fallback = nullptr);

void rejectUnknownKeys(const json& object, std::initializer_list<const char*> allowed,
                       const std::string& where);

struct Particle {
  Superquadric shape;
  Pose pose;
};
/// {"centre": [x,y,z], "quaternion": [w,x,y,z], "a","b","c" (m), "n1","n2" or "eta1","eta2"}.
Particle readParticle(const json& p, const std::string& where);

extern template Eigen::Matrix<double, 3, 1> vector<3>(const json&, const std::string&, const std::string&);
extern template Eigen::Matrix<double, 4, 1> vector<4>(const json&, const std::string&, const std::string&);

}  // namespace sqdem::probe
