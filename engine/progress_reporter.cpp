#include "engine/progress_reporter.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace shockmap {
namespace {

// Plain lines every 5 s keep CI logs readable; a terminal bar redraws at most 10 times a second.
constexpr double kLineInterval_s = 5.0;
constexpr double kBarInterval_s = 0.1;
constexpr int kBarWidth = 30;

}  // namespace

std::string FormatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const auto s = static_cast<long>(std::lround(seconds));
  if (s < 60) return fmt::format("{} s", s);
  if (s < 3600) return fmt::format("{} min {:02} s", s / 60, s % 60);
  return fmt::format("{} h {:02} min", s / 3600, (s % 3600) / 60);
}

ProgressReporter::ProgressReporter(std::string phase, std::string unit, double total,
                                   std::FILE* out, bool enabled, ProgressListener listener)
    : phase_(std::move(phase)),
      unit_(std::move(unit)),
      total_(total),
      out_(out),
      enabled_(enabled && total > 0),
      terminal_(isatty(fileno(out)) != 0),
      listener_(total > 0 ? std::move(listener) : ProgressListener{}),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

void ProgressReporter::HoldEstimate() {
  estimate_held_ = true;
  estimate_started_ = false;
}

void ProgressReporter::StartEstimate(double done) {
  estimate_held_ = false;
  estimate_started_ = true;
  estimate_start_ = std::chrono::steady_clock::now();
  estimate_start_done_ = done;
}

void ProgressReporter::Update(double done, std::string_view detail) {
  if (!enabled_ && !listener_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!estimate_held_ && !estimate_started_ && done > 0.0) StartEstimate(done);
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (terminal_ || listener_ ? kBarInterval_s : kLineInterval_s)) return;
  last_print_ = now;
  Report(done, detail, false);
}

void ProgressReporter::Finish(double done, std::string_view detail) { Report(done, detail, true); }

void ProgressReporter::Report(double done, std::string_view detail, bool final_line) {
  if (listener_) listener_(phase_, done, total_);
  if (enabled_) Print(done, detail, final_line);
}

void ProgressReporter::Print(double done, std::string_view detail, bool final_line) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0.0 ? done / elapsed : 0.0;
  const std::string eta =
      final_line ? "took " + FormatDuration(elapsed) : Eta(done, std::chrono::steady_clock::now());
  std::string line =
      fmt::format("{} {:.4g}/{:.4g} {}, {:.3g}/s, {}", phase_, done, total_, unit_, rate, eta);
  if (!detail.empty()) line += fmt::format(", {}", detail);
  if (terminal_) {
    // The tolerance fills the bar at the end of a phase whose done is a sum of floats.
    const int filled = static_cast<int>(kBarWidth * std::clamp(done / total_, 0.0, 1.0) + 1e-6);
    const std::string bar = std::string(filled, '#') + std::string(kBarWidth - filled, '.');
    // Redrawn in place: carriage return, then erase what a longer previous line left.
    std::fprintf(out_, "\r\033[K[%s] %s%s", bar.c_str(), line.c_str(), final_line ? "\n" : "");
  } else {
    std::fprintf(out_, "progress: %s\n", line.c_str());
  }
  std::fflush(out_);
}

std::string ProgressReporter::Eta(double done, std::chrono::steady_clock::time_point now) const {
  const double since = std::chrono::duration<double>(now - estimate_start_).count();
  const double done_since = done - estimate_start_done_;
  if (estimate_held_ || !estimate_started_ || done_since <= 0.0 || since < kEstimateAfter_s) {
    return "ETA estimating";
  }
  return "ETA " + FormatDuration((total_ - done) * since / done_since);
}

}  // namespace shockmap
