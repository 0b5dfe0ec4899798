#include "tests/calculix_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <thread>
#include <vector>

extern char** environ;

namespace shockmap::testing {
namespace {

constexpr std::size_t kLogTailBytes = 4096;

bool IsExecutableFile(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error) && ::access(path.c_str(), X_OK) == 0;
}

std::string LogTail(const std::filesystem::path& log) {
  std::ifstream in(log, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string all = text.str();
  return all.size() > kLogTailBytes ? all.substr(all.size() - kLogTailBytes) : all;
}

// This process's environment with the solver's thread counts set to `threads`.
std::vector<std::string> ChildEnvironment(int threads) {
  std::vector<std::string> entries;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string_view text(*entry);
    if (text.starts_with("OMP_NUM_THREADS=") || text.starts_with("CCX_NPROC_EQUATION_SOLVER="))
      continue;
    entries.emplace_back(text);
  }
  entries.push_back("OMP_NUM_THREADS=" + std::to_string(threads));
  entries.push_back("CCX_NPROC_EQUATION_SOLVER=" + std::to_string(threads));
  return entries;
}

std::vector<char*> Pointers(std::vector<std::string>& strings) {
  std::vector<char*> pointers;
  for (std::string& s : strings) pointers.push_back(s.data());
  pointers.push_back(nullptr);
  return pointers;
}

// In the forked child: only async-signal-safe calls until execve. Dies with its parent; reports
// a failed exec through `report` (closed on exec).
[[noreturn]] void ExecInChild(const char* directory, int log_fd, int report, const char* program,
                              char* const argv[], char* const envp[]) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  int error = 0;
  const int null_fd = ::open("/dev/null", O_RDONLY);
  if (null_fd < 0 || ::chdir(directory) != 0 || ::dup2(null_fd, 0) < 0 || ::dup2(log_fd, 1) < 0 ||
      ::dup2(log_fd, 2) < 0) {
    error = errno;
  } else {
    ::execve(program, argv, envp);
    error = errno;
  }
  [[maybe_unused]] const ssize_t written = ::write(report, &error, sizeof error);
  ::_exit(127);
}

// Waits for `pid`, killing it past `limit`; returns waitpid's status and whether it timed out.
int WaitWithLimit(pid_t pid, std::chrono::seconds limit, bool& timed_out) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  timed_out = false;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) return status;
    if (done < 0 && errno != EINTR) return status;
    if (!timed_out && std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      timed_out = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

const char* StatusName(CalculixRun::Status status) {
  switch (status) {
    case CalculixRun::Status::kCompleted:
      return "completed";
    case CalculixRun::Status::kNotFound:
      return "not found";
    case CalculixRun::Status::kCannotStart:
      return "could not be started";
    case CalculixRun::Status::kFailed:
      return "failed";
    case CalculixRun::Status::kTimedOut:
      return "timed out (killed)";
    case CalculixRun::Status::kKilled:
      return "killed by a signal";
  }
  return "?";
}

}  // namespace

std::optional<std::filesystem::path> FindCalculix() {
  if (const char* given = std::getenv("SHOCKMAP_CCX"); given != nullptr && *given != '\0') {
    if (IsExecutableFile(given)) return std::filesystem::path(given);
    return std::nullopt;
  }
  const char* path = std::getenv("PATH");
  std::string_view dirs = path != nullptr ? path : "/usr/bin:/bin";
  while (!dirs.empty()) {
    const std::size_t colon = dirs.find(':');
    const std::string_view dir = dirs.substr(0, colon);
    dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / "ccx";
    if (IsExecutableFile(candidate)) return candidate;
  }
  return std::nullopt;
}

std::string CalculixMissingMessage() {
  return "CalculiX (ccx) is not on the PATH (nor in $SHOCKMAP_CCX): install it "
         "(apt-get install calculix-ccx) to compare shockmap with an independent FE code";
}

std::string CalculixRun::Describe() const {
  std::string text = "ccx " + std::string(StatusName(status));
  if (exit_code >= 0) text += ", exit code " + std::to_string(exit_code);
  if (!log.empty()) text += ", log " + log.string();
  if (!log_text.empty()) {
    // From ccx's first error, else its last lines.
    const std::size_t error = log_text.find("*ERROR");
    const std::size_t from = error != std::string::npos ? error
                             : log_text.size() > 600    ? log_text.size() - 600
                                                        : 0;
    text += ", it printed: " + log_text.substr(from, 800);
  }
  return text;
}

CalculixRun RunCalculix(const std::filesystem::path& directory, const std::string& jobname,
                        const CalculixOptions& options) {
  CalculixRun run;
  const std::optional<std::filesystem::path> ccx = FindCalculix();
  if (!ccx) {
    run.log_text = CalculixMissingMessage();
    return run;
  }
  run.status = CalculixRun::Status::kCannotStart;
  run.log = directory / (jobname + ".log");
  const int log_fd = ::open(run.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  int report[2];
  if (log_fd < 0 || ::pipe2(report, O_CLOEXEC) != 0) {
    run.log_text = std::string("cannot open the log: ") + std::strerror(errno);
    if (log_fd >= 0) ::close(log_fd);
    return run;
  }
  std::vector<std::string> args = {"ccx", "-i", jobname};
  std::vector<std::string> env = ChildEnvironment(options.threads);
  const std::vector<char*> argv = Pointers(args), envp = Pointers(env);
  const std::string program = ccx->string(), dir = directory.string();
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0)
    ExecInChild(dir.c_str(), log_fd, report[1], program.c_str(), argv.data(), envp.data());
  ::close(log_fd);
  ::close(report[1]);
  if (pid < 0) {
    ::close(report[0]);
    run.log_text = std::string("fork: ") + std::strerror(errno);
    return run;
  }
  int exec_error = 0;
  const bool exec_failed = ::read(report[0], &exec_error, sizeof exec_error) == sizeof exec_error;
  ::close(report[0]);
  bool timed_out = false;
  const int status = WaitWithLimit(pid, options.time_limit, timed_out);
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.log_text = LogTail(run.log);
  if (exec_failed) {
    run.log_text = "cannot run " + program + ": " + std::strerror(exec_error);
    return run;
  }
  if (timed_out) {
    run.status = CalculixRun::Status::kTimedOut;
  } else if (WIFEXITED(status)) {
    run.exit_code = WEXITSTATUS(status);
    const bool error_printed = run.log_text.find("*ERROR") != std::string::npos;
    run.status = run.exit_code == 0 && !error_printed ? CalculixRun::Status::kCompleted
                                                      : CalculixRun::Status::kFailed;
  } else {
    run.status = CalculixRun::Status::kKilled;
  }
  return run;
}

}  // namespace shockmap::testing
