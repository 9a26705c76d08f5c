#pragma once
// The output directory of a run and the files sqdem owns in it.

#include <filesystem>
#include <string>

namespace sqdem {

/// The files a run named `name` writes, and those of runs resumed from it (`<name>_from_step<N>`):
/// `<name>.csv`, `<name>_{particles,surfaces,contacts,walls}.pvd`, their `_NNNNN.{vtu,vtp,pvtp}` frames
/// and `_NNNNN_<rank>.vtp` pieces,
/// `<name>_after_<stage>.checkpoint`, `<name>_latest.checkpoint`, and their `.tmp<pid>` temporaries.
bool ownsFile(const std::string& file, const std::string& name);

/// Creates `dir`; removes temporaries of writers that no longer run (`*.tmp<pid>`, atomic_file.hpp);
/// refuses (SceneError) a directory that holds files of this name (for a fresh run: any file)
/// unless `overwrite`, which removes sqdem's own files of that name first and nothing else.
void prepareOutputDirectory(const std::filesystem::path& dir, const std::string& name, bool fresh, bool overwrite);

}  // namespace sqdem
