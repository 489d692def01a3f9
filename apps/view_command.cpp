#include "view_command.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "outputs/atomic_file.hpp"
#include "outputs/output_files.hpp"
#include "session/exit_codes.hpp"
#include "viewer/frame_renderer.hpp"
#include "viewer/view_page.hpp"

namespace swarmnet {

namespace {

namespace fs = std::filesystem;

int refuse(int code, const std::string& message) {
  std::fprintf(stderr, "swarmnet view: error: %s\n", message.c_str());
  return code;
}

// "1280x720" -> width, height.
bool parse_size(const std::string& text, int& width, int& height) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return false;
  const char* begin = text.data();
  const auto [w_end, w_error] = std::from_chars(begin, begin + x, width);
  const auto [h_end, h_error] = std::from_chars(begin + x + 1, begin + text.size(), height);
  return w_error == std::errc() && h_error == std::errc() && w_end == begin + x &&
         h_end == begin + text.size() && width >= 16 && height >= 16 && width <= 7680 &&
         height <= 4320;
}

}  // namespace

int view_command(const ViewCommandOptions& options) {
  FrameRequest request;
  if (!parse_size(options.size, request.width, request.height)) {
    return refuse(kExitBadInput,
                  "--size " + options.size + ": expected WIDTHxHEIGHT, e.g. 1280x720");
  }
  request.label = options.label;
  if (options.frame_s.has_value() != !options.png.empty()) {
    return refuse(kExitBadInput, "--frame T and --png FILE go together");
  }
  if (!(options.fps > 0.0 && options.fps <= 240.0)) {
    return refuse(kExitBadInput, "--fps must be in (0, 240]");
  }
  const fs::path run_dir = options.run_dir;
  const fs::path page = options.out.empty() ? run_dir / kViewPageFile : fs::path(options.out);
  double duration_s = 0.0;
  try {
    const ViewData data = read_view_data(run_dir);
    duration_s = data.meta["duration_s"].get<double>();
    const std::string html = render_view_page(data);
    AtomicFile file(page);  // under a temporary name, renamed when whole
    file.stream() << html;
    file.commit();
    if (!options.quiet) {
      std::printf("%s: %.1f MB, %s robots, %.1f s (open it in a browser)\n", page.c_str(),
                  static_cast<double>(html.size()) / 1e6, data.meta["robots"].dump().c_str(),
                  duration_s);
    }
  } catch (const std::exception& error) {
    return refuse(kExitBadInput, error.what());
  }

  try {
    if (options.frame_s) {
      if (!(*options.frame_s >= 0.0 && *options.frame_s <= duration_s)) {
        return refuse(kExitBadInput, "--frame " + std::to_string(*options.frame_s) +
                                         " is outside the run (0 .. " + std::to_string(duration_s) +
                                         " s)");
      }
      request.from_s = *options.frame_s;
      request.count = 1;
      render_frames(page, request, [&](std::string_view png) {
        std::ofstream out(options.png, std::ios::binary | std::ios::trunc);
        out.write(png.data(), static_cast<std::streamsize>(png.size()));
        if (!out) throw std::runtime_error("cannot write " + options.png);
      });
      if (!options.quiet)
        std::printf("%s: frame at t = %g s\n", options.png.c_str(), *options.frame_s);
    }
    if (!options.video.empty()) {
      const double from = options.from_s.value_or(0.0);
      const double to = options.to_s.value_or(duration_s);
      if (!(from >= 0.0 && to <= duration_s + 1e-9 && to > from)) {
        return refuse(kExitBadInput, "--from/--to must satisfy 0 <= from < to <= " +
                                         std::to_string(duration_s) + " s (the run's length)");
      }
      request.from_s = from;
      request.fps = options.fps;
      request.count =
          static_cast<std::size_t>(std::max(1.0, std::round((to - from) * options.fps)));
      render_video(page, request, options.video);
      if (!options.quiet) {
        std::printf("%s: %zu frames at %g fps, t = %g .. %g s\n", options.video.c_str(),
                    request.count, options.fps, from, to);
      }
    }
  } catch (const std::exception& error) {
    return refuse(kExitRunFailed, error.what());
  }
  return 0;
}

}  // namespace swarmnet
