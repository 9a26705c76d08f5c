#include "sqdem/scene/compression_report.hpp"

#include <algorithm>
#include <sstream>

#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/gnuplot.hpp"

namespace sqdem {

std::size_t CompressionRecord::peak() const {
  const auto pressure = [](const Sample& x) { return x.plate.pressure; };
  return static_cast<std::size_t>(std::ranges::max_element(samples_, {}, pressure) - samples_.begin());
}

std::optional<CompressionSummary> CompressionRecord::summary() const {
  if (samples_.empty()) return std::nullopt;
  const std::size_t top = peak();
  CompressionSummary s;
  s.peakPressure = samples_[top].plate.pressure;
  if (!(s.peakPressure > 0.0)) return std::nullopt;
  const double bearing = threshold * s.peakPressure;
  const auto bears = [&](const Sample& x) { return x.plate.pressure >= bearing; };
  const auto first = std::find_if(samples_.begin(), samples_.begin() + top + 1, bears);
  const auto after = std::find_if_not(samples_.begin() + top, samples_.end(), bears);
  s.released = after != samples_.end();
  const PlateMeasures& last = s.released ? (after - 1)->plate : samples_.back().plate;
  s.thicknessBefore = first->plate.gap;
  s.thicknessAtPeak = samples_[top].plate.gap;
  s.thicknessAfter = last.gap;
  s.porosityBefore = first->plate.porosity;
  s.porosityAtPeak = samples_[top].plate.porosity;
  s.porosityAfter = last.porosity;
  return s;
}

std::optional<std::filesystem::path> CompressionRecord::write(const std::filesystem::path& directory,
                                                              const std::string& name) const {
  const std::string data = name + "_compression";
  std::ostringstream csv;
  csv.precision(12);
  csv << "time_s,plate_gap_m,plate_pressure_Pa,porosity,branch\n";
  const std::size_t top = samples_.empty() ? 0 : peak();
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const auto& [time, plate] = samples_[k];
    csv << time << ',' << plate.gap << ',' << plate.pressure << ',' << plate.porosity << ',' << (k <= top ? "loading" : "unloading")
        << '\n';
  }
  writeFileAtomically(directory / (data + ".csv"), csv.str());
  if (!summary()) return std::nullopt;  // the plate never bore on the bed: nothing to plot
  std::ostringstream gp;
  gp << "# gnuplot script written by `sqdem run`; run: gnuplot " << data << ".gp\n"
     << gnuplotPreamble(data, 1200, 500) << "set datafile separator ','\nset datafile columnheaders\nset grid\nset key top right\n"
     << "set multiplot layout 1,2\n"
     << "set title 'plate pressure against porosity'\nset xlabel 'porosity (-)'\nset ylabel 'plate pressure (MPa)'\n"
     << "plot '" << data << ".csv' using 4:(strcol(5) eq 'loading' ? $3 / 1e6 : NaN) with lines lw 2 title 'loading', \\\n"
     << "     '' using 4:(strcol(5) eq 'unloading' ? $3 / 1e6 : NaN) with lines lw 2 title 'unloading'\n"
     << "set title 'plate gap (the coating thickness while the plate bears on it)'\nset xlabel 'time (ms)'\n"
     << "set ylabel 'plate gap (um)'\nunset key\n"
     << "plot '" << data << ".csv' using ($1 * 1e3):($2 * 1e6) with lines lw 2\n"
     << "unset multiplot\n";
  return plotPng(directory, data, gp.str());
}

}  // namespace sqdem
