// `sqdem validate table1`: the Table 1 verification report (004 Table 1).

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "sqdem/validation/table1.hpp"
#include "sqdem/validation/table1_curve.hpp"

namespace sqdem::cli {
namespace {

constexpr double targetDeviation = 0.3;  // % from the review's accurate model (issue target)

double percent(double value, double reference) { return 100.0 * (value - reference) / reference; }

/// The curve of one case as a row, and the overlap where it crosses the FEM value (log-log
/// interpolation between the bracketing points; 0 where it does not cross).
void printCurveRow(const std::vector<Table1CurvePoint>& curve, int caseId) {
  std::printf("%-5d", caseId);
  const Table1CurvePoint* previous = nullptr;
  double crossing = 0.0, fem = 0.0;
  for (const Table1CurvePoint& p : curve) {
    if (p.caseId != caseId) continue;
    std::printf(" %8.4f", p.normalisedForce);
    fem = p.fem;
    if (previous && crossing == 0.0 && (previous->normalisedForce - fem) * (p.normalisedForce - fem) <= 0.0 &&
        previous->normalisedForce != p.normalisedForce) {
      const double s = std::log(fem / previous->normalisedForce) / std::log(p.normalisedForce / previous->normalisedForce);
      crossing = previous->overlapOverRvol * std::pow(p.overlapOverRvol / previous->overlapOverRvol, s);
    }
    previous = &p;
  }
  std::printf("   %.4f   ", fem);
  if (crossing > 0.0) std::printf("%.1e\n", crossing);
  else std::printf("none in range\n");
}

void printCurves(const std::vector<Table1CurvePoint>& curve, const std::string& law) {
  std::printf("\nThe normalised force against the overlap, law %s (docs/contact_laws.md, \"Blocky contacts\"):\n", law.c_str());
  std::printf("%-5s", "case");
  for (const double f : table1Overlaps) std::printf(" %8.0e", f);
  std::printf("   %-8s %s\n", "FEM", "meets FEM at delta/R_vol");
  for (const Table1Case& c : table1Cases) printCurveRow(curve, c.id);
}

}  // namespace

int validateTable1(const Arguments& args) {
  const char* usage = "usage: sqdem validate table1 [--law review|elliptic_hertz|boundary_element] [--json]\n";
  if (args.empty() || args[0] != "table1") {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  std::string law = "review";
  bool json = false, lawGiven = false;
  for (std::size_t k = 1; k < args.size(); ++k) {
    if (args[k] == "--json" && !json) {
      json = true;
    } else if (args[k] == "--law" && !lawGiven && k + 1 < args.size()) {
      law = args[++k];
      lawGiven = true;
    } else {
      std::fprintf(stderr, "sqdem validate: unexpected or repeated argument '%s'\n%s", args[k].c_str(), usage);
      return 2;
    }
  }
  try {
    requireTable1CurveLaw(law);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "sqdem validate table1: --law: %s\n", e.what());
    return 2;
  }
  std::vector<Table1Result> results;
  for (const Table1Case& c : table1Cases) results.push_back(runTable1Case(c));
  bool pass = true;
  for (const Table1Result& r : results) pass = pass && std::abs(percent(r.normalisedForce, r.reference.accurate)) <= targetDeviation;
  const std::vector<Table1CurvePoint> curve = table1Curve(law);
  if (json) {
    nlohmann::ordered_json out;
    out["law"] = law;
    out["cases"] = nlohmann::ordered_json::array();
    for (const Table1CurvePoint& p : curve) {
      out["cases"].push_back({{"case", p.caseId}, {"overlap_over_rvol", p.overlapOverRvol}, {"normalised_force", p.normalisedForce}, {"fem", p.fem}});
    }
    std::printf("%s\n", out.dump(2).c_str());
    return pass ? 0 : 1;
  }
  std::printf(
      "Table 1 of Kildashti, Dong & Yu (2023), seed 004: normalised normal force\n"
      "F / (4/3 E* R_vol^1/2 delta^3/2) of two superquadrics n1 = n2 = 6, a = b, c = 2b.\n"
      "sqdem: common-normal detector -> principal curvatures -> Ri, Rj (cap 10 R_vol) ->\n"
      "explicit e^2 (Eq. 14) -> gamma (Eq. 11). Deviations in %% from FEM unless stated.\n\n");
  std::printf("%-5s %-24s %-20s %-18s %-24s %-9s\n", "case", "(i) sqdem [vs review]",
              "(ii) review accurate", "(iii) FEM", "(iv) simplified sqdem", "review");
  for (const Table1Result& r : results) {
    const Table1Case& c = r.reference;
    const double fromReview = percent(r.normalisedForce, c.accurate);
    std::printf("%-5d %.4f %+6.2f [%+6.3f]   %.4f %+6.2f        %.4f             %.4f %+7.2f          %.4f %+7.2f\n",
                c.id, r.normalisedForce, percent(r.normalisedForce, c.fem), fromReview, c.accurate,
                percent(c.accurate, c.fem), c.fem, r.simplifiedForce,
                percent(r.simplifiedForce, c.fem), table1Simplified,
                percent(table1Simplified, c.fem));
  }
  std::printf("\nGeometry per case (lengths in R_vol):\n");
  std::printf("%-5s %-10s %-10s %-10s %-12s %-10s %-10s %-10s %-6s %-10s\n", "case", "overlap",
              "Ri", "Rj", "omega(deg)", "Rc", "gamma_exp", "gamma_ex", "iters", "(i) exact e2");
  for (const Table1Result& r : results) {
    const Table1Case& c = r.reference;
    const double R = r.volumeEquivalentRadius;
    std::printf("%-5d %-10.3e %-10.5f %-10.5f %-12.4f %-10.5f %-10.5f %-10.5f %-6d %.4f\n", c.id,
                r.contact.overlap / R, r.radii.Ri / R, r.radii.Rj / R,
                r.radii.omega() * 180.0 / std::numbers::pi, r.radii.Rc / R, r.explicitFactors.gamma,
                r.exactFactors.gamma, r.contact.iterations, r.normalisedForceExact);
  }
  printCurves(curve, law);
  std::printf("\n%s: sqdem within %.1f %% of the review's accurate model in all cases\n",
              pass ? "PASS" : "FAIL", targetDeviation);
  return pass ? 0 : 1;
}

}  // namespace sqdem::cli
