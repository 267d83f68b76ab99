// Progress line on stderr for sim:run, see paddy/io/progress.hpp.
#include <paddy/io/progress.hpp>

#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace paddy::io {

namespace {

std::string duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char buf[32];
  const long total = std::lround(s);
  if (total >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", total / 3600, (total % 3600) / 60);
  else if (total >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", total / 60, total % 60);
  else std::snprintf(buf, sizeof buf, "%lds", total);
  return buf;
}

std::string rate(double r) {
  char buf[32];
  if (r >= 1e6) std::snprintf(buf, sizeof buf, "%.2fM", r / 1e6);
  else if (r >= 1e3) std::snprintf(buf, sizeof buf, "%.1fk", r / 1e3);
  else std::snprintf(buf, sizeof buf, "%.0f", r);
  return buf;
}

}  // namespace

ProgressLine::ProgressLine(std::uint64_t total_steps, double t_start, double dt, bool enabled,
                           std::FILE* stream, double plain_interval)
    : total_(total_steps), t0_(t_start), dt_(dt), enabled_(enabled), stream_(stream),
      plain_interval_(plain_interval), start_(Clock::now()), last_(start_) {
  tty_ = enabled_ && ::isatty(::fileno(stream_));
}

ProgressLine::~ProgressLine() {
  if (drawn_ && tty_ && !finished_) std::fputc('\n', stream_);
}

std::string ProgressLine::format(double t, double t_end, double fraction, double pps, double eta) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "t = %.4g / %.4g s  %5.1f %%  %s particle-steps/s  ETA %s", t, t_end,
                100.0 * fraction, rate(pps).c_str(), duration(eta).c_str());
  return buf;
}

void ProgressLine::update(std::uint64_t done, std::size_t particles, bool force) {
  if (done > last_done_) particle_steps_ += double(done - last_done_) * double(particles);
  last_done_ = done;
  if (!enabled_) return;
  const auto now = Clock::now();
  const double since_last = std::chrono::duration<double>(now - last_).count();
  const double interval = tty_ ? 0.25 : plain_interval_;
  if (!force && since_last < interval) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = total_ ? double(done) / double(total_) : 1.0;
  const double pps = elapsed > 0 ? particle_steps_ / elapsed : 0.0;
  const double eta = (fraction > 0 && elapsed > 0) ? elapsed * (1.0 - fraction) / fraction : NAN;
  const std::string line = format(t0_ + double(done) * dt_, t0_ + double(total_) * dt_, fraction, pps, eta);
  if (tty_) std::fprintf(stream_, "\r\033[K%s", line.c_str());
  else std::fprintf(stream_, "%s\n", line.c_str());
  std::fflush(stream_);
  drawn_ = true;
}

void ProgressLine::finish(std::uint64_t done, std::size_t particles) {
  if (!enabled_ || finished_) return;
  // A short run on a pipe prints nothing: only runs that already showed a line get a last one.
  if (tty_ || drawn_) update(done, particles, true);
  if (tty_ && drawn_) std::fputc('\n', stream_);
  finished_ = true;
}

}  // namespace paddy::io
