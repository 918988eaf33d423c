#pragma once
// PlanetaryLayout (example plugin, docs/new-layout.md): a whole planetary
// mill layout as one element type, built from milldyn's own elements.

#include "plugins/scene/ElementRegistry.h"

namespace planetary_layout {

/**
 * A carrier (a body of the model file, on a pin whose axis is the fixed
 * gear's axis) gets n drums on pins at the arm a, evenly spaced from
 * first_drum_angle θ0:
 * <pre>
 *   internal rolling (drums inside a fixed ring of pitch radius R):  a = R − r
 *   external rolling (drums on a fixed sun of pitch radius R):       a = R + r
 *   drum k at a (cos θk, sin θk) in the carrier frame, θk = θ0 + 2π(k−1)/n
 * </pre>
 * and, for each drum, the built-in elements it needs, built through the
 * registry exactly as if the model file had listed them: GearMesh
 * (`rolling` internal: ω2,abs = −ω1 (R − r)/r), SegmentCharge (the charge),
 * JournalFriction and JointReaction at its pin. Names: `PREFIXdrumK`,
 * `PREFIXmeshK`, `PREFIXchargeK`, `PREFIXfriction_BK`, `PREFIXreaction_BK`
 * (the built-in external-rolling model's names with an empty prefix).
 * The carrier's own drive, friction and reaction stay in the model file as
 * built-in elements: the layout is the part that repeats per drum.
 */
void registerPlanetaryLayout(milldyn::ElementRegistry& registry);

}  // namespace planetary_layout
