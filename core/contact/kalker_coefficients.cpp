#include "contact/kalker_coefficients.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Kalker, J.J., Three-dimensional elastic bodies in rolling contact, 1990,
// Table E.3 (also tests/data/kalker_cij.csv). Rows g = 0.1 .. 1.0;
// per row and coefficient the values for nu = 0, 0.25, 0.5.
// Index: [case][row][coefficient C11, C22, C23, C33][nu].
// case 0: a <= b, g = a/b;  case 1: a > b, g = b/a.
constexpr double kTable[2][10][4][3] = {
    {
        {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}},
        {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}},
        {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}},
        {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}},
        {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}},
        {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}},
        {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}},
        {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}},
        {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}},
        {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}},
    },
    {
        {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.795, 0.526, 0.228}},
        {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.828, 0.601, 0.341}},
        {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.868, 0.674, 0.446}},
        {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.912, 0.747, 0.549}},
        {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.958, 0.819, 0.650}},
        {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.892, 0.751}},
        {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.965, 0.852}},
        {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.954}},
        {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}},
        {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}},
    },
};

// One coefficient at a table point g (0.1 .. 1), any nu: linear in g between
// rows; the three nu columns are joined by the parabola through 1/C, which is
// how CONTACT (Vollebregt & Kalker, m_hertz.f90) interpolates Table E.3.
double table_value(int table_case, int coefficient, double g, double nu)
{
    const double t = 10.0 * g - 1.0;  // 0 at g = 0.1, 9 at g = 1
    const int row = std::clamp(static_cast<int>(std::floor(t)), 0, 8);
    const double w = t - row;
    double inverse = 0.0;
    const double lagrange[3] = {
        8.0 * (nu - 0.25) * (nu - 0.5),
        -16.0 * nu * (nu - 0.5),
        8.0 * nu * (nu - 0.25),
    };
    for (int k = 0; k < 3; ++k) {
        const double c = (1.0 - w) * kTable[table_case][row][coefficient][k] +
                         w * kTable[table_case][row + 1][coefficient][k];
        inverse += lagrange[k] / c;
    }
    return 1.0 / inverse;
}

// Kalker 1990, Table E.3, asymptotes for a/b -> 0 (g = a/b).
CreepCoefficients thin_across(double g, double nu)
{
    CreepCoefficients c{};
    c.C11 = kPi * kPi / (4.0 * (1.0 - nu));
    c.C22 = kPi * kPi / 4.0;
    c.C23 = kPi * std::sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (std::log(16.0 / g) - 5.0));
    // C33: no published asymptote could be confirmed here. C33 grows like 1/g
    // as a/b -> 0 (table rows 0.1, 0.2 and the form pi^2/(16 (1-nu) g)), so
    // the g = 0.1 row is continued with that 1/g law. FASTSIM does not use
    // C33; the calibrated model's moment flexibility does.
    c.C33 = table_value(0, 3, 0.1, nu) * (0.1 / g);
    return c;
}

// Kalker 1990, Table E.3, asymptotes for b/a -> 0 (g = b/a).
CreepCoefficients thin_along(double g, double nu)
{
    const double lam = std::log(16.0 / (g * g));
    const double ln4 = std::log(4.0);
    CreepCoefficients c{};
    c.C11 = 2.0 * kPi / ((lam - 2.0 * nu) * g) * (1.0 + (3.0 - ln4) / (lam - 2.0 * nu));
    const double d = (1.0 - nu) * lam + 2.0 * nu;
    c.C22 = 2.0 * kPi / g * (1.0 + (1.0 - nu) * (3.0 - ln4) / d) / d;
    c.C23 = 2.0 * kPi / (3.0 * std::pow(g, 1.5) * ((1.0 - nu) * lam - 2.0 + 4.0 * nu));
    // C33: no published asymptote confirmed; the table varies slowly here
    // (0.828 -> 0.795 for nu = 0 from g = 0.2 to 0.1), so hold the g = 0.1 row.
    c.C33 = table_value(1, 3, 0.1, nu);
    return c;
}

CreepCoefficients coefficients_of(double a_over_b, double nu)
{
    const int table_case = a_over_b <= 1.0 ? 0 : 1;
    const double g = table_case == 0 ? a_over_b : 1.0 / a_over_b;
    if (g < 0.1) return table_case == 0 ? thin_across(g, nu) : thin_along(g, nu);
    return {table_value(table_case, 0, g, nu), table_value(table_case, 1, g, nu),
            table_value(table_case, 2, g, nu), table_value(table_case, 3, g, nu)};
}

} // namespace

CreepCoefficients kalker_coefficients(double a_over_b, double nu)
{
    // The last answer of this thread, returned as computed (bitwise): the
    // calibrated Jacobian asks for one contact's coefficients in each of its
    // differenced setups (they were 22 % of its time on 20 x 20).
    thread_local double last_a_over_b = std::nan(""), last_nu = std::nan("");
    thread_local CreepCoefficients last{};
    if (a_over_b == last_a_over_b && nu == last_nu) return last;
    last = coefficients_of(a_over_b, nu);
    last_a_over_b = a_over_b;
    last_nu = nu;
    return last;
}

Flexibilities kalker_flexibilities(double a, double b, double G, const CreepCoefficients& c)
{
    return {8.0 * a / (3.0 * c.C11 * G), 8.0 * a / (3.0 * c.C22 * G),
            kPi * a * std::sqrt(a / b) / (4.0 * c.C23 * G)};
}

} // namespace creepwork
