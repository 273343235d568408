#include <gtest/gtest.h>

#include <cmath>

#include "core/optimisation/nelder_mead.hpp"

namespace pilempm {

// Rosenbrock's valley: the minimum at (1, 1), value 0, hard for a simplex to follow.
TEST(NelderMead, FindsTheMinimumOfRosenbrocksValley) {
    auto f = [](const std::vector<double>& x) {
        return 100.0 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1.0 - x[0], 2);
    };
    const NelderMeadResult r = nelder_mead(f, {-1.2, 1.0}, {0.5, 0.5}, {2000, 1e-14, 1e-8});
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x[0], 1.0, 1e-5);
    EXPECT_NEAR(r.x[1], 1.0, 1e-5);
    EXPECT_LT(r.value, 1e-10);
}

// A quadratic bowl in five coordinates, each with its own scale and centre; a budget
// cut short stops at the budget, not converged.
TEST(NelderMead, FitsFiveParametersAndStopsAtItsBudget) {
    const std::vector<double> centre = {0.3, -2.0, 1.5, 4.0, -0.7};
    auto f = [&](const std::vector<double>& x) {
        double s = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) s += (i + 1.0) * std::pow(x[i] - centre[i], 2);
        return s;
    };
    const NelderMeadResult r = nelder_mead(f, std::vector<double>(5, 0.0), std::vector<double>(5, 1.0),
                                           {4000, 1e-16, 1e-7});
    ASSERT_TRUE(r.converged);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(r.x[i], centre[i], 1e-5) << i;
    const NelderMeadResult cut = nelder_mead(f, std::vector<double>(5, 0.0), std::vector<double>(5, 1.0), {20});
    EXPECT_FALSE(cut.converged);
    EXPECT_LE(cut.evaluations, 20 + 1 + 5);  // the last iteration may finish a contraction and a shrink
    EXPECT_LT(cut.value, f(std::vector<double>(5, 0.0)));
}

}  // namespace pilempm
