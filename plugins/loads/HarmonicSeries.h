#pragma once
// The harmonic sum of a periodic load, Σ_k (a_k cos kθ + b_k sin kθ), by
// the angle-addition recurrence: shared by PeriodicLoad (time) and
// AngleLoad (shaft angle).

#include <algorithm>
#include <cmath>
#include <vector>

namespace milldyn {

/**
 * Σ_{k=1..K} (a_k·cos kθ + b_k·sin kθ) [the coefficients' unit], K the
 * longer of the two lists (a missing coefficient is 0), from one sine and
 * one cosine of θ:
 *
 * <pre>
 *   sin((k+1)θ) = sin kθ·cos θ + cos kθ·sin θ,   cos((k+1)θ) = cos kθ·cos θ − sin kθ·sin θ
 * </pre>
 *
 * whose rounding grows like k·ε (PeriodicLoadTest checks it against the
 * direct sum in long double: ≤ 1e-13 of Σ|b_k| up to 50 harmonics). A sine
 * series alone is summed in the order PeriodicLoad always summed it.
 */
inline double harmonicSeries(const std::vector<double>& cosine, const std::vector<double>& sine, double theta) {
    const std::size_t na = cosine.size(), nb = sine.size(), K = std::max(na, nb);
    if (K == 0) return 0;
    const double s1 = std::sin(theta);
    double sum = nb > 0 ? sine[0] * s1 : 0.0;
    if (K == 1 && na == 0) return sum;
    const double c1 = std::cos(theta);
    if (na > 0) sum += cosine[0] * c1;
    double sk = s1, ck = c1;
    for (std::size_t k = 1; k < K; ++k) {
        const double next = sk * c1 + ck * s1;
        ck = ck * c1 - sk * s1;
        sk = next;
        if (k < nb) sum += sine[k] * sk;
        if (k < na) sum += cosine[k] * ck;
    }
    return sum;
}

}  // namespace milldyn
