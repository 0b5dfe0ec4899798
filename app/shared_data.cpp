#include "app/shared_data.h"

#include "core/input_error.h"

namespace shockmap {

std::filesystem::path SharedDataFolder() {
  std::error_code ec;
  const std::filesystem::path binary = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return (binary.parent_path() / ".." / "share" / "shockmap").lexically_normal();
}

std::string DefaultDataFile(const std::string& relative, const std::string& flag) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(relative, ec)) return relative;
  const std::filesystem::path folder = SharedDataFolder();
  const std::filesystem::path shared = folder / relative;
  if (!folder.empty() && std::filesystem::is_regular_file(shared, ec)) return shared.string();
  const std::filesystem::path here = std::filesystem::absolute(relative, ec);
  throw InputError(flag + ": the default file " + relative + " is neither in the working folder (" +
                   here.string() + ") nor in the shared data beside the binary (" +
                   (folder.empty() ? std::string("/proc/self/exe unreadable") : shared.string()) +
                   "); give " + flag + " FILE");
}

}  // namespace shockmap
