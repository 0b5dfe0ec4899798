#include "reference/analytic_basis.h"

#include <gsl/gsl_integration.h>

#include <cassert>
#include <cmath>
#include <memory>
#include <numbers>

namespace shockmap {
namespace {

// Values of every mode at every node: nodes x modes.
Eigen::MatrixXd SampleShapes(const AnalyticBasis& basis, const BeamQuadrature& q) {
  Eigen::MatrixXd s(static_cast<Eigen::Index>(q.xi.size()), basis.NumModes());
  for (int j = 0; j < basis.NumModes(); ++j) {
    for (std::size_t k = 0; k < q.xi.size(); ++k)
      s(static_cast<Eigen::Index>(k), j) = basis.Phi(j, q.xi[k]);
  }
  return s;
}

Eigen::Map<const Eigen::VectorXd> Weights(const BeamQuadrature& q) {
  return {q.weight.data(), static_cast<Eigen::Index>(q.weight.size())};
}

// A product of two modes oscillates at most like e^{i 2 b_max xi}; a 16-point rule on panels
// of phase 2 b_max / panels <= 4 rad integrates it to rounding.
constexpr int kPointsPerPanel = 16;
int PanelsFor(double b_max) { return 8 + static_cast<int>(std::ceil(b_max / 2.0)); }

}  // namespace

double RootOfFrequency(const BeamProperties& beam, double f_hz) {
  return std::sqrt(2.0 * std::numbers::pi * f_hz / beam.OmegaOf(1.0));
}

int BeamQuadratureNodes(double b_max) { return kPointsPerPanel * PanelsFor(b_max); }

BeamQuadrature MakeBeamQuadrature(double b_max) {
  const int panels = PanelsFor(b_max);
  std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)>
      table(gsl_integration_glfixed_table_alloc(kPointsPerPanel),
            gsl_integration_glfixed_table_free);
  BeamQuadrature q;
  for (int p = 0; p < panels; ++p) {
    const double a = static_cast<double>(p) / panels;
    const double b = static_cast<double>(p + 1) / panels;
    for (int i = 0; i < kPointsPerPanel; ++i) {
      double xi = 0.0, w = 0.0;
      gsl_integration_glfixed_point(a, b, i, &xi, &w, table.get());
      q.xi.push_back(xi);
      q.weight.push_back(w);
    }
  }
  return q;
}

AnalyticBasis MakeAnalyticBasis(const BeamProperties& beam, double kappa, double f_max_hz,
                                const BeamQuadrature& quadrature) {
  const double b_max = RootOfFrequency(beam, f_max_hz);
  AnalyticBasis basis;
  basis.kappa = kappa;
  for (double b : CharacteristicRoots(kappa, b_max, 1)) basis.shapes.emplace_back(b);
  const int n = basis.NumModes();
  basis.omega_rad_s.resize(n);
  basis.scale = Eigen::VectorXd::Ones(n);
  for (int i = 0; i < n; ++i) basis.omega_rad_s[i] = beam.OmegaOf(basis.shapes[i].B());
  const Eigen::MatrixXd raw = SampleShapes(basis, quadrature);
  const Eigen::VectorXd norm2 =
      beam.rho_a_kg_per_m * beam.length_m *
      (raw.array().square().colwise() * Weights(quadrature).array()).colwise().sum().transpose();
  basis.scale = norm2.cwiseSqrt().cwiseInverse();
  basis.on_nodes = raw * basis.scale.asDiagonal();  // phi_j = scale_j W_j, as Phi computes it.
  basis.tip.resize(n);
  for (int i = 0; i < n; ++i) basis.tip[i] = basis.Phi(i, 1.0);
  return basis;
}

Eigen::MatrixXd MassProjection(const BeamProperties& beam, const AnalyticBasis& to,
                               const AnalyticBasis& from, const BeamQuadrature& quadrature) {
  assert(to.on_nodes.rows() == static_cast<Eigen::Index>(quadrature.xi.size()) &&
         from.on_nodes.rows() == to.on_nodes.rows());
  return beam.rho_a_kg_per_m * beam.length_m *
         (to.on_nodes.transpose() * Weights(quadrature).asDiagonal() * from.on_nodes);
}

Eigen::VectorXd ProjectDeflection(const BeamProperties& beam, const AnalyticBasis& basis,
                                  const std::function<double(double)>& u_of_xi,
                                  const BeamQuadrature& quadrature) {
  Eigen::VectorXd weighted_u(static_cast<Eigen::Index>(quadrature.xi.size()));
  for (std::size_t k = 0; k < quadrature.xi.size(); ++k) {
    weighted_u[static_cast<Eigen::Index>(k)] = quadrature.weight[k] * u_of_xi(quadrature.xi[k]);
  }
  assert(basis.on_nodes.rows() == weighted_u.size());
  return beam.rho_a_kg_per_m * beam.length_m * (basis.on_nodes.transpose() * weighted_u);
}

}  // namespace shockmap
