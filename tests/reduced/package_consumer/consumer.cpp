// Prints the restitution of the published example through the installed library.
#include <impact_reduced/hunt_crossley.hpp>

#include <cstdio>

int main() {
  const impact::reduced::HuntCrossleyImpact impact(0.1, 1.7135e10, 1.5, 0.1, 1.0);
  std::printf("%.9f\n", impact.restitution());
  return impact.restitution() > 0.9374 && impact.restitution() < 0.9375 ? 0 : 1;
}
