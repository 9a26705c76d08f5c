// Random insertion benchmark (a timing harness; numbers are printed, never asserted): buildWorld
// on scenes inserting N ellipsoids (the peer benchmark's 1.5 : 1 : 1 grain, bench/scenes/
// bed_ellipsoid.yaml) by random sequential addition into a box periodic in x and y, sized so that
// their bounding spheres fill 0.3 of it (loose: the addition jams near 0.38). The time includes
// the rest of buildWorld (sampling, the World and its neighbour list), which is O(N) as well.
//
// usage: bench_insertion [N ...], default 10000 100000 1000000

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "median.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/scene_loader.hpp"

using namespace sqdem;

int main(int argc, char** argv) {
  std::vector<long> counts;
  for (int a = 1; a < argc; ++a) counts.push_back(std::atol(argv[a]));
  if (counts.empty()) counts = {10'000, 100'000, 1'000'000};
  const double a = 1.31918e-3, b = 0.87066e-3;  // semi-axes (m)
  const double boundingFraction = 0.3;
  std::printf("random insertion of 1.5:1:1 ellipsoids, bounding spheres at %.2f of a box periodic in x and y\n",
              boundingFraction);
  std::printf("%10s %12s %10s %10s %14s\n", "particles", "box side (m)", "samples", "time (s)", "particles/s");
  for (const long n : counts) {
    // A cube: n bounding spheres of radius a fill boundingFraction of it.
    const double side = std::cbrt(n * 4.0 / 3.0 * std::numbers::pi * a * a * a / boundingFraction);
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("sqdem_insertion_bench_" + std::to_string(n) + ".yaml");
    {
      std::ofstream out(path);
      out << "seed: 1\n"
          << "domain: {lo: [0, 0, 0], hi: [" << side << ", " << side << ", " << side << "], periodic: [x, y]}\n"
          << "materials:\n  grain: {youngs_modulus: 1.0e7, poisson_ratio: 0.3, density: 2500, friction: 0.3, restitution: 0.5}\n"
          << "shapes:\n  grain_shape: {semi_axes: [" << a << ", " << b << ", " << b << "]}\n"
          << "interactions:\n  - materials: [grain, grain]\n"
          << "insert:\n  - {count: " << n << ", shape: grain_shape, material: grain, region: {lo: [0, 0, 0], hi: [" << side
          << ", " << side << ", " << side << "]}}\n"
          << "stages:\n  - {name: none, duration: 1.0e-6}\n";
    }
    const Scene scene = loadScene(path.string());
    std::filesystem::remove(path);
    const int samples = n <= 10'000 ? 3 : 1;
    std::vector<double> seconds;
    for (int s = 0; s < samples; ++s) {
      const auto start = std::chrono::steady_clock::now();
      const World world = buildWorld(scene);
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (world.particles().size() != static_cast<std::size_t>(n)) return 1;
    }
    const double t = median(seconds);
    std::printf("%10ld %12.4g %10d %10.3f %14.4g\n", n, side, samples, t, n / t);
  }
}
