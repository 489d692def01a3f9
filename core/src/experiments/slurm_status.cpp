#include "experiments/slurm_status.hpp"

#include <charconv>
#include <set>
#include <sstream>

#include "experiments/captured_command.hpp"

namespace swarmnet {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(separator, begin);
    parts.push_back(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if (end == std::string::npos) return parts;
    begin = end + 1;
  }
}

bool parse_index(const std::string& text, std::size_t& index) {
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, index);
  return !text.empty() && error == std::errc() && rest == end;
}

bool is_job_id(const std::string& text) {
  return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
}

// "CANCELLED by 0" -> "CANCELLED"
std::string first_word(const std::string& text) { return text.substr(0, text.find(' ')); }

template <typename LineParser>
std::map<SlurmTaskId, SlurmTaskState> parse_lines(const std::string& text, LineParser parse) {
  std::map<SlurmTaskId, SlurmTaskState> tasks;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) parse(line, tasks);
  }
  return tasks;
}

}  // namespace

bool slurm_state_is_active(const std::string& state) {
  static const std::set<std::string> active = {
      "PENDING",   "RUNNING",     "CONFIGURING",  "COMPLETING", "SUSPENDED",
      "REQUEUED",  "REQUEUE_FED", "REQUEUE_HOLD", "RESIZING",   "SIGNALING",
      "STAGE_OUT", "STOPPED",     "RESV_DEL_HOLD"};
  return active.contains(state);
}

bool slurm_state_is_pending(const std::string& state) {
  return state == "PENDING" || state == "REQUEUED" || state == "REQUEUE_FED" ||
         state == "REQUEUE_HOLD" || state == "RESV_DEL_HOLD";
}

std::map<SlurmTaskId, SlurmTaskState> parse_squeue(const std::string& text) {
  return parse_lines(text, [](const std::string& line, auto& tasks) {
    const auto fields = split(line, '|');
    std::size_t index = 0;
    if (fields.size() < 3 || !is_job_id(fields[0]) || !parse_index(fields[1], index)) return;
    tasks[{fields[0], index}] = {first_word(fields[2]), ""};
  });
}

std::map<SlurmTaskId, SlurmTaskState> parse_sacct(const std::string& text) {
  return parse_lines(text, [](const std::string& line, auto& tasks) {
    const auto fields = split(line, '|');
    if (fields.size() < 3) return;
    const auto parts = split(fields[0], '_');
    std::size_t index = 0;
    if (parts.size() != 2 || !is_job_id(parts[0]) || !parse_index(parts[1], index)) return;
    tasks[{parts[0], index}] = {first_word(fields[1]), fields[2]};
  });
}

std::map<SlurmTaskId, SlurmTaskState> parse_scontrol(const std::string& text) {
  return parse_lines(text, [](const std::string& line, auto& tasks) {
    std::map<std::string, std::string> values;
    for (const auto& word : split(line, ' ')) {
      const auto equals = word.find('=');
      if (equals != std::string::npos) values[word.substr(0, equals)] = word.substr(equals + 1);
    }
    std::size_t index = 0;
    if (!is_job_id(values["ArrayJobId"]) || !parse_index(values["ArrayTaskId"], index)) return;
    tasks[{values["ArrayJobId"], index}] = {values["JobState"], values["ExitCode"]};
  });
}

SlurmQuery query_slurm(const std::vector<std::string>& job_ids) {
  SlurmQuery query;
  if (job_ids.empty()) {
    query.queue_known = true;
    return query;
  }
  std::string list;
  for (const auto& id : job_ids) list += (list.empty() ? "" : ",") + id;
  const std::set<std::string> ours(job_ids.begin(), job_ids.end());

  // Every queued job, not only ours: squeue refuses a list naming a job it has forgotten.
  const std::vector<std::string> squeue = {"squeue", "-h", "-r", "-o", "%F|%K|%T"};
  const CapturedCommand queued = run_captured(squeue);
  if (queued.started && queued.exit_code == 0) {
    query.queue_known = true;
    for (auto& [task, state] : parse_squeue(queued.output)) {
      if (ours.contains(task.first)) query.queued.emplace(task, std::move(state));
    }
  } else {
    query.notes.push_back("squeue failed (" + describe_failure(squeue, queued) +
                          "); queued and running tasks are unknown");
  }

  const std::vector<std::string> sacct = {"sacct", "-n", "-P", "-X", "-o", "JobID,State,ExitCode",
                                          "-j",    list};
  const CapturedCommand accounted = run_captured(sacct);
  if (accounted.started && accounted.exit_code == 0) {
    query.ended = parse_sacct(accounted.output);
  } else {
    query.notes.push_back(
        "sacct is unavailable (" + describe_failure(sacct, accounted) +
        "); the Slurm states of ended tasks come from scontrol, which keeps a job only for a "
        "few minutes after it ends, and done or failed from the run directories");
    for (const auto& id : job_ids) {
      const CapturedCommand shown = run_captured({"scontrol", "-o", "show", "job", id});
      if (!shown.started || shown.exit_code != 0) continue;  // forgotten by slurmctld
      for (auto& [task, state] : parse_scontrol(shown.output)) {
        query.ended.emplace(task, std::move(state));
      }
    }
  }
  return query;
}

}  // namespace swarmnet
