// The viewer page: one self-contained HTML file (script, style and data inside, nothing loaded
// from anywhere) that replays a run directory (docs/viewer.md).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "viewer/view_data.hpp"

namespace swarmnet {

// The page for `data`: the template page/viewer.html with its style, script, the data's meta
// (JSON) and blob (base64) put in.
std::string render_view_page(const ViewData& data);

// Reads `run_dir` and writes its page to `out` (under a temporary name, then renamed). Throws
// RunError naming the file at fault.
void write_view_page(const std::filesystem::path& run_dir, const std::filesystem::path& out,
                     const ViewLimits& limits = {});

// RFC 4648 base64 with padding.
std::string base64_encode(const std::uint8_t* data, std::size_t size);

}  // namespace swarmnet
