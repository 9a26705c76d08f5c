#include "sqdem/probe/pair_geometry.hpp"

#include <cmath>

#include "sqdem/contact/detector.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem::probe {
namespace {

json toJson(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

}  // namespace

json pairGeometry(const json& input) {
  if (!input.is_object()) throw InputError("top level must be a JSON object");
  rejectUnknownKeys(input, {"particles", "E_star", "cap_factor", "cutoff"}, "top level");
  if (!input.contains("particles") || !input["particles"].is_array() || input["particles"].size() != 2) {
    throw InputError("'particles' must be an array of exactly two particle objects");
  }
  const Particle A = readParticle(input["particles"][0], "particles[0]");
  const Particle B = readParticle(input["particles"][1], "particles[1]");
  const double capFactor = input.contains("cap_factor") ? number(input, "cap_factor", "top level") : 10.0;
  if (!(capFactor > 0.0)) throw InputError("'cap_factor' must be > 0");
  DetectorSettings settings;
  if (input.contains("cutoff")) settings.cutoff = number(input, "cutoff", "top level");
  if (settings.cutoff < 0.0) throw InputError("'cutoff' must be >= 0 (m)");

  const ContactGeometry g = detectContact(A.shape, A.pose, B.shape, B.pose, settings);
  json out;
  out["status"] = describe(g.status);
  out["converged"] = g.converged();
  out["iterations"] = g.iterations;
  out["residual"] = g.residual;
  // An overlap only where the detector found one: a common normal, a gap beyond the cut-off
  // (a lower bound, negative) or a degenerate pair's penetration depth.
  const bool degenerate = g.status == ContactStatus::Degenerate;
  out["overlap"] = g.converged() || degenerate || g.status == ContactStatus::Separated ? json(g.overlap) : json(nullptr);
  const double RvolRef = referenceVolumeRadius(A.shape, B.shape);
  out["R_vol_ref"] = RvolRef;
  if (!g.converged() && !degenerate) return out;

  out["normal"] = toJson(g.normal);
  out["point_a"] = toJson(g.pointA);
  out["point_b"] = toJson(g.pointB);
  if (degenerate) return out;  // no common normal: no curvatures
  out["curvatures_a"] = json::array({g.curvatureA.k1, g.curvatureA.k2});
  out["curvatures_b"] = json::array({g.curvatureB.k1, g.curvatureB.k2});
  out["directions_a"] = json::array({toJson(g.curvatureA.d1), toJson(g.curvatureA.d2)});
  out["directions_b"] = json::array({toJson(g.curvatureB.d1), toJson(g.curvatureB.d2)});
  const RelativeRadii radii = relativeRadii(g.curvatureA, g.curvatureB, capFactor * RvolRef);
  out["omega"] = radii.omega();
  out["Ri"] = radii.Ri;
  out["Rj"] = radii.Rj;
  out["Rc"] = radii.Rc;
  const HertzFactors exact = hertzFactors(radii.ratio(), EccentricityMethod::Exact);
  const HertzFactors approx = hertzFactors(radii.ratio(), EccentricityMethod::Explicit);
  out["e2_exact"] = exact.e2;
  out["e2_approx"] = approx.e2;
  out["gamma_exact"] = exact.gamma;
  out["gamma_approx"] = approx.gamma;
  out["beta_exact"] = exact.beta;
  out["beta_approx"] = approx.beta;
  out["normalised_force"] = approx.gamma * std::sqrt(radii.Rc / RvolRef);
  if (input.contains("E_star")) {
    const double Estar = number(input, "E_star", "top level");
    if (!(Estar > 0.0)) throw InputError("'E_star' must be > 0 (Pa)");
    out["force"] = ellipticHertzForce(Estar, radii.Rc, g.overlap, approx.gamma);
  }
  return out;
}

}  // namespace sqdem::probe
