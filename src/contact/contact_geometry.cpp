#include "sqdem/contact/contact_geometry.hpp"

namespace sqdem {

const char* describe(ContactStatus status) {
  switch (status) {
    case ContactStatus::Converged: return "converged";
    case ContactStatus::Separated: return "separated beyond the cut-off";
    case ContactStatus::MaxIterations: return "not converged: iteration limit reached";
    case ContactStatus::Stalled: return "not converged: residual could not be reduced";
    case ContactStatus::WrongBranch: return "not converged: a common-normal pair that is not the contact (far side, or not the least penetration)";
    case ContactStatus::NonFinite: return "not converged: non-finite value (degenerate input)";
    case ContactStatus::Degenerate: return "degenerate: centres coincide or one lies inside the other body";
  }
  return "unknown status";
}

}  // namespace sqdem
