// `sqdem plot <log.csv>`: the run plot (io/run_plot.hpp) of a run's CSV log, next to it.

#include <cstdio>

#include "commands.hpp"
#include "sqdem/io/run_plot.hpp"

namespace sqdem::cli {

int plotCommand(const Arguments& args) {
  if (args.size() != 1) {
    std::fprintf(stderr, "usage: sqdem plot <run log .csv>   (e.g. out/nmc_packing/nmc_packing.csv)\n");
    return 2;
  }
  const std::optional<std::filesystem::path> png = plotRun(args[0]);
  if (!png) {
    std::fprintf(stderr, "sqdem plot: gnuplot is not installed (Debian: apt-get install gnuplot-nox)\n");
    return 1;
  }
  std::printf("%s\n", png->string().c_str());
  return 0;
}

}  // namespace sqdem::cli
