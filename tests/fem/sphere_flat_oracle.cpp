// The published fits of elastic-plastic sphere-on-rigid-flat contact, from
// the reduced library (impact::reduced, sphere_flat_fits.hpp), for the fem
// indentation test and its benchmark: the oracle the FEM is compared with.
//
// Usage: fem_test_sphere_flat_oracle RADIUS CONTACT_MODULUS YIELD_STRENGTH
//        POISSON_RATIO OMEGA_MAX [OMEGA_MAX ...]
// (SI units). Prints one JSON object: the critical interference and load of
// Jackson & Green (2005) and of Kogut & Etsion (2002), and for every
// maximum interference omega_max: the loads of both fits, the Jackson-Green
// contact radius, and the residual interference after unloading from the
// Jackson-Green loading by Brake's (2015) rule and by the
// contact-radius-preserving rule. Invalid input: the reduced library's
// message on stderr, exit status 1.
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/sphere_flat_fits.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  namespace r = impact::reduced;
  if (argc < 6) {
    std::fprintf(stderr,
                 "usage: %s RADIUS CONTACT_MODULUS YIELD_STRENGTH "
                 "POISSON_RATIO OMEGA_MAX [OMEGA_MAX ...]\n",
                 argv[0]);
    return 2;
  }
  try {
    const r::SphereFlatContact contact{std::stod(argv[1]), std::stod(argv[2]), std::stod(argv[3]),
                                       std::stod(argv[4])};
    std::printf(
        "{\"jackson_green_critical_interference\": %.17g,\n"
        " \"jackson_green_critical_load\": %.17g,\n"
        " \"kogut_etsion_critical_interference\": %.17g,\n"
        " \"kogut_etsion_critical_load\": %.17g,\n"
        " \"points\": [",
        r::jackson_green_critical_interference(contact), r::jackson_green_critical_load(contact),
        r::kogut_etsion_critical_interference(contact), r::kogut_etsion_critical_load(contact));
    const double ke_omega = r::kogut_etsion_critical_interference(contact);
    const double ke_load = r::kogut_etsion_critical_load(contact);
    for (int i = 5; i < argc; ++i) {
      const double omega = std::stod(argv[i]);
      std::printf(
          "%s\n  {\"interference\": %.17g, \"jackson_green_load\": %.17g, "
          "\"kogut_etsion_load\": %.17g, \"jackson_green_contact_radius\": %.17g, "
          "\"residual_brake\": %.17g, \"residual_contact_radius\": %.17g}",
          i == 5 ? "" : ",", omega, r::jackson_green_load(omega, contact),
          ke_load * r::kogut_etsion_load_ratio(omega / ke_omega, contact.poisson_ratio),
          r::jackson_green_contact_radius(omega, contact),
          r::jackson_green_residual_interference(omega, contact, r::JacksonGreenUnloading::brake),
          r::jackson_green_residual_interference(omega, contact,
                                                 r::JacksonGreenUnloading::contact_radius));
    }
    std::printf("]}\n");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  }
  return 0;
}
