// libFuzzer target: sweep files (grid, linked axes, seeds) through load_sweep() and the run
// count, never expanding more than the bound allows.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "experiments/sweep_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // load_sweep() reads a file: one per fuzzing process, rewritten for every input.
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("swarmnet-fuzz-sweep-" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    const swarmnet::SweepSpec spec = swarmnet::load_sweep(file);
    if (spec.run_count() <= 10000) (void)spec.expand();
  } catch (const std::exception&) {
    // SweepError and the run-count bound are the expected answers to a bad sweep.
  }
  return 0;
}
