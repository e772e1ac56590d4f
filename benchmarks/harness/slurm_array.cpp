#include "benchmarks/harness/slurm_array.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "benchmarks/harness/process_runner.h"

namespace alplan::bench {
namespace {

namespace fs = std::filesystem;

const std::set<std::string>& slurm_options_with_value() {
  static const std::set<std::string> names{"--slurm", "--partition", "--time", "--mem", "--batch"};
  return names;
}

nlohmann::json to_json(const SlurmOptions& s) {
  return {{"partition", s.partition}, {"time", s.time}, {"mem", s.mem}, {"batch", s.batch}, {"sbatch", s.sbatch},
          {"submit", s.submit}};
}

SlurmOptions slurm_from_json(const nlohmann::json& j) {
  SlurmOptions s;
  s.partition = j.value("partition", "");
  s.time = j.value("time", "");
  s.mem = j.value("mem", "");
  s.batch = j.value("batch", 1);
  s.sbatch = j.value("sbatch", "sbatch");
  s.submit = j.value("submit", true);  // --no-submit: resubmissions are written, not submitted, too
  return s;
}

void write_manifest(const std::string& dir, const ArrayManifest& m) {
  const nlohmann::json j{{"kind", m.kind},       {"working_dir", m.working_dir}, {"command", m.command},
                         {"tasks", m.tasks},     {"job_ids", m.job_ids},         {"slurm", to_json(m.slurm)}};
  const fs::path path = fs::path(dir) / "manifest.json";
  std::ofstream out(path.string() + ".new");
  out << j.dump(2) << "\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
  fs::rename(path.string() + ".new", path);
}

// "0-41", or "3,7,9" for a resubmission.
std::string array_spec(const std::vector<int>& tasks) {
  if (tasks.empty()) throw std::runtime_error("no array tasks to submit");
  bool contiguous = true;
  for (std::size_t i = 1; i < tasks.size(); ++i) contiguous = contiguous && tasks[i] == tasks[i - 1] + 1;
  if (contiguous) return std::to_string(tasks.front()) + "-" + std::to_string(tasks.back());
  std::string spec;
  for (int t : tasks) spec += (spec.empty() ? "" : ",") + std::to_string(t);
  return spec;
}

// The job script: the command again, in task role, for $SLURM_ARRAY_TASK_ID.
std::string job_script(const std::string& dir, const ArrayManifest& m, const std::vector<int>& tasks) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Written by `alplan bench " << m.kind << " --slurm`; merge with `alplan bench merge " << dir << "`.\n"
    << "#SBATCH --job-name=alplan-" << m.kind << "\n"
    << "#SBATCH --array=" << array_spec(tasks) << "\n"
    << "#SBATCH --output=" << (fs::path(dir) / "logs" / "task-%a.out").string() << "\n"
    << "#SBATCH --chdir=" << m.working_dir << "\n"
    << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
  if (!m.slurm.partition.empty()) s << "#SBATCH --partition=" << m.slurm.partition << "\n";
  if (!m.slurm.time.empty()) s << "#SBATCH --time=" << m.slurm.time << "\n";
  if (!m.slurm.mem.empty()) s << "#SBATCH --mem=" << m.slurm.mem << "\n";
  s << "exec";
  for (const std::string& a : m.command) s << " " << shell_quoted(a);
  s << " --slurm-task " << shell_quoted(dir) << " --slurm-task-index \"$SLURM_ARRAY_TASK_ID\"\n";
  return s.str();
}

// Writes the script and submits it; returns the job id ("" when not submitted).
std::string submit_script(const std::string& dir, const ArrayManifest& m, const std::vector<int>& tasks,
                          const std::string& file) {
  const fs::path script = fs::path(dir) / file;
  std::ofstream(script) << job_script(dir, m, tasks);
  fs::permissions(script, fs::perms::owner_all, fs::perm_options::add);
  if (!m.slurm.submit) return "";
  const RunResult r = run_process({"/usr/bin/env", m.slurm.sbatch, "--parsable", script.string()}, {120, 4096});
  if (r.exit_code != 0) {
    throw std::runtime_error("sbatch " + script.string() + " failed (exit " + std::to_string(r.exit_code) +
                             "): " + (r.err.empty() ? r.out : r.err));
  }
  std::string id = r.out.substr(0, r.out.find_first_of(";\n"));
  return id;
}

// The array tasks squeue still lists for the manifest's jobs ("123_4").
std::set<int> queued_tasks(const ArrayManifest& m) {
  std::set<int> queued;
  if (m.job_ids.empty()) return queued;
  std::string jobs;
  for (const std::string& id : m.job_ids) jobs += (jobs.empty() ? "" : ",") + id;
  const RunResult r = run_process({"/usr/bin/env", "squeue", "-h", "-r", "-j", jobs, "-o", "%K"}, {60, 4096});
  if (r.exit_code != 0) return queued;  // no squeue here, or the jobs are long gone
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    const bool number = !line.empty() && std::all_of(line.begin(), line.end(), [](unsigned char c) { return std::isdigit(c); });
    if (number) queued.insert(std::stoi(line));
  }
  return queued;
}

std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

}  // namespace

std::vector<std::string> strip_slurm_options(const std::vector<std::string>& argv) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a == "--no-submit") continue;
    if (slurm_options_with_value().count(a)) {
      ++i;  // its value
      continue;
    }
    const std::size_t eq = a.find('=');
    if (eq != std::string::npos && slurm_options_with_value().count(a.substr(0, eq))) continue;
    out.push_back(a);
  }
  return out;
}

int array_tasks(int items, int batch) {
  batch = std::max(1, batch);
  return (items + batch - 1) / batch;
}

std::pair<int, int> task_items(int task, int items, int batch) {
  batch = std::max(1, batch);
  const int first = std::min(items, task * batch);
  return {first, std::min(items, first + batch)};
}

void submit_array(const std::string& dir, ArrayManifest m, std::ostream& out) {
  fs::create_directories(fs::path(dir) / "logs");
  fs::create_directories(fs::path(dir) / "tasks");
  if (!fs::is_empty(fs::path(dir) / "tasks")) {
    throw std::runtime_error(dir + "/tasks already holds results: merge them, or choose another folder");
  }
  std::vector<int> all(m.tasks.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
  write_manifest(dir, m);  // before submitting: a task may start at once
  const std::string id = submit_script(dir, m, all, "job.sbatch");
  if (!id.empty()) m.job_ids.push_back(id);
  write_manifest(dir, m);
  out << m.tasks.size() << " array tasks in " << dir << "/job.sbatch";
  if (id.empty()) out << " (not submitted: `sbatch " << dir << "/job.sbatch`)";
  else out << ", submitted as job " << id;
  out << "\nwhen they are done: alplan bench merge " << dir << "\n";
}

ArrayManifest read_manifest(const std::string& dir) {
  const fs::path path = fs::path(dir) / "manifest.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string() + " (not a folder written by --slurm?)");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("command") || !j.contains("tasks")) {
    throw std::runtime_error(path.string() + " is not a manifest written by --slurm");
  }
  ArrayManifest m;
  m.kind = j.value("kind", "");
  m.working_dir = j.value("working_dir", "");
  m.command = j["command"].get<std::vector<std::string>>();
  m.tasks = j["tasks"].get<std::vector<std::string>>();
  m.job_ids = j.value("job_ids", std::vector<std::string>{});
  m.slurm = slurm_from_json(j.value("slurm", nlohmann::json::object()));
  return m;
}

void write_task_result(const std::string& dir, int task, const nlohmann::json& result) {
  const fs::path path = fs::path(dir) / "tasks" / (std::to_string(task) + ".json");
  fs::create_directories(path.parent_path());
  const std::string temporary = path.string() + ".new";
  std::ofstream out(temporary);
  out << nlohmann::json{{"task", task}, {"status", "done"}, {"result", result}}.dump() << "\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + temporary);
  fs::rename(temporary, path);
}

void write_task_failure(const std::string& dir, int task, const std::string& error) {
  const fs::path path = fs::path(dir) / "tasks" / (std::to_string(task) + ".json");
  fs::create_directories(path.parent_path());
  std::ofstream(path.string() + ".new") << nlohmann::json{{"task", task}, {"status", "failed"}, {"error", error}}.dump();
  fs::rename(path.string() + ".new", path);
}

void run_array_task(const std::string& dir, int task, const std::function<void()>& body) {
  try {
    body();
  } catch (const std::exception& e) {
    write_task_failure(dir, task, e.what());
    throw;
  }
}

CollectedTasks collect_tasks(const std::string& dir, const ArrayManifest& m) {
  CollectedTasks c;
  const std::set<int> queued = queued_tasks(m);
  for (int t = 0; t < static_cast<int>(m.tasks.size()); ++t) {
    const fs::path result = fs::path(dir) / "tasks" / (std::to_string(t) + ".json");
    const fs::path log = fs::path(dir) / "logs" / ("task-" + std::to_string(t) + ".out");
    std::ifstream in(result);
    const nlohmann::json j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    if (j.is_object() && j.value("status", "") == "done" && j.contains("result")) {
      c.results[t] = j["result"];
    } else if (queued.count(t)) {
      c.pending.push_back(t);
    } else if (j.is_object() && j.value("status", "") == "failed") {
      c.failed[t] = j.value("error", "failed");
    } else if (fs::exists(log)) {
      // Started and left no result: killed (time, memory) or crashed.
      const std::string last = last_line(log);
      c.failed[t] = last.empty() ? "no result and an empty log" : "no result; its log ends: " + last;
    } else {
      c.missing.push_back(t);
    }
  }
  return c;
}

void report_incomplete(const ArrayManifest& m, const CollectedTasks& c, std::ostream& out) {
  auto name = [&](int t) { return "task " + std::to_string(t) + " (" + m.tasks[static_cast<std::size_t>(t)] + ")"; };
  for (const auto& [t, error] : c.failed) out << "failed: " << name(t) << ": " << error << "\n";
  for (int t : c.pending) out << "pending: " << name(t) << " is still queued or running\n";
  for (int t : c.missing) out << "missing: " << name(t) << " never ran or left nothing\n";
  if (!c.complete()) {
    out << c.results.size() << " of " << m.tasks.size() << " tasks finished; " << c.failed.size() << " failed, "
        << c.pending.size() << " pending, " << c.missing.size() << " missing\n";
  }
}

void resubmit_tasks(const std::string& dir, const CollectedTasks& c, std::ostream& out) {
  std::vector<int> again = c.missing;
  for (const auto& [t, error] : c.failed) again.push_back(t);
  std::sort(again.begin(), again.end());
  if (again.empty()) {
    out << "nothing to resubmit\n";
    return;
  }
  ArrayManifest m = read_manifest(dir);
  for (int t : again) {
    fs::remove(fs::path(dir) / "tasks" / (std::to_string(t) + ".json"));
    fs::remove(fs::path(dir) / "logs" / ("task-" + std::to_string(t) + ".out"));
  }
  const std::string file = "job-resubmit-" + std::to_string(m.job_ids.size()) + ".sbatch";
  const std::string id = submit_script(dir, m, again, file);
  if (!id.empty()) m.job_ids.push_back(id);
  write_manifest(dir, m);
  out << "resubmitted " << again.size() << " tasks (" << array_spec(again) << ") in " << dir << "/" << file;
  if (!id.empty()) out << " as job " << id;
  out << "\n";
}

std::string exec_merge(const std::string& dir, const ArrayManifest& m) {
  if (m.command.empty()) return "the manifest holds no command";
  const std::string absolute_dir = fs::absolute(dir).string();
  if (!m.working_dir.empty() && chdir(m.working_dir.c_str()) != 0) {
    return "cannot enter " + m.working_dir + ": " + std::strerror(errno);
  }
  std::vector<std::string> argv = m.command;
  argv.push_back("--slurm-merge");
  argv.push_back(absolute_dir);
  std::vector<char*> args;
  for (std::string& a : argv) args.push_back(a.data());
  args.push_back(nullptr);
  execv(args[0], args.data());
  return "cannot run " + argv[0] + ": " + std::strerror(errno);
}

}  // namespace alplan::bench
