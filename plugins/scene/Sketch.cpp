#include "plugins/scene/Sketch.h"

namespace milldyn {

namespace {
/// A shape of `kind` at (x, y) [m] with the rest left zero for the caller.
Sketch::Shape start(Sketch::Kind kind, const std::string& role, const std::string& label, double x, double y) {
    Sketch::Shape s;
    s.kind = kind;
    s.role = role;
    s.label = label;
    s.x = x;
    s.y = y;
    return s;
}
}  // namespace

void Sketch::circle(const std::string& role, double x, double y, double radius, const std::string& label) {
    Shape s = start(Kind::Circle, role, label, x, y);
    s.radius = radius;
    m_shapes.push_back(s);
}

void Sketch::segment(const std::string& role, double x, double y, double radius, double direction, double halfAngle,
                     const std::string& label) {
    Shape s = start(Kind::Segment, role, label, x, y);
    s.radius = radius;
    s.direction = direction;
    s.halfAngle = halfAngle;
    m_shapes.push_back(s);
}

void Sketch::line(const std::string& role, double x1, double y1, double x2, double y2, const std::string& label) {
    Shape s = start(Kind::Line, role, label, x1, y1);
    s.x2 = x2;
    s.y2 = y2;
    m_shapes.push_back(s);
}

void Sketch::arrow(const std::string& role, double x, double y, double fx, double fy, const std::string& label) {
    Shape s = start(Kind::Arrow, role, label, x, y);
    s.x2 = fx;
    s.y2 = fy;
    m_shapes.push_back(s);
}

}  // namespace milldyn
