// Interactions::ellipses: the contact ellipse of every stored contact, from its area and the
// Hertz aspect of its relative radii (interactions.hpp). A contact whose roller the detector no
// longer finds at the current poses is left zero.

#include <cmath>
#include <numbers>

#include "contact_force.hpp"
#include "sqdem/interaction/interactions.hpp"

namespace sqdem {

std::vector<ContactEllipse> Interactions::ellipses(const InteractionScene& scene) const {
  std::vector<ContactEllipse> out(store_.size());
  const ParticleStore& p = scene.particles;
  for (const Group& group : groups_) {
    const ContactModel& model = scene.models[group.model];
    const bool elliptic = !round(group.kind) && model.usesCurvatures();
    for (const std::uint32_t k : group.members) {
      const double area = store_.load[k].area;
      if (!store_.acting[k] || !(area > 0.0)) continue;
      if (!elliptic) {
        const double radius = std::sqrt(area / std::numbers::pi);
        out[k] = {radius, radius, Vec3::Zero()};
        continue;
      }
      const std::uint32_t a = store_.a[k], b = store_.b[k];
      const Superquadric& A = scene.shapes[p.shape[a]];
      const Pose poseA{p.position[a], p.orientation[a]};
      ContactGeometry g;
      g.localPointA = store_.localA[k];
      g.localPointB = store_.localB[k];
      g.normal = store_.normal[k];
      ContactKinematics motion;
      motion.volumeRadiusA = A.volumeEquivalentRadius();
      if (group.kind == PairKind::ParticleCylinder) {
        // The roller's curvatures depend on which part of it touches (its barrel, a rounded end,
        // a flat end or its rim): its detector gives them, warm from the stored answer.
        Cylinder image = scene.walls[b & ~wallFlag].get<CylinderWall>().cylinder;
        image.point += store_.wallImage[k];
        const WarmStart warm{store_.localA[k], store_.localB[k], store_.overlap[k]};
        g = detectContact(A, poseA, image, {.cutoff = scene.skin, .tolerance = scene.detector.tolerance, .curvatures = true}, &warm);
        if (!g.converged()) continue;
      } else if (withWall(group.kind)) {  // a plane, or a mesh's face, edge or vertex: flat
        addCurvatures(g, A, poseA);
        g.curvatureB = PrincipalCurvatures::flat(-g.normal);
      } else {
        const Superquadric& B = scene.shapes[p.shape[b]];
        addCurvatures(g, A, poseA, B, Pose{p.position[b], p.orientation[b]});
        motion.volumeRadiusB = B.volumeEquivalentRadius();
      }
      const double aspect = std::sqrt(1.0 - detail::normalContact(model, g, motion).factors.e2);  // b / a
      const double major = std::sqrt(area / (std::numbers::pi * aspect));
      out[k] = {major, major * aspect, contactMajorAxis(g.curvatureA, g.curvatureB, g.normal)};
    }
  }
  return out;
}

}  // namespace sqdem
