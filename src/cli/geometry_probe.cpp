// `sqdem geometry <file.json|->`: the contact geometry probe of one particle pair
// (probe/pair_geometry.hpp has the input and output).

#include <iostream>

#include "commands.hpp"
#include "sqdem/probe/pair_geometry.hpp"

namespace sqdem::cli {

int geometryProbe(const Arguments& args) {
  if (args.size() != 1) {
    std::cerr << "usage: sqdem geometry <file.json|->\n";
    return 2;
  }
  try {
    std::cout << probe::pairGeometry(probe::readJsonInput(args[0])).dump(2) << "\n";
    return 0;
  } catch (const probe::InputError& e) {
    std::cerr << "sqdem geometry: " << (args[0] == "-" ? "<stdin>" : args[0]) << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sqdem::cli
