// `sqdem contact <file.json|-> [--out DIR] [--allow-detector-failures]`: the single-contact driver
// (probe/contact_drive.hpp drives the curves) and its files: per curve a CSV of displacement,
// overlap, forces, contact area and regime, then a gnuplot script and its PNG, and a JSON summary
// on stdout. Input keys and units: README.md, "sqdem contact".

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <system_error>

#include "commands.hpp"
#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/gnuplot.hpp"
#include "sqdem/probe/contact_drive.hpp"

namespace sqdem::cli {
namespace {

namespace fs = std::filesystem;
using probe::ContactDrive;
using probe::DrivenCurve;
using probe::InputError;
using probe::json;

/// Engineering prefix for axis labels: values are divided by the returned scale.
std::pair<double, std::string> prefixFor(double magnitude, const std::string& unit) {
  static const std::array<std::pair<double, const char*>, 5> prefixes{
      {{1e-9, "n"}, {1e-6, "µ"}, {1e-3, "m"}, {1.0, ""}, {1e3, "k"}}};
  for (auto it = prefixes.rbegin(); it != prefixes.rend(); ++it) {
    if (magnitude >= it->first) return {it->first, it->second + unit};
  }
  return {prefixes.front().first, prefixes.front().second + unit};
}

std::string csvNumber(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

/// Writes the drive's CSVs, plot script and PNG into outDir; prints the summary.
int writeContact(const ContactDrive& drive, const fs::path& outDir, bool allowDetectorFailures) {
  std::error_code error;
  fs::create_directories(outDir, error);
  if (error || !fs::is_directory(outDir)) {
    throw std::runtime_error(outDir.string() + ": cannot create the output directory" +
                             (error ? ": " + error.message() : std::string(": it is not a directory")));
  }
  const bool tangential = !drive.tangentialDisplacement.empty();
  json summary = {{"name", drive.name}, {"curves", json::array()}};
  std::vector<std::string> csvFiles;
  double xMax = 0.0, yMax = 0.0;
  for (const DrivenCurve& c : drive.curves) {
    std::ostringstream csv;
    csv << "step,displacement,overlap,normal_force,contact_area,equivalent_contact_radius,regime";
    if (tangential) csv << ",tangential_displacement,tangential_force";
    csv << "\n";
    double maxOverlap = 0.0, maxForce = 0.0, maxTangential = 0.0;
    for (std::size_t k = 0; k < drive.displacement.size(); ++k) {
      csv << k << ',' << csvNumber(drive.displacement[k]) << ',' << csvNumber(c.overlap[k]) << ',' << csvNumber(c.normalForce[k]) << ',';
      if (c.area[k]) csv << csvNumber(*c.area[k]) << ',' << csvNumber(std::sqrt(*c.area[k] / std::numbers::pi));
      else csv << ',';
      csv << ',' << c.regime[k];
      if (tangential) {
        csv << ',' << csvNumber(drive.tangentialDisplacement[k]) << ',' << csvNumber(c.tangentialForce[k]);
        maxTangential = std::max(maxTangential, std::abs(c.tangentialForce[k]));
      }
      csv << "\n";
      maxOverlap = std::max(maxOverlap, std::abs(c.overlap[k]));
      maxForce = std::max(maxForce, std::abs(c.normalForce[k]));
    }
    const std::string file = drive.name + "_" + c.label + ".csv";
    writeFileAtomically(outDir / file, csv.str());
    csvFiles.push_back(file);
    json entry = {{"label", c.label}, {"csv", (outDir / file).string()}, {"Ri", c.radii.Ri}, {"Rj", c.radii.Rj},
                  {"Rc", c.radii.Rc}, {"max_abs_force", maxForce}, {"detector_failures", c.detectorFailures}};
    if (c.meanRadiusSum > 0.0) entry["r_IJ"] = c.meanRadiusSum;
    entry["constants"] = c.constants;
    summary["curves"].push_back(entry);
    xMax = std::max(xMax, drive.plotTangential
                              ? std::abs(*std::max_element(drive.tangentialDisplacement.begin(), drive.tangentialDisplacement.end(),
                                                           [](double a, double b) { return std::abs(a) < std::abs(b); }))
                              : maxOverlap);
    yMax = std::max(yMax, drive.plotTangential ? maxTangential : maxForce);
  }

  // gnuplot script (kept next to the CSVs so the user can restyle) and its PNG.
  auto [xs, xUnit] = prefixFor(xMax, "m");
  auto [ys, yUnit] = prefixFor(yMax, "N");
  std::string xLabel = (drive.plotTangential ? "tangential displacement (" : "overlap (") + xUnit + ")";
  std::string yLabel = (drive.plotTangential ? "tangential force (" : "normal force (") + yUnit + ")";
  if (drive.plotNormalised) {
    const YieldPoint& reference = *drive.curves.front().yield;
    xs = reference.overlap;
    ys = reference.force;
    xLabel = "overlap / yield overlap of " + drive.curves.front().label;
    yLabel = "normal force / yield force of " + drive.curves.front().label;
  }
  const int xColumn = drive.plotTangential ? 8 : 3, yColumn = drive.plotTangential ? 9 : 4;
  std::ostringstream gp;
  gp << "# gnuplot script written by `sqdem contact`; run: gnuplot " << drive.name << ".gp\n"
     << gnuplotPreamble(drive.name)
     << "set datafile separator ','\nset key top left\nset grid\n"
     << "set title '" << drive.title << "' noenhanced\n"
     << "set xlabel '" << xLabel << "' noenhanced\nset ylabel '" << yLabel << "' noenhanced\n"
     << "set xzeroaxis\nplot ";
  for (std::size_t i = 0; i < drive.curves.size(); ++i) {
    gp << (i ? ", \\\n     " : "") << "'" << csvFiles[i] << "' using ($" << xColumn << "/" << csvNumber(xs)
       << "):($" << yColumn << "/" << csvNumber(ys) << ") with lines lw 2 title '" << drive.curves[i].label << "' noenhanced";
  }
  gp << "\n";
  summary["gnuplot_script"] = (outDir / (drive.name + ".gp")).string();
  summary["plot"] = nullptr;
  if (const auto png = plotPng(outDir, drive.name, gp.str())) {
    summary["plot"] = png->string();
  } else {
    std::cerr << "sqdem contact: warning: gnuplot not found (scripts/setup.sh installs gnuplot-nox); "
                 "CSV and script written, PNG skipped\n";
  }
  std::cout << summary.dump(2) << "\n";
  int failures = 0;
  for (const DrivenCurve& c : drive.curves) failures += c.detectorFailures;
  if (failures > 0 && !allowDetectorFailures) {
    std::cerr << "sqdem contact: " << failures << " step(s) the detector could not resolve (their overlap is the "
                 "prescribed approach, see 'detector_failures'); the poses or the path may be outside the shapes' "
                 "reach. --allow-detector-failures accepts such curves\n";
    return 1;
  }
  return 0;
}

}  // namespace

int contactDriver(const Arguments& args) {
  const char* usage = "usage: sqdem contact <file.json|-> [--out DIR] [--allow-detector-failures]\n";
  std::string input;
  fs::path outDir = ".";
  bool outGiven = false, allowDetectorFailures = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--out") {
      if (i + 1 == args.size() || outGiven) {
        std::cerr << "sqdem contact: '--out' needs one directory (given once)\n" << usage;
        return 2;
      }
      outDir = args[++i];
      outGiven = true;
    } else if (args[i] == "--allow-detector-failures") {
      allowDetectorFailures = true;
    } else if (input.empty() && (args[i] == "-" || args[i].rfind("--", 0) != 0)) {
      input = args[i];
    } else {
      std::cerr << "sqdem contact: unexpected argument '" << args[i] << "'\n" << usage;
      return 2;
    }
  }
  if (input.empty()) {
    std::cerr << usage;
    return 2;
  }
  ContactDrive drive;
  try {
    drive = probe::driveContact(probe::readJsonInput(input), input == "-" ? "contact" : fs::path(input).stem().string());
  } catch (const InputError& e) {
    std::cerr << "sqdem contact: " << (input == "-" ? "<stdin>" : input) << ": " << e.what() << "\n";
    return 1;
  }
  try {
    return writeContact(drive, outDir, allowDetectorFailures);
  } catch (const std::exception& e) {
    std::cerr << "sqdem contact: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sqdem::cli
