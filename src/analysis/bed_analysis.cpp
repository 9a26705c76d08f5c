#include "sqdem/analysis/bed_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "sqdem/analysis/electronic_network.hpp"
#include "sqdem/analysis/surface_area.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The pores along x, y and z of the image, each axis' concentrations dropped (memory) but z's
/// when `keepZ`.
std::array<PoreDiffusion, 3> poresOf(const VoxelImage& image, const Domain& domain, bool keepZ) {
  std::array<PoreDiffusion, 3> out;
  for (int axis = 0; axis < 3; ++axis) {
    out[axis] = solvePoreDiffusion(image, axis, domain.periodic[0] && domain.periodic[1]);
    if (axis < 2 || !keepZ) out[axis].concentration = {};
  }
  return out;
}

}  // namespace

BedAnalysis analyseBed(const World& world, const BedAnalysisOptions& options) {
  const ParticleStore& p = world.particles();
  const Domain& domain = world.domain();
  if (options.voxels < 4) throw std::invalid_argument("analyseBed: at least 4 voxels along the longest edge");
  if (p.size() == 0) throw std::invalid_argument("analyseBed: the world holds no particle");
  BedAnalysis out;
  const PlaneWall* floor = floorWall(world);
  const double zLow = options.zLow.value_or(floor ? floor->plane.point.z() : domain.lo.z());
  const double zHigh = options.zHigh.value_or(zLow + equivalentBedHeight(world, zLow));
  if (!(zHigh > zLow)) throw std::invalid_argument("analyseBed: the box's top must lie above its bottom");
  out.lo = Vec3(domain.lo.x(), domain.lo.y(), zLow);
  out.hi = Vec3(domain.hi.x(), domain.hi.y(), zHigh);
  const double boxVolume = (out.hi - out.lo).prod();
  const auto inBox = [&](std::size_t i) { return p.position[i].z() >= zLow && p.position[i].z() < zHigh; };
  for (std::size_t i = 0; i < p.size(); ++i) out.particles += inBox(i) ? 1 : 0;
  if (out.particles == 0) throw std::invalid_argument("no particle's centre lies in the box (--region, a stage's analyse.region)");

  // The electronic network first (cheap, and it refuses a box too thin for its electrodes).
  auto start = std::chrono::steady_clock::now();
  const std::vector<ContactEllipse> spots = world.contactEllipses();  // the network's and the surface's
  out.network = electronicNetwork(world, spots, options.conductivity, zLow, zHigh);
  for (int axis = 0; axis < 3; ++axis) out.conduction[axis] = solveConduction(out.network, axis);
  std::vector<double> volumeOf(world.materials().size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (inBox(i)) volumeOf[p.material[i]] += world.shapes()[p.shape[i]].volume();
  }
  out.referenceConductivity = options.conductivity[std::max_element(volumeOf.begin(), volumeOf.end()) - volumeOf.begin()];
  out.seconds.network = secondsSince(start);

  // Pores at N and 2 N voxels.
  start = std::chrono::steady_clock::now();
  std::vector<PlacedShape> placed(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) placed[i] = {&world.shapes()[p.shape[i]], p.position[i], p.orientation[i]};
  const std::array<bool, 3> periodic{domain.periodic[0], domain.periodic[1], false};
  const VoxelImage image = voxelise(placed, out.lo, out.hi, periodic, options.voxels);
  out.fineImage = voxelise(placed, out.lo, out.hi, periodic, 2 * options.voxels);
  out.porosity = out.fineImage.porosity();
  out.voxelEdge = {image.voxel.maxCoeff(), out.fineImage.voxel.maxCoeff()};
  out.voxelsAlongLongest = {*std::max_element(image.size.begin(), image.size.end()),
                            *std::max_element(out.fineImage.size.begin(), out.fineImage.size.end())};
  out.seconds.voxels = secondsSince(start);
  start = std::chrono::steady_clock::now();
  out.pores = poresOf(image, domain, false);
  out.finePores = poresOf(out.fineImage, domain, true);
  out.seconds.pores = secondsSince(start);

  // Surface, coordination and the profiles: each particle where its centre lies.
  const double thickness = zHigh - zLow;
  double diameter = 0.0, surface = 0.0;
  const std::vector<int> contactsOf = coordinationNumbers(world);
  std::vector<double> areaOf(world.shapes().size(), -1.0);  // per shape, when first needed
  long contacts = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!inBox(i)) continue;
    const Superquadric& shape = world.shapes()[p.shape[i]];
    diameter += 2.0 * shape.volumeEquivalentRadius();
    double& area = areaOf[p.shape[i]];
    if (area < 0.0) area = surfaceArea(shape);
    surface += area;
    contacts += contactsOf[i];
  }
  out.coordination = static_cast<double>(contacts) / static_cast<double>(out.particles);
  // Each contact buries its spot's area pi a b on each side in the box (a wall's: the particle's side).
  for (const ContactView c : world.contacts()) {
    const ContactEllipse& spot = spots[c.slot()];
    const double buried = std::numbers::pi * spot.major * spot.minor;
    surface -= inBox(c.a()) ? buried : 0.0;
    if (!c.onWall()) surface -= inBox(world.ownedSlot(c.b())) ? buried : 0.0;
  }
  out.specificSurface = surface / boxVolume;

  const int slices = std::max(1, static_cast<int>(std::lround(thickness / (diameter / static_cast<double>(out.particles)))));
  out.profile.resize(static_cast<std::size_t>(slices));
  for (int s = 0; s < slices; ++s) {
    out.profile[s].zLow = zLow + thickness * s / slices;
    out.profile[s].zHigh = zLow + thickness * (s + 1) / slices;
  }
  const auto sliceOf = [&](double z) { return std::min(slices - 1, static_cast<int>((z - zLow) / thickness * slices)); };
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!inBox(i)) continue;
    BedSlice& slice = out.profile[sliceOf(p.position[i].z())];
    ++slice.particles;
    slice.coordination += contactsOf[i];
  }
  std::vector<double> voxels(static_cast<std::size_t>(slices), 0.0);
  const VoxelImage& fine = out.fineImage;
  for (int k = 0; k < fine.size[2]; ++k) {
    const int s = sliceOf(zLow + (k + 0.5) * fine.voxel.z());
    for (int j = 0; j < fine.size[1]; ++j) {
      for (int i = 0; i < fine.size[0]; ++i) out.profile[s].porosity += fine.pore[fine.index(i, j, k)];
    }
    voxels[s] += static_cast<double>(fine.size[0]) * fine.size[1];
  }
  for (int s = 0; s < slices; ++s) {
    BedSlice& slice = out.profile[s];
    slice.porosity = voxels[s] > 0.0 ? slice.porosity / voxels[s] : std::numeric_limits<double>::quiet_NaN();
    slice.coordination = slice.particles ? slice.coordination / static_cast<double>(slice.particles) : std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

}  // namespace sqdem
