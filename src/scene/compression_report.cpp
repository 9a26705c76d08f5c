#include "sqdem/scene/compression_report.hpp"

#include <algorithm>
#include <sstream>

#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/gnuplot.hpp"

namespace sqdem {

std::vector<CompressionRecord::Press> CompressionRecord::split() const {
  const auto pressure = [&](std::size_t k) { return samples_[k].plate.pressure; };
  std::vector<Press> ranges;
  Press current;
  double most = 0.0;
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    if (pressure(k) > most) {
      most = pressure(k);
      current.peak = k;
    } else if (most > 0.0 && pressure(k) < threshold * most) {
      current.end = k;
      current.letGo = k - 1;
      ranges.push_back(current);
      current = Press{k, k, k, std::nullopt};
      most = 0.0;
    }
  }
  if (most > 0.0) ranges.push_back(current);
  if (ranges.empty()) return ranges;
  double largest = 0.0;
  for (const Press& r : ranges) largest = std::max(largest, pressure(r.peak));
  std::vector<Press> presses;
  std::optional<std::size_t> touched;  // where a touch before the press began
  for (Press r : ranges) {
    if (pressure(r.peak) < threshold * largest) {
      touched = touched.value_or(r.start);
      continue;
    }
    r.start = touched.value_or(r.start);
    touched.reset();
    presses.push_back(r);
  }
  presses.back().end = samples_.size();
  return presses;
}

CompressionSummary CompressionRecord::summarise(const Press& press) const {
  CompressionSummary s;
  s.peakPressure = samples_[press.peak].plate.pressure;
  const double bearing = threshold * s.peakPressure;
  const auto first = std::find_if(samples_.begin() + press.start, samples_.begin() + press.peak + 1,
                                  [&](const Sample& x) { return x.plate.pressure >= bearing; });
  s.released = press.letGo.has_value();
  const PlateMeasures& last = samples_[press.letGo.value_or(samples_.size() - 1)].plate;
  s.thicknessBefore = first->plate.gap;
  s.thicknessAtPeak = samples_[press.peak].plate.gap;
  s.thicknessAfter = last.gap;
  s.porosityBefore = first->plate.porosity;
  s.porosityAtPeak = samples_[press.peak].plate.porosity;
  s.porosityAfter = last.porosity;
  return s;
}

std::vector<CompressionSummary> CompressionRecord::presses() const {
  std::vector<CompressionSummary> out;
  for (const Press& p : split()) out.push_back(summarise(p));
  return out;
}

std::optional<CompactionFit> CompressionRecord::compaction() const {
  const std::vector<CompressionSummary> all = presses();
  if (all.empty()) return std::nullopt;
  std::vector<double> load{0.0}, porosity{all.front().porosityBefore};
  for (const CompressionSummary& p : all) {
    if (!p.released) continue;
    load.push_back(p.peakPressure);
    porosity.push_back(p.porosityAfter);
  }
  return fitCompaction(load, porosity);
}

std::optional<std::filesystem::path> CompressionRecord::write(const std::filesystem::path& directory,
                                                              const std::string& name) const {
  const std::string data = name + "_compression";
  std::ostringstream csv;
  csv.precision(12);
  csv << "time_s,plate_gap_m,plate_pressure_Pa,porosity,press,branch\n";
  const auto row = [&](std::size_t k, std::size_t press, bool loading) {
    const auto& [time, plate] = samples_[k];
    csv << time << ',' << plate.gap << ',' << plate.pressure << ',' << plate.porosity << ',' << press << ','
        << (loading ? "loading" : "unloading") << '\n';
  };
  const std::vector<Press> presses = split();
  if (presses.empty()) {
    for (std::size_t k = 0; k < samples_.size(); ++k) row(k, 0, true);
  }
  for (std::size_t n = 0; n < presses.size(); ++n) {
    for (std::size_t k = presses[n].start; k < presses[n].end; ++k) row(k, n + 1, k <= presses[n].peak);
  }
  writeFileAtomically(directory / (data + ".csv"), csv.str());
  if (presses.empty()) return std::nullopt;  // the plate never bore on the bed: nothing to plot
  std::ostringstream gp;
  gp << "# gnuplot script written by `sqdem run`; run: gnuplot " << data << ".gp\n"
     << gnuplotPreamble(data, 1200, 500) << "set datafile separator ','\nset datafile columnheaders\nset grid\nset key top right\n"
     << "set multiplot layout 1,2\n"
     << "set title 'plate pressure against porosity'\nset xlabel 'porosity (-)'\nset ylabel 'plate pressure (MPa)'\n"
     << "plot '" << data << ".csv' using 4:(strcol(6) eq 'loading' ? $3 / 1e6 : NaN) with lines lw 2 title 'loading', \\\n"
     << "     '' using 4:(strcol(6) eq 'unloading' ? $3 / 1e6 : NaN) with lines lw 2 title 'unloading'\n"
     << "set title 'plate gap (the coating thickness while the plate bears on it)'\nset xlabel 'time (ms)'\n"
     << "set ylabel 'plate gap (um)'\nunset key\n"
     << "plot '" << data << ".csv' using ($1 * 1e3):($2 * 1e6) with lines lw 2\n"
     << "unset multiplot\n";
  return plotPng(directory, data, gp.str());
}

}  // namespace sqdem
