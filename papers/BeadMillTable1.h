#pragma once
// Seed 004 (bead mill), Table 1: the coefficients of eq (2),
//   d = k1·L³ − k2·L² + k3·L + k4   (d in mm, L = L_p in m, 0.15 <= L_p <= 0.5),
// as printed, and the two readings of it. Plain data: neither the model
// (plugins/shafts/FlexibleRotor) nor the oracle (validation/oracles/
// BeadMillOracle) owns it; both read it from here and evaluate eq (2)
// themselves.
#include <array>

namespace milldyn::papers {

/// Which reading of Table 1 to use.
enum class BeadMillTableReading {
    /// As printed: the columns D_d = 0.1, 0.17, 0.23, 0.3 m in print order,
    /// k taken from the first block printed under each disc count (5: block
    /// A, 6 and 7: block C, 8: block D).
    Literal,
    /// The reading under which the text's ranges hold: the four distinct
    /// blocks A, B, C, D are k = 5, 6, 7, 8 and the diameter columns run
    /// the other way (first column 0.3 m, last 0.1 m).
    Resolved,
};

/// The printed coefficient k1..k4 (`coefficient` 1..4) of one of the four
/// distinct blocks (`block` 0..3 = A..D) and printed column (0..3).
/// Throws std::invalid_argument outside the table.
double beadMillTableCoefficient(int block, int column, int coefficient);

/// The coefficients {k1, k2, k3, k4} of eq (2) for `discs` in {5, 6, 7, 8}
/// and `discDiameter` [m] in {0.1, 0.17, 0.23, 0.3} (within 1e-9) under a
/// reading. Throws std::invalid_argument for anything outside the table.
std::array<double, 4> beadMillTableRow(int discs, double discDiameter, BeadMillTableReading reading);

/// The span range eq (2) is fitted on [m].
constexpr double kBeadMillTableSpanMin = 0.15;
constexpr double kBeadMillTableSpanMax = 0.5;

}  // namespace milldyn::papers
