#pragma once
// A fixture for the layer check (cmake/check_layer_includes.cmake): as a file of the interaction
// layer, this include of the world layer goes against the direction of the layers and must be
// refused.
#include "sqdem/world/world.hpp"
