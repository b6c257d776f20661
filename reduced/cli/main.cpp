// impact-reduced: command-line front end of the reduced impact library.
// Exit codes: 0 success, 2 bad input (message on stderr names the parameter), 1 internal error.

#include "commands.hpp"
#include "impact_reduced/invalid_input.hpp"

#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

const char* usage = R"(usage: impact-reduced COMMAND [--option value ...]

commands:
  hc          Hunt-Crossley impact in closed form (x_max, peak force, contact time, restitution, ...)
              --mass M --stiffness C --exponent N --damping B --velocity V [--history P]
  damping     damping constant b of Hunt-Crossley from a restitution
              --restitution E --velocity V
  law         a comparison contact law: the damping its own formula assigns and the
              restitution it really produces
              --model NAME --restitution E --velocity V --mass M --stiffness C [...]
  oscillator  free decay of a damped oscillator with power-law stiffness (Olshanskiy)
              --mass M --viscous K --c1 C1 --c2 C2 --power NU --a0 A0 --count N
              --method numeric|implicit|lambert|lambert-approx
  thin-plate  a sphere on an infinite thin (Kirchhoff) plate, Zener's model: restitution,
              contact time, peaks, energy into the plate, Zener's lambda
              --plate-modulus E --plate-poisson NU --plate-density RHO --thickness H
              (--stiffness C [--exponent N] | --sphere-modulus E --sphere-poisson NU --radius R)
              (--mass M | --sphere-density RHO --radius R) [--damping B] --velocity V[,V...]
  plastic     elastic-plastic impact of a sphere on a flat (or two spheres: effective radius
              and mass): restitution, contact time, peak force, maximum and permanent
              approach, V/V_y, for a list of velocities
              --model thornton|jackson-green --radius R (--mass M | --density RHO)
              --modulus E --poisson NU [--flat-modulus E --flat-poisson NU]
              --yield-strength Y [--criterion johnson|jackson-green] --velocity V[,V...]
              [--unloading contact-radius|brake] (jackson-green)
              [--loop N]: CSV time,approach,approach_rate,force of one impact's loop

Units are SI. Output is JSON, or CSV where it is a table (--format csv).
Exit codes: 0 success, 2 bad input (the message names the parameter), 1 internal error.
)";

} // namespace

int main(int argc, char** argv) {
  using namespace impact::cli;
  const std::map<std::string, std::function<int(CommandLine&, std::ostream&)>> commands = {
      {"hc", run_hc_command},
      {"damping", run_damping_command},
      {"law", run_law_command},
      {"oscillator", run_oscillator_command},
      {"thin-plate", run_thin_plate_command},
      {"plastic", run_plastic_command},
  };
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    (argc < 2 ? std::cerr : std::cout) << usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string name = argv[1];
  const auto command = commands.find(name);
  if (command == commands.end()) {
    std::cerr << "impact-reduced: unknown command '" << name << "'\n\n" << usage;
    return 2;
  }
  try {
    CommandLine options(name, std::vector<std::string>(argv + 2, argv + argc));
    return command->second(options, std::cout);
  } catch (const UsageError& error) {
    std::cerr << "impact-reduced " << name << ": error: " << error.what() << '\n';
    return 2;
  } catch (const impact::reduced::InvalidInput& error) {
    std::cerr << "impact-reduced " << name << ": error: " << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "impact-reduced " << name << ": internal error: " << error.what() << '\n';
    return 1;
  }
}
