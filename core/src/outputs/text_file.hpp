// Reading a whole file of the run or sweep directory as text.
#pragma once

#include <filesystem>
#include <string>

namespace swarmnet {

// The file's bytes; throws RunError naming the file when it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace swarmnet
