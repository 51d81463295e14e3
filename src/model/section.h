#pragma once
// The cask's two-dimensional section in the plane of excitation: a convex polygon with
// rounded corners, its mass properties, and the corners that can touch the floor.
//
// A cylinder (diameter D = 2r, height H = 2h, mass m) becomes a rectangle of half-width b
// with the cylinder's mass, centre of mass and moment of inertia I = m (r^2/4 + h^2/3)
// (about a horizontal diameter through the centre of mass; or the value given). Two rules
// for b, both documented in docs/model.md ("Cask section"):
//   radius    b = r: the rigid cylinder's own pivots, so alpha = atan(r / h) and the
//             rocking of a rigid cylinder in the plane is reproduced (same alpha, I_O, p, e).
//   gyration  the source paper's choice: b = r/2, the radius of gyration of the circular
//             base about its diameter, sqrt(I_base / A_base) with I_base = pi r^4 / 4. Two
//             corner springs at +-b then give the section the rocking stiffness of the real
//             base on its distributed springs, K b^2 = k I_base, and the impacts the soft
//             transfer of a cylinder rolling onto its rim: with the paper's stiffness and
//             damping (5.6 % at 135 Hz) this rule gives a free-rocking restitution near the
//             0.963 it measured, the radius rule about 0.78 (see docs/model.md). Its alpha is
//             atan(r / 2h), so rocking starts earlier than for a rigid cylinder.
// Either way the out-of-plane depth is (base area) / (2 b), so that the distributed
// contact stiffness times the section's base area equals the stiffness of the cylinder's
// circular base.
//
// Distributed footprint (footprint_points = N > 0, b = r): instead of two corners, N contacts
// across the base diameter in the plane of excitation, the outer two the rounded corners at the
// rim, the others on the base between them at equal spacing. Each carries the share of the
// circle's area that its strip of the diameter holds, A_i = integral of the chord 2 sqrt(r^2 -
// x^2) over the strip (the Winkler foundation of the circular base, cut into strips), adjusted
// by a factor (a + c x_i^2) so that the sums are exact: sum A_i = pi r^2 = A and
// sum A_i x_i^2 = pi r^4 / 4 = I_base. The standing cask then has the vertical stiffness k A and
// the rocking stiffness k I_base of its circular base, as the gyration rule's two corners
// have, and a tilted cask pivots on its rim (alpha = atan(r / h)), as the radius rule's do: an
// impact rolls the load from the rim across the base instead of slapping it onto one spring.
// Its contact lengths are A_i / depth, so k times them times the depth is k A_i.
//
// Rounding (Cundall's UDEC): each corner is replaced by a circular arc of radius r_c
// tangent to both edges; the arc centres are the vertices of the polygon offset inward by
// r_c: C = P + r_c (n1 + n2) / (1 + n1.n2), n1, n2 the inward unit normals of the edges
// meeting at P.
//
// Contact corners: a corner carries half of each adjacent edge that faces the floor
// (outward normal pointing down in the body frame); those lengths are the contact lengths
// of UDEC's corner contacts ("an edge lying on an edge is two corner contacts"). Corners
// with no such edge (the top corners) never touch the floor before the cask has tipped over.

#include <optional>
#include <string>
#include <vector>

namespace caskdem {

struct Point {
  double x = 0.0;
  double y = 0.0;
};

enum class HalfWidthRule { gyration, radius };

struct Cylinder {
  double diameter = 0.0;  // m
  double height = 0.0;    // m
  double mass = 0.0;      // kg
  std::optional<double> inertia;  // kg m^2 about a horizontal diameter through the centre of mass
  std::optional<double> axial_inertia;  // kg m^2 about the axis (the 3D cask; m R^2 / 2 when not given)
  HalfWidthRule rule = HalfWidthRule::gyration;
  double eccentricity = 0.0;  // m: horizontal offset of the centre of mass from the axis
  // 0: two corners at +-b (the rule above); N >= 3: a distributed footprint of N contacts
  // across the diameter (needs the radius rule: it pivots on the rim).
  int footprint_points = 0;
};

// A distributed footprint's default number of contacts: odd, so that one sits at the base
// centre (where a convex base's camber acts), and enough that the load rolls across the base.
inline constexpr int kDefaultFootprintPoints = 9;
inline constexpr int kMinFootprintPoints = 3;

struct Section {
  std::vector<Point> outline;  // outer polygon, counter-clockwise, body frame (origin at the base centre)
  double depth = 0.0;          // out-of-plane thickness, m
  double mass = 0.0;           // kg
  double inertia = 0.0;        // kg m^2 about the centre of mass, in the plane
  Point centre_of_mass;        // body frame, m
  double rounding = 0.0;       // corner arc radius, m
  double base_area = 0.0;      // contact area the distributed stiffness acts on, m^2
  int footprint_points = 0;    // 0: the base's corners; N: a distributed circular footprint (above)
};

struct ContactCorner {
  Point arc_centre;          // body frame
  double contact_length = 0.0;  // m
  double rest_gap = 0.0;     // gap to the floor when the undeformed section stands upright, m
};

// The half-width a rule gives for a cylinder (used by cylinder_section, shown by the CLI).
double equivalent_half_width(const Cylinder& cylinder);

// Both throw std::invalid_argument with a message saying what is wrong with the geometry.
Section cylinder_section(const Cylinder& cylinder, double rounding);
Section polygon_section(std::vector<Point> vertices, double depth, double mass, std::optional<double> inertia,
                        std::optional<Point> centre_of_mass, double rounding);

// Arc centres of the rounded corners, in outline order.
std::vector<Point> rounded_corner_centres(const Section& section);
std::vector<ContactCorner> contact_corners(const Section& section);

// Static stability angle: the rotation (positive, counter-clockwise; or negative, clockwise)
// at which the centre of mass passes over the pivot, found on the convex hull of the corner
// arcs (a chamfered base can lower it). Returns its magnitude.
double stability_angle(const Section& section, int direction);

double section_height(const Section& section);
// Area and centroid of a polygon (shoelace), and its polar moment of inertia per unit
// density and depth about the centroid.
double polygon_area(const std::vector<Point>& vertices);
Point polygon_centroid(const std::vector<Point>& vertices);
double polygon_inertia_about_centroid(const std::vector<Point>& vertices);

}  // namespace caskdem
