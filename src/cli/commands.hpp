#pragma once
// Sub-commands of the sqdem executable; each returns the process exit code.

#include <string>
#include <vector>

namespace sqdem::cli {

using Arguments = std::vector<std::string>;

int validateTable1(const Arguments& args);
int geometryProbe(const Arguments& args);
int stickingVelocity(const Arguments& args);
int contactDriver(const Arguments& args);
int runCommand(const Arguments& args);
int plotCommand(const Arguments& args);
int analyseCommand(const Arguments& args);

}  // namespace sqdem::cli
