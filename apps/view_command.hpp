// `swarmnet view RUN_DIR [--out FILE.html] [--video OUT.mp4 --fps N --from S --to S --size WxH]
// [--frame T --png OUT.png]` (docs/viewer.md): the run's replay page, and videos and figures
// drawn by that page in headless Chromium.
#pragma once

#include <optional>
#include <string>

namespace swarmnet {

struct ViewCommandOptions {
  std::string run_dir;
  std::string out;    // the page; default RUN_DIR/view.html
  std::string video;  // --video
  double fps = 30.0;
  std::optional<double> from_s;
  std::optional<double> to_s;
  std::string size = "1280x720";
  std::optional<double> frame_s;  // --frame
  std::string png;                // --png
  bool label = true;              // the time label on frames (--no-label: none)
  bool quiet = false;
};

// Returns the exit code; errors (a run directory's file at fault, Chromium or ffmpeg missing) are
// printed on stderr.
int view_command(const ViewCommandOptions& options);

}  // namespace swarmnet
