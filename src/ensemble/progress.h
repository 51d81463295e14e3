#pragma once
// Progress on stderr: a bar redrawn in place when stderr is a terminal, otherwise one plain
// line every few seconds (for logs and batch systems).

#include <chrono>
#include <cstdint>

namespace caskdem {

class Progress {
 public:
  Progress(std::int64_t total, std::int64_t already_done, bool enabled);
  void update(std::int64_t done);  // realisations completed so far (including already_done)
  void finish();

 private:
  void draw(std::int64_t done, bool final);
  std::int64_t total_;
  std::int64_t start_done_;
  bool enabled_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace caskdem
