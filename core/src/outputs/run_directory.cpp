#include "outputs/run_directory.hpp"

#include <algorithm>
#include <array>

#include "outputs/output_files.hpp"
#include "outputs/run_error.hpp"
#include "scenario/shown_value.hpp"

namespace swarmnet {

namespace {

constexpr std::array kOutputFiles = {
    kSummaryFile,         kResolvedScenarioFile, kLogFile,           kPacketTraceFile,
    kFrameTraceFile,      kSensingTraceFile,     kMobilityTraceFile, kPositionsTraceFile,
    kTrafficScheduleFile, kSendOptionsFile,      kRouteQueriesFile,  kObjectTraceFile,
    kViewStatesFile,      kViewPageFile,         kHeadingsTraceFile, kRobotMetricsFile,
    kSeriesFile};

bool is_output_file(const std::string& name) {
  return std::find(kOutputFiles.begin(), kOutputFiles.end(), name) != kOutputFiles.end();
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < 5; ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > 5) text += " and " + std::to_string(names.size() - 5) + " more";
  return text;
}

}  // namespace

bool is_leftover_file(const std::string& name) {
  return name.find(".partial-") != std::string::npos;
}

std::vector<std::filesystem::path> remove_leftover_files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> removed;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.is_regular_file(ec) && is_leftover_file(entry.path().filename().string()) &&
        std::filesystem::remove(entry.path(), ec)) {
      removed.push_back(entry.path());
    }
  }
  std::sort(removed.begin(), removed.end());
  return removed;
}

std::vector<std::string> prepare_run_directory(const std::filesystem::path& dir, bool overwrite) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
    throw RunError("the run directory " + dir.string() + " is a file");
  }
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    throw RunError("cannot create run directory " + shown_value(dir.string(), kShownPathChars) +
                   ": " + ec.message());
  }

  std::vector<std::string> ours;
  std::vector<std::string> others;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (is_leftover_file(name)) continue;
    (is_output_file(name) ? ours : others).push_back(name);
  }
  std::sort(ours.begin(), ours.end());
  std::sort(others.begin(), others.end());
  if (!overwrite && !ours.empty()) {
    throw RunError(dir.string() + " holds an earlier run (" + listed(ours) +
                   "); pass --overwrite to replace it, or choose another --out");
  }
  if (!overwrite && !others.empty()) {
    throw RunError(dir.string() + " holds files SwarmNet did not write (" + listed(others) +
                   "); choose an empty or new directory with --out, or pass --overwrite (they "
                   "are kept)");
  }
  std::vector<std::string> notes;
  const auto leftovers = remove_leftover_files(dir);
  if (!leftovers.empty()) {
    notes.push_back("removed " + std::to_string(leftovers.size()) +
                    " temporary file(s) an interrupted run left in " + dir.string());
  }
  for (const std::string& name : ours) {
    if (!std::filesystem::remove(dir / name, ec) || ec) {
      throw RunError("cannot remove " + (dir / name).string() +
                     " to replace it: " + (ec ? ec.message() : "not removed"));
    }
  }
  if (!ours.empty()) {
    notes.push_back("--overwrite: removed the earlier run's " + listed(ours));
  }
  return notes;
}

}  // namespace swarmnet
