// Atomic file output (tmp + rename), see paddy/io/atomic_file.hpp.
#include <paddy/io/atomic_file.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <limits>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace paddy::io {

namespace fs = std::filesystem;

namespace {

fs::path temporaryFor(const fs::path& path) {
  return fs::path(path.string() + ".tmp." + std::to_string(::getpid()));
}

void ensureParent(const fs::path& path) {
  if (path.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot create directory '" + path.parent_path().string() + "': " + ec.message());
  }
}

// "cannot write 'PATH' (temporary 'TMP'): CAUSE", the cause from errno (EFBIG, ENOSPC, EACCES, ...).
[[noreturn]] void fail(const char* what, const fs::path& path, const fs::path& tmp, int err) {
  throw std::runtime_error(std::string("cannot ") + what + " '" + path.string() + "' (temporary '" + tmp.string() +
                           "'): " + std::strerror(err));
}

// PADDY_STOP_WRITING_AT (see the header): the moment (Unix time, s) from which this process stops
// in its next atomic write; NaN = never. Read at every write (writes are few; a forked process
// sees its own environment).
double stopWritingAt() {
  const char* v = std::getenv("PADDY_STOP_WRITING_AT");
  if (!v || !*v) return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double x = std::strtod(v, &end);
  return (*end == '\0' && std::isfinite(x)) ? x : std::numeric_limits<double>::quiet_NaN();
}
std::atomic<bool> stopped_in_write{false};

// The test hook's place: the caller has its temporary open or written, not renamed.
void writeFaultPoint() {
  const double at = stopWritingAt();
  if (!(at == at)) return;  // NaN: unset
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  if (now >= at && !stopped_in_write.exchange(true)) std::raise(SIGSTOP);
}

// produceFileAtomic; `fault_point`: the test hook's stop here (writeFileAtomic stops inside its own
// write instead).
void produce(const fs::path& path, const std::function<void(const fs::path&)>& write, bool fault_point) {
  ensureParent(path);
  const fs::path tmp = temporaryFor(path);
  try {
    write(tmp);
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    // The message names the file being written (the writer may only know the temporary name).
    if (std::string(e.what()).find(path.string()) == std::string::npos)
      throw std::runtime_error("cannot write '" + path.string() + "': " + e.what());
    throw;
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
  if (fault_point) writeFaultPoint();
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error("cannot rename '" + tmp.string() + "' to '" + path.string() + "': " + ec.message());
  }
}

}  // namespace

void produceFileAtomic(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  produce(path, write, true);
}

void writeFileAtomic(const fs::path& path, std::string_view content) {
  produce(path, [&](const fs::path& tmp) {
    // POSIX calls rather than a stream: every failure keeps its errno for the message.
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) fail("create", path, tmp, errno);
    // In two halves: the write fault point (header) falls between them.
    const std::size_t half = content.size() / 2;
    std::size_t done = 0;
    bool counted = false;
    while (done < content.size()) {
      if (done == half && !counted) {
        counted = true;
        writeFaultPoint();
      }
      const std::size_t upto = done < half ? half : content.size();
      const ssize_t n = ::write(fd, content.data() + done, upto - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {  // EFBIG past `ulimit -f` (SIGXFSZ is ignored by paddy), ENOSPC, EIO, ...
        const int err = n < 0 ? errno : EIO;
        ::close(fd);
        fail("write", path, tmp, err);
      }
      done += static_cast<std::size_t>(n);
    }
    if (content.empty()) writeFaultPoint();
    if (::close(fd) != 0) fail("write", path, tmp, errno);
  }, false);
}

bool isTemporaryName(std::string_view filename) {
  constexpr std::string_view marker = ".tmp.";
  const auto at = filename.rfind(marker);
  if (at == std::string_view::npos || at == 0) return false;
  const std::string_view pid = filename.substr(at + marker.size());
  if (pid.empty()) return false;
  for (char ch : pid)
    if (ch < '0' || ch > '9') return false;
  return true;
}

std::size_t removeTemporaries(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  std::vector<fs::path> found;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->is_regular_file(ec) && isTemporaryName(it->path().filename().string())) found.push_back(it->path());
  }
  std::size_t removed = 0;
  for (const auto& p : found)
    if (fs::remove(p, ec)) ++removed;
  return removed;
}

}  // namespace paddy::io
