#pragma once
// Output files of the commands: created with their directory, written fully or not at all, and
// every failure reported with the system's reason.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "formats/signal_cleanup.h"

namespace shockmap {

// Creates `dir` and its parents. Throws InputError naming it when that fails.
void CreateOutputDirectory(const std::filesystem::path& dir);

// Throws InputError naming `flag` and `path` when the path is longer than the system allows
// (PATH_MAX bytes in all, NAME_MAX bytes per name), before any work is done for it.
void CheckPathLength(const std::filesystem::path& path, std::string_view flag);

// Throws InputError naming `flag` when `dir` exists as something other than a directory, or
// cannot be created; creates it otherwise. Meant to run before a long computation.
void PrepareOutputDirectory(const std::filesystem::path& dir, std::string_view flag);

// Prepares `dir` as PrepareOutputDirectory does, then calls `write`. When `write` throws, the
// folders this call created (the outermost, with all it holds) are removed before the exception
// goes on: an output refused or failed half-way leaves no folder behind.
void WriteIntoDirectory(const std::filesystem::path& dir, std::string_view flag,
                        const std::function<void()>& write);

// One output file, written in full or not at all: the bytes go to a temporary file in the same
// folder, which Commit() renames over `path`. Destroyed without Commit() (an exception on the
// way) or ended by a signal (formats/signal_cleanup.h), the process removes the temporary, and
// whatever `path` held before is untouched. Doubles are
// written with the shortest digits that read back as the same value (docs/database.md).
class AtomicFile {
 public:
  // Throws InputError naming `path` with the system's reason when the folder takes no file.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& Stream() { return stream_; }
  // Flushes, syncs and renames. Throws InputError naming `path` with the system's reason
  // (e.g. "No space left on device") when any byte did not reach the disk.
  void Commit();

 private:
  class Buffer;
  std::filesystem::path path_;
  std::filesystem::path temp_;
  std::optional<RemovedOnSignal> temp_on_signal_;
  std::unique_ptr<Buffer> buffer_;
  std::ostream stream_;
  bool committed_ = false;
};

// `bytes` as the whole content of `path`, through an AtomicFile.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// `name` as part of a file name: letters, digits, '-' and '_' kept, every other byte as '_'.
// Names that give the same part (or parts differing only in case, as on a case-insensitive
// file system) would share their files: the study files refuse such names.
std::string FileNamePart(std::string_view name);

// A name in `dir` that no file has yet, for a temporary file of this process.
std::filesystem::path UnusedTemporaryName(const std::filesystem::path& dir);

// Throws InputError with the system's reason when anything written to standard output so far
// failed; flushes first when `flush`. Cheap without `flush`: call it per row of long outputs.
void CheckStandardOutput(bool flush);

// A CSV field: quoted (with doubled quotes) when it holds a comma, a quote or a line break.
std::string CsvField(const std::string& text);

}  // namespace shockmap
