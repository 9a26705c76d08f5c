// sqdem command-line entry point: dispatches to the sub-commands in commands.hpp. Every command
// answers --help (or -h) among its arguments with its own section of the usage text.

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

#include "commands.hpp"

namespace {

struct Command {
  const char* name;
  const char* help;  ///< synopsis and description, as printed under "commands:"
  int (*run)(const sqdem::cli::Arguments&);
};

constexpr Command commands[] = {
    {"run", R"(  run <scene.yaml> [--threads N] [--simd PATH] [--out DIR] [--overwrite] [--resume CHECKPOINT] [--progress-every S]
                         Run a DEM scene (YAML; keys in docs/scene_reference.md): builds the
                         particles, runs the stages, writes to DIR (default out/<scene name>;
                         docs/output.md) ParaView series (.pvd/.vtp) and a view script, a CSV
                         log and its plot, a checkpoint after every stage; prints a summary. --threads: OpenMP threads
                         (default: OMP_NUM_THREADS if set, otherwise one per core; results do
                         not depend on it). --simd: the code path of the kernels that compute
                         several contacts per instruction, scalar, baseline or avx2 (default:
                         the widest this CPU runs; results do not depend on it). --overwrite: replace an earlier run's files in DIR
                         (without it, a DIR holding them is an error). --resume continues a
                         checkpoint of the same scene with its remaining stages. Progress: a
                         line on a terminal; otherwise a 'progress:' record every S seconds
                         (default 60; 0: none) for following a batch job's log.
)",
     sqdem::cli::runCommand},
    {"plot", R"(  plot <log.csv>         Plot a run's CSV log (written by run, which also plots it at its end):
                         kinetic energy, solid fractions, mean coordination and the plane
                         walls' pressures against time (with a pressing plate also its pressure
                         against the solid fraction) to <log>_run.png next to it, through
                         gnuplot; the script <log>_run.gp is kept for restyling.
)",
     sqdem::cli::plotCommand},
    {"analyse", R"(  analyse <scene.yaml> --particles FILE [--out DIR] [--region ZLO ZHI] [--voxels N]
                         Electrode analysis of a particle file (a run's <name>_final_particles.csv)
                         with the scene's materials, laws and walls (docs/electrode_analysis.md):
                         porosity, coordination, specific surface, the pores' tortuosity factor
                         along x, y, z at N and 2N voxels (N in [4, 256], default 64, along the longest edge), the
                         electronic conductivity of the contact network (material key
                         electronic_conductivity, S/m); the box: x, y the domain's, z from ZLO to ZHI
                         (m; default the floor, or the domain's bottom, to the bed's top). Prints one
                         JSON object; writes analysis.json, pores.vti, network.vtp, profile.csv and
                         profile.png to DIR (default <FILE's stem>_analysis beside FILE).
)",
     sqdem::cli::analyseCommand},
    {"validate", R"(  validate table1 [--law NAME] [--json]
                         Reproduce Table 1 of the review (Kildashti et al. 2023):
                         normalised elliptic Hertz force of two n = 6 superquadrics in three
                         poses, against the review's accurate model, FEM and simplified model;
                         then each case's normalised force at delta/R_vol = 1e-4 ... 3e-2 with
                         the law NAME: review (default), elliptic_hertz or boundary_element (the
                         half-space reference of the true gap, ~15 s). --json prints the curves
                         only, as {"law", "cases": [{"case", "overlap_over_rvol",
                         "normalised_force", "fem"}]}. Exit code 1 if sqdem is more than 0.3 %
                         from the accurate model.
)",
     sqdem::cli::validateTable1},
    {"geometry", R"(  geometry <file|->      Contact geometry probe: reads a JSON pair description (file, or - for
                         standard input) and prints the detector's and the elliptic-Hertz
                         factors' results as one JSON object. See docs in README.md.
)",
     sqdem::cli::geometryProbe},
    {"sticking-velocity", R"(  sticking-velocity --radius R --density RHO --youngs-modulus E --poisson-ratio NU
                    --wall-youngs-modulus EW --wall-poisson-ratio NUW
                    --work-of-adhesion W --yield-pressure PY
                         Critical velocities (m/s) of a sphere hitting a flat wall under Nan et
                         al.'s elasto-plastic adhesive law (2022, Eqs. 73-79; SI units):
                         prints {"V_s", "V_y0", "V_y", "V_ys"} as one JSON object.
)",
     sqdem::cli::stickingVelocity},
    {"contact", R"(  contact <file|-> [--out DIR]
                         Single-contact driver: drives one contact (two posed shapes through the
                         detector, or prescribed radii) along a normal (and optional tangential)
                         displacement history with one or more of the normal laws
                         (docs/contact_laws.md); writes one CSV per curve, a gnuplot script and a PNG to DIR
                         (default .), and prints a JSON summary. See README.md and examples/.
)",
     sqdem::cli::contactDriver},
};

constexpr const char* header = R"(sqdem - DEM for superquadric and ellipsoidal particles

usage: sqdem <command> [arguments]    (sqdem <command> --help: that command alone)

commands:
)";

constexpr const char* footer = R"(  help, --help, -h       This text.
  version, --version     The version of sqdem.
)";

void printUsage(std::FILE* out) {
  std::fputs(header, out);
  for (const Command& c : commands) std::fputs(c.help, out);
  std::fputs(footer, out);
}

bool asksForHelp(const sqdem::cli::Arguments& args) {
  return std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
}

}  // namespace

int main(int argc, char** argv) {
  const sqdem::cli::Arguments args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    printUsage(args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "version" || args[0] == "--version") {
    std::printf("sqdem %s\n", SQDEM_VERSION);
    return 0;
  }
  const sqdem::cli::Arguments rest(args.begin() + 1, args.end());
  const auto command = std::find_if(std::begin(commands), std::end(commands),
                                    [&](const Command& c) { return args[0] == c.name; });
  if (command == std::end(commands)) {
    std::string names;
    for (const Command& c : commands) names += std::string(c.name) + ", ";
    std::fprintf(stderr, "sqdem: unknown command '%s' (allowed: %shelp, version)\n", args[0].c_str(), names.c_str());
    return 2;
  }
  if (asksForHelp(rest)) {
    std::printf("usage: sqdem\n%s", command->help);
    return 0;
  }
  try {
    return command->run(rest);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sqdem %s: error: %s\n", command->name, e.what());
    return 1;
  }
}
