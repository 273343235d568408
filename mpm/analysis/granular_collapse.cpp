#include "mpm/analysis/granular_collapse.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pilempm::mpm {

template <int D>
double deposit_front(const mpm::MpmModel<D>& m) {
    const auto& g = m.grid;
    std::vector<char> occupied(g.cells[0], 0);
    for (std::size_t i = 0; i < m.particles.size(); ++i) occupied[g.cell_of(0, m.particles.x[D * i])] = 1;
    int last = 0;
    while (last + 1 < g.cells[0] && occupied[last + 1]) ++last;
    double front = g.origin[0];
    for (std::size_t i = 0; i < m.particles.size(); ++i)
        if (g.cell_of(0, m.particles.x[D * i]) <= last) front = std::max(front, m.particles.x[D * i]);
    return front;
}

std::vector<double> deposit_profile(const mpm::MpmModel<2>& m) {
    const auto& g = m.grid;
    std::vector<double> volume(g.cells[0], 0.0);
    for (std::size_t i = 0; i < m.particles.size(); ++i)
        volume[g.cell_of(0, m.particles.x[2 * i])] += m.particles.volume[i];
    for (int k = 0; k < g.cells[0]; ++k) {
        const double r1 = g.coordinate(0, k), r2 = g.coordinate(0, k + 1);
        volume[k] /= m.axisymmetric ? 0.5 * (r2 * r2 - r1 * r1) : r2 - r1;
    }
    return volume;
}

double thickness_front(const mpm::MpmModel<2>& m, const std::vector<double>& profile, double thickness) {
    std::size_t k = 0;
    while (k < profile.size() && profile[k] >= thickness) ++k;
    return m.grid.coordinate(0, static_cast<int>(k));
}

double lube_runout(double a, bool axisymmetric) {
    if (axisymmetric) return a < 1.7 ? 1.24 * a : 1.6 * std::sqrt(a);
    auto tall = [](double x) { return 1.9 * std::cbrt(x * x); };
    if (a < 1.8) return 1.2 * a;
    if (a > 2.8) return tall(a);
    return 1.2 * 1.8 + (a - 1.8) / (2.8 - 1.8) * (tall(2.8) - 1.2 * 1.8);
}

double lube_final_height(double a, bool axisymmetric) {
    if (axisymmetric) return a < 0.7 ? a : 0.88 * std::pow(a, 1.0 / 6.0);
    return a < 1.15 ? a : std::pow(a, 0.4);
}

double deposit_height(const std::vector<double>& profile) {
    double h = 0.0;
    for (double t : profile) h = std::max(h, t);
    return h;
}

template double deposit_front<2>(const mpm::MpmModel<2>&);
template double deposit_front<3>(const mpm::MpmModel<3>&);

}  // namespace pilempm::mpm
