#include "core/modes.h"

#include <numbers>

namespace shockmap {

void NormalizeModeSigns(Eigen::MatrixXd& shapes) {
  for (int j = 0; j < shapes.cols(); ++j) {
    Eigen::Index at = 0;
    shapes.col(j).cwiseAbs().maxCoeff(&at);
    if (shapes(at, j) < 0.0) shapes.col(j) *= -1.0;
  }
}

double ModalBasis::HighestFrequencyHz() const {
  return NumModes() == 0 ? 0.0 : omega_rad_s[NumModes() - 1] / (2.0 * std::numbers::pi);
}

}  // namespace shockmap
