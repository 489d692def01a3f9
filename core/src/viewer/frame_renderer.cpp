#include "viewer/frame_renderer.hpp"

#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "experiments/captured_command.hpp"
#include "outputs/run_error.hpp"

namespace swarmnet {

namespace fs = std::filesystem;

namespace {

// Frames per Chromium run: enough to pay for its start, few enough to keep its DOM small.
constexpr std::size_t kFramesPerRun = 60;

std::optional<fs::path> on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

fs::path find_tool(const char* variable, const std::vector<std::string>& names,
                   const std::string& missing) {
  if (const char* chosen = std::getenv(variable); chosen != nullptr && *chosen != '\0') {
    if (::access(chosen, X_OK) != 0) {
      throw RunError(std::string(variable) + "=" + chosen + " is not an executable file");
    }
    return chosen;
  }
  for (const std::string& name : names) {
    if (auto found = on_path(name)) return *found;
  }
  throw RunError(missing);
}

// A private temporary directory, removed with everything in it.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (fs::temp_directory_path() / "swarmnet-view-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw RunError("cannot create a temporary directory");
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const std::size_t start = text.find(open);
  if (start == std::string::npos) return {};
  const std::size_t begin = text.find('>', start) + 1;
  const std::size_t end = text.find(close, begin);
  return end == std::string::npos ? std::string() : text.substr(begin, end - begin);
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

}  // namespace

fs::path find_chromium() {
  return find_tool("SWARMNET_CHROMIUM", {"chromium", "chromium-browser", "google-chrome"},
                   "Chromium is needed to render frames and was not found on PATH; install it "
                   "(Debian: apt-get install chromium; ./swarmnet view does for --png and "
                   "--video) or set SWARMNET_CHROMIUM");
}

fs::path find_ffmpeg() {
  return find_tool("SWARMNET_FFMPEG", {"ffmpeg"},
                   "ffmpeg is needed to encode a video and was not found on PATH; install it "
                   "(Debian: apt-get install ffmpeg; ./swarmnet view does for --video) or set "
                   "SWARMNET_FFMPEG");
}

std::vector<std::string> chromium_dump_command(const fs::path& chromium,
                                               const fs::path& profile_dir, const std::string& url,
                                               int width, int height) {
  std::vector<std::string> command = {
      chromium.string(),
      "--headless=new",
      "--disable-gpu",
      "--hide-scrollbars",
      "--mute-audio",
      "--no-first-run",
      "--no-default-browser-check",
      "--disable-extensions",
      "--disable-background-networking",
      "--user-data-dir=" + profile_dir.string(),
      "--window-size=" + std::to_string(width) + "," + std::to_string(height)};
  // Chromium refuses to run as root with its sandbox; the page is this program's own file.
  if (::geteuid() == 0 || std::getenv("SWARMNET_CHROMIUM_NO_SANDBOX") != nullptr) {
    command.emplace_back("--no-sandbox");
  }
  command.emplace_back("--dump-dom");
  command.push_back(url);
  return command;
}

std::string base64_decode(std::string_view text) {
  std::array<int, 256> value{};
  value.fill(-1);
  constexpr std::string_view kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (std::size_t i = 0; i < kAlphabet.size(); ++i)
    value[static_cast<unsigned char>(kAlphabet[i])] = static_cast<int>(i);
  std::string out;
  out.reserve(text.size() / 4 * 3);
  std::uint32_t acc = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const int v = value[static_cast<unsigned char>(c)];
    if (v < 0) throw std::invalid_argument("not base64");
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((acc >> bits) & 255U);
    }
  }
  return out;
}

void render_frames(const fs::path& page, const FrameRequest& request,
                   const std::function<void(std::string_view png)>& sink) {
  const fs::path chromium = find_chromium();
  const TemporaryDirectory profile;
  const std::string base = "file://" + fs::absolute(page).lexically_normal().string();
  for (std::size_t first = 0; first < request.count; first += kFramesPerRun) {
    const std::size_t count = std::min(kFramesPerRun, request.count - first);
    const std::string url =
        base + "#frames&from=" + number(request.from_s) + "&fps=" + number(request.fps) +
        "&first=" + std::to_string(first) + "&count=" + std::to_string(count) +
        "&w=" + std::to_string(request.width) + "&h=" + std::to_string(request.height) +
        (request.label ? "" : "&label=0");
    const auto command =
        chromium_dump_command(chromium, profile.path(), url, request.width, request.height);
    const CapturedCommand result = run_captured(command);
    if (!result.started) throw RunError("cannot start " + chromium.string() + ": " + result.error);
    if (result.exit_code != 0) throw RunError(describe_failure(command, result));
    const std::string status = between(result.output, "<div id=\"status\"", "</div>");
    if (status != "ok") {
      throw RunError("the viewer page did not draw its frames (" +
                     (status.empty()
                          ? std::string("no status; is ") + page.string() + " a viewer page?"
                          : status) +
                     ")");
    }
    std::istringstream lines(between(result.output, "<pre id=\"out\"", "</pre>"));
    std::string line;
    std::size_t got = 0;
    constexpr std::string_view kPrefix = "data:image/png;base64,";
    while (std::getline(lines, line)) {
      if (!line.starts_with(kPrefix)) continue;
      sink(base64_decode(std::string_view(line).substr(kPrefix.size())));
      ++got;
    }
    if (got != count) {
      throw RunError("Chromium handed out " + std::to_string(got) + " frames of the " +
                     std::to_string(count) + " asked");
    }
  }
}

void render_video(const fs::path& page, const FrameRequest& request, const fs::path& video) {
  if (request.width % 2 != 0 || request.height % 2 != 0) {
    throw RunError("a video's width and height must be even (H.264, yuv420p); got " +
                   std::to_string(request.width) + "x" + std::to_string(request.height));
  }
  const fs::path ffmpeg = find_ffmpeg();
  const TemporaryDirectory frames;
  std::size_t index = 0;
  render_frames(page, request, [&](std::string_view png) {
    char name[32];
    std::snprintf(name, sizeof name, "frame%06zu.png", index++);
    std::ofstream out(frames.path() / name, std::ios::binary);
    out.write(png.data(), static_cast<std::streamsize>(png.size()));
    if (!out) throw RunError("cannot write a frame into " + frames.path().string());
  });
  const std::vector<std::string> command = {ffmpeg.string(),
                                            "-nostdin",
                                            "-y",
                                            "-loglevel",
                                            "error",
                                            "-framerate",
                                            number(request.fps),
                                            "-i",
                                            (frames.path() / "frame%06d.png").string(),
                                            "-c:v",
                                            "libx264",
                                            "-pix_fmt",
                                            "yuv420p",
                                            "-movflags",
                                            "+faststart",
                                            video.string()};
  const CapturedCommand result = run_captured(command);
  if (!result.started) throw RunError("cannot start " + ffmpeg.string() + ": " + result.error);
  if (result.exit_code != 0) throw RunError(describe_failure(command, result));
}

}  // namespace swarmnet
