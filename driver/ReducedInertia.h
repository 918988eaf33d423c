#pragma once
// The whole train's inertia referred to each shaft (issue 20 item 4): the
// reduced inertia the papers print (seed 000 eq 1 J_pr, seed 003's J1 + J2
// on the motor shaft, seed 004's I0 = I1 + I), as derived values.

#include "plugins/scene/Scene.h"

namespace milldyn {

/// What one addReducedInertias did, counted for the test of its growth
/// (issue 26 item 9: a dense full-pivot LU made `milldyn info` cubic in the
/// number of bodies, 14.4 s for 2000).
struct ReducedInertiaWork {
    long long realizations = 0;     ///< velocity realizations to find the residual rows
    long long matrixNonzeros = 0;   ///< nonzeros of the rows the rigid motion must zero
    long long factorNonzeros = 0;   ///< nonzeros of the sparse QR factor R
    bool dense = false;             ///< the dense fallback was used (small models only)
};

/**
 * Adds `BODY.reduced_inertia` [kg*m^2] for every body that turns when the
 * train moves as one rigid train: J_BODY = 2T/ω_BODY² = vᵀ M v / ω_BODY²,
 * M Simbody's mass matrix and v the train's one rigid motion — the velocity
 * that satisfies every constraint (G v = 0) and leaves every steady residual
 * unchanged (couplings untwisting, charges held in their drums, clutches not
 * slipping). Evaluated in the model's default configuration (all angles 0).
 * A model with more than one such motion (two independent drives) or none
 * gets no reduced inertia, and a note says why.
 *
 * v is the kernel of those rows, found by a sparse QR (COLAMD ordering):
 * a train's rows touch two or three shafts each, so the work grows about
 * linearly with the bodies; the kernel is checked (|A v| small) and a
 * model of at most 400 mobilities whose sparse answer fails the check is
 * solved densely (full-pivot LU) as before.
 */
void addReducedInertias(Scene& scene, ReducedInertiaWork* work = nullptr);

}  // namespace milldyn
