// The run directory a run writes into (DESIGN.md section 6). A run never mixes its files with an
// earlier run's: a directory holding an earlier run is refused unless the user asks to replace
// it (--overwrite), and files an interrupted run left under temporary names are removed, and
// said so. Files SwarmNet did not write are never removed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace swarmnet {

// Creates `dir`, or makes an existing one ready for a new run: leftover temporary files are
// removed; SwarmNet's own output files of an earlier run are removed when `overwrite`, else the
// directory is refused (RunError), as is one holding other files without `overwrite`. Returns
// lines for run.log saying what was removed.
std::vector<std::string> prepare_run_directory(const std::filesystem::path& dir, bool overwrite);

// Removes the temporary files (NAME.partial-PID) an interrupted run left in `dir`; returns them.
std::vector<std::filesystem::path> remove_leftover_files(const std::filesystem::path& dir);

// Whether `name` is a temporary file of an output (AtomicFile's NAME.partial-PID).
bool is_leftover_file(const std::string& name);

}  // namespace swarmnet
