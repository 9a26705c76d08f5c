#pragma once
// A validated scene description: what a scene file declares (see examples/*.yaml and README.md
// "Scene files" for every key with its unit). The scene layer reads it (scene_loader.hpp), builds
// a World from it (build_world.hpp) and runs its stages (stage_runner.hpp).

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sqdem/io/vtk_xml.hpp"
#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/interaction/contact_model.hpp"
#include "sqdem/geometry/domain.hpp"
#include "sqdem/scene/wall_path.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct NamedMaterial {
  std::string name;
  Material material;
  /// (S/m) for the electrode analysis' electronic network (docs/electrode_analysis.md); the
  /// engine does not read it.
  std::optional<double> electronicConductivity;
};

/// A shape family: fixed semi-axes, or a distribution of volume-equivalent radius and the
/// aspect ratios b/a, c/a (002 Table 2 style), sampled per particle.
struct ShapeFamily {
  std::string name;
  /// The semi-axes as given (m): every particle of the family has exactly these (the ranges
  /// below then hold the values they imply, each a single value).
  std::optional<Vec3> semiAxes;
  std::array<double, 2> volumeRadius{0.0, 0.0};  ///< [min, max] (m), uniform in radius
  std::array<double, 2> aspectB{1.0, 1.0};       ///< b/a range
  std::array<double, 2> aspectC{1.0, 1.0};       ///< c/a range
  double n1 = 2.0, n2 = 2.0;                     ///< superquadric exponents
};

struct InteractionSpec {
  std::uint32_t materialA = 0, materialB = 0;
  std::string normalName = "elliptic_hertz";  ///< its name in the registry (law_registry.hpp)
  NormalLaw normal = HertzLaw{};
  bool curvatures = true;       ///< the normal law works on the detector's curvatures
  std::vector<std::pair<std::string, double>> lawParameters;  ///< every key the law read, with its value
  bool ellipticTangential = true;  ///< tangential: elliptic_mindlin (else circular_mindlin)
  EccentricityMethod eccentricity = EccentricityMethod::Tabulated;
  double capFactor = 10.0;
  double curvatureTolerance = ContactModel{}.curvatureTolerance;  ///< ContactModel::curvatureTolerance (-)
  double restitution = 0.0;     ///< pair restitution e (0: min of the materials'), sets the damping
  double friction = -1.0;       ///< pair friction mu (< 0: min of the materials')
  double stiffnessScale = 1.0;  ///< reduced-stiffness factor E_mod/E (001 Eq. 24)
  double rollingHysteresis = 0.0;  ///< dgamma/gamma of the rolling resistance (0: off, needs haervig_jkr)
  std::optional<ParallelBond> bond;  ///< the pair's bonds, where a stage forms them (`bond`)
  bool deepOverlapsExpected = false;  ///< `deep_overlaps: expected` (ContactModel::deepOverlapsExpected)
};

/// A wall as the scene gives it (walls_section.cpp): the engine's wall at the start, and a mesh
/// wall's mesh, read, repaired and scaled to m at load (the world takes it and sets MeshWall::mesh:
/// build_world.cpp).
struct WallSpec {
  Wall wall;
  std::shared_ptr<const MeshFeatures> mesh;
};

/// One species of a random insertion: a shape family of one material, and its share.
struct InsertedSpecies {
  std::uint32_t shape = 0, material = 0;
  double volumeFraction = 1.0;  ///< of the insertion's particle volume (a recipe's mass fractions converted)
};

/// A random insertion (`insert: [{count | solid_fraction, shape, material, region}]`), or a
/// recipe of several species (`recipe: [{shape, material, fraction}, ...], by: mass | volume`).
struct InsertionSpec {
  std::vector<InsertedSpecies> species;  ///< one, or the recipe's in its order
  std::size_t count = 0;         ///< particles of the first species (the others by their share), or
  double solidFraction = 0.0;    ///< (> 0) insert until the particle volume is this x the region's
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  ///< region for the centres (m)
  bool randomOrientation = true;
};

/// A particle placed explicitly: an entry of `particles:` or a row of a particle file
/// (`insert: [{file: ...}]`, particle_file.hpp).
struct ParticleSpec {
  std::string origin;             ///< "particles[3]" or "bed.csv:12", for messages
  std::optional<std::uint32_t> shape;  ///< a fixed-size shape family, or
  Vec3 semiAxes = Vec3::Zero();   ///< the superquadric's semi-axes (m)
  double n1 = 2.0, n2 = 2.0;      ///< and exponents
  std::uint32_t material = 0;
  Vec3 centre = Vec3::Zero();     ///< (m)
  Quat orientation = Quat::Identity();  ///< body -> world
  Vec3 velocity = Vec3::Zero();   ///< (m/s)
  Vec3 angularVelocity = Vec3::Zero();  ///< world frame (rad/s)
  bool allowOverlap = false;      ///< may start overlapping other particles or walls
};

/// The electrode analysis of a bed (`stages[].analyse`, `sqdem analyse`; docs/electrode_analysis.md).
struct AnalysisSpec {
  std::optional<double> zLow, zHigh;  ///< the box's bottom and top (m); defaults: the floor, the bed's top
  int voxels = 64;                    ///< along the box's longest edge (also at twice that)
};

struct StageSpec {
  std::string name;
  double duration = 0.0;            ///< simulated time limit (s)
  double kineticEnergyRatio = 0.0;  ///< stop when E_kin / scale falls below (0: off), scale =
                                    ///< sum m |g| R_vol, or sum m v_s^2 / 2 with a velocity scale
  double velocityScale = 0.0;       ///< v_s (m/s) of that scale (0: use gravity)
  double wallPressure = 0.0;        ///< stop when wall `pressureWall` carries this pressure (Pa, 0: off)
  double porosity = 0.0;            ///< stop when the plate `pressureWall` has pressed the bed to this
                                    ///< porosity (PlateMeasures::porosity, 0: off)
  std::size_t pressureWall = 0;
  double minimumDuration = 0.0;     ///< the stop criteria are checked only after this (s)
  double viscousDamping = 0.0;      ///< background drag c (1/s), F = -c m v
  /// Bonds formed as the stage starts (`form_bonds.gap`): between the pairs whose interaction
  /// has a bond, with a gap up to this times the smaller volume radius (-)
  std::optional<double> bondGap;
  std::optional<std::size_t> wall;  ///< wall moved in this stage
  Vec3 wallVelocity = Vec3::Zero(); ///< its velocity during the stage (m/s), or
  WallPath wallPath;                ///< its position along its normal (when points are given)
  std::optional<std::size_t> servoWall;  ///< wall under force control in this stage
  WallServo servo;
  std::optional<AnalysisSpec> analysis;  ///< analyse the bed at the stage's end (`analyse`)
};

struct OutputSpec {
  std::size_t frames = 20;      ///< VTK frames per stage (plus the initial state)
  std::size_t logEvery = 0;     ///< CSV row every N steps (0: 200 rows per stage)
  bool contacts = true;         ///< write the contact network (.vtp)
  /// Particles' surfaces drawn with 6 N^2 quads each (0: not written); unset: planRun decides.
  std::optional<int> surfaceResolution;
  std::uint64_t checkpointSteps = 0;  ///< also write <name>_latest.checkpoint every N steps (0: off)
  double checkpointMinutes = 10.0;    ///< ... and every M wall-clock minutes (0: off)
  bool energy = false;          ///< keep an energy ledger (world/energy_ledger.hpp) and log it
  bool sphereOrientation = false;  ///< advance spheres' orientations (World::setSphereOrientations)
  VtkCompression vtkCompression = VtkCompression::ZLib;  ///< of the .vtp frames
  std::optional<std::size_t> compressionWall;  ///< the pressing plate: compression_report.hpp
};

struct Scene {
  std::string path;
  std::uint64_t seed = 1;
  Domain domain;
  Vec3 gravity = Vec3::Zero();
  std::optional<double> timeStep;  ///< explicit (s); otherwise timeStepFraction x Rayleigh time
  double timeStepFraction = 0.2;
  double impactVelocity = 0.0;     ///< (m/s) > 0: auto also resolves a Hertz impact at this speed
  double stepsPerCollision = 50.0; ///< ... with this many steps
  double skin = 0.0;               ///< Verlet skin (m); 0: 0.2 x smallest volume radius
  double detectorTolerance = 0.0;  ///< DetectorControl::tolerance (-); 0: the engine's default
  std::optional<BroadPhase> broadPhase;  ///< how candidate pairs are found; unset (auto): automaticBroadPhase
  int reorderEvery = 20;           ///< Hilbert re-ordering every N neighbour-list builds (0: off)
  std::vector<NamedMaterial> materials;
  std::vector<ShapeFamily> shapes;
  std::vector<InteractionSpec> interactions;
  std::vector<WallSpec> walls;
  std::vector<ParticleSpec> particles;     ///< placed first (the list, then the files of `insert`)
  std::vector<InsertionSpec> insertions;   ///< random insertions, avoiding every particle before them
  std::vector<StageSpec> stages;
  OutputSpec output;
};

}  // namespace sqdem
