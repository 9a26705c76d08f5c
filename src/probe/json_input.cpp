#include "sqdem/probe/json_input.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace sqdem::probe {

json readJsonInput(const std::string& path) {
  std::stringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
  } else {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
      throw InputError(std::filesystem::is_directory(path, error) ? "is a directory, not a JSON file" : "cannot open the file");
    }
    std::ifstream file(path);
    if (!file) throw InputError("cannot open the file");
    text << file.rdbuf();
  }
  try {
    return json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw InputError("not valid JSON: " + std::string(e.what()));
  } catch (const json::out_of_range& e) {  // e.g. 1e400: a number beyond double
    throw InputError("not valid JSON (a number out of range): " + std::string(e.what()));
  }
}

double number(const json& object, const std::string& key, const std::string& where) {
  if (!object.contains(key)) throw InputError(where + ": missing key '" + key + "'");
  const json& v = object.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>())) {
    throw InputError(where + ": '" + key + "' must be a finite number");
  }
  return v.get<double>();
}

double number(const json& object, const std::string& key, const std::string& where, double fallback) {
  return object.contains(key) ? number(object, key, where) : fallback;
}

template <int N>
Eigen::Matrix<double, N, 1> vector(const json& object, const std::string& key, const std::string& where) {
  if (!object.contains(key)) throw InputError(where + ": missing key '" + key + "'");
  const json& v = object.at(key);
  if (!v.is_array() || v.size() != N) {
    throw InputError(where + ": '" + key + "' must be an array of " + std::to_string(N) + " numbers");
  }
  Eigen::Matrix<double, N, 1> out;
  for (int i = 0; i < N; ++i) {
    if (!v[i].is_number()) throw InputError(where + ": '" + key + "' must contain numbers");
    out(i) = v[i].get<double>();
  }
  if (!out.allFinite()) throw InputError(where + ": '" + key + "' must be finite");
  return out;
}
template Eigen::Matrix<double, 3, 1> vector<3>(const json&, const std::string&, const std::string&);
template Eigen::Matrix<double, 4, 1> vector<4>(const json&, const std::string&, const std::string&);

namespace {
std::string joined(std::initializer_list<const char*> words) {
  std::string list;
  for (const char* w : words) list += std::string(list.empty() ? "" : ", ") + w;
  return list;
}
}  // namespace

std::string choice(const json& object, const std::string& key, const std::string& where,
                   std::initializer_list<const char*> allowed, const char* fallback) {
  if (!object.contains(key)) {
    if (fallback) return fallback;
    throw InputError(where + ": missing key '" + key + "' (one of: " + joined(allowed) + ")");
  }
  const json& v = object.at(key);
  if (v.is_string()) {
    for (const char* a : allowed) {
      if (v.get<std::string>() == a) return a;
    }
  }
  throw InputError(where + ": '" + key + "' must be one of: " + joined(allowed) + " (got " + v.dump() + ")");
}

void rejectUnknownKeys(const json& object, std::initializer_list<const char*> allowed,
                       const std::string& where) {
  for (const auto& [key, value] : object.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) throw InputError(where + ": unknown key '" + key + "' (allowed: " + joined(allowed) + ")");
  }
}

Particle readParticle(const json& p, const std::string& where) {
  if (!p.is_object()) throw InputError(where + " must be an object");
  rejectUnknownKeys(p, {"centre", "quaternion", "a", "b", "c", "n1", "n2", "eta1", "eta2"}, where);
  const auto exponent = [&](const char* n, const char* eta) {
    if (p.contains(n) && p.contains(eta)) {
      throw InputError(where + ": give either '" + n + "' or '" + eta + "', not both");
    }
    if (p.contains(eta)) return 2.0 / number(p, eta, where);
    return number(p, n, where, 2.0);
  };
  const double n1 = exponent("n1", "eta1"), n2 = exponent("n2", "eta2");
  const Eigen::Vector4d q = p.contains("quaternion") ? vector<4>(p, "quaternion", where)
                                                     : Eigen::Vector4d(1.0, 0.0, 0.0, 0.0);
  if (std::abs(q.norm() - 1.0) > 1e-6) {
    throw InputError(where + ": 'quaternion' [w,x,y,z] must have unit norm (got " +
                     std::to_string(q.norm()) + ")");
  }
  try {
    Particle out{Superquadric(number(p, "a", where), number(p, "b", where), number(p, "c", where), n1, n2), {}};
    out.pose.position = vector<3>(p, "centre", where);
    out.pose.orientation = Quat(q(0), q(1), q(2), q(3)).normalized();
    return out;
  } catch (const std::invalid_argument& e) {
    throw InputError(where + ": " + e.what());
  }
}

}  // namespace sqdem::probe
