#include "papers/BeadMillTable1.h"

#include <cmath>
#include <stdexcept>

namespace milldyn::papers {

namespace {

// Table 1 as printed: the four distinct blocks A..D (print order A, B, C, D,
// C, D, D under k = 5, 5, 6, 6, 7, 7, 8), rows k1..k4, columns in print order
// (headed 0.1, 0.17, 0.23, 0.3 m).
const double kTable[4][4][4] = {
    {{202.99, 197.11, 188.4, 181.78}, {238.21, 231.37, 221.16, 213.27},
     {99.92, 96.906, 92.539, 89.24}, {13.155, 11.313, 9.5482, 7.4404}},
    {{205.16, 199.96, 192.5, 190.1}, {240.58, 234.54, 225.81, 222.83},
     {101.25, 98.573, 94.818, 93.601}, {16.649, 14.419, 12.262, 9.6745}},
    {{207.15, 202.62, 196.57, 199.11}, {242.72, 237.48, 230.39, 233.17},
     {102.44, 100.1, 97.033, 98.265}, {20.17, 17.557, 15.015, 11.97}},
    {{209.08, 205.25, 200.75, 208.99}, {244.78, 240.38, 235.11, 244.5},
     {103.55, 101.56, 99.273, 103.33}, {23.715, 20.724, 17.807, 14.334}},
};
const double kTableDiameters[4] = {0.1, 0.17, 0.23, 0.3};  // column headings [m]

void require(bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(what);
}

}  // namespace

double beadMillTableCoefficient(int block, int column, int coefficient) {
    require(block >= 0 && block < 4 && column >= 0 && column < 4 && coefficient >= 1 && coefficient <= 4,
            "table index out of range");
    return kTable[block][coefficient - 1][column];
}

std::array<double, 4> beadMillTableRow(int discs, double discDiameter, BeadMillTableReading reading) {
    require(discs >= 5 && discs <= 8, "discs must be 5, 6, 7 or 8 (Table 1)");
    int dIndex = -1;
    for (int i = 0; i < 4; ++i)
        if (std::abs(discDiameter - kTableDiameters[i]) < 1e-9) dIndex = i;
    require(dIndex >= 0, "disc diameter must be one of 0.1, 0.17, 0.23, 0.3 m (Table 1)");
    int block, column;
    if (reading == BeadMillTableReading::Resolved) {
        block = discs - 5;
        column = 3 - dIndex;
    } else {
        static const int firstBlockUnder[4] = {0, 2, 2, 3};  // k = 5, 6, 7, 8 as printed
        block = firstBlockUnder[discs - 5];
        column = dIndex;
    }
    return {kTable[block][0][column], kTable[block][1][column], kTable[block][2][column], kTable[block][3][column]};
}

}  // namespace milldyn::papers
