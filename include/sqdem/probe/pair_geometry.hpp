#pragma once
// The contact geometry probe of one particle pair (`sqdem geometry`, sqdem.geometry): the
// common-normal detector with both surfaces' principal curvatures, and the elliptic Hertz
// quantities of the pair (docs/architecture.md, "Layers").
//
// Input:  {"particles": [{"centre": [x,y,z], "quaternion": [w,x,y,z], "a":..,"b":..,"c":..,
//                         "n1":..,"n2":..}, {...}],            (or "eta1"/"eta2" = 2/n)
//          "E_star": Pa (optional, adds "force"), "cap_factor": 10 (optional),
//          "cutoff": m (optional, default 0: report gaps only when touching)}
// Output: one JSON object, keys documented in README.md: status, converged, iterations,
// residual, overlap (null where the detector found none), R_vol_ref; where it converged the
// normal, both points, curvatures and directions, the relative radii and Hertz factors.

#include "sqdem/probe/json_input.hpp"

namespace sqdem::probe {

/// InputError naming the key for a description it cannot use.
json pairGeometry(const json& input);

}  // namespace sqdem::probe
