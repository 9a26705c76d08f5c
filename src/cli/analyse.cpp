// `sqdem analyse <scene.yaml> --particles FILE [--out DIR] [--region ZLO ZHI] [--voxels N]`: the
// electrode analysis of a particle file (analysis/bed_analysis.hpp; docs/electrode_analysis.md)
// with the scene's materials, laws and walls: one JSON object on stdout (also analysis.json),
// and in DIR the voxel image (pores.vti), the electronic network (network.vtp) and the profiles
// through the thickness (profile.csv, profile.png).

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "commands.hpp"
#include "sqdem/analysis/bed_analysis.hpp"
#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/gnuplot.hpp"
#include "sqdem/io/vtk_xml.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/particle_file.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace sqdem::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;  // keys in the order written

constexpr const char* usage = "usage: sqdem analyse <scene.yaml> --particles FILE [--out DIR] [--region ZLO ZHI] [--voxels N]\n";

struct AnalyseArguments {
  std::string scene;
  fs::path particles, out;
  std::optional<double> zLow, zHigh;
  int voxels = 64;
};

/// The number in `text`, whole; nullopt otherwise.
std::optional<double> numberIn(const std::string& text) {
  std::size_t used = 0;
  try {
    const double x = std::stod(text, &used);
    if (used == text.size() && std::isfinite(x)) return x;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

/// The arguments, or the message that refuses them.
std::variant<AnalyseArguments, std::string> parse(const Arguments& args) {
  AnalyseArguments a;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& key = args[i];
    const auto values = [&](std::size_t n) { return i + n < args.size(); };
    if (key == "--particles" && values(1)) {
      a.particles = args[++i];
    } else if (key == "--out" && values(1)) {
      a.out = args[++i];
    } else if (key == "--region" && values(2)) {
      a.zLow = numberIn(args[i + 1]);
      a.zHigh = numberIn(args[i + 2]);
      if (!a.zLow || !a.zHigh || !(*a.zHigh > *a.zLow)) return "'--region' takes two numbers ZLO < ZHI (m), not '" + args[i + 1] + " " + args[i + 2] + "'";
      i += 2;
    } else if (key == "--voxels" && values(1)) {
      const std::optional<double> n = numberIn(args[++i]);
      if (!n || *n != std::floor(*n) || *n < 4 || *n > 1024) return "'--voxels' takes a whole number in [4, 1024], not '" + args[i] + "'";
      a.voxels = static_cast<int>(*n);
    } else if (a.scene.empty() && key.rfind("--", 0) != 0) {
      a.scene = key;
    } else {
      return "unexpected argument '" + key + "' (or a value missing after it)";
    }
  }
  if (a.scene.empty() || a.particles.empty()) return "a scene and --particles FILE are needed";
  if (a.out.empty()) a.out = a.particles.parent_path() / (a.particles.stem().string() + "_analysis");
  return a;
}

/// Per material its conductivity (S/m): the scene's `electronic_conductivity`; without any, 1 for
/// every material (the ratios need none); a wall material without one conducts ideally. Throws
/// SceneError for a particle material without one when others have one.
std::vector<double> conductivities(const Scene& scene) {
  std::vector<std::uint8_t> ofParticles(scene.materials.size(), 0);
  for (const ParticleSpec& p : scene.particles) ofParticles[p.material] = 1;
  bool any = false;
  for (const NamedMaterial& m : scene.materials) any = any || m.electronicConductivity.has_value();
  std::vector<double> out(scene.materials.size(), 1.0);
  for (std::size_t m = 0; m < out.size(); ++m) {
    const std::optional<double>& sigma = scene.materials[m].electronicConductivity;
    if (!any) continue;
    if (sigma) out[m] = *sigma;
    else if (ofParticles[m]) throw SceneError(scene.path + ": materials." + scene.materials[m].name + ".electronic_conductivity: missing (S/m): other materials give one");
    else out[m] = std::numeric_limits<double>::infinity();
  }
  return out;
}

/// {"x": f(0), "y": f(1), "z": f(2)}.
template <typename F>
json perAxis(F&& f) { return {{"x", f(0)}, {"y", f(1)}, {"z", f(2)}}; }

/// The fine image: phase (1 pore, 0 solid) and the concentration of the diffusion along z.
void writeImage(const BedAnalysis& a, const fs::path& file) {
  const VoxelImage& image = a.fineImage;
  ImageData data{image.size, image.origin, image.voxel, {}, "pore"};
  data.cellData.push_back({"pore", 1, std::vector<std::uint8_t>(image.pore)});
  if (!a.finePores[2].concentration.empty()) {
    DataArray c{"concentration_z", 1, std::vector<float>{}};
    c.reserve(image.count());
    for (const double x : a.finePores[2].concentration) c.push(x);
    data.cellData.push_back(std::move(c));
  }
  writeVti(data, file, VtkCompression::ZLib);
}

/// Particles as points (id order, the potential of the conduction along z), contacts as lines
/// (a contact across a periodic face drawn to its image) with their conductance and current.
void writeNetwork(const World& world, const BedAnalysis& a, const fs::path& file) {
  const ParticleStore& p = world.particles();
  std::vector<Vec3> centre(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) centre[p.id[i]] = p.position[i];
  PolyData data;
  data.cells = PolyData::Cells::Lines;
  DataArray potential{"potential_z", 1, std::vector<double>{}}, id{"id", 1, std::vector<std::int64_t>{}};
  for (std::size_t i = 0; i < centre.size(); ++i) {
    data.points.push(centre[i]);
    potential.push(a.conduction[2].potential[i]);
    id.push(static_cast<double>(i));
  }
  DataArray conductance{"conductance", 1, std::vector<double>{}}, current{"current_z", 1, std::vector<double>{}};
  for (std::size_t k = 0; k < a.network.links.size(); ++k) {
    const ConductorNetwork::Link& l = a.network.links[k];
    const bool image = l.shift != std::array<std::int8_t, 3>{0, 0, 0};
    data.connectivity.push_back(l.a);
    if (image) {
      data.connectivity.push_back(static_cast<std::int64_t>(data.pointCount()));
      data.points.push(centre[l.a] + l.branch);
      potential.push(std::numeric_limits<double>::quiet_NaN());
      id.push(static_cast<double>(l.b));
    } else {
      data.connectivity.push_back(l.b);
    }
    data.endCell();
    conductance.push(l.conductance);
    current.push(a.conduction[2].current[k]);
  }
  data.pointData = {std::move(potential), std::move(id)};
  data.cellData = {std::move(conductance), std::move(current)};
  data.cellScalars = "current_z";
  writeVtp(data, file, VtkCompression::ZLib);
}

/// profile.csv and its plot: porosity and coordination through the thickness.
std::vector<std::string> writeProfile(const BedAnalysis& a, const fs::path& dir) {
  std::ostringstream csv;
  csv.precision(10);
  csv << "z_low,z_high,porosity,coordination,particles\n";
  for (const BedSlice& s : a.profile) csv << s.zLow << ',' << s.zHigh << ',' << s.porosity << ',' << s.coordination << ',' << s.particles << '\n';
  writeFileAtomically(dir / "profile.csv", csv.str());
  std::vector<std::string> files{(dir / "profile.csv").string()};
  const std::string script = gnuplotPreamble("profile") +
      "set datafile separator ','\nset key top left\nset xlabel 'height above the box bottom (um)'\n"
      "set ylabel 'porosity'\nset y2label 'coordination'\nset ytics nomirror\nset y2tics\n"
      "z0 = " + std::to_string(a.lo.z()) + "\n"
      "plot 'profile.csv' skip 1 using ((($1 + $2) / 2 - z0) * 1e6):3 with linespoints title 'porosity', "
      "'' skip 1 using ((($1 + $2) / 2 - z0) * 1e6):4 axes x1y2 with linespoints title 'coordination'\n";
  if (const auto png = plotPng(dir, "profile", script)) files.push_back(png->string());
  return files;
}

}  // namespace

int analyseCommand(const Arguments& args) {
  const auto parsed = parse(args);
  if (const auto* message = std::get_if<std::string>(&parsed)) {
    std::cerr << "sqdem analyse: " << *message << "\n" << usage;
    return 2;
  }
  const AnalyseArguments& a = std::get<AnalyseArguments>(parsed);
  try {
    Scene scene = loadScene(a.scene);
    scene.particles = readParticleFile(a.particles, scene.materials);
    for (ParticleSpec& p : scene.particles) p.allowOverlap = true;
    scene.insertions.clear();
    BedAnalysisOptions options;
    options.zLow = a.zLow;
    options.zHigh = a.zHigh;
    options.voxels = a.voxels;
    options.conductivity = conductivities(scene);
    World world = buildWorld(scene);
    world.computeForces();
    const BedAnalysis result = analyseBed(world, options);

    std::error_code error;
    fs::create_directories(a.out, error);
    if (error || !fs::is_directory(a.out)) throw std::runtime_error(a.out.string() + ": cannot create the output directory");
    std::vector<std::string> files;
    writeImage(result, a.out / "pores.vti");
    files.push_back((a.out / "pores.vti").string());
    writeNetwork(world, result, a.out / "network.vtp");
    files.push_back((a.out / "network.vtp").string());
    for (const std::string& f : writeProfile(result, a.out)) files.push_back(f);

    bool conducts = false;
    for (const NamedMaterial& m : scene.materials) conducts = conducts || m.electronicConductivity.has_value();
    const VoxelImage& fine = result.fineImage;
    const int longest = std::max({fine.size[0], fine.size[1], fine.size[2]});
    json out = {
        {"scene", a.scene},
        {"particles_file", a.particles.string()},
        {"box", {{"lo", {result.lo.x(), result.lo.y(), result.lo.z()}}, {"hi", {result.hi.x(), result.hi.y(), result.hi.z()}}}},
        {"particles", result.particles},
        {"porosity", result.porosity},
        {"solid_fraction", 1.0 - result.porosity},
        {"coordination", result.coordination},
        {"specific_surface_area_m2_per_m3", result.specificSurface},
        {"tortuosity_factor", perAxis([&](int d) { return result.finePores[d].tortuosityFactor; })},
        {"effective_diffusivity_ratio", perAxis([&](int d) { return result.finePores[d].diffusivityRatio; })},
        {"voxel_convergence",
         {{"voxels_along_longest_edge", {longest / 2, longest}},
          {"voxel_edge_m", {2.0 * fine.voxel.maxCoeff(), fine.voxel.maxCoeff()}},
          {"porosity", {result.pores[0].porosity, result.finePores[0].porosity}},
          {"tortuosity_factor", perAxis([&](int d) { return json{result.pores[d].tortuosityFactor, result.finePores[d].tortuosityFactor}; })}}},
        {"electronic_conductivity_ratio", perAxis([&](int d) { return result.conduction[d].conductivity / result.referenceConductivity; })},
        {"electronic_conductivity_s_per_m", conducts ? perAxis([&](int d) { return result.conduction[d].conductivity; }) : json(nullptr)},
        {"reference_conductivity_s_per_m", conducts ? json(result.referenceConductivity) : json(nullptr)},
        {"network",
         {{"nodes", result.network.nodes},
          {"contacts", result.network.links.size()},
          {"percolates", perAxis([&](int d) { return result.conduction[d].percolates; })},
          {"carrying_nodes", perAxis([&](int d) { return result.conduction[d].carryingNodes; })}}},
        {"seconds", {{"voxels", result.seconds.voxels}, {"pores", result.seconds.pores}, {"network", result.seconds.network}}},
        {"files", files}};
    writeFileAtomically(a.out / "analysis.json", out.dump(2) + "\n");
    std::cout << out.dump(2) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "sqdem analyse: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace sqdem::cli
