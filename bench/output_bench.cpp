// Output benchmark (a timing harness with medians; numbers are printed, never asserted): the
// ParaView frames (io/vtk_writer.hpp) of the dense bed of bench_engine (ellipsoids 1:0.8:0.6,
// mean coordination ~6, contacts on), written 5 times at each size with each compression
// (output.vtk_compression); the median write time per frame and each file's size.
//
// usage: bench_output [directory for the frames, default a temporary one] [surface resolution,
//        default 8; 0: no surfaces] [edges, default 8 46]

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "dense_bed.hpp"
#include "median.hpp"
#include "sqdem/io/vtk_writer.hpp"

using namespace sqdem;

int main(int argc, char** argv) {
  const std::filesystem::path root = argc > 1 ? std::filesystem::path(argv[1]) : std::filesystem::temp_directory_path() / "sqdem_bench_output";
  std::vector<int> edges;
  const int resolution = argc > 2 ? std::atoi(argv[2]) : 8;
  for (int k = 3; k < argc; ++k) edges.push_back(std::atoi(argv[k]));
  if (edges.empty()) edges = {8, 46};
  const double R = 1e-3;
  const Case c{"ellipsoids 1:0.8:0.6", Superquadric::ellipsoid(R, 0.8 * R, 0.6 * R), true};
  for (const int edge : edges) {
    World world = denseBed(c, edge, 1);
    world.computeForces();
    for (const auto& [codec, compression] : {std::pair{"zlib", VtkCompression::ZLib}, std::pair{"lz4", VtkCompression::LZ4},
                                             std::pair{"none", VtkCompression::None}}) {
      const std::filesystem::path directory = root / (std::to_string(edge) + "_" + codec);
      std::filesystem::remove_all(directory);
      std::filesystem::create_directories(directory);
      VtkSeries series(directory, "bed", {.contacts = true, .surfaceResolution = resolution, .compression = compression});
      std::vector<double> seconds;
      for (int frame = 0; frame < 5; ++frame) {
        const auto t0 = std::chrono::steady_clock::now();
        series.writeFrame(world);
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
      std::printf("%s, %zu particles, %zu contacts, surface resolution %d, vtk_compression %s: %.3g s per frame (median of 5)\n",
                  c.name, world.particles().size(), world.contacts().size(), resolution, codec, median(seconds));
      std::fflush(stdout);
      std::map<std::string, std::uintmax_t> sizes;  // the first frame's files, by name
      for (const auto& entry : std::filesystem::directory_iterator(directory)) {
        const std::string name = entry.path().filename().string();
        if (name.find("_00000.") != std::string::npos) sizes[name] = entry.file_size();
      }
      for (const auto& [name, size] : sizes) std::printf("  %-28s %10.3f MB\n", name.c_str(), size / 1e6);
    }
  }
  return 0;
}
