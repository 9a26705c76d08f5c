#include "sqdem/mechanics/mindlin_spring.hpp"

#include "sqdem/mechanics/mindlin_deresiewicz.hpp"

namespace sqdem {

Vec3 MindlinSpring::ellipticForce(const NormalContact& c, const Vec3& u, const Vec3& n, double area, const Vec3& vt,
                                  double limit, const ViscousDamping& damping, double mass, Vec3& spring) const {
  // Stiffness along the ellipse's major axis u and minor axis v.
  const double scale = 8.0 * effectiveShear * contactSemiMajorAxis(area, c.factors.e2);
  const MindlinPhi phi = mindlinPhi(c.factors.K, c.factors.D, poissonRatio);
  const double ku = scale / phi.major, kv = scale / phi.minor;
  const Vec3 v = n.cross(u);
  const double etaU = damping.coefficient(mass, ku), etaV = damping.coefficient(mass, kv);
  const double vu = vt.dot(u), vv = vt.dot(v);
  Vec3 Ft = -(ku * spring.dot(u) + etaU * vu) * u - (kv * spring.dot(v) + etaV * vv) * v;
  if (Ft.squaredNorm() > limit * limit) {
    Ft *= limit / Ft.norm();
    spring = ku > 0.0 && kv > 0.0 ? Vec3(-(Ft.dot(u) + etaU * vu) / ku * u - (Ft.dot(v) + etaV * vv) / kv * v) : Vec3::Zero();
  }
  return Ft;
}

}  // namespace sqdem
