// `sqdem contact <file.json|-> [--out DIR] [--allow-detector-failures]`: the single-contact driver. Drives one contact along
// a prescribed normal (and optional tangential) displacement history for one or more "curves"
// (a geometry + a normal law each) and writes, per curve, a CSV of displacement, overlap,
// forces, contact area and regime, then a gnuplot script and its PNG. Input keys and units are
// documented in README.md ("Single-contact driver").

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <optional>
#include <regex>
#include <sstream>


#include "commands.hpp"
#include "driven_law.hpp"
#include "json_input.hpp"
#include "sqdem/contact/detector.hpp"
#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/gnuplot.hpp"
#include "sqdem/io/plain_name.hpp"
#include "sqdem/mechanics/mindlin_deresiewicz.hpp"

namespace sqdem::cli {
namespace {

namespace fs = std::filesystem;
using std::numbers::pi;

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

/// Engineering prefix for axis labels: values are divided by the returned scale.
std::pair<double, std::string> prefixFor(double magnitude, const std::string& unit) {
  static const std::array<std::pair<double, const char*>, 5> prefixes{
      {{1e-9, "n"}, {1e-6, "µ"}, {1e-3, "m"}, {1.0, ""}, {1e3, "k"}}};
  for (auto it = prefixes.rbegin(); it != prefixes.rend(); ++it) {
    if (magnitude >= it->first) return {it->first, it->second + unit};
  }
  return {prefixes.front().first, prefixes.front().second + unit};
}

std::string csvNumber(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
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

struct CurveResult {
  std::string label;
  std::string csv;
  double maxOverlap = 0.0, maxForce = 0.0, maxTangential = 0.0;
};

int runContact(const std::string& inputPath, const fs::path& outDir, bool allowDetectorFailures) {
  const json input = readJsonInput(inputPath);
  if (!input.is_object()) throw InputError("top level must be a JSON object");
  rejectUnknownKeys(input, {"name", "title", "material", "material_b", "path", "tangential", "curves", "plot"},
                    "top level");
  std::string name = inputPath == "-" ? "contact" : fs::path(inputPath).stem().string();
  if (input.contains("name")) {
    if (!input["name"].is_string()) throw InputError("'name' must be a string");
    name = input["name"].get<std::string>();
  }
  const std::regex safe("[A-Za-z0-9_.-]+");
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
    CurveGeometry geometry;
    std::unique_ptr<DrivenLaw> law;
  };
  std::vector<Curve> curves;
  for (std::size_t i = 0; i < input["curves"].size(); ++i) {
    const json& c = input["curves"][i];
    const std::string where = "curves[" + std::to_string(i) + "]";
    if (!c.is_object()) throw InputError(where + " must be an object");
    rejectUnknownKeys(c, {"label", "geometry", "law"}, where);
    if (!c.contains("label") || !c["label"].is_string() || !std::regex_match(c["label"].get<std::string>(), safe)) {
      throw InputError(where + ": 'label' must be a string of letters, digits, '_', '.', '-'");
    }
    const std::string label = c["label"].get<std::string>();
    for (const Curve& other : curves) {
      if (other.label == label) throw InputError(where + ": label '" + label + "' is used twice");
    }
    if (!c.contains("geometry")) throw InputError(where + ": missing key 'geometry'");
    if (!c.contains("law")) throw InputError(where + ": missing key 'law'");
    CurveGeometry geometry(c["geometry"], where + ".geometry");
    auto law = std::make_unique<DrivenLaw>(c["law"], where + ".law", geometry.radii(), materials, geometry.meanRadiusSum());
    curves.push_back({label, std::move(geometry), std::move(law)});
  }
  const DisplacementPath path = readPath(input, curves.front().geometry.meanRadiusSum());

  TangentialDrive tangentialTemplate;
  if (!path.tangential.empty()) {
    const json& t = input["tangential"];
    tangentialTemplate.friction = number(t, "friction", "tangential");
    if (!(tangentialTemplate.friction > 0.0)) throw InputError("tangential: 'friction' must be > 0");
    tangentialTemplate.angle = number(t, "angle", "tangential", 0.0) * pi / 180.0;
    for (const Curve& c : curves) {
      if (c.law->adhesive()) {
        throw InputError("tangential: the Mindlin-Deresiewicz drive needs a non-adhesive normal law "
                         "(elliptic_hertz, becker_kamlah or jamari); curve '" + c.label + "' is adhesive");
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
  std::optional<YieldPoint> reference;
  if (normalised) {
    reference = curves.front().law->yield();
    if (!reference) throw InputError("plot: normalise 'yield' needs a first curve with a yield point (becker_kamlah, nan_adhesive or jamari)");
  }

  fs::create_directories(outDir);
  json summary = {{"name", name}, {"curves", json::array()}};
  std::vector<CurveResult> results;
  for (Curve& c : curves) {
    TangentialDrive tangential = tangentialTemplate;
    tangential.e2 = hertzFactors(c.geometry.radii().ratio(), EccentricityMethod::Exact).e2;
    std::ostringstream csv;
    csv << "step,displacement,overlap,normal_force,contact_area,equivalent_contact_radius,regime";
    if (!path.tangential.empty()) csv << ",tangential_displacement,tangential_force";
    csv << "\n";
    CurveResult r{c.label, name + "_" + c.label + ".csv"};
    for (std::size_t k = 0; k < path.normal.size(); ++k) {
      const double overlap = c.geometry.overlapAt(path.normal[k]);
      const LawSample s = c.law->at(overlap);
      if (!std::isfinite(s.force)) throw std::runtime_error("curve '" + c.label + "': non-finite force at step " + std::to_string(k));
      csv << k << ',' << csvNumber(path.normal[k]) << ',' << csvNumber(overlap) << ',' << csvNumber(s.force) << ',';
      if (s.area) csv << csvNumber(*s.area) << ',' << csvNumber(std::sqrt(*s.area / pi));
      else csv << ',';
      csv << ',' << s.regime;
      if (!path.tangential.empty()) {
        const double ft = tangential.force(path.tangential[k], s, materials);
        csv << ',' << csvNumber(path.tangential[k]) << ',' << csvNumber(ft);
        r.maxTangential = std::max(r.maxTangential, std::abs(ft));
      }
      csv << "\n";
      r.maxOverlap = std::max(r.maxOverlap, std::abs(overlap));
      r.maxForce = std::max(r.maxForce, std::abs(s.force));
    }
    writeFileAtomically(outDir / r.csv, csv.str());
    const RelativeRadii& radii = c.geometry.radii();
    json entry = {{"label", c.label}, {"csv", (outDir / r.csv).string()}, {"Ri", radii.Ri}, {"Rj", radii.Rj},
                  {"Rc", radii.Rc}, {"max_abs_force", r.maxForce}, {"detector_failures", c.geometry.detectorFailures()}};
    if (c.geometry.meanRadiusSum() > 0.0) entry["r_IJ"] = c.geometry.meanRadiusSum();
    entry["constants"] = c.law->constants();
    summary["curves"].push_back(entry);
    results.push_back(r);
  }

  // gnuplot script (kept next to the CSVs so the user can restyle) and its PNG.
  double xMax = 0.0, yMax = 0.0;
  for (const CurveResult& r : results) {
    xMax = std::max(xMax, tangentialPlot ? std::abs(*std::max_element(path.tangential.begin(), path.tangential.end(),
                                                                    [](double a, double b) { return std::abs(a) < std::abs(b); }))
                                         : r.maxOverlap);
    yMax = std::max(yMax, tangentialPlot ? r.maxTangential : r.maxForce);
  }
  auto [xs, xUnit] = prefixFor(xMax, "m");
  auto [ys, yUnit] = prefixFor(yMax, "N");
  std::string xLabel = (tangentialPlot ? "tangential displacement (" : "overlap (") + xUnit + ")";
  std::string yLabel = (tangentialPlot ? "tangential force (" : "normal force (") + yUnit + ")";
  if (reference) {
    xs = reference->overlap;
    ys = reference->force;
    xLabel = "overlap / yield overlap of " + curves.front().label;
    yLabel = "normal force / yield force of " + curves.front().label;
  }
  const int xColumn = tangentialPlot ? 8 : 3, yColumn = tangentialPlot ? 9 : 4;
  std::ostringstream gp;
  gp << "# gnuplot script written by `sqdem contact`; run: gnuplot " << name << ".gp\n"
     << gnuplotPreamble(name)
     << "set datafile separator ','\nset key top left\nset grid\n"
     << "set title '" << title << "' noenhanced\n"
     << "set xlabel '" << xLabel << "' noenhanced\nset ylabel '" << yLabel << "' noenhanced\n"
     << "set xzeroaxis\nplot ";
  for (std::size_t i = 0; i < results.size(); ++i) {
    gp << (i ? ", \\\n     " : "") << "'" << results[i].csv << "' using ($" << xColumn << "/" << csvNumber(xs)
       << "):($" << yColumn << "/" << csvNumber(ys) << ") with lines lw 2 title '" << results[i].label << "' noenhanced";
  }
  gp << "\n";
  summary["gnuplot_script"] = (outDir / (name + ".gp")).string();
  summary["plot"] = nullptr;
  if (const auto png = plotPng(outDir, name, gp.str())) {
    summary["plot"] = png->string();
  } else {
    std::cerr << "sqdem contact: warning: gnuplot not found (scripts/setup.sh installs gnuplot-nox); "
                 "CSV and script written, PNG skipped\n";
  }
  std::cout << summary.dump(2) << "\n";
  int failures = 0;
  for (const Curve& c : curves) failures += c.geometry.detectorFailures();
  if (failures > 0 && !allowDetectorFailures) {
    std::cerr << "sqdem contact: " << failures << " step(s) the detector could not resolve (their overlap is the "
                 "prescribed approach, see 'detector_failures'); the poses or the path may be outside the shapes' "
                 "reach. --allow-detector-failures accepts such curves\n";
    return 1;
  }
  return 0;
}

}  // namespace

int contactDriver(const Arguments& args) {
  const char* usage = "usage: sqdem contact <file.json|-> [--out DIR] [--allow-detector-failures]\n";
  std::string input;
  fs::path outDir = ".";
  bool outGiven = false, allowDetectorFailures = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--out") {
      if (i + 1 == args.size() || outGiven) {
        std::cerr << "sqdem contact: '--out' needs one directory (given once)\n" << usage;
        return 2;
      }
      outDir = args[++i];
      outGiven = true;
    } else if (args[i] == "--allow-detector-failures") {
      allowDetectorFailures = true;
    } else if (input.empty() && (args[i] == "-" || args[i].rfind("--", 0) != 0)) {
      input = args[i];
    } else {
      std::cerr << "sqdem contact: unexpected argument '" << args[i] << "'\n" << usage;
      return 2;
    }
  }
  if (input.empty()) {
    std::cerr << usage;
    return 2;
  }
  try {
    return runContact(input, outDir, allowDetectorFailures);
  } catch (const InputError& e) {
    std::cerr << "sqdem contact: " << (input == "-" ? "<stdin>" : input) << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sqdem::cli
