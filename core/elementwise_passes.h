#pragma once
// The element-by-element passes of an explicit step (Newmark's predictor and corrector, the
// modal restoring force, loads and damping), compiled twice: for AVX2 and for the baseline x86-64
// (SSE2), the one the CPU supports chosen when the program loads. Each element is computed with the
// same operations in the same order in both (no fused multiply-add: AVX2 does not imply it), so the
// results are equal bit for bit to the Eigen expressions they replace on any x86-64; AVX2 does
// each pass in half the instructions (docs/performance.md, "Explicit steps and bundles").
// Pointers of one call must not overlap.

#include <Eigen/Core>
#include <span>

namespace shockmap {

// x += dt v + cx a, then v += cv a, element by element.
void PredictInPlace(Eigen::VectorXd& x, Eigen::VectorXd& v, const Eigen::VectorXd& a, double dt,
                    double cx, double cv);

// v += c a.
void AddScaledInPlace(Eigen::VectorXd& v, double c, const Eigen::VectorXd& a);

// a = (a - d .* v) ./ divisor: the modal damping's implicit velocity term.
void DampInPlace(Eigen::VectorXd& a, const Eigen::VectorXd& d, const Eigen::VectorXd& v,
                 const Eigen::VectorXd& divisor);

// largest[i] = std::max(largest[i], values[i]): each contact's largest force so far.
void RaiseToMaxInPlace(std::span<double> largest, std::span<const double> values);

// out = -(w .* x), out resized to w's size.
void NegativeProduct(const Eigen::VectorXd& w, const Eigen::VectorXd& x, Eigen::VectorXd& out);

// out = -(w .* x) + c s, out resized to w's size: NegativeProduct then AddScaledInPlace in one
// pass, equal to them bit for bit (the restoring force and one load).
void NegativeProductPlusScaled(const Eigen::VectorXd& w, const Eigen::VectorXd& x, double c,
                               const Eigen::VectorXd& s, Eigen::VectorXd& out);

}  // namespace shockmap
