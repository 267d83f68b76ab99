// Progress line for long runs, on stderr: simulated time, percentage, particle-steps per second
// and the estimated time left. On a terminal the line is redrawn in place (at most 4 times a
// second); otherwise a plain line is printed every `plain_interval` seconds of wall time.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace paddy::io {

class ProgressLine {
 public:
  // `total_steps` steps of `dt` seconds each make 100 %.
  ProgressLine(std::uint64_t total_steps, double t_start, double dt, bool enabled,
               std::FILE* stream = stderr, double plain_interval = 5.0);
  ~ProgressLine();  // ends the line on a terminal
  // Reports that `done` of the total steps are taken, over `particles` particles.
  void update(std::uint64_t done, std::size_t particles, bool force = false);
  void finish(std::uint64_t done, std::size_t particles);
  // The text of the line (without terminal control characters); exposed for tests.
  static std::string format(double t, double t_end, double fraction, double particle_steps_per_s,
                            double eta_s);

 private:
  using Clock = std::chrono::steady_clock;
  std::uint64_t total_;
  double t0_, dt_;
  bool enabled_, tty_, drawn_ = false, finished_ = false;
  std::FILE* stream_;
  double plain_interval_;
  Clock::time_point start_, last_;
  double particle_steps_ = 0.0;
  std::uint64_t last_done_ = 0;
};

}  // namespace paddy::io
