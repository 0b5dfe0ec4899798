#include "engine/progress_reporter.h"

#include <unistd.h>

#include <string>

namespace shockmap {
namespace {

// Plain lines every 5 s keep CI logs readable; a terminal bar redraws at most 10 times a second.
constexpr double kLineInterval_s = 5.0;
constexpr double kBarInterval_s = 0.1;

}  // namespace

ProgressReporter::ProgressReporter(long total, std::FILE* out, bool enabled)
    : total_(total),
      out_(out),
      enabled_(enabled && total > 0),
      terminal_(isatty(fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

void ProgressReporter::Update(long done, long diverged, long failed) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (terminal_ ? kBarInterval_s : kLineInterval_s)) return;
  last_print_ = now;
  Print(done, diverged, failed, false);
}

void ProgressReporter::Finish(long done, long diverged, long failed) {
  if (enabled_) Print(done, diverged, failed, true);
}

void ProgressReporter::Print(long done, long diverged, long failed, bool final_line) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
  const double eta = rate > 0.0 ? static_cast<double>(total_ - done) / rate : 0.0;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * done / total_);
    const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
    std::fprintf(out_, "\r[%s] %ld/%ld points, %.1f/s, ETA %.0f s, diverged %ld, failed %ld  ",
                 bar.c_str(), done, total_, rate, eta, diverged, failed);
    if (final_line) std::fprintf(out_, "\n");
  } else {
    std::fprintf(out_, "progress: %ld/%ld points, %.1f/s, ETA %.0f s, diverged %ld, failed %ld\n",
                 done, total_, rate, eta, diverged, failed);
  }
  std::fflush(out_);
}

}  // namespace shockmap
