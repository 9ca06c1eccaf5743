#include "calibrated/moment_flexibility.hpp"

namespace creepwork {

double moment_consistent_flexibility(double b, double G, double C33)
{
    return 8.0 * b / (15.0 * G * C33);
}

} // namespace creepwork
