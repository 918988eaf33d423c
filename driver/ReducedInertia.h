#pragma once
// The whole train's inertia referred to each shaft (issue 20 item 4): the
// reduced inertia the papers print (seed 000 eq 1 J_pr, seed 003's J1 + J2
// on the motor shaft, seed 004's I0 = I1 + I), as derived values.

#include "plugins/scene/Scene.h"

namespace milldyn {

/**
 * Adds `BODY.reduced_inertia` [kg*m^2] for every body that turns when the
 * train moves as one rigid train: J_BODY = 2T/ω_BODY² = vᵀ M v / ω_BODY²,
 * M Simbody's mass matrix and v the train's one rigid motion — the velocity
 * that satisfies every constraint (G v = 0) and leaves every steady residual
 * unchanged (couplings untwisting, charges held in their drums, clutches not
 * slipping). Evaluated in the model's default configuration (all angles 0).
 * A model with more than one such motion (two independent drives) or none
 * gets no reduced inertia, and a note says why.
 */
void addReducedInertias(Scene& scene);

}  // namespace milldyn
