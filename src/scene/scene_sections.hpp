#pragma once
// The scene document's sections, each read and checked by its own reader (scene_loader.cpp calls
// them in this order: a section may refer to what an earlier one defined, e.g. interactions to
// materials, stages to walls). Keys and units: docs/scene_reference.md.

#include <yaml-cpp/yaml.h>

#include "sqdem/scene/scene.hpp"
#include "scene_reader.hpp"

namespace sqdem::detail {

/// `materials:` name -> properties.
void readMaterials(const Reader& r, const YAML::Node& root, Scene& scene);
/// `shapes:` name -> semi-axes or a distribution, or a shape file.
void readShapes(const Reader& r, const YAML::Node& root, Scene& scene);
/// `interactions:` one entry per material pair: the normal law (law_registry.hpp) and the pair's
/// tangential law, damping and friction.
void readInteractions(const Reader& r, const YAML::Node& root, Scene& scene);
/// `walls:` planes, cylinders and meshes.
void readWalls(const Reader& r, const YAML::Node& root, Scene& scene);
/// `particles:` and `insert:` (particle files, random insertions).
void readParticles(const Reader& r, const YAML::Node& root, Scene& scene);
/// `stages:` durations, stop criteria, wall motions.
void readStages(const Reader& r, const YAML::Node& root, Scene& scene);
/// `output:` frames, log, checkpoints, compression of the frames.
void readOutput(const Reader& r, const YAML::Node& root, Scene& scene);

}  // namespace sqdem::detail
