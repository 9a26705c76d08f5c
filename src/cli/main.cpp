// sqdem command-line entry point: dispatches to the sub-commands in commands.hpp.

#include <cstdio>
#include <exception>
#include <string>

#include "commands.hpp"

namespace {

constexpr const char* usage = R"(sqdem - DEM for superquadric and ellipsoidal particles

usage: sqdem <command> [arguments]

commands:
  run <scene.yaml> [--threads N] [--out DIR] [--resume CHECKPOINT]
                         Run a DEM scene (YAML; keys in README.md "Scene files"): builds the
                         particles, runs the stages, writes ParaView files (.pvd/.vtu/.vtp), a
                         CSV log and a checkpoint after every stage to DIR (default
                         out/<scene name>), prints a summary. --resume continues a checkpoint
                         of the same scene with its remaining stages.
  validate table1        Reproduce Table 1 of the review (Kildashti et al. 2023, seed 004):
                         normalised elliptic Hertz force of two n = 6 superquadrics in three
                         poses, against the review's accurate model, FEM and simplified model.
                         Exit code 1 if sqdem is more than 0.3 % from the accurate model.
  geometry <file|->      Contact geometry probe: reads a JSON pair description (file, or - for
                         standard input) and prints the detector's and the elliptic-Hertz
                         factors' results as one JSON object. See docs in README.md.
  sticking-velocity --radius R --density RHO --youngs-modulus E --poisson-ratio NU
                    --wall-youngs-modulus EW --wall-poisson-ratio NUW
                    --work-of-adhesion W --yield-pressure PY
                         Critical velocities (m/s) of a sphere hitting a flat wall under Nan et
                         al.'s elasto-plastic adhesive law (seed 000, Eqs. 73-79; SI units):
                         prints {"V_s", "V_y0", "V_y", "V_ys"} as one JSON object.
  contact <file|-> [--out DIR]
                         Single-contact driver: drives one contact (two posed shapes through the
                         detector, or prescribed radii) along a normal (and optional tangential)
                         displacement history with one or more laws (hertz, becker_kamlah, jkr,
                         nan); writes one CSV per curve, a gnuplot script and a PNG to DIR
                         (default .), and prints a JSON summary. See README.md and examples/.
  help, --help, -h       This text.
)";

}  // namespace

int main(int argc, char** argv) {
  const sqdem::cli::Arguments args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::fputs(usage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const sqdem::cli::Arguments rest(args.begin() + 1, args.end());
  try {
    if (args[0] == "validate") return sqdem::cli::validateTable1(rest);
    if (args[0] == "geometry") return sqdem::cli::geometryProbe(rest);
    if (args[0] == "sticking-velocity") return sqdem::cli::stickingVelocity(rest);
    if (args[0] == "contact") return sqdem::cli::contactDriver(rest);
    if (args[0] == "run") return sqdem::cli::runCommand(rest);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sqdem %s: error: %s\n", args[0].c_str(), e.what());
    return 1;
  }
  std::fprintf(stderr, "sqdem: unknown command '%s' (allowed: run, validate, geometry, sticking-velocity, contact, help)\n",
               args[0].c_str());
  return 2;
}
