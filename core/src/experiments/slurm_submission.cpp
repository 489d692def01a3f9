#include "experiments/slurm_submission.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "experiments/captured_command.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/run_error.hpp"
#include "outputs/text_file.hpp"

namespace swarmnet {

namespace {

// 'text' for bash, with ' written as '\''.
std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

void check_one_line(const std::string& what, const std::string& text) {
  if (text.find_first_of("\n\r") != std::string::npos) {
    throw std::invalid_argument(what +
                                " holds a line break, which a job script cannot carry: " + text);
  }
}

std::filesystem::path tasks_file(const std::filesystem::path& sweep_dir, int number) {
  return slurm_directory(sweep_dir) / ("submit-" + std::to_string(number) + ".tasks");
}

}  // namespace

std::filesystem::path slurm_directory(const std::filesystem::path& sweep_dir) {
  return sweep_dir / "slurm";
}

std::filesystem::path slurm_task_log(const std::filesystem::path& sweep_dir,
                                     const std::string& job_id, std::size_t index) {
  return slurm_directory(sweep_dir) / "logs" / (job_id + "_" + std::to_string(index) + ".log");
}

std::string job_array_script(const std::filesystem::path& sweep_dir, const std::string& name,
                             int number, std::size_t tasks, const SlurmJobSettings& settings) {
  if (!sweep_dir.is_absolute() || !settings.swarmnet.is_absolute()) {
    throw std::invalid_argument("the sweep directory and the swarmnet path must be absolute");
  }
  if (tasks == 0) throw std::invalid_argument("a job array needs at least one task");
  const std::string dir = sweep_dir.lexically_normal().string();
  const std::filesystem::path slurm = slurm_directory(sweep_dir.lexically_normal());
  const std::string tasks_name = "submit-" + std::to_string(number) + ".tasks";
  std::vector<std::string> options = {
      "--job-name=" + name,
      "--array=0-" + std::to_string(tasks - 1) +
          (settings.max_parallel > 0 ? "%" + std::to_string(settings.max_parallel) : ""),
      "--ntasks=1",
      "--cpus-per-task=" + std::to_string(settings.cpus_per_run),
      "--output=" + (slurm / "logs" / "%A_%a.log").string(),
      "--chdir=" + dir};
  if (!settings.partition.empty()) options.push_back("--partition=" + settings.partition);
  if (!settings.time_limit.empty()) options.push_back("--time=" + settings.time_limit);
  options.insert(options.end(), settings.sbatch_args.begin(), settings.sbatch_args.end());
  check_one_line("the sweep directory", dir);
  check_one_line("the swarmnet path", settings.swarmnet.string());
  std::ostringstream script;
  script << "#!/bin/bash\n"
         << "# Submission " << number << " of the sweep in " << dir << ", written by\n"
         << "# `swarmnet sweep --slurm` (docs/experiments.md, \"On a cluster\"). Array index I "
            "runs the run\n"
         << "# on line I+1 of " << tasks_name
         << " with the arguments in args/<run id>, as a "
            "local sweep would.\n";
  for (const auto& option : options) {
    check_one_line("the sbatch option", option);
    script << "#SBATCH " << option << "\n";
  }
  script << "set -euo pipefail\n"
         << "sweep_dir=" << shell_quoted(dir) << "\n"
         << "swarmnet=" << shell_quoted(settings.swarmnet.string()) << "\n"
         << "if [[ ! -x $swarmnet ]]; then\n"
         << "  echo \"swarmnet sweep: $swarmnet is not an executable on $(hostname); give the "
            "cluster's copy with --swarmnet\" >&2\n"
         << "  exit 2\n"
         << "fi\n"
         << "index=${SLURM_ARRAY_TASK_ID:?not run as a Slurm array task}\n"
         << "id=$(sed -n \"$((index + 1))p\" \"$sweep_dir/slurm/" << tasks_name << "\")\n"
         << "if [[ -z $id ]]; then\n"
         << "  echo \"swarmnet sweep: no run for array index $index in "
            "$sweep_dir/slurm/"
         << tasks_name << "\" >&2\n"
         << "  exit 2\n"
         << "fi\n"
         << "mapfile -d '' -t args < \"$sweep_dir/slurm/args/$id\"\n"
         << "run_dir=$sweep_dir/runs/$id\n"
         << "mkdir -p \"$run_dir\"\n"
         << "echo \"swarmnet sweep: run $id on $(hostname), output in $run_dir/output.log\"\n"
         << "exec \"$swarmnet\" \"${args[@]}\" </dev/null >\"$run_dir/output.log\" 2>&1\n";
  return script.str();
}

std::vector<SlurmSubmission> read_submissions(const std::filesystem::path& sweep_dir) {
  std::vector<SlurmSubmission> submissions;
  const auto record = slurm_directory(sweep_dir) / "jobs";
  if (!std::filesystem::exists(record)) return submissions;
  std::istringstream lines(read_text_file(record));
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    std::istringstream fields(line);
    SlurmSubmission submission;
    if (!(fields >> submission.number >> submission.job_id)) {
      throw RunError(record.string() + ": not a submission record: " + line);
    }
    std::istringstream ids(read_text_file(tasks_file(sweep_dir, submission.number)));
    std::string id;
    while (std::getline(ids, id)) {
      if (!id.empty()) submission.runs.push_back(id);
    }
    submissions.push_back(std::move(submission));
  }
  return submissions;
}

std::size_t slurm_max_array_size() {
  constexpr std::size_t kSlurmDefault = 1001;
  const CapturedCommand config = run_captured({"scontrol", "show", "config"});
  if (!config.started || config.exit_code != 0) return kSlurmDefault;
  std::istringstream lines(config.output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string key;
    std::string equals;
    std::size_t value = 0;
    if (words >> key >> equals >> value && key == "MaxArraySize" && equals == "=" && value > 0) {
      return value;
    }
  }
  return kSlurmDefault;
}

SlurmSubmission submit_job_array(const std::filesystem::path& sweep_dir, const std::string& name,
                                 const std::vector<std::string>& run_ids,
                                 const std::vector<std::vector<std::string>>& arguments,
                                 const SlurmJobSettings& settings) {
  const auto slurm = slurm_directory(sweep_dir);
  std::vector<SlurmSubmission> earlier = read_submissions(sweep_dir);
  SlurmSubmission submission;
  submission.number = earlier.empty() ? 1 : earlier.back().number + 1;
  submission.runs = run_ids;

  std::error_code ec;
  for (const char* sub : {"args", "logs"}) {
    std::filesystem::create_directories(slurm / sub, ec);
    if (ec) throw RunError("cannot create " + (slurm / sub).string() + ": " + ec.message());
  }
  std::string tasks;
  for (std::size_t i = 0; i < run_ids.size(); ++i) {
    std::string packed;
    for (const auto& argument : arguments[i]) {
      if (argument.find('\0') != std::string::npos) {
        throw RunError("run " + run_ids[i] + ": an argument holds a NUL byte");
      }
      packed.append(argument).push_back('\0');
    }
    write_file_atomically(slurm / "args" / run_ids[i], packed);
    tasks.append(run_ids[i]).push_back('\n');
  }
  write_file_atomically(tasks_file(sweep_dir, submission.number), tasks);
  std::string script;
  try {
    script = job_array_script(sweep_dir, name, submission.number, run_ids.size(), settings);
  } catch (const std::invalid_argument& error) {
    throw RunError(error.what());
  }
  const auto script_path = slurm / ("submit-" + std::to_string(submission.number) + ".sh");
  write_file_atomically(script_path, script);

  const std::vector<std::string> command = {"sbatch", "--parsable", script_path.string()};
  const CapturedCommand result = run_captured(command);
  if (!result.started || result.exit_code != 0) {
    throw RunError("sbatch did not accept the job array " + script_path.string() + " (" +
                   describe_failure(command, result) + ")");
  }
  // --parsable prints "JOBID" or "JOBID;CLUSTER".
  std::string id = result.output.substr(0, result.output.find_first_of(";\n"));
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
    throw RunError("sbatch accepted " + script_path.string() +
                   " but printed no job id: " + result.output);
  }
  submission.job_id = id;
  std::string record;
  for (const auto& before : earlier) {
    record += std::to_string(before.number) + " " + before.job_id + "\n";
  }
  record += std::to_string(submission.number) + " " + submission.job_id + "\n";
  write_file_atomically(slurm / "jobs", record);
  return submission;
}

}  // namespace swarmnet
