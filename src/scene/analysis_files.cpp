// writeAnalysis (electrode_analysis.hpp): an analysis' JSON object and files.

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/gnuplot.hpp"
#include "sqdem/io/vtk_xml.hpp"
#include "sqdem/scene/electrode_analysis.hpp"

namespace sqdem {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;  // keys in the order written

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
  std::ostringstream bottom;  // all its digits: std::to_string keeps six decimals, a micrometre
  bottom.precision(17);
  bottom << a.lo.z();
  const std::string script = gnuplotPreamble("profile") +
      "set datafile separator ','\nset key top left\nset xlabel 'height above the box bottom (um)'\n"
      "set ylabel 'porosity'\nset y2label 'coordination'\nset ytics nomirror\nset y2tics\n"
      "z0 = " + bottom.str() + "\n"
      "plot 'profile.csv' skip 1 using ((($1 + $2) / 2 - z0) * 1e6):3 with linespoints title 'porosity', "
      "'' skip 1 using ((($1 + $2) / 2 - z0) * 1e6):4 axes x1y2 with linespoints title 'coordination'\n";
  if (const auto png = plotPng(dir, "profile", script)) files.push_back(png->string());
  return files;
}

}  // namespace

std::string writeAnalysis(const AnalysedBed& bed, const std::string& scenePath, const std::string& source,
                          const fs::path& directory) {
  const World& world = bed.world;
  const BedAnalysis& result = bed.analysis;
  const auto converged = [](const auto& solve) { return solve.converged; };
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory)) throw std::runtime_error(directory.string() + ": cannot create the output directory");
  std::vector<std::string> files;
  writeImage(result, directory / "pores.vti");
  files.push_back((directory / "pores.vti").string());
  writeNetwork(world, result, directory / "network.vtp");
  files.push_back((directory / "network.vtp").string());
  for (const std::string& f : writeProfile(result, directory)) files.push_back(f);
  files.push_back((directory / "analysis.json").string());
  const bool conducts = bed.conductivitiesGiven;
  json out = {
      {"scene", scenePath},
      {"particles_file", source},
      {"box", {{"lo", {result.lo.x(), result.lo.y(), result.lo.z()}}, {"hi", {result.hi.x(), result.hi.y(), result.hi.z()}}}},
      {"particles", result.particles},
      {"porosity", result.porosity},
      {"solid_fraction", 1.0 - result.porosity},
      {"coordination", result.coordination},
      {"specific_surface_area_m2_per_m3", result.specificSurface},
      {"tortuosity_factor", perAxis([&](int d) { return result.finePores[d].tortuosityFactor; })},
      {"effective_diffusivity_ratio", perAxis([&](int d) { return result.finePores[d].diffusivityRatio; })},
      {"voxel_convergence",
       {{"voxels_along_longest_edge", result.voxelsAlongLongest},
        {"voxel_edge_m", result.voxelEdge},
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
      {"solvers_converged", std::ranges::all_of(result.pores, converged) && std::ranges::all_of(result.finePores, converged) &&
                                std::ranges::all_of(result.conduction, converged)},
      {"seconds", {{"voxels", result.seconds.voxels}, {"pores", result.seconds.pores}, {"network", result.seconds.network}}},
      {"files", files}};
  const std::string text = out.dump(2) + "\n";
  writeFileAtomically(directory / "analysis.json", text);
  return text;
}

}  // namespace sqdem
