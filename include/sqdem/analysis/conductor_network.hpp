#pragma once
// Steady conduction through a network of nodes joined by conductances (docs/electrode_analysis.md,
// "Electronic network"): Kirchhoff's current law at every node, solved by conjugate gradients
// (spd_solve.hpp). Along an axis the box is either
//   periodic: the potential drops by dV per period, phi(x + L e_d) = phi(x) - dV, so that a link
//             to the image of its node b shifted by s periods carries g (phi_a - phi_b + s_d dV);
//             the mean current density is the volume average (1/V) sum_l I_l l_l,d (l the link's
//             branch vector, a to b's image), and sigma_eff = <J_d> L_d / dV;
//   between electrodes: nodes joined to the low electrode (potential dV) and to the high one (0),
//             each by a conductance or ideally (the node then at the electrode's potential);
//             sigma_eff = I L_d / (A dV), I the current out of the low electrode, A the box's
//             cross-section.
// Nodes that carry no current are left out: along a periodic axis those of clusters that do not
// wrap around the period (their potential can follow the drop without current), between electrodes
// those of clusters that do not join both electrodes. A network without a path conducts nothing.

#include <array>
#include <cstdint>
#include <vector>

#include "sqdem/math/types.hpp"

namespace sqdem {

struct ConductorNetwork {
  /// A conductance between node a and the image of node b shifted by `shift` periods.
  struct Link {
    std::uint32_t a = 0, b = 0;
    double conductance = 0.0;             ///< (S)
    std::array<std::int8_t, 3> shift{0, 0, 0};
    Vec3 branch = Vec3::Zero();           ///< (m) from a to b's image
  };
  /// A node's connection to an electrode; an infinite conductance joins it ideally.
  struct Terminal {
    std::uint32_t node = 0;
    double conductance = 0.0;  ///< (S)
  };

  std::size_t nodes = 0;
  std::vector<Link> links;
  Vec3 box = Vec3::Zero();                 ///< (m) the box's edges
  std::array<bool, 3> periodic{true, true, false};
  /// Per axis (not periodic), the nodes joined to the electrode at its low and high face.
  std::array<std::vector<Terminal>, 3> low, high;
};

struct NetworkConduction {
  int axis = 2;
  bool percolates = false;             ///< a path joins the electrodes, or wraps the period
  double conductivity = 0.0;           ///< sigma_eff (S/m); 0 without a path
  std::size_t carryingNodes = 0;       ///< the nodes of the clusters that carry current
  double currentImbalance = 0.0;       ///< |I_in - I_out| / I_in between electrodes, else 0
  long iterations = 0;                 ///< conjugate-gradient iterations
  bool converged = true;               ///< to the tolerance, within the iteration limit
  std::vector<double> potential;       ///< per node (dV = 1); NaN for the nodes left out
  std::vector<double> current;         ///< per link, from a to b (A at dV = 1 V)
};

/// The network's conduction along `axis`, to the relative residual `tolerance`. Throws
/// std::invalid_argument for an axis outside 0-2, a link to a missing node or whose conductance is
/// not finite and > 0, a terminal of a periodic axis or whose conductance is not > 0, a node joined
/// ideally to both electrodes (a short circuit) or a box edge <= 0.
NetworkConduction solveConduction(const ConductorNetwork& network, int axis, double tolerance = 1e-10);

}  // namespace sqdem
