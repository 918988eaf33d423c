#pragma once
// CircularSegment: geometry of the circular segment of half-angle γ (the
// cross-section of a mill charge lying in a drum of radius r), as pure
// functions of γ without Simbody.
//
//   area                A   = r² (2γ − sin 2γ) / 2
//   centroid distance   l_c = r · 4 sin³γ / (3 (2γ − sin 2γ))
//   polar inertia about the drum axis, per unit mass and r²:
//                       k_a = (12γ − 4 sin 2γ − sin 4γ) / (12 (2γ − sin 2γ))
//   polar inertia about the centroid, per unit mass and r²:
//                       k_c = k_a − (l_c / r)²            (parallel axes)
//   fill fraction       f   = (2γ − sin 2γ) / (2π)
//
// (textbook segment formulas; the charge model is that of seeds 001/003,
// docs/burr_mill.md). Written as they stand, 2γ − sin 2γ loses all digits
// below γ ≈ 1e-5 and k_c (a difference of two numbers near 1) goes
// negative; below γ = 0.5 every factor is summed from its Taylor series in
// γ² instead, so nothing cancels (issue 16, item 3). Accurate to a few ulp
// from γ = 1e-300 to π.

namespace milldyn {
namespace circular_segment {

/// 2γ − sin 2γ [1] (twice the area over r²), for 0 ≤ γ ≤ π.
double calcAreaFactor(double gamma);
/// l_c / r = 4 sin³γ / (3 (2γ − sin 2γ)) [1]; 1 at γ → 0, 0 at π.
double calcCentroidFactor(double gamma);
/// k_a: polar inertia about the drum axis over m r² [1]; 1 at γ → 0, ½ at π.
double calcAxisInertiaFactor(double gamma);
/// k_c: polar inertia about the centroid over m r² [1]; γ²/5 at γ → 0, ½ at π.
double calcCentralInertiaFactor(double gamma);
/// f = (2γ − sin 2γ) / 2π [1].
double calcFillFraction(double gamma);
/// The half-angle γ [rad] of fill fraction `fill` in (0, 1]: the inverse of
/// calcFillFraction to a few ulp, tiny fills included (γ ≈ (3π f / 2)^⅓).
/// Throws std::invalid_argument outside (0, 1].
double calcHalfAngleForFill(double fill);

}  // namespace circular_segment
}  // namespace milldyn
