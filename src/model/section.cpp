#include "model/section.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/text.h"
#include "kernels/model.h"

namespace caskdem {

namespace {

double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
Point minus(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
double length(Point a) { return std::hypot(a.x, a.y); }

// Inward unit normal of the edge a -> b of a counter-clockwise polygon.
Point inward_normal(Point a, Point b) {
  const Point d = minus(b, a);
  const double l = length(d);
  return {-d.y / l, d.x / l};
}

std::string format_point(Point p) { return "(" + number_text(p.x) + ", " + number_text(p.y) + ")"; }

void require_convex_counter_clockwise(const std::vector<Point>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = v[i], b = v[(i + 1) % n], c = v[(i + 2) % n];
    if (length(minus(b, a)) <= 0.0) throw std::invalid_argument("two consecutive vertices coincide at " + format_point(a));
    if (cross(minus(b, a), minus(c, b)) <= 0.0) {
      throw std::invalid_argument("the section must be a convex polygon; the turn at vertex " + format_point(b) +
                                  " is not convex (or three vertices are collinear)");
    }
  }
}

}  // namespace

double polygon_area(const std::vector<Point>& v) {
  double twice = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) twice += cross(v[i], v[(i + 1) % v.size()]);
  return 0.5 * twice;
}

Point polygon_centroid(const std::vector<Point>& v) {
  double twice_area = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Point a = v[i], b = v[(i + 1) % v.size()];
    const double w = cross(a, b);
    twice_area += w;
    cx += (a.x + b.x) * w;
    cy += (a.y + b.y) * w;
  }
  return {cx / (3.0 * twice_area), cy / (3.0 * twice_area)};
}

double polygon_inertia_about_centroid(const std::vector<Point>& v) {
  // Polar second moment about the origin, sum over triangles (0, a, b), then the parallel-axis shift.
  double polar = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Point a = v[i], b = v[(i + 1) % v.size()];
    polar += cross(a, b) * (a.x * a.x + a.x * b.x + b.x * b.x + a.y * a.y + a.y * b.y + b.y * b.y);
  }
  polar /= 12.0;
  const double area = polygon_area(v);
  const Point c = polygon_centroid(v);
  return polar - area * (c.x * c.x + c.y * c.y);
}

double equivalent_half_width(const Cylinder& cylinder) {
  const double r = 0.5 * cylinder.diameter;
  if (cylinder.footprint_points > 0) return r;  // a distributed footprint pivots on the rim
  // Radius of gyration of a disc about its diameter: sqrt((pi r^4 / 4) / (pi r^2)) = r / 2.
  return cylinder.rule == HalfWidthRule::radius ? r : 0.5 * r;
}

Section cylinder_section(const Cylinder& cylinder, double rounding) {
  if (!(cylinder.diameter > 0.0)) throw std::invalid_argument("the diameter must be positive");
  if (!(cylinder.height > 0.0)) throw std::invalid_argument("the height must be positive");
  if (!(cylinder.mass > 0.0)) throw std::invalid_argument("the mass must be positive");
  if (cylinder.inertia && !(*cylinder.inertia > 0.0)) throw std::invalid_argument("the moment of inertia must be positive");
  const double b = equivalent_half_width(cylinder);
  const double r = 0.5 * cylinder.diameter;
  const double h = 0.5 * cylinder.height;
  Section s;
  s.outline = {{-b, 0.0}, {b, 0.0}, {b, cylinder.height}, {-b, cylinder.height}};
  s.mass = cylinder.mass;
  s.centre_of_mass = {cylinder.eccentricity, h};
  s.inertia = cylinder.inertia ? *cylinder.inertia : cylinder.mass * (r * r / 4.0 + h * h / 3.0);
  s.base_area = std::numbers::pi * r * r;
  s.depth = s.base_area / (2.0 * b);
  s.rounding = rounding;
  if (cylinder.footprint_points != 0) {
    if (cylinder.footprint_points < kMinFootprintPoints || cylinder.footprint_points > kMaxCorners) {
      throw std::invalid_argument("a distributed footprint needs " + std::to_string(kMinFootprintPoints) + " to " +
                                  std::to_string(kMaxCorners) + " contact points, not " +
                                  std::to_string(cylinder.footprint_points));
    }
    if (cylinder.rule != HalfWidthRule::radius) {
      throw std::invalid_argument("a distributed footprint pivots on the rim: its half-width is the radius, not the "
                                  "gyration rule's r/2");
    }
    s.footprint_points = cylinder.footprint_points;
  }
  if (std::abs(cylinder.eccentricity) >= b) throw std::invalid_argument("the eccentricity puts the centre of mass outside the base");
  if (!(rounding >= 0.0) || rounding >= 0.5 * std::min(2.0 * b, cylinder.height)) {
    throw std::invalid_argument("the rounding radius must be non-negative and smaller than half the section's width");
  }
  return s;
}

Section polygon_section(std::vector<Point> vertices, double depth, double mass, std::optional<double> inertia,
                        std::optional<Point> centre_of_mass, double rounding) {
  if (vertices.size() < 3) throw std::invalid_argument("a polygon needs at least 3 vertices");
  if (polygon_area(vertices) < 0.0) std::reverse(vertices.begin(), vertices.end());
  require_convex_counter_clockwise(vertices);
  // The lowest vertex sets the floor level y = 0.
  double lowest = vertices[0].y;
  for (const Point& p : vertices) lowest = std::min(lowest, p.y);
  for (Point& p : vertices) p.y -= lowest;
  if (centre_of_mass) centre_of_mass->y -= lowest;
  if (!(depth > 0.0)) throw std::invalid_argument("the depth must be positive");
  if (!(mass > 0.0)) throw std::invalid_argument("the mass must be positive");
  Section s;
  s.outline = vertices;
  s.depth = depth;
  s.mass = mass;
  s.rounding = rounding;
  s.centre_of_mass = centre_of_mass ? *centre_of_mass : polygon_centroid(vertices);
  const double area = polygon_area(vertices);
  s.inertia = inertia ? *inertia : mass / area * polygon_inertia_about_centroid(vertices) +
                                       mass * (std::pow(s.centre_of_mass.x - polygon_centroid(vertices).x, 2) +
                                               std::pow(s.centre_of_mass.y - polygon_centroid(vertices).y, 2));
  if (!(s.inertia > 0.0)) throw std::invalid_argument("the moment of inertia must be positive");
  if (!(rounding >= 0.0)) throw std::invalid_argument("the rounding radius must be non-negative");
  double footprint = 0.0;
  for (const ContactCorner& c : contact_corners(s)) footprint += c.contact_length;
  s.base_area = footprint * depth;
  return s;
}

std::vector<Point> rounded_corner_centres(const Section& section) {
  const std::vector<Point>& v = section.outline;
  const std::size_t n = v.size();
  std::vector<Point> centres(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point previous = v[(i + n - 1) % n], here = v[i], next = v[(i + 1) % n];
    const Point n1 = inward_normal(previous, here);
    const Point n2 = inward_normal(here, next);
    const double denominator = 1.0 + n1.x * n2.x + n1.y * n2.y;
    centres[i] = {here.x + section.rounding * (n1.x + n2.x) / denominator,
                  here.y + section.rounding * (n1.y + n2.y) / denominator};
  }
  // The offset polygon must keep every edge (the rounding must not swallow a side).
  for (std::size_t i = 0; i < n; ++i) {
    const Point original = minus(v[(i + 1) % n], v[i]);
    const Point offset = minus(centres[(i + 1) % n], centres[i]);
    if (original.x * offset.x + original.y * offset.y <= 0.0) {
      throw std::invalid_argument("the rounding radius " + number_text(section.rounding) +
                                  " m is too large for the edge from " + format_point(v[i]) + " to " +
                                  format_point(v[(i + 1) % n]));
    }
  }
  return centres;
}

namespace {

// The distributed footprint's contacts (section.h): the base's two rounded corners and N - 2
// points between their arc centres, each weighted by its strip of the circle of radius b.
std::vector<ContactCorner> distributed_footprint(const Section& section, const ContactCorner& left,
                                                 const ContactCorner& right) {
  const int n = section.footprint_points;
  const double b = 0.5 * (section.outline[1].x - section.outline[0].x);
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = left.arc_centre.x + (right.arc_centre.x - left.arc_centre.x) * i / (n - 1);
  // Area of the circle between -b and u: the integral of its chord, 2 sqrt(b^2 - x^2).
  const auto area_to = [b](double u) {
    const double v = std::clamp(u / b, -1.0, 1.0);
    return b * b * (v * std::sqrt(1.0 - v * v) + std::asin(v));
  };
  std::vector<double> weight(n);
  double s0 = 0.0, s2 = 0.0, s4 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double from = i == 0 ? -b : 0.5 * (x[i - 1] + x[i]);
    const double to = i == n - 1 ? b : 0.5 * (x[i] + x[i + 1]);
    weight[i] = area_to(to) - area_to(from);
    s0 += weight[i];
    s2 += weight[i] * x[i] * x[i];
    s4 += weight[i] * x[i] * x[i] * x[i] * x[i];
  }
  // (a + c x^2) makes both moments exact: a s0 + c s2 = A, a s2 + c s4 = I_base.
  const double area = std::numbers::pi * b * b, second_moment = 0.25 * std::numbers::pi * b * b * b * b;
  const double determinant = s0 * s4 - s2 * s2;
  const double a = (area * s4 - second_moment * s2) / determinant;
  const double c = (s0 * second_moment - s2 * area) / determinant;
  std::vector<ContactCorner> points;
  for (int i = 0; i < n; ++i) {
    const double w = weight[i] * (a + c * x[i] * x[i]);
    if (!(w > 0.0)) throw std::invalid_argument("the distributed footprint's points cannot carry the base's moments");
    points.push_back({{x[i], left.arc_centre.y}, w / section.depth, left.rest_gap});
  }
  return points;
}

}  // namespace

std::vector<ContactCorner> contact_corners(const Section& section) {
  const std::vector<Point>& v = section.outline;
  const std::size_t n = v.size();
  const std::vector<Point> centres = rounded_corner_centres(section);
  // Half of each floor-facing edge (outward normal pointing down) goes to each of its ends.
  std::vector<double> share(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = v[i], b = v[(i + 1) % n];
    const Point outward = {-inward_normal(a, b).x, -inward_normal(a, b).y};
    if (outward.y < -1e-12) {
      const double half = 0.5 * length(minus(b, a));
      share[i] += half;
      share[(i + 1) % n] += half;
    }
  }
  std::vector<ContactCorner> corners;
  for (std::size_t i = 0; i < n; ++i) {
    if (share[i] <= 0.0) continue;
    corners.push_back({centres[i], share[i], centres[i].y - section.rounding});
  }
  if (corners.empty()) throw std::invalid_argument("the section has no edge facing the floor");
  if (section.footprint_points > 0) {
    if (corners.size() != 2) throw std::invalid_argument("a distributed footprint needs a flat base with two corners");
    return distributed_footprint(section, corners[0], corners[1]);
  }
  return corners;
}

double stability_angle(const Section& section, int direction) {
  // The height of the centre of mass above the floor at rotation theta is the support
  // function max_i [R(theta)(G - C_i)]_y + r_c over the arc centres C_i. Each term peaks
  // where G is straight above C_i, at theta_i = atan2(G_x - C_i.x, G_y - C_i.y); the
  // first such peak (in the given direction) where C_i is the lowest point is where the
  // cask passes from stable to unstable.
  const std::vector<Point> centres = rounded_corner_centres(section);
  const Point g = section.centre_of_mass;
  auto height_of = [&](double theta, const Point& c) {
    return std::sin(theta) * (g.x - c.x) + std::cos(theta) * (g.y - c.y);
  };
  double best = std::numeric_limits<double>::infinity();
  for (const Point& c : centres) {
    const double theta = std::atan2(g.x - c.x, g.y - c.y);
    if (theta * direction <= 0.0) continue;
    const double here = height_of(theta, c);
    bool lowest = true;
    for (const Point& other : centres) {
      if (height_of(theta, other) > here + 1e-12 * (1.0 + std::abs(here))) lowest = false;
    }
    if (lowest) best = std::min(best, std::abs(theta));
  }
  if (!std::isfinite(best)) {
    throw std::invalid_argument("the centre of mass is not above the base: the section cannot stand");
  }
  return best;
}

double section_height(const Section& section) {
  double top = 0.0;
  for (const Point& p : section.outline) top = std::max(top, p.y);
  return top;
}

}  // namespace caskdem
