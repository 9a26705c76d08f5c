#include "sqdem/interaction/contact_model.hpp"

#include "contact_force.hpp"

namespace sqdem {

ContactForce contactForce(const ContactModel& model, const ContactGeometry& geometry, const ContactKinematics& motion,
                          ContactHistory& history, double dt) {
  return std::visit([&](const auto& law) { return detail::contactForce(model, law, detail::lawGeometry(model, geometry, motion), motion, history, dt); },
                    model.normal);
}

}  // namespace sqdem
