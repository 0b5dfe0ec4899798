#include "views/signal_csv.h"

#include "formats/output_file.h"

namespace shockmap {

void WriteSignalsCsv(const StoredSignals& signals, const std::filesystem::path& path) {
  if (path.has_parent_path()) CreateOutputDirectory(path.parent_path());
  AtomicFile file(path);
  std::ostream& out = file.Stream();
  out << "t_s";
  for (const std::string& name : signals.names) out << ',' << CsvField(name);
  out << '\n';
  const std::size_t rows = signals.values.empty() ? 0 : signals.values.front().size();
  for (std::size_t i = 0; i < rows; ++i) {
    out << static_cast<double>(i) * signals.output_dt_s;  // docs/database.md: t = i output_dt_s
    for (const auto& column : signals.values) out << ',' << column[i];
    out << '\n';
  }
  file.Commit();
}

}  // namespace shockmap
