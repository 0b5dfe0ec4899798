#include "formats/calculix_job.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "formats/signal_cleanup.h"
#include "formats/structure_files.h"

extern char** environ;

namespace shockmap {
namespace {

constexpr const char* kJobName = "structure";
constexpr std::size_t kLogExcerptBytes = 1500;

bool IsExecutableFile(const std::filesystem::path& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
         ::access(path.c_str(), X_OK) == 0;
}

std::string Upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), ::toupper);
  return text;
}

bool StartsKeyword(const std::string& line, const std::string& keyword) {
  const std::string upper = Upper(line.substr(0, keyword.size() + 1));
  return upper.starts_with(keyword) &&
         (upper.size() == keyword.size() || upper[keyword.size()] == ',' ||
          upper[keyword.size()] == ' ');
}

// An *INCLUDE line with its INPUT= path made absolute.
std::string AbsoluteInclude(const std::string& line, const std::filesystem::path& folder) {
  const std::size_t at = Upper(line).find("INPUT=");
  if (at == std::string::npos) return line;
  const std::size_t start = at + 6;
  const std::size_t end = std::min(line.find(',', start), line.size());
  std::string name = line.substr(start, end - start);
  name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
  const std::filesystem::path path(name);
  const std::string absolute = path.is_absolute() ? name : (folder / path).string();
  return line.substr(0, start) + absolute + line.substr(end);
}

// The tail of ccx's log, for messages.
std::string LogExcerpt(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  return all.size() > kLogExcerptBytes ? "..." + all.substr(all.size() - kLogExcerptBytes) : all;
}

}  // namespace

int RunCalculixJob(const std::filesystem::path& ccx, const std::filesystem::path& folder,
                   const std::string& jobname) {
  std::string arg0 = ccx.string(), arg1 = "-i", arg2 = jobname;
  char* argv[] = {arg0.data(), arg1.data(), arg2.data(), nullptr};
  const std::string log = (folder / (jobname + ".log")).string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, arg0.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw CalculixError("cannot start " + arg0 + ": " + std::strerror(rc));
  const KilledOnSignal child(pid);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

namespace {

// A temporary folder removed with everything in it when destroyed (or on a signal).
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "shockmap-ccx-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw CalculixError("cannot create a temporary folder: " + std::string(std::strerror(errno)));
    }
    path_ = pattern;
    on_signal_.emplace(path_);
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& Path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::optional<RemovedOnSignal> on_signal_;
};

}  // namespace

std::optional<std::filesystem::path> FindCalculixExecutable() {
  if (const char* given = std::getenv("SHOCKMAP_CCX"); given != nullptr && *given != '\0') {
    return IsExecutableFile(given) ? std::optional<std::filesystem::path>(given) : std::nullopt;
  }
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "/usr/bin:/bin");
  for (std::string folder; std::getline(folders, folder, ':');) {
    if (folder.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(folder) / "ccx";
    if (IsExecutableFile(candidate)) return candidate;
  }
  return std::nullopt;
}

std::string MatrixStorageDeck(const std::filesystem::path& deck) {
  std::ifstream in(deck);
  if (!in) throw InputError(deck.string() + ": cannot be opened for reading");
  const std::filesystem::path folder = std::filesystem::absolute(deck).parent_path();
  std::ostringstream model;
  enum class Part { kModel, kFirstStep, kStepBoundary, kAfter } part = Part::kModel;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const bool keyword = line.starts_with('*') && !line.starts_with("**");
    if (keyword && StartsKeyword(line, "*INCLUDE")) line = AbsoluteInclude(line, folder);
    if (keyword && StartsKeyword(line, "*STEP") && part == Part::kModel) part = Part::kFirstStep;
    if (keyword && StartsKeyword(line, "*END STEP") && part != Part::kModel) part = Part::kAfter;
    if (keyword && part == Part::kStepBoundary) part = Part::kFirstStep;
    if (keyword && part == Part::kFirstStep && StartsKeyword(line, "*BOUNDARY")) {
      part = Part::kStepBoundary;
    }
    if (part == Part::kModel || part == Part::kStepBoundary) model << line << "\n";
  }
  model << "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n";
  return model.str();
}

FeStructure ImportCalculixDeck(const std::filesystem::path& deck) {
  const std::string text = MatrixStorageDeck(deck);
  const auto ccx = FindCalculixExecutable();
  if (!ccx) {
    throw CalculixError(
        "CalculiX's ccx was not found ($SHOCKMAP_CCX, or `ccx` on the PATH); install it "
        "(Debian: apt-get install calculix-ccx) to import " +
        deck.string());
  }
  const TemporaryFolder folder;
  const std::filesystem::path stem = folder.Path() / kJobName;
  std::ofstream(stem.string() + ".inp") << text;
  const int status = RunCalculixJob(*ccx, folder.Path(), kJobName);
  const std::filesystem::path log = stem.string() + ".log";
  if (WIFSIGNALED(status)) {
    throw CalculixError(ccx->string() + " was ended by signal " + std::to_string(WTERMSIG(status)) +
                        " on " + deck.string());
  }
  const std::string excerpt = LogExcerpt(log);
  if (WEXITSTATUS(status) != 0 || excerpt.find("*ERROR") != std::string::npos ||
      !std::filesystem::exists(stem.string() + ".dof")) {
    throw InputError(deck.string() + ": ccx did not store its matrices (exit code " +
                     std::to_string(WEXITSTATUS(status)) + "); its log ends:\n" + excerpt);
  }
  FeStructure s = ReadCalculixMatrixStorage(stem.string(), deck.string());
  s.name = deck.stem().string();
  return s;
}

}  // namespace shockmap
