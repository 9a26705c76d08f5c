#pragma once
// `<name>_view.py`, written next to a run's ParaView output: a ParaView 5.11 Python script that
// opens the series (the particles' surfaces coloured by coordination, or their centres if
// surfaces are off; the walls translucent; the contact network coloured by normal force; the
// bonds coloured by their utilisation), goes
// to the last frame and frames the camera:
//   paraview --script=out/<name>/<name>_view.py          (the GUI, ready to explore)
//   pvbatch out/<name>/<name>_view.py --png picture.png  (a picture of the last frame)

#include <filesystem>
#include <string>

namespace sqdem {

struct ParaViewSeries {
  bool surfaces = true, contacts = true, walls = true, bonds = false;
};

/// Writes <directory>/<name>_view.py atomically.
void writeParaViewScript(const std::filesystem::path& directory, const std::string& name, ParaViewSeries series);

}  // namespace sqdem
