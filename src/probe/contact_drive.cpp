#include "sqdem/probe/contact_drive.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "sqdem/contact/detector.hpp"
#include "sqdem/probe/boundary_element_law.hpp"
#include "sqdem/probe/true_gap_law.hpp"
#include "sqdem/io/plain_name.hpp"
#include "sqdem/mechanics/mindlin_deresiewicz.hpp"

namespace sqdem::probe {
namespace {

using std::numbers::pi;

/// A curve's label (it names a CSV file): letters, digits, '_', '.', '-'.
bool isPlainLabel(const std::string& label) {
  return !label.empty() && std::all_of(label.begin(), label.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
  });
}

/// Where a curve's contact geometry comes from: two posed particles (the detector is called at
/// every step, body B translated against the normal) or prescribed relative radii.
class CurveGeometry {
 public:
  CurveGeometry(const json& g, const std::string& where) {
    if (!g.is_object()) throw InputError(where + " must be an object");
    rejectUnknownKeys(g, {"particles", "radii", "cap_factor"}, where);
    if (g.contains("particles") == g.contains("radii")) {
      throw InputError(where + ": give exactly one of 'particles' (two posed shapes) or 'radii' ([R1, R2], m)");
    }
    if (g.contains("radii")) {
      const json& r = g["radii"];
      if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() ||
          !(r[0].get<double>() > 0.0) || !(r[1].get<double>() > 0.0)) {
        throw InputError(where + ": 'radii' must be two positive relative principal radii [R1, R2] (m)");
      }
      const double R1 = r[0].get<double>(), R2 = r[1].get<double>();
      radii_ = {std::min(R1, R2), std::max(R1, R2), 0.0, R1 * R2 / (R1 + R2)};
      return;
    }
    const json& p = g["particles"];
    if (!p.is_array() || p.size() != 2) throw InputError(where + ": 'particles' must be an array of two particles");
    particles_ = {readParticle(p[0], where + ".particles[0]"), readParticle(p[1], where + ".particles[1]")};
    const Superquadric &A = (*particles_)[0].shape, &B = (*particles_)[1].shape;
    const double capFactor = number(g, "cap_factor", where, 10.0);
    if (!(capFactor > 0.0)) throw InputError(where + ": 'cap_factor' must be > 0");
    settings_.cutoff = 4.0 * (A.boundingRadius() + B.boundingRadius());
    start_ = detectContact(A, (*particles_)[0].pose, B, (*particles_)[1].pose, settings_);
    if (!start_.converged()) {
      throw InputError(where + ": the detector found no contact normal for these poses (" +
                       describe(start_.status) + ")");
    }
    radii_ = relativeRadii(start_.curvatureA, start_.curvatureB, capFactor * referenceVolumeRadius(A, B));
    meanRadiusSum_ = A.volumeEquivalentRadius() + B.volumeEquivalentRadius();
    last_ = start_;
  }

  const RelativeRadii& radii() const { return radii_; }
  double meanRadiusSum() const { return meanRadiusSum_; }  ///< r_IJ (m), 0 for prescribed radii
  /// The two posed particles (none for prescribed radii) and the detector's contact at their poses.
  const std::optional<std::array<Particle, 2>>& particles() const { return particles_; }
  const ContactGeometry& start() const { return start_; }
  int detectorFailures() const { return failures_; }

  /// Overlap (m) when body B has approached by `approach` (m) from touching; the detector's
  /// value for particles (the prescribed value if it cannot resolve the contact, counted).
  double overlapAt(double approach) {
    if (!particles_) return approach;
    const auto& [A, B] = *particles_;
    Pose poseB = B.pose;
    poseB.position -= (approach - start_.overlap) * start_.normal;
    const ContactGeometry g = detectContact(A.shape, A.pose, B.shape, poseB, settings_, last_);
    if (!g.converged()) {
      ++failures_;
      return approach;
    }
    last_ = g;
    return g.overlap;
  }

 private:
  std::optional<std::array<Particle, 2>> particles_;
  DetectorSettings settings_;
  ContactGeometry start_, last_;
  RelativeRadii radii_;
  double meanRadiusSum_ = 0.0;
  int failures_ = 0;
};

/// The prescribed history: piecewise linear through the points, `steps` steps per segment.
struct DisplacementPath {
  std::vector<double> normal;      ///< approach (m)
  std::vector<double> tangential;  ///< tangential displacement (m), empty if not driven
};

std::vector<double> readPoints(const json& object, const std::string& where, double scale) {
  if (!object.contains("points") || !object["points"].is_array() || object["points"].size() < 2) {
    throw InputError(where + ": 'points' must be an array of at least two numbers");
  }
  std::vector<double> points;
  for (const json& v : object["points"]) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) throw InputError(where + ": 'points' must contain finite numbers");
    points.push_back(scale * v.get<double>());
  }
  return points;
}

std::vector<double> interpolate(const std::vector<double>& points, int steps) {
  std::vector<double> out{points.front()};
  for (std::size_t i = 1; i < points.size(); ++i) {
    for (int k = 1; k <= steps; ++k) out.push_back(points[i - 1] + (points[i] - points[i - 1]) * k / steps);
  }
  return out;
}

DisplacementPath readPath(const json& input, double meanRadiusSum) {
  const std::string where = "path";
  if (!input.contains("path") || !input["path"].is_object()) throw InputError("missing object 'path'");
  const json& path = input["path"];
  rejectUnknownKeys(path, {"unit", "points", "steps"}, where);
  const std::string unit = choice(path, "unit", where, {"m", "um", "r_IJ"}, "m");
  double scale = unit == "m" ? 1.0 : unit == "um" ? 1e-6 : meanRadiusSum;
  if (!(scale > 0.0)) throw InputError("path: unit 'r_IJ' needs the first curve's geometry as 'particles'");
  const double steps = number(path, "steps", where, 200.0);
  if (!(steps >= 1.0 && steps <= 1e6) || steps != std::floor(steps)) {
    throw InputError("path: 'steps' (per segment) must be an integer in [1, 1e6]");
  }
  DisplacementPath out;
  out.normal = interpolate(readPoints(path, where, scale), static_cast<int>(steps));
  if (input.contains("tangential")) {
    const json& t = input["tangential"];
    if (!t.is_object()) throw InputError("'tangential' must be an object");
    rejectUnknownKeys(t, {"points", "friction", "angle"}, "tangential");
    const std::vector<double> points = readPoints(t, "tangential", scale);
    if (points.size() != path["points"].size()) {
      throw InputError("tangential: 'points' must have as many entries as path.points (one per turning point)");
    }
    out.tangential = interpolate(points, static_cast<int>(steps));
  }
  return out;
}

/// Elliptic Mindlin-Deresiewicz (004 Eqs. 56-68) at the current normal force and area.
struct TangentialDrive {
  double friction = 0.0, angle = 0.0;  ///< mu (-), theta (rad) to the ellipse's major axis
  double e2 = 0.0;                     ///< the curve's contact-ellipse e^2 (fixed geometry)
  MindlinDeresiewiczHistory history;

  double force(double displacement, const LawSample& normal, const ContactMaterials& m) {
    if (normal.force <= 0.0 || !normal.area || *normal.area <= 0.0) {
      history = {};
      return 0.0;
    }
    const MindlinDeresiewicz law(m.effectiveShearModulus(), contactSemiMajorAxis(*normal.area, e2), e2,
                                 m.meanPoisson(), angle, friction, normal.force);
    return law.force(displacement, history);
  }
};

ContactMaterials readMaterials(const json& input) {
  const auto read = [&](const char* key) {
    const json& m = input.at(key);
    if (!m.is_object()) throw InputError(std::string("'") + key + "' must be an object");
    rejectUnknownKeys(m, {"youngs_modulus", "poisson_ratio"}, key);
    const double E = number(m, "youngs_modulus", key), nu = number(m, "poisson_ratio", key);
    if (!(E > 0.0)) throw InputError(std::string(key) + ": 'youngs_modulus' must be > 0 (Pa)");
    if (!(nu > -1.0 && nu < 0.5)) throw InputError(std::string(key) + ": 'poisson_ratio' must be in (-1, 0.5)");
    return std::pair{E, nu};
  };
  if (!input.contains("material")) throw InputError("missing object 'material' ({youngs_modulus: Pa, poisson_ratio})");
  const auto [EA, nuA] = read("material");
  const auto [EB, nuB] = input.contains("material_b") ? read("material_b") : std::pair{EA, nuA};
  return {EA, nuA, EB, nuB};
}

/// The plot title: user text that goes into a gnuplot script, so only characters that gnuplot
/// treats literally inside a single-quoted, noenhanced string (no quotes, backslash, backtick,
/// '$', '@' or control characters), at most 200 bytes.
std::string readTitle(const json& input, const std::string& fallback) {
  if (!input.contains("title")) return fallback;
  const json& t = input["title"];
  const std::string title = t.is_string() ? t.get<std::string>() : std::string();
  const bool safe = std::none_of(title.begin(), title.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f || std::string_view("'\"`\\$@").find(c) != std::string_view::npos;
  });
  if (!t.is_string() || title.empty() || title.size() > 200 || !safe) {
    throw InputError("'title' must be a string of 1 to 200 characters without quotes, backslashes, backticks, "
                     "'$', '@' or control characters");
  }
  return title;
}

}  // namespace

ContactDrive driveContact(const json& input, const std::string& defaultName) {
  if (!input.is_object()) throw InputError("top level must be a JSON object");
  rejectUnknownKeys(input, {"name", "title", "material", "material_b", "path", "tangential", "curves", "plot"},
                    "top level");
  std::string name = defaultName;
  if (input.contains("name")) {
    if (!input["name"].is_string()) throw InputError("'name' must be a string");
    name = input["name"].get<std::string>();
  }
  if (!isPlainName(name)) {
    throw InputError("'name' may contain only letters, digits, '_', '.', '-' and may not start with '.' or '-'");
  }
  const std::string title = readTitle(input, name);
  const ContactMaterials materials = readMaterials(input);
  if (!input.contains("curves") || !input["curves"].is_array() || input["curves"].empty()) {
    throw InputError("'curves' must be a non-empty array of {label, geometry, law}");
  }

  struct Curve {
    std::string label;
    std::unique_ptr<CurveGeometry> geometry;  // on the heap: the reference law refers to its particles
    std::unique_ptr<CurveLaw> law;
  };
  std::vector<Curve> curves;
  for (std::size_t i = 0; i < input["curves"].size(); ++i) {
    const json& c = input["curves"][i];
    const std::string where = "curves[" + std::to_string(i) + "]";
    if (!c.is_object()) throw InputError(where + " must be an object");
    rejectUnknownKeys(c, {"label", "geometry", "law"}, where);
    if (!c.contains("label") || !c["label"].is_string() || !isPlainLabel(c["label"].get<std::string>())) {
      throw InputError(where + ": 'label' must be a string of letters, digits, '_', '.', '-'");
    }
    const std::string label = c["label"].get<std::string>();
    for (const Curve& other : curves) {
      if (other.label == label) throw InputError(where + ": label '" + label + "' is used twice");
    }
    if (!c.contains("geometry")) throw InputError(where + ": missing key 'geometry'");
    if (!c.contains("law")) throw InputError(where + ": missing key 'law'");
    curves.push_back({label, std::make_unique<CurveGeometry>(c["geometry"], where + ".geometry"), nullptr});
    const json& law = c["law"];
    const CurveGeometry& g = *curves.back().geometry;
    const std::string type = law.is_object() && law.contains("type") && law["type"].is_string() ? law["type"].get<std::string>() : "";
    if (type == "boundary_element" || type == "true_gap") {
      if (!g.particles()) throw InputError(where + ".law: " + type + " needs the curve's geometry as 'particles' (two posed shapes)");
      const auto& [A, B] = *g.particles();
      if (type == "boundary_element") {
        curves.back().law = std::make_unique<BoundaryElementLaw>(law, where + ".law", A, B, g.start(), materials);
      } else {
        curves.back().law = std::make_unique<TrueGapCurveLaw>(law, where + ".law", A, B, g.start(), g.radii(), materials);
      }
    } else {
      curves.back().law = std::make_unique<DrivenLaw>(law, where + ".law", g.radii(), materials, g.meanRadiusSum());
    }
  }
  const DisplacementPath path = readPath(input, curves.front().geometry->meanRadiusSum());

  TangentialDrive tangentialTemplate;
  if (!path.tangential.empty()) {
    const json& t = input["tangential"];
    tangentialTemplate.friction = number(t, "friction", "tangential");
    if (!(tangentialTemplate.friction > 0.0)) throw InputError("tangential: 'friction' must be > 0");
    tangentialTemplate.angle = number(t, "angle", "tangential", 0.0) * pi / 180.0;
    for (const Curve& c : curves) {
      if (c.law->normalOnly()) {
        throw InputError("tangential: the Mindlin-Deresiewicz drive needs a law of the registry; curve '" + c.label +
                         "' is a law of the true gap (boundary_element or true_gap: normal only)");
      }
      if (c.law->adhesive()) {
        throw InputError("tangential: the Mindlin-Deresiewicz drive needs a non-adhesive normal law (" +
                         lawNames([](const NormalLawEntry& e) { return e.curvatures && e.traits.adhesion != Adhesion::Always; }) +
                         ", without surface_energy); curve '" + c.label + "' is adhesive");
      }
    }
  }

  const json plot = input.value("plot", json::object());
  if (!plot.is_object()) throw InputError("'plot' must be an object");
  rejectUnknownKeys(plot, {"normalise", "quantity"}, "plot");
  const bool normalised = choice(plot, "normalise", "plot", {"none", "yield"}, "none") == "yield";
  const bool tangentialPlot = choice(plot, "quantity", "plot", {"normal", "tangential"}, "normal") == "tangential";
  if (tangentialPlot && path.tangential.empty()) throw InputError("plot: quantity 'tangential' needs 'tangential'");
  if (tangentialPlot && normalised) throw InputError("plot: normalise 'yield' applies to the normal quantity only");
  if (normalised && !curves.front().law->yield()) {
    throw InputError("plot: normalise 'yield' needs a first curve with a yield point (" +
                     lawNames([](const NormalLawEntry& e) { return e.traits.plastic; }) + ")");
  }

  ContactDrive drive{name, title, path.normal, path.tangential, {}, normalised, tangentialPlot};
  for (Curve& c : curves) {
    TangentialDrive tangential = tangentialTemplate;
    tangential.e2 = hertzFactors(c.geometry->radii().ratio(), EccentricityMethod::Exact).e2;
    DrivenCurve out{.label = c.label, .radii = c.geometry->radii(), .meanRadiusSum = c.geometry->meanRadiusSum(),
                    .constants = c.law->constants(), .yield = c.law->yield()};
    for (std::size_t k = 0; k < path.normal.size(); ++k) {
      const double overlap = c.geometry->overlapAt(path.normal[k]);
      const LawSample s = c.law->at(overlap);
      if (!std::isfinite(s.force)) throw std::runtime_error("curve '" + c.label + "': non-finite force at step " + std::to_string(k));
      out.overlap.push_back(overlap);
      out.normalForce.push_back(s.force);
      out.area.push_back(s.area);
      out.regime.emplace_back(s.regime);
      if (!path.tangential.empty()) out.tangentialForce.push_back(tangential.force(path.tangential[k], s, materials));
    }
    out.detectorFailures = c.geometry->detectorFailures();
    drive.curves.push_back(std::move(out));
  }
  return drive;
}

}  // namespace sqdem::probe
