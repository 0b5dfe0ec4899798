#include "formats/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <locale>

#include "core/input_error.h"

namespace shockmap {
namespace {

std::string Reason(int error) { return error != 0 ? std::strerror(error) : "write error"; }

std::string PathExcerpt(const std::string& text) {
  return text.size() <= 80 ? text : text.substr(0, 60) + "..." + text.substr(text.size() - 16);
}

// Writes every double as the shortest digits that read back as the same value (std::to_chars),
// so that the numbers of an output file lose nothing.
class ShortestRoundTrip : public std::num_put<char> {
 protected:
  iter_type do_put(iter_type out, std::ios_base&, char_type, double v) const override {
    std::array<char, 32> digits{};
    const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), v).ptr;
    return std::copy(digits.data(), end, out);
  }
};

}  // namespace

void CreateOutputDirectory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("cannot create directory " + dir.string() + ": " + ec.message());
}

void CheckPathLength(const std::filesystem::path& path, std::string_view flag) {
  const std::string text = path.string();
  if (text.size() >= PATH_MAX) {
    throw InputError(std::string(flag) + ": the path \"" + PathExcerpt(text) + "\" is " +
                     std::to_string(text.size()) + " bytes long; the system allows at most " +
                     std::to_string(PATH_MAX - 1));
  }
  for (const auto& part : path) {
    if (part.string().size() > NAME_MAX) {
      throw InputError(std::string(flag) + ": the name \"" + PathExcerpt(part.string()) + "\" is " +
                       std::to_string(part.string().size()) +
                       " bytes long; the system allows at most " + std::to_string(NAME_MAX) +
                       " bytes per file or folder name");
    }
  }
}

void PrepareOutputDirectory(const std::filesystem::path& dir, std::string_view flag) {
  CheckPathLength(dir, flag);
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
    throw InputError(std::string(flag) + ": " + dir.string() +
                     " exists and is not a directory; name a directory for the outputs");
  }
  CreateOutputDirectory(dir);
}

namespace {

// The outermost of `dir` and its parents that does not exist yet; empty when `dir` exists.
std::filesystem::path OutermostMissing(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::path missing;
  for (auto p = dir; !p.empty() && !std::filesystem::exists(p, ec); p = p.parent_path()) {
    missing = p;
    if (p == p.parent_path()) break;
  }
  return missing;
}

}  // namespace

void WriteIntoDirectory(const std::filesystem::path& dir, std::string_view flag,
                        const std::function<void()>& write) {
  const std::filesystem::path created = OutermostMissing(dir);
  PrepareOutputDirectory(dir, flag);
  try {
    write();
  } catch (...) {
    std::error_code ignored;
    if (!created.empty()) std::filesystem::remove_all(created, ignored);
    throw;
  }
}

// A stream buffer over a file descriptor that keeps the first write error's errno.
class AtomicFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd) { setp(data_.data(), data_.data() + data_.size()); }
  ~Buffer() override {
    if (fd_ >= 0) ::close(fd_);
  }
  // Writes what is buffered, syncs and closes; the first errno met, 0 when all went through.
  int Finish() {
    Drain();
    if (error_ == 0 && ::fsync(fd_) != 0) error_ = errno;
    if (::close(fd_) != 0 && error_ == 0) error_ = errno;
    fd_ = -1;
    return error_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!Drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return Drain() ? 0 : -1; }

 private:
  bool Drain() {
    for (const char* p = pbase(); error_ == 0 && p < pptr();) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n > 0) {
        p += n;
      } else if (n < 0 && errno != EINTR) {
        error_ = errno;
      } else if (n == 0) {
        error_ = EIO;
      }
    }
    setp(data_.data(), data_.data() + data_.size());
    return error_ == 0;
  }

  int fd_;
  int error_ = 0;
  std::array<char, 1 << 16> data_{};
};

std::string FileNamePart(std::string_view name) {
  std::string part(name);
  for (char& c : part) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  }
  return part;
}

std::filesystem::path UnusedTemporaryName(const std::filesystem::path& dir) {
  static std::atomic<unsigned> counter{0};
  for (;;) {
    auto name = dir / (".shockmap-" + std::to_string(::getpid()) + "-" +
                       std::to_string(counter.fetch_add(1)) + ".tmp");
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(name, ec))) return name;
  }
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)), stream_(nullptr) {
  const auto dir = path_.has_parent_path() ? path_.parent_path() : std::filesystem::path(".");
  int fd = -1;
  int error = 0;
  do {
    temp_ = UnusedTemporaryName(dir);
    fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    error = errno;
  } while (fd < 0 && error == EEXIST);
  // Registered once ours: a signal before this leaves the temporary, never removes another's.
  if (fd >= 0) temp_on_signal_.emplace(temp_);
  if (fd < 0) throw InputError("cannot write " + path_.string() + ": " + Reason(error));
  buffer_ = std::make_unique<Buffer>(fd);
  stream_.rdbuf(buffer_.get());
  stream_.imbue(std::locale(std::locale::classic(), new ShortestRoundTrip));
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  buffer_.reset();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
}

void AtomicFile::Commit() {
  stream_.flush();
  int error = buffer_->Finish();
  if (error == 0 && std::rename(temp_.c_str(), path_.c_str()) != 0) error = errno;
  if (error != 0) {
    throw InputError("cannot write " + path_.string() + ": " + Reason(error) +
                     "; the file was left as it was");
  }
  committed_ = true;
  temp_on_signal_.reset();
}

void WriteFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  AtomicFile file(path);
  file.Stream() << bytes;
  file.Commit();
}

void CheckStandardOutput(bool flush) {
  // A failed write of stdio leaves its errno behind; no later call on the stream repeats it.
  const int earlier = errno;
  errno = 0;
  if (flush) std::cout.flush();
  if ((!flush || std::fflush(stdout) == 0) && std::cout && !std::ferror(stdout)) {
    errno = earlier;
    return;
  }
  const int error = errno != 0 ? errno : earlier;
  throw InputError("cannot write standard output: " + Reason(error));
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

}  // namespace shockmap
