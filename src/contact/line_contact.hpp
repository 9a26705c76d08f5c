#pragma once
// A convex particle against the outside of an infinite cylinder of radius >= 0: with radius 0,
// a straight line (a mesh edge, mesh_detector.cpp). cylinder_detector.cpp has the method. Sets
// every field of the answer but B's curvatures, which the caller knows (the barrel's, or a
// mesh edge's flat stand-in).

#include "sqdem/contact/detector.hpp"

namespace sqdem {

ContactGeometry lineContact(const Superquadric& A, const Pose& poseA, const Cylinder& line,
                            const DetectorSettings& settings, const WarmStart* previous);

}  // namespace sqdem
