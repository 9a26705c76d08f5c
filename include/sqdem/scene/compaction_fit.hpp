#pragma once
// Meyer et al.'s exponential compaction law for calendered electrodes (docs/references.md: Meyer,
// Bockholt, Haselrieder & Kwade 2017, J. Mater. Process. Technol. 249, 172-178):
//   eps(p) = eps_min + (eps_0 - eps_min) exp(-p / gamma_c)
// eps the coating's porosity after calendering at the load p (their line load; here the plate's
// peak pressure), eps_0 the uncalendered porosity, eps_min the least porosity the coating reaches,
// gamma_c its compaction resistance (the load's unit). Fitted by least squares: for a fixed
// gamma_c the law is linear in eps_min and eps_0 - eps_min (solved exactly), and gamma_c is the
// minimum of the remaining sum of squares (Brent's method in log gamma_c, Boost.Math).

#include <optional>
#include <span>

namespace sqdem {

struct CompactionFit {
  double porosityMin = 0.0;     ///< eps_min (-)
  double porosityStart = 0.0;   ///< eps_0 (-)
  double resistance = 0.0;      ///< gamma_c (the loads' unit: Pa for the plate)
  double rmsResidual = 0.0;     ///< root-mean-square porosity residual of the fit (-)

  double porosity(double load) const;
};

/// The fit of (load, porosity) points; nothing with fewer than 4 points (3 parameters and one
/// degree of freedom) or when the loads do not spread (all equal). gamma_c is searched between
/// 1e-3 and 1e3 times the largest load.
std::optional<CompactionFit> fitCompaction(std::span<const double> load, std::span<const double> porosity);

}  // namespace sqdem
