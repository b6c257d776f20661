// The grid convergence index (fem/include/impact_fem/verification/) on
// sequences with known orders.
#include <impact_fem/verification/grid_convergence.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using impact_fem::verification::grid_convergence;

namespace {
// f(h) = f0 + C h^p on h = 1, r, r^2.
double value(const double f0, const double C, const double p, const double h) {
  return f0 + C * std::pow(h, p);
}
} // namespace

TEST(GridConvergence, SecondOrderSequence) {
  const double r = 1.5, f0 = 102.5, C = 0.3;
  const auto g =
      grid_convergence(value(f0, C, 2, 1), value(f0, C, 2, r), value(f0, C, 2, r * r), r, 2);
  EXPECT_EQ(g.convergence, "monotone");
  EXPECT_NEAR(g.observed_order, 2, 1e-12);
  EXPECT_NEAR(g.extrapolated, f0, 1e-12);
  // GCI = 1.25 |f2 - f1| / (r^2 - 1), and it bounds the true error of f1.
  const double e21 = value(f0, C, 2, r) - value(f0, C, 2, 1);
  EXPECT_NEAR(g.gci_absolute, 1.25 * e21 / (r * r - 1), 1e-12);
  EXPECT_NEAR(g.gci_relative, g.gci_absolute / value(f0, C, 2, 1), 1e-15);
  EXPECT_GT(g.gci_absolute, std::abs(value(f0, C, 2, 1) - f0));
}

TEST(GridConvergence, AnOrderAboveTheFormalOneIsNotTrustedForTheIndex) {
  const double r = 2, f0 = 1, C = -0.01;
  const auto g =
      grid_convergence(value(f0, C, 4, 1), value(f0, C, 4, r), value(f0, C, 4, r * r), r, 2);
  EXPECT_NEAR(g.observed_order, 4, 1e-10);
  EXPECT_NEAR(g.extrapolated, f0, 1e-12);
  const double e21 = std::abs(value(f0, C, 4, r) - value(f0, C, 4, 1));
  EXPECT_NEAR(g.gci_absolute, 1.25 * e21 / (r * r - 1), 1e-14); // q = 2, not 4
}

TEST(GridConvergence, OscillatoryAndDivergentSequencesGetTheConservativeIndex) {
  const auto oscillatory = grid_convergence(1.0, 1.01, 0.99, 1.5, 2);
  EXPECT_EQ(oscillatory.convergence, "oscillatory");
  EXPECT_TRUE(std::isnan(oscillatory.observed_order));
  EXPECT_TRUE(std::isnan(oscillatory.extrapolated));
  EXPECT_NEAR(oscillatory.gci_absolute, 3 * 0.02, 1e-14);

  const auto divergent = grid_convergence(1.0, 1.02, 1.03, 1.5, 2);
  EXPECT_EQ(divergent.convergence, "divergent");
  EXPECT_NEAR(divergent.gci_absolute, 3 * 0.02, 1e-14);
}

TEST(GridConvergence, IdenticalValuesAreConverged) {
  const auto g = grid_convergence(0.9375, 0.9375, 0.9375, 1.5, 2);
  EXPECT_EQ(g.convergence, "converged");
  EXPECT_EQ(g.gci_absolute, 0);
  EXPECT_EQ(g.extrapolated, 0.9375);
  const auto finest = grid_convergence(2.0, 2.0, 2.1, 1.5, 2);
  EXPECT_EQ(finest.convergence, "monotone");
  EXPECT_EQ(finest.gci_absolute, 0);
}

TEST(GridConvergence, BadInputThrows) {
  EXPECT_THROW(grid_convergence(1, 2, 3, 1.0, 2), std::invalid_argument);
  EXPECT_THROW(grid_convergence(1, 2, 3, 1.5, 0), std::invalid_argument);
  EXPECT_THROW(grid_convergence(NAN, 2, 3, 1.5, 2), std::invalid_argument);
}
