// Frames of the viewer page drawn by headless Chromium (`swarmnet view --png/--video`): the same
// page and the same drawing code as in a browser, asked through its URL fragment to draw frames
// and hand them out as PNG data URLs (#frames mode, page/viewer.js), read from Chromium's
// --dump-dom; videos are those PNGs encoded by ffmpeg.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace swarmnet {

struct FrameRequest {
  double from_s = 0.0;  // time of frame 0
  double fps = 30.0;    // frame k is at from_s + k / fps
  std::size_t count = 1;
  int width = 1280;
  int height = 720;
  bool label = true;  // the time label in the top-left corner
};

// Chromium's executable: $SWARMNET_CHROMIUM, else chromium, chromium-browser, google-chrome on
// PATH. Throws RunError saying how to install it when there is none.
std::filesystem::path find_chromium();
// ffmpeg's: $SWARMNET_FFMPEG, else ffmpeg on PATH; throws RunError likewise.
std::filesystem::path find_ffmpeg();

// The arguments that make Chromium load `url` headless and print its DOM when loaded.
std::vector<std::string> chromium_dump_command(const std::filesystem::path& chromium,
                                               const std::filesystem::path& profile_dir,
                                               const std::string& url, int width, int height);

// Draws the frames of `page` (a viewer page file) and hands each PNG to `sink`, in order.
// Throws RunError with Chromium's or the page's error.
void render_frames(const std::filesystem::path& page, const FrameRequest& request,
                   const std::function<void(std::string_view png)>& sink);

// Renders the frames and encodes them with ffmpeg (H.264, yuv420p) into `video`; width and
// height must be even.
void render_video(const std::filesystem::path& page, const FrameRequest& request,
                  const std::filesystem::path& video);

// RFC 4648 base64 decoding; throws std::invalid_argument on a character outside the alphabet.
std::string base64_decode(std::string_view text);

}  // namespace swarmnet
