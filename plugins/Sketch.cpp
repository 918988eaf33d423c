#include "plugins/Sketch.h"

namespace milldyn {

void Sketch::circle(const std::string& role, double x, double y, double radius, const std::string& label) {
    Shape s;
    s.kind = Kind::Circle;
    s.role = role;
    s.label = label;
    s.x = x;
    s.y = y;
    s.radius = radius;
    m_shapes.push_back(s);
}

void Sketch::segment(const std::string& role, double x, double y, double radius, double direction, double halfAngle,
                     const std::string& label) {
    Shape s;
    s.kind = Kind::Segment;
    s.role = role;
    s.label = label;
    s.x = x;
    s.y = y;
    s.radius = radius;
    s.direction = direction;
    s.halfAngle = halfAngle;
    m_shapes.push_back(s);
}

void Sketch::line(const std::string& role, double x1, double y1, double x2, double y2, const std::string& label) {
    Shape s;
    s.kind = Kind::Line;
    s.role = role;
    s.label = label;
    s.x = x1;
    s.y = y1;
    s.x2 = x2;
    s.y2 = y2;
    m_shapes.push_back(s);
}

void Sketch::arrow(const std::string& role, double x, double y, double fx, double fy, const std::string& label) {
    Shape s;
    s.kind = Kind::Arrow;
    s.role = role;
    s.label = label;
    s.x = x;
    s.y = y;
    s.x2 = fx;
    s.y2 = fy;
    m_shapes.push_back(s);
}

}  // namespace milldyn
