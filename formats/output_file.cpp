#include "formats/output_file.h"

#include "core/input_error.h"

namespace shockmap {

void CreateOutputDirectory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("cannot create directory " + dir.string() + ": " + ec.message());
}

std::ofstream OpenForWriting(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw InputError("cannot write " + file.string());
  out.precision(12);
  return out;
}

void CloseWritten(std::ofstream& out, const std::filesystem::path& file) {
  out.close();
  if (!out) throw InputError("error while writing " + file.string());
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

}  // namespace shockmap
