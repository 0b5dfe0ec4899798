#include "views/gnuplot.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "core/input_error.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/signal_cleanup.h"

extern char** environ;

namespace shockmap {
namespace {

// How much of gnuplot's output a failure message quotes (its last bytes, where errors are).
constexpr std::size_t kExcerptBytes = 600;

// The variable by which RunGnuplot names the file a script draws (see GnuplotOutputName).
constexpr const char* kOutputVariable = "shockmap_output";

struct ChildOutcome {
  int status = 0;      // As waitpid reports it.
  std::string output;  // stdout and stderr, the last kExcerptBytes * 4 bytes.
};

// What `fd` gives until its end, the last `keep` bytes of it.
std::string ReadTail(int fd, std::size_t keep) {
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > keep) text.erase(0, text.size() - keep);
  }
  return text;
}

// posix_spawnp with the cleanup signals (SIGINT, SIGTERM, SIGHUP) held until the child is
// registered as KilledOnSignal in `child`: a signal in between would leave it drawing. The child
// starts with this thread's own signal mask.
int SpawnKilledOnSignal(pid_t& pid, const posix_spawn_file_actions_t& actions, char* argv[],
                        std::optional<KilledOnSignal>& child) {
  sigset_t held, previous;
  sigemptyset(&held);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held, signal);
  pthread_sigmask(SIG_BLOCK, &held, &previous);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setsigmask(&attributes, &previous);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  const int rc = posix_spawnp(&pid, "gnuplot", &actions, &attributes, argv, environ);
  posix_spawnattr_destroy(&attributes);
  if (rc == 0) child.emplace(pid);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  return rc;
}

// Runs `gnuplot -e "shockmap_output = './DRAWING'" ./NAME` in the script's folder with stdin
// from /dev/null and its output piped back; a signal that ends this process kills it. Throws
// PlotError when gnuplot cannot be started.
ChildOutcome SpawnGnuplot(const std::filesystem::path& script_file,
                          const std::filesystem::path& image,
                          const std::filesystem::path& drawing) {
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0)
    throw PlotError("pipe: " + std::string(std::strerror(errno)));
  const std::string dir =
      script_file.has_parent_path() ? script_file.parent_path().string() : std::string(".");
  // "./" keeps a name such as "-m.gp" from being read as an option.
  std::string arg0 = "gnuplot", arg1 = "-e",
              arg2 = std::string(kOutputVariable) + " = " + GnuplotFileName(drawing),
              arg3 = "./" + script_file.filename().string();
  char* argv[] = {arg0.data(), arg1.data(), arg2.data(), arg3.data(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  pid_t pid = 0;
  std::optional<KilledOnSignal> child;
  const int rc = SpawnKilledOnSignal(pid, actions, argv, child);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (rc != 0) {
    ::close(pipe_fds[0]);
    throw PlotError(rc == ENOENT ? "gnuplot was not found on the PATH; install gnuplot to draw " +
                                       image.string() + " (script " + script_file.string() + ")"
                                 : "cannot start gnuplot for " + script_file.string() + ": " +
                                       std::strerror(rc));
  }
  ChildOutcome outcome;
  outcome.output = ReadTail(pipe_fds[0], 4 * kExcerptBytes);
  ::close(pipe_fds[0]);
  while (::waitpid(pid, &outcome.status, 0) < 0 && errno == EINTR) {
  }
  child.reset();  // Reaped: its pid may be another process's from now on.
  return outcome;
}

std::string Excerpt(const std::string& output) {
  if (output.empty()) return "it printed nothing";
  const std::size_t from = output.size() > kExcerptBytes ? output.size() - kExcerptBytes : 0;
  return "it printed: " + output.substr(from);
}

// True when `drawing` ends as a whole PNG (its IEND chunk) or SVG (its closing tag), as
// `image` names it, does: gnuplot exits 0 even when the disk took only part of the image.
bool IsCompleteImage(const std::filesystem::path& drawing, const std::filesystem::path& image) {
  std::ifstream in(drawing, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (!in || size < 12) return false;
  const std::streamoff tail = std::min<std::streamoff>(size, 64);
  std::string end(static_cast<std::size_t>(tail), '\0');
  in.seekg(size - tail);
  in.read(end.data(), tail);
  if (image.extension() == ".svg") return end.find("</svg>") != std::string::npos;
  return end.ends_with(std::string("IEND\xae\x42\x60\x82", 8));
}

// The file-size limit of this process and its children (ulimit -f), in bytes.
rlim_t FileSizeLimit() {
  struct rlimit limit {};
  return ::getrlimit(RLIMIT_FSIZE, &limit) == 0 ? limit.rlim_cur : RLIM_INFINITY;
}

bool ReachesFileSizeLimit(std::uintmax_t bytes) {
  return FileSizeLimit() != RLIM_INFINITY && bytes >= FileSizeLimit();
}

// Why the run failed, or "" when it drew `image` into `drawing`; `partial` tells the image was
// cut short.
std::string Failure(bool& partial, const ChildOutcome& child,
                    const std::filesystem::path& script_file, const std::filesystem::path& image,
                    const std::filesystem::path& drawing) {
  if (WIFSIGNALED(child.status)) {
    return fmt::format("gnuplot was killed by signal {} ({}) on {}; {}", WTERMSIG(child.status),
                       strsignal(WTERMSIG(child.status)), script_file.string(),
                       Excerpt(child.output));
  }
  if (WEXITSTATUS(child.status) != 0) {
    return fmt::format("gnuplot exited with status {} on {}; {}", WEXITSTATUS(child.status),
                       script_file.string(), Excerpt(child.output));
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(drawing, ec)) {
    return fmt::format("gnuplot ended without writing {} (script {}); {}", image.string(),
                       script_file.string(), Excerpt(child.output));
  }
  if (!IsCompleteImage(drawing, image)) {
    partial = true;
    // Say what is known, the bytes written and the room left, rather than guess at the cause.
    const std::uintmax_t bytes = std::filesystem::file_size(drawing, ec);
    const auto space =
        std::filesystem::space(image.parent_path().empty() ? "." : image.parent_path(), ec);
    const std::string room =
        ReachesFileSizeLimit(bytes)
            ? fmt::format("the file-size limit (ulimit -f) of {} bytes", FileSizeLimit())
        : ec                   ? "its disk's free space unknown"
        : space.available == 0 ? "its disk full"
                               : fmt::format("{:.3g} MB free on its disk", space.available / 1e6);
    return fmt::format("gnuplot wrote only part of {} ({} bytes, {}), script {}; {}",
                       image.string(), bytes, room, script_file.string(), Excerpt(child.output));
  }
  return "";
}

}  // namespace

std::string TerminalFor(const std::filesystem::path& file, int width, int height) {
  GnuplotFileName(file);  // Its data and script files share its name but for the extension.
  if (file.extension() == ".svg") {
    return fmt::format("svg size {},{} dynamic font 'DejaVu Sans,12' background '#ffffff'", width,
                       height);
  }
  if (file.extension() == ".png") {
    return fmt::format("pngcairo size {},{} font 'DejaVu Sans,11'", width, height);
  }
  throw InputError(file.string() + ": the plot file must end in .png or .svg");
}

std::string GnuplotQuoted(std::string_view text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') {
      quoted += "''";
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      quoted += ' ';
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string GnuplotFileName(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  for (char c : name) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      throw InputError("the plot file name \"" + Excerpt(name, 0) +
                       "\" holds a line break or another control character (U+0000 to U+001F "
                       "or U+007F), which gnuplot cannot be given; name the file without one");
    }
  }
  // "./" keeps gnuplot from reading a leading '|' (output) or '<' (data) as a command to run.
  return GnuplotQuoted("./" + name);
}

std::string GnuplotOutputName(const std::filesystem::path& image) {
  return fmt::format("(exists('{0}') ? {0} : {1})", kOutputVariable, GnuplotFileName(image));
}

std::string GnuplotTics(const char* axis, std::vector<double> values) {
  std::ranges::sort(values);
  std::string tics;
  for (double v : values) tics += fmt::format("{}'{:.4g}' {}", tics.empty() ? "" : ", ", v, v);
  return fmt::format("set {}tics ({}){}\n", axis, tics,
                     std::string(axis) == "x" ? " rotate by -35 offset 0,0" : "");
}

void RunGnuplot(const std::string& script, const std::filesystem::path& script_file,
                const std::filesystem::path& image) {
  WriteFileAtomically(script_file, script);
  const auto dir = image.has_parent_path() ? image.parent_path() : std::filesystem::path(".");
  const auto drawing = UnusedTemporaryName(dir);
  const RemovedOnSignal drawing_on_signal(drawing);
  std::string failure;
  bool partial = false;
  try {
    failure =
        Failure(partial, SpawnGnuplot(script_file, image, drawing), script_file, image, drawing);
  } catch (const PlotError& e) {
    failure = e.what();
  }
  std::error_code ec;
  if (failure.empty()) {
    std::filesystem::rename(drawing, image, ec);
    if (!ec) return;
    failure = "cannot write " + image.string() + ": " + ec.message();
    partial = true;  // Drawn, but not where asked: an output that could not be written.
  }
  std::filesystem::remove(drawing, ec);
  if (partial) throw InputError(failure + "; " + image.string() + " was left as it was");
  throw PlotError(failure);
}

}  // namespace shockmap
