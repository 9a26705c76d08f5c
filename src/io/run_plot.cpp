#include "sqdem/io/run_plot.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sqdem/io/gnuplot.hpp"
#include "sqdem/io/plain_name.hpp"

namespace sqdem {
namespace {

/// An empty panel saying why (gnuplot refuses a plot without a valid point).
std::string nothing(const std::string& why) {
  return "set label 1 '" + why + "' at graph 0.5, 0.5 center\nplot [0:1][0:1] 2 notitle\nunset label 1\n";
}

}  // namespace

std::optional<std::filesystem::path> plotRun(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string header;
  if (!in || !std::getline(in, header)) throw std::runtime_error("cannot read '" + csv.string() + "'");
  const std::string file = csv.filename().string();
  if (!isPlainName(file) || !file.ends_with(".csv")) {
    throw std::runtime_error("'" + csv.string() + "': the log's file name must be letters, digits, _ . - ending in .csv");
  }
  if (header.rfind("time_s,step,stage,", 0) != 0) {
    throw std::runtime_error("'" + csv.string() + "' is not an sqdem run log (its header does not start time_s,step,stage)");
  }
  std::vector<std::string> pressures;
  bool plate = false;
  std::stringstream line(header);
  for (std::string c; std::getline(line, c, ',');) {
    if (c.rfind("wall", 0) == 0 && c.ends_with("_p_Pa")) pressures.push_back(c);
    plate = plate || c == "plate_pressure_Pa";
  }
  const std::string name = csv.stem().string() + "_run";
  std::ostringstream gp;
  gp << "# gnuplot script written by sqdem; run: gnuplot " << name << ".gp\n"
     << gnuplotPreamble(name, 1400, plate ? 1350 : 900)
     << "set datafile separator ','\nset datafile columnheaders\nset grid\nset xlabel 'time (ms)'\n"
     << "set multiplot layout " << (plate ? 3 : 2) << ",2\n"
     << "set title 'kinetic energy'\nset ylabel 'J'\nunset key\n"
     << "stats '" << file << "' using 'kinetic_energy_J' nooutput name 'kinetic'\n"
     << "if (kinetic_max > 0) {\n  set logscale y\n"
     << "  plot '" << file << "' using ($1 * 1e3):(column('kinetic_energy_J') > 0 ? column('kinetic_energy_J') : NaN) with lines lw 2\n"
     << "  unset logscale y\n} else {\n" << nothing("the particles never moved") << "}\n"
     << "set key top left\n"
     << "set title 'solid fraction'\nset ylabel '-'\n"
     << "plot '" << file << "' using ($1 * 1e3):'solid_fraction' with lines lw 2 title 'bed (below its top)', \\\n"
     << "     '' using ($1 * 1e3):(column('between_walls_solid_fraction') > 0 ? column('between_walls_solid_fraction') : NaN) "
        "with lines lw 2 title 'between floor and lid'\n"
     << "unset key\nset title 'mean coordination (particle-particle contacts per particle)'\n"
     << "plot '" << file << "' using ($1 * 1e3):'mean_coordination' with lines lw 2\n"
     << "set key top right\nset title 'wall pressure (compressive > 0)'\nset ylabel 'Pa'\n";
  if (pressures.empty()) {
    gp << nothing("no plane wall along an axis");
  } else {
    gp << "plot ";
    for (std::size_t k = 0; k < pressures.size(); ++k) {
      const std::string& p = pressures[k];
      gp << (k ? ", \\\n     " : "") << "'" << file << "' using ($1 * 1e3):'" << p << "' with lines lw 2 title '"
         << p.substr(0, p.size() - 5) << "'";
    }
    gp << "\n";
  }
  if (plate) {
    gp << "unset key\nset title 'plate pressure against solid fraction between the plates'\nset xlabel 'solid fraction (-)'\n"
       << "set ylabel 'MPa'\nplot '" << file << "' using (1 - column('porosity')):(column('plate_pressure_Pa') / 1e6) with lines lw 2\n";
  }
  gp << "unset multiplot\n";
  return plotPng(csv.parent_path().empty() ? "." : csv.parent_path(), name, gp.str());
}

}  // namespace sqdem
