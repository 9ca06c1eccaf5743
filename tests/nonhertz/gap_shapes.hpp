// The non-Hertzian validation shapes of tests/nonhertz: gaps made by formula
// on a regular grid, with the load, material and creepages of each case.
// tools/contact_reference/make_contact_reference.cpp gave exactly these inputs to CONTACT
// (data/README.md) and the tests rebuild them here, so the data files hold
// only CONTACT's results. None of these shapes was used to choose anything
// in the model (the DEV shapes of tests/data/nonhertz were the ones
// looked at while it was written).
//
// SI units; x along the rolling direction, positive gap = separation.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace gapshapes {

struct Shape {
    std::string id, description;
    int nx = 0, ny = 0;
    double x0 = 0, y0 = 0, dx = 0, dy = 0; // centre of cell (0, 0), spacing [m]
    std::vector<double> h;                  // [i + nx j]
    bool approach_given = false;
    double normal_force = 0, approach = 0;  // [N], [m]
    double G = 82e9, nu = 0.28, mu = 0.3;
    // Creepages as level * xi_sat * (cos theta, sin theta), spin
    // spin_frac * xi_sat / c, with xi_sat = 3 mu N / (4.2 G c^2) and c the
    // radius of a circle of the contact's area (as the DEV cases; the
    // generator fills xi_x, xi_y, phi from CONTACT's area without creepage).
    double level = 0.5, theta_deg = 0, spin_frac = 0;
    double xi_x = 0, xi_y = 0, phi = 0;
    int rolling_direction = 1;
};

constexpr double kPi = 3.14159265358979323846;
constexpr double mm = 1e-3, um = 1e-6;

// A grid of nx x ny cells of dx x dy centred on (xc, yc), gap h(x, y).
template <class F>
Shape make(const std::string& id, const std::string& description, int nx, int ny, double dx,
           double dy, double xc, double yc, F&& h)
{
    Shape s;
    s.id = id;
    s.description = description;
    s.nx = nx;
    s.ny = ny;
    s.dx = dx;
    s.dy = dy;
    s.x0 = xc - 0.5 * (nx - 1) * dx;
    s.y0 = yc - 0.5 * (ny - 1) * dy;
    s.h.resize(static_cast<size_t>(nx) * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) s.h[i + static_cast<size_t>(nx) * j] = h(s.x0 + i * dx, s.y0 + j * dy);
    return s;
}

inline double paraboloid(double x, double y, double Rx, double Ry)
{
    return x * x / (2 * Rx) + y * y / (2 * Ry);
}

inline std::vector<Shape> shapes()
{
    std::vector<Shape> v;
    {
        // Hollow-worn tread: two lateral minima 5 mm either side, 8 um neck,
        // tilted so that one side is 1 um lower.
        Shape s = make("N01_hollow", "x^2/(2 R) + k (y^2 - w^2)^2 + s y, w = 5 mm, neck 8 um, tilt 1 um",
                       36, 56, 0.32 * mm, 0.36 * mm, 0, 0, [](double x, double y) {
                           const double w = 5 * mm, k = 8 * um / std::pow(w, 4);
                           return x * x / (2 * 0.46) + k * std::pow(y * y - w * w, 2) +
                                  (1 * um / w) * y;
                       });
        s.normal_force = 60e3;
        s.G = 80e9, s.nu = 0.3, s.mu = 0.25;
        s.level = 0.6, s.theta_deg = 20, s.spin_frac = 0.1;
        v.push_back(s);
    }
    {
        // Cubic along x: flatter behind (the curvature 2A + 6Cx stays > 0).
        Shape s = make("N02_cubic_x", "A x^2 (1 + x / 30 mm) + B y^2: curvature along x rising towards the front",
                       54, 44, 0.3 * mm, 0.3 * mm, 0, 0, [](double x, double y) {
                           const double A = 1 / (2 * 0.25), C = A / (30 * mm), B = 1 / (2 * 0.25);
                           return A * x * x + C * x * x * x + B * y * y;
                       });
        s.normal_force = 50e3;
        s.level = 0.3, s.theta_deg = -60, s.spin_frac = 0.3;
        v.push_back(s);
    }
    {
        // Three unequal lobes: three or fewer patches.
        Shape s = make("N03_three_lobes", "min of three paraboloids at (0,-9), (2,0), (-1,8) mm, 0, 5, 2 um high",
                       60, 76, 0.3 * mm, 0.4 * mm, 0, 0, [](double x, double y) {
                           const double a = paraboloid(x, y + 9 * mm, 0.4, 0.08);
                           const double b = paraboloid(x - 2 * mm, y, 0.5, 0.15) + 5 * um;
                           const double c = paraboloid(x + 1 * mm, y - 8 * mm, 0.3, 0.06) + 2 * um;
                           return std::min(a, std::min(b, c));
                       });
        s.normal_force = 70e3;
        s.G = 79.3e9, s.nu = 0.25, s.mu = 0.35;
        s.level = 0.8, s.theta_deg = 135, s.spin_frac = -0.2;
        v.push_back(s);
    }
    {
        // A crescent: the valley of the gap bends along y.
        Shape s = make("N04_crescent", "A (x - k y^2)^2 + B y^2, k = 60 1/m: a banana-shaped patch, with spin",
                       60, 60, 0.28 * mm, 0.3 * mm, 1.5 * mm, 0, [](double x, double y) {
                           const double k = 60.0, u = x - k * y * y;
                           return u * u / (2 * 0.45) + y * y / (2 * 0.9);
                       });
        s.normal_force = 40e3;
        s.level = 0.4, s.theta_deg = 10, s.spin_frac = 0.6;
        v.push_back(s);
    }
    {
        // A bump in the middle of a Hertzian gap: a ring of contact.
        Shape s = make("N05_ring", "x^2/(2 Rx) + y^2/(2 Ry) + 40 um exp(-r^2/(2.5 mm)^2): contact around a hole",
                       44, 44, 0.4 * mm, 0.4 * mm, 0, 0, [](double x, double y) {
                           const double r2 = x * x + y * y, s2 = 2.5 * mm * 2.5 * mm;
                           return paraboloid(x, y, 0.35, 0.3) + 40 * um * std::exp(-r2 / s2);
                       });
        s.normal_force = 90e3;
        s.mu = 0.3;
        s.level = 0.5, s.theta_deg = 80, s.spin_frac = 0;
        v.push_back(s);
    }
    {
        // Two-point contact: tread lobe and a flange-root lobe of small
        // lateral radius 14 mm away, 3 um higher.
        Shape s = make("N06_flange_root", "tread (Ry 300 mm) and flange root (Ry 12 mm) 14 mm apart, root 3 um higher",
                       40, 84, 0.3 * mm, 0.35 * mm, 0, 5 * mm, [](double x, double y) {
                           const double tread = paraboloid(x, y, 0.46, 0.3);
                           const double root = paraboloid(x, y - 14 * mm, 0.42, 0.012) + 3 * um;
                           return std::min(tread, root);
                       });
        s.normal_force = 45e3;
        s.mu = 0.4;
        s.level = 1.5, s.theta_deg = 100, s.spin_frac = 0.05;
        v.push_back(s);
    }
    {
        // A wide, flat-topped patch of about 1,200 elements (the benchmark
        // shape): cubic lateral shape, fine grid.
        Shape s = make("N07_wide", "x^2/(2 0.46 m) + c |y|^3 + 2 um sin(y / 3 mm): wide patch, about 1,200 elements",
                       50, 60, 0.22 * mm, 0.26 * mm, 0, 0, [](double x, double y) {
                           const double c = 40 * um / std::pow(7 * mm, 3);
                           return x * x / (2 * 0.46) + c * std::pow(std::fabs(y), 3) +
                                  2 * um * std::sin(y / (3 * mm));
                       });
        s.normal_force = 30e3;
        s.level = 0.5, s.theta_deg = 30, s.spin_frac = 0.15;
        v.push_back(s);
    }
    {
        // The approach prescribed (from a datum 5 um below the lowest point).
        Shape s = make("N08_approach", "A x^2 + C y^4 - 5 um, approach 45 um prescribed",
                       40, 40, 0.35 * mm, 0.3 * mm, 0.5 * mm, -0.5 * mm, [](double x, double y) {
                           const double C = 30 * um / std::pow(5 * mm, 4);
                           const double u = x - 0.5 * mm, w = y + 0.5 * mm;
                           return u * u / (2 * 0.5) + C * std::pow(w, 4) - 5 * um;
                       });
        s.approach_given = true;
        s.approach = 45 * um;
        s.G = 81e9, s.nu = 0.29, s.mu = 0.3;
        s.level = 0.7, s.theta_deg = -150, s.spin_frac = 0;
        v.push_back(s);
    }
    {
        // A rotated ellipse rolled towards -x.
        Shape s = make("N09_rolling_back", "ellipse rotated by 35 deg, rolling towards -x",
                       40, 40, 0.35 * mm, 0.35 * mm, 0, 0, [](double x, double y) {
                           const double c = std::cos(35 * kPi / 180), sn = std::sin(35 * kPi / 180);
                           const double u = c * x + sn * y, w = -sn * x + c * y;
                           return paraboloid(u, w, 0.6, 0.2);
                       });
        s.normal_force = 35e3;
        s.rolling_direction = -1;
        s.level = 0.5, s.theta_deg = 45, s.spin_frac = 0.25;
        v.push_back(s);
    }
    {
        // A Hertzian gap on cells twice as wide as long.
        Shape s = make("N10_tall_cells", "paraboloid on cells dy = 2 dx", 56, 30, 0.25 * mm, 0.5 * mm,
                       0, 0, [](double x, double y) { return paraboloid(x, y, 0.2, 0.6); });
        s.normal_force = 30e3;
        s.mu = 0.2;
        s.level = 0.9, s.theta_deg = 0, s.spin_frac = 0.4;
        v.push_back(s);
    }
    {
        // Lateral ripple: stripes of contact.
        Shape s = make("N11_ripple_y", "paraboloid + 6 um cos(2 pi y / 4 mm): lateral ripple",
                       56, 84, 0.3 * mm, 0.3 * mm, 0, 0, [](double x, double y) {
                           return paraboloid(x, y, 0.5, 0.4) + 6 * um * std::cos(2 * kPi * y / (4 * mm));
                       });
        s.normal_force = 65e3;
        s.G = 82e9, s.nu = 0.28, s.mu = 0.3;
        s.level = 0.3, s.theta_deg = 70, s.spin_frac = -0.3;
        v.push_back(s);
    }
    return v;
}

} // namespace gapshapes
