#pragma once
// Drawing primitives an element contributes to the 2-D schematic of its
// machine (`milldyn run MODEL --schematic`, driver/outputs/Schematic.h).
// Every element draws itself from a state (Scene::addSketch); the writer
// knows no element. Coordinates are metres in the ground frame (x, y of the
// plane z = 0, y up); forces are newtons in ground axes.

#include <string>
#include <vector>

namespace milldyn {

class Sketch {
public:
    enum class Kind { Circle, Segment, Line, Arrow };
    struct Shape {
        Kind kind = Kind::Circle;
        /// What it is, one word, shown in the legend and used as the SVG
        /// class: carrier, drum, gear, fixed_gear, sheave, charge, belt, reaction.
        std::string role;
        std::string label;   ///< shown next to it (may be empty)
        double x = 0, y = 0;     ///< centre [m] (Circle, Segment) or start [m] (Line, Arrow)
        double x2 = 0, y2 = 0;   ///< end [m] (Line); force [N] (Arrow)
        double radius = 0;       ///< [m] (Circle, Segment)
        double direction = 0;    ///< Segment: direction of centre → centroid from +x [rad]
        double halfAngle = 0;    ///< Segment: half the central angle γ [rad]
    };

    /// A circle of `radius` [m] about (x, y) [m].
    void circle(const std::string& role, double x, double y, double radius, const std::string& label = "");
    /// A circular segment of a circle of `radius` [m] about (x, y) [m]:
    /// central angle 2γ = 2 `halfAngle` [rad], its centroid on the ray at
    /// `direction` [rad] from +x (a charge at its lag).
    void segment(const std::string& role, double x, double y, double radius, double direction, double halfAngle,
                 const std::string& label = "");
    /// A straight line from (x1, y1) to (x2, y2) [m].
    void line(const std::string& role, double x1, double y1, double x2, double y2, const std::string& label = "");
    /// A force (fx, fy) [N] acting at (x, y) [m]; the writer scales every
    /// arrow of a schematic by one factor, so lengths compare.
    void arrow(const std::string& role, double x, double y, double fx, double fy, const std::string& label = "");

    const std::vector<Shape>& shapes() const { return m_shapes; }

private:
    std::vector<Shape> m_shapes;
};

}  // namespace milldyn
