#include "ensemble/progress.h"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace caskdem {

Progress::Progress(std::int64_t total, std::int64_t already_done, bool enabled)
    : total_(total),
      start_done_(already_done),
      enabled_(enabled),
      terminal_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void Progress::update(std::int64_t done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_draw_).count();
  if (since < (terminal_ ? 0.2 : 5.0)) return;
  last_draw_ = now;
  draw(done, false);
}

void Progress::finish() {
  if (enabled_) draw(total_, true);
}

void Progress::draw(std::int64_t done, bool final) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0.0 ? double(done - start_done_) / elapsed : 0.0;
  const double left = rate > 0.0 ? double(total_ - done) / rate : 0.0;
  char line[160];
  if (terminal_) {
    const int width = 30;
    const int filled = total_ > 0 ? int(width * double(done) / double(total_)) : width;
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::snprintf(line, sizeof line, "\r[%s] %lld/%lld realisations  %.1f/s  %s %.0f s ", bar.c_str(), (long long)done,
                  (long long)total_, rate, final ? "took" : "left", final ? elapsed : left);
    std::fputs(line, stderr);
    if (final) std::fputc('\n', stderr);
  } else {
    std::snprintf(line, sizeof line, "progress: %lld/%lld realisations, %.1f per s, %s %.0f s\n", (long long)done,
                  (long long)total_, rate, final ? "took" : "about", final ? elapsed : left);
    std::fputs(line, stderr);
  }
  std::fflush(stderr);
}

}  // namespace caskdem
