// The plate press's report split into presses, and Meyer et al.'s compaction fit
// (compression_report.hpp, compaction_fit.hpp; docs/output.md, "Compression").
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sqdem/scene/compaction_fit.hpp"
#include "sqdem/scene/compression_report.hpp"

using namespace sqdem;

namespace {

// Meyer et al. 2017 Eq. 1 with parameters of the size a calendered NMC coating shows.
const CompactionFit law{0.18, 0.45, 90e6, 0.0};

}  // namespace

// Points on the law are fitted back to its three parameters (the fit's closed form for a fixed
// gamma_c and Brent's minimum in gamma_c), with no residual.
TEST(CompactionFit, RecoversTheLawFromPointsOnIt) {
  const std::vector<double> load{0.0, 50e6, 100e6, 200e6, 300e6};
  std::vector<double> porosity;
  for (const double p : load) porosity.push_back(law.porosity(p));
  const auto fit = fitCompaction(load, porosity);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->porosityMin, law.porosityMin, 1e-6);
  EXPECT_NEAR(fit->porosityStart, law.porosityStart, 1e-6);
  EXPECT_NEAR(fit->resistance / law.resistance, 1.0, 1e-5);
  EXPECT_LT(fit->rmsResidual, 1e-8);
}

TEST(CompactionFit, NeedsFourSpreadPoints) {
  const std::vector<double> three{0.0, 1e6, 2e6}, four{1e6, 1e6, 1e6, 1e6}, porosity{0.4, 0.35, 0.3, 0.3};
  EXPECT_FALSE(fitCompaction(three, std::vector<double>{0.4, 0.35, 0.3}));
  EXPECT_FALSE(fitCompaction(four, porosity));
}

// A press cycle of a plate: the porosity falls linearly with the gap from `before`; the
// pressure rises linearly from where the plate takes hold to `peak`, and falls on release to
// zero at the gap `after` (its samples one step of the gap apart).
void press(CompressionRecord& record, double& time, double peak, double gapHold, double gapPeak, double gapAfter) {
  const double step = 0.01e-6;
  const auto porosity = [](double gap) { return 1.0 - 10e-6 / gap; };  // 10 um of solid
  for (double gap = gapHold + 10 * step; gap > gapPeak; gap -= step) {
    const double p = gap > gapHold ? 0.0 : peak * (gapHold - gap) / (gapHold - gapPeak);
    record.add(time += 1e-6, {gap, p, porosity(gap)});
  }
  record.add(time += 1e-6, {gapPeak, peak, porosity(gapPeak)});
  for (double gap = gapPeak + step; gap < gapAfter + 10 * step; gap += step) {
    const double p = gap > gapAfter ? 0.0 : peak * (gapAfter - gap) / (gapAfter - gapPeak);
    record.add(time += 1e-6, {gap, p, porosity(gap)});
  }
}

// Three presses to rising peaks, each let go, after a touch of the loose top (0.2 % of the
// largest peak): three summaries with their peaks, gaps and porosities, the touch counted with
// the first press, and the fit through (0, first porosity before), (peak, porosity after).
TEST(CompressionRecord, SplitsPressesAndFitsTheirPorosityAfter) {
  CompressionRecord record;
  double time = 0.0;
  press(record, time, 0.4e6, 21.0e-6, 20.99e-6, 21.0e-6);  // the touch
  const std::vector<double> peaks{50e6, 100e6, 200e6, 300e6};
  std::vector<double> after;
  for (const double p : peaks) after.push_back(10e-6 / (1.0 - law.porosity(p)));
  const double hold = 10e-6 / (1.0 - law.porosityStart);
  double gapHold = hold;
  for (std::size_t k = 0; k < peaks.size(); ++k) {
    press(record, time, peaks[k], gapHold, after[k] - 0.3e-6, after[k]);
    gapHold = after[k];
  }
  const std::vector<CompressionSummary> presses = record.presses();
  ASSERT_EQ(presses.size(), peaks.size());
  for (std::size_t k = 0; k < peaks.size(); ++k) {
    EXPECT_DOUBLE_EQ(presses[k].peakPressure, peaks[k]);
    EXPECT_TRUE(presses[k].released);
    // 'before' and 'after' are the samples where the linear ramps reach 1 % of the peak, within one gap step.
    const double gapPeak = after[k] - 0.3e-6, held = k == 0 ? hold : after[k - 1];
    EXPECT_NEAR(presses[k].thicknessBefore, held - CompressionRecord::threshold * (held - gapPeak), 0.01e-6);
    EXPECT_NEAR(presses[k].thicknessAfter, after[k] - CompressionRecord::threshold * 0.3e-6, 0.01e-6);
    EXPECT_NEAR(presses[k].thicknessAtPeak, gapPeak, 1e-12);
  }
  const auto fit = record.compaction();
  ASSERT_TRUE(fit);
  std::printf("fit of the presses: eps_min %.5f (%.5f), eps_0 %.5f (%.5f), gamma_c %.4g (%.4g), rms %.2g\n", fit->porosityMin,
              law.porosityMin, fit->porosityStart, law.porosityStart, fit->resistance, law.resistance, fit->rmsResidual);
  // The sampled gaps are within 0.02 um of the law's: porosity within ~1e-3.
  EXPECT_NEAR(fit->porosityMin, law.porosityMin, 5e-3);
  EXPECT_NEAR(fit->porosityStart, law.porosityStart, 2e-3);
  EXPECT_NEAR(fit->resistance / law.resistance, 1.0, 0.05);
}

// A press the plate never let go of: one summary, not released, its 'after' the last gap; no fit.
TEST(CompressionRecord, APressHeldToTheEndIsNotReleased) {
  CompressionRecord record;
  record.add(0.0, {30e-6, 0.0, 0.5});
  record.add(1.0, {29e-6, 1e6, 0.48});
  record.add(2.0, {28e-6, 2e6, 0.46});
  const auto presses = record.presses();
  ASSERT_EQ(presses.size(), 1u);
  EXPECT_FALSE(presses[0].released);
  EXPECT_EQ(presses[0].thicknessAfter, 28e-6);
  EXPECT_EQ(presses[0].thicknessBefore, 29e-6);
  EXPECT_FALSE(record.compaction());
}
