#include "core/optimisation/nelder_mead.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace pilempm {

NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f,
                             const std::vector<double>& x0, const std::vector<double>& steps,
                             const NelderMeadOptions& options) {
    const std::size_t n = x0.size();
    if (n == 0 || steps.size() != n) throw std::invalid_argument("nelder_mead: a start and one step per coordinate");
    NelderMeadResult r;
    std::vector<std::vector<double>> p(n + 1, x0);
    std::vector<double> v(n + 1);
    auto eval = [&](const std::vector<double>& x) {
        ++r.evaluations;
        const double y = f(x);
        return std::isfinite(y) ? y : HUGE_VAL;  // a failed model is worse than any
    };
    for (std::size_t i = 0; i < n; ++i) p[i + 1][i] += steps[i];
    for (std::size_t i = 0; i <= n; ++i) v[i] = eval(p[i]);

    std::vector<std::size_t> order(n + 1);
    std::vector<double> centre(n), trial(n);
    auto towards = [&](const std::vector<double>& a, const std::vector<double>& b, double t) {
        for (std::size_t j = 0; j < n; ++j) trial[j] = a[j] + t * (b[j] - a[j]);
        return trial;
    };
    while (true) {
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&v](std::size_t a, std::size_t b) { return v[a] < v[b]; });
        const std::size_t best = order.front(), worst = order.back(), second = order[n - 1];
        double spread = 0.0;
        for (std::size_t i = 0; i <= n; ++i)
            for (std::size_t j = 0; j < n; ++j) spread = std::max(spread, std::abs(p[i][j] - p[best][j]));
        if (v[worst] - v[best] <= options.value_tolerance && spread <= options.step_tolerance) {
            r.converged = true;
            break;
        }
        if (r.evaluations >= options.max_evaluations) break;
        std::fill(centre.begin(), centre.end(), 0.0);
        for (std::size_t i = 0; i <= n; ++i)
            if (i != worst)
                for (std::size_t j = 0; j < n; ++j) centre[j] += p[i][j] / static_cast<double>(n);
        const std::vector<double> reflected = towards(centre, p[worst], -1.0);
        const double fr = eval(reflected);
        if (fr < v[best]) {
            const std::vector<double> expanded = towards(centre, p[worst], -2.0);
            const double fe = eval(expanded);
            if (fe < fr) p[worst] = expanded, v[worst] = fe;
            else p[worst] = reflected, v[worst] = fr;
            continue;
        }
        if (fr < v[second]) {
            p[worst] = reflected, v[worst] = fr;
            continue;
        }
        // Contract toward the better of the worst point and its reflection.
        const bool outside = fr < v[worst];
        const std::vector<double> contracted = towards(centre, outside ? reflected : p[worst], 0.5);
        const double fc = eval(contracted);
        if (fc < (outside ? fr : v[worst])) {
            p[worst] = contracted, v[worst] = fc;
            continue;
        }
        for (std::size_t i = 0; i <= n; ++i)
            if (i != best) {
                p[i] = towards(p[best], p[i], 0.5);
                v[i] = eval(p[i]);
            }
    }
    const std::size_t best = static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
    r.x = p[best];
    r.value = v[best];
    return r;
}

}  // namespace pilempm
