#include "formats/history_csv.h"

#include <stdexcept>

#include "formats/output_file.h"

namespace shockmap {

void WriteComparisonCsv(const ComparisonResult& result, const std::filesystem::path& dir) {
  CreateOutputDirectory(dir);

  const TransientResult& h = result.histories;
  if (!h.displacement_m.empty() &&
      (h.velocity_m_s.empty() ||
       h.energy.kinetic_j.values.size() != h.displacement_m[0].values.size())) {
    throw std::logic_error("WriteComparisonCsv: histories not recorded RecordedHistories::kAll");
  }
  const auto num_file = dir / "numerical.csv";
  AtomicFile num_out(num_file);
  std::ostream& num = num_out.Stream();
  num << "t_s,tip_displacement_m,tip_velocity_m_s,contact_force_n,kinetic_j,strain_j,contact_j,"
         "dissipated_j\n";
  if (!h.displacement_m.empty()) {
    const UniformSignal& u = h.displacement_m[0];
    for (std::size_t i = 0; i < u.values.size(); ++i) {
      num << u.TimeAt(i) << ',' << u.values[i] << ',' << h.velocity_m_s[0].values[i] << ','
          << h.contact_force_n[0].values[i] << ',' << h.energy.kinetic_j.values[i] << ','
          << h.energy.strain_j.values[i] << ',' << h.energy.contact_j.values[i] << ','
          << h.energy.dissipated_j.values[i] << '\n';
    }
  }

  const auto ref_file = dir / "reference.csv";
  AtomicFile ref_out(ref_file);
  std::ostream& ref = ref_out.Stream();
  ref << "t_s,tip_displacement_m,contact_force_n\n";
  const UniformSignal& u = result.reference->tip_m;
  for (std::size_t i = 0; i < u.values.size(); ++i) {
    ref << u.TimeAt(i) << ',' << u.values[i] << ',' << result.reference->force_n.values[i] << '\n';
  }
  // Both written in full before either replaces a file: a write that fails changes neither.
  num_out.Commit();
  ref_out.Commit();
}

}  // namespace shockmap
