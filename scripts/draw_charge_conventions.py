#!/usr/bin/env python3
"""Draws docs/images/charge_lag_conventions.svg: the two lag conventions of
SegmentCharge (lag_from: vertical and lag_from: carrier_radius).
Standard library only; run from anywhere:
    python3 scripts/draw_charge_conventions.py
"""
import math
import os

W, H = 760, 380
out = []


def P(cx, cy, x, y, s):
    """Math coordinates (y up) around (cx, cy) at scale s -> SVG (y down)."""
    return cx + s * x, cy - s * y


def line(a, b, style="stroke:#000;stroke-width:1.5", marker=False):
    m = ' marker-end="url(#arrow)"' if marker else ""
    out.append(f'<line x1="{a[0]:.1f}" y1="{a[1]:.1f}" x2="{b[0]:.1f}" y2="{b[1]:.1f}" style="{style}"{m}/>')


def text(p, s, size=13, anchor="start", style=""):
    out.append(f'<text x="{p[0]:.1f}" y="{p[1]:.1f}" font-family="sans-serif" font-size="{size}" '
               f'text-anchor="{anchor}" style="{style}">{s}</text>')


def segment(cx, cy, s, r, d, g):
    """Circular segment of half-angle g centred on direction d (radians)."""
    a = P(cx, cy, r * math.cos(d - g), r * math.sin(d - g), s)
    b = P(cx, cy, r * math.cos(d + g), r * math.sin(d + g), s)
    large = 1 if 2 * g > math.pi else 0
    out.append(f'<path d="M {a[0]:.1f} {a[1]:.1f} A {s*r:.1f} {s*r:.1f} 0 {large} 0 {b[0]:.1f} {b[1]:.1f} Z" '
               'style="fill:#d9b36c;stroke:#8a6d2f;stroke-width:1"/>')


def arc(cx, cy, s, r, a0, a1, marker=False, style="fill:none;stroke:#c0392b;stroke-width:1.5"):
    p0 = P(cx, cy, r * math.cos(a0), r * math.sin(a0), s)
    p1 = P(cx, cy, r * math.cos(a1), r * math.sin(a1), s)
    sweep = 0 if a1 > a0 else 1  # SVG y is down: counter-clockwise in math is sweep 0
    large = 1 if abs(a1 - a0) > math.pi else 0
    m = ' marker-end="url(#arrow)"' if marker else ""
    out.append(f'<path d="M {p0[0]:.1f} {p0[1]:.1f} A {s*r:.1f} {s*r:.1f} 0 {large} {sweep} {p1[0]:.1f} {p1[1]:.1f}" '
               f'style="{style}"{m}/>')


def centroid_distance(r, g):
    return 4 * r * math.sin(g) ** 3 / (3 * (2 * g - math.sin(2 * g)))


out.append(f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}">')
out.append('<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" '
           'orient="auto-start-reverse"><path d="M 0 0 L 10 5 L 0 10 z"/></marker></defs>')
out.append(f'<rect width="{W}" height="{H}" fill="white"/>')

# ---- left: lag_from: vertical (tumbling mill, drum axis fixed) ----
cx, cy, s, r = 190, 200, 110, 1.0
alpha, gamma = math.radians(40), math.radians(72)
down = -math.pi / 2
d = down + alpha
text((190, 28), "lag_from: vertical", 15, "middle", "font-weight:bold")
text((190, 46), "(tumbling mill: axis fixed, anywhere)", 12, "middle")
out.append(f'<circle cx="{cx}" cy="{cy}" r="{s*r}" style="fill:none;stroke:#000;stroke-width:2"/>')
segment(cx, cy, s, r, d, gamma)
line(P(cx, cy, 0, 0, s), P(cx, cy, 0, -1.25, s), "stroke:#555;stroke-width:1;stroke-dasharray:5,4")
text(P(cx, cy, 0.04, -1.22, s), "downward vertical (gravity)", 11)
lc = centroid_distance(r, gamma)
c = P(cx, cy, lc * math.cos(d), lc * math.sin(d), s)
line(P(cx, cy, 0, 0, s), c, "stroke:#000;stroke-width:1.5")
out.append(f'<circle cx="{c[0]:.1f}" cy="{c[1]:.1f}" r="4" fill="#000"/>')
text((c[0] + 6, c[1] - 4), "c", 13)
arc(cx, cy, s, 0.35, down, d)
text(P(cx, cy, 0.2, -0.5, s), "α", 15, "start", "fill:#c0392b")
line(c, (c[0], c[1] + 45), "stroke:#1f5fa8;stroke-width:2", True)
text((c[0] + 5, c[1] + 45), "m g", 12, "start", "fill:#1f5fa8")
line(P(cx, cy, 0, -0.02, s), (c[0], P(cx, cy, 0, -0.02, s)[1]), "stroke:#1f5fa8;stroke-width:1;stroke-dasharray:3,3")
text(P(cx, cy, 0.05, 0.06, s), "r_c sin α", 11, "start", "fill:#1f5fa8")
arc(cx, cy, s, 1.12, math.radians(-20), math.radians(40), True, "fill:none;stroke:#000;stroke-width:1.5")
text(P(cx, cy, 1.1, 0.55, s), "ω &gt; 0 (+z)", 12)
out.append(f'<circle cx="{cx}" cy="{cy}" r="3" fill="#000"/>')
text((cx - 8, cy - 6), "B", 12, "end")
text((190, 350), "α from the downward vertical, + in the +z sense", 12, "middle")
text((190, 366), "(the sense of a positive drum speed)", 12, "middle")

# ---- right: lag_from: carrier_radius (planetary, seed 000 eq 22) ----
ax, ay, s2 = 440, 290, 95
text((585, 28), "lag_from: carrier_radius", 15, "middle", "font-weight:bold")
text((585, 46), "(planetary: drum axis B carried round A; seed 000 eq 22)", 12, "middle")
out.append(f'<circle cx="{ax}" cy="{ay}" r="4" fill="#000"/>')
text((ax - 8, ay + 16), "A", 12, "end")
th = math.radians(35)
R = 1.75
bx, by = R * math.cos(th), R * math.sin(th)
B = P(ax, ay, bx, by, s2)
line(P(ax, ay, 0, 0, s2), B, "stroke:#555;stroke-width:1.2;stroke-dasharray:6,3")
rd = 0.75
out.append(f'<circle cx="{B[0]:.1f}" cy="{B[1]:.1f}" r="{s2*rd:.1f}" style="fill:none;stroke:#000;stroke-width:2"/>')
eout = th
et = th + math.pi / 2
alpha2 = math.radians(60)
u = math.atan2(math.cos(alpha2) * math.sin(et) + math.sin(alpha2) * math.sin(eout),
               math.cos(alpha2) * math.cos(et) + math.sin(alpha2) * math.cos(eout))
segment(B[0], B[1], s2, rd, u, math.radians(80))
line(B, P(B[0], B[1], 1.05 * math.cos(eout), 1.05 * math.sin(eout), s2), "stroke:#1f5fa8;stroke-width:1.8", True)
text(P(B[0], B[1], 1.1 * math.cos(eout), 1.1 * math.sin(eout), s2), "e_out", 12, "start", "fill:#1f5fa8")
line(B, P(B[0], B[1], 1.05 * math.cos(et), 1.05 * math.sin(et), s2), "stroke:#1f5fa8;stroke-width:1.8", True)
text(P(B[0], B[1], 1.1 * math.cos(et), 1.1 * math.sin(et), s2), "e_t = z × e_out", 12, "end", "fill:#1f5fa8")
lc2 = centroid_distance(rd, math.radians(80))
c2 = P(B[0], B[1], lc2 * math.cos(u), lc2 * math.sin(u), s2)
line(B, c2)
out.append(f'<circle cx="{c2[0]:.1f}" cy="{c2[1]:.1f}" r="4" fill="#000"/>')
text((c2[0] + 6, c2[1] - 2), "c", 13)
arc(B[0], B[1], s2, 0.3, et, u)
text(P(B[0], B[1], 0.28 * math.cos((et + u) / 2) + 0.02, 0.36 * math.sin((et + u) / 2) + 0.05, s2), "α", 15,
     "start", "fill:#c0392b")
text((585, 350), "u = sin α e_out + cos α e_t: α from the tangent", 12, "middle")
text((585, 366), "toward the outward radius A→B", 12, "middle")
out.append("</svg>")

path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "images", "charge_lag_conventions.svg")
with open(path, "w") as f:
    f.write("\n".join(out) + "\n")
print("wrote", os.path.normpath(path))
