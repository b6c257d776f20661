#include <impact_fem/as_written.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>
#include <impact_fem/mesh/contact_surfaces.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#ifndef IMPACT_FEM_MESH_DIRECTORY
#define IMPACT_FEM_MESH_DIRECTORY "meshes"
#endif

namespace impact_fem
{
  void
  SpherePlateMesh::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Contact element size",
                      "auto",
                      *discretisation::number_or_auto_pattern(),
                      "Edge length of the elements at the contact point "
                      "[m], > 0 and smaller than the sphere radius; 'auto': "
                      "the expected contact radius a / 20 (a of Hertz), or "
                      "a / 30 if a body is expected to yield (a of "
                      "Jackson-Green's elastic-plastic impact); the run's "
                      "log and summary.json say which.");
    prm.declare_entry("Uniform zone radius",
                      "auto",
                      *discretisation::number_or_auto_pattern(),
                      "Distance from the contact point within which the "
                      "elements keep the contact element size [m], >= 0; "
                      "'auto': 1.5 a (at most the contact surface radius).");
    prm.declare_entry("Growth factor",
                      "1.2",
                      Patterns::Double(),
                      "Beyond the uniform zone, the element size grows by "
                      "this factor from one element to the next [-], in "
                      "[1, 3].");
    prm.declare_entry("Maximum element size",
                      "20e-3",
                      Patterns::Double(),
                      "Largest element edge length [m], >= the contact "
                      "element size.");
    prm.declare_entry("Elements across the plate thickness",
                      "4",
                      Patterns::Double(),
                      "Least number of elements across the plate thickness "
                      "H [-], >= 1: the element size is at most H / this "
                      "(a thin plate bends; 4 elements of degree 2 resolve "
                      "its bending, fem/README.md). Need not be an integer "
                      "(the verification divides it by its ratio).");
    prm.declare_entry("Contact surface radius",
                      "auto",
                      *discretisation::number_or_auto_pattern(),
                      "Radius of the candidate contact surfaces of sphere "
                      "and plate [m], in (0, R/2]; must exceed the largest "
                      "contact radius (1.4 mm at 5 m/s for the default "
                      "ball); 'auto': 2.5 a, at most R/2.");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 6),
                      "Number of uniform refinements of the gmsh mesh [-], "
                      "0..6; each halves every element size.");
    prm.declare_entry("Contact refinements",
                      "0",
                      Patterns::Integer(0, 6),
                      "Number of additional refinements of the cells within "
                      "the contact surface radius of the contact point [-], "
                      "0..6.");
    prm.declare_entry("Contact surface refinements",
                      "auto",
                      *discretisation::number_or_auto_pattern(),
                      "Number of additional refinements of the cells with a "
                      "face on a contact surface [-], an integer in 0..6 "
                      "(after the contact refinements): each halves the "
                      "spacing of the contact nodes, and only of them. "
                      "'auto': " +
                        discretisation::AutomaticDiscretisation::
                          contact_surface_refinements_rule() +
                        ". A fully plastic contact force rises in a step as "
                        "each node enters contact.");
    prm.declare_entry("Polynomial degree",
                      "2",
                      Patterns::Integer(1, 4),
                      "Degree of the Lagrange elements and of the mapping "
                      "[-], 1..4.");
    prm.declare_entry("Gmsh executable",
                      "gmsh",
                      Patterns::Anything(),
                      "Command that runs gmsh (a name in PATH or a path).");
    prm.declare_entry("Geometry file",
                      IMPACT_FEM_MESH_DIRECTORY "/sphere_on_plate.geo",
                      Patterns::Anything(),
                      "gmsh .geo source of sphere and plate with the "
                      "physical groups the model expects.");
    prm.leave_subsection();
  }


  namespace
  {
    /// Mesh/Contact surface refinements of the current subsection: its
    /// integer, or 0 if it is "auto" (@p automatic tells which).
    unsigned int
    surface_refinements_or_auto(const ParameterHandler &prm, bool &automatic)
    {
      const double count =
        discretisation::number_or_auto(prm,
                                       "Contact surface refinements",
                                       "Mesh/Contact surface refinements",
                                       0,
                                       automatic);
      AssertThrow(count >= 0 && count <= 6 && count == std::floor(count),
                  ExcMessage("Mesh/Contact surface refinements must be "
                             "'auto' or an integer in 0..6, got " +
                             as_written(count) + "."));
      return static_cast<unsigned int>(count);
    }
  } // namespace


  void
  SpherePlateMesh::parse_parameters(
    ParameterHandler                                               &prm,
    const Geometry                                                 &geometry_in,
    const std::function<discretisation::AutomaticDiscretisation()> &automatic)
  {
    geometry = geometry_in;
    prm.enter_subsection("Mesh");
    const char *const sized[3]      = {"Contact element size",
                                       "Uniform zone radius",
                                       "Contact surface radius"};
    double            size[3]       = {0, 0, 0};
    bool              any_automatic = false;
    for (unsigned int i = 0; i < 3; ++i)
      {
        size[i] = discretisation::number_or_auto(
          prm, sized[i], std::string("Mesh/") + sized[i], 0, automatic_size[i]);
        any_automatic = any_automatic || automatic_size[i];
      }
    contact_surface_refinements =
      surface_refinements_or_auto(prm, automatic_surface_refinements);
    if (any_automatic)
      {
        const discretisation::AutomaticDiscretisation rule = automatic();
        const double ruled[3] = {rule.contact_element_size,
                                 rule.uniform_zone_radius,
                                 rule.contact_surface_radius};
        for (unsigned int i = 0; i < 3; ++i)
          if (automatic_size[i])
            size[i] = ruled[i];
        // A contact element size the scenario sets is the scenario's mesh:
        // the rule refines only a mesh it sized itself ("auto" is 0 there).
        if (automatic_surface_refinements && automatic_size[0])
          contact_surface_refinements = rule.contact_surface_refinements;
      }
    contact_element_size   = size[0];
    uniform_zone_radius    = size[1];
    contact_surface_radius = size[2];
    growth_factor          = prm.get_double("Growth factor");
    maximum_element_size   = prm.get_double("Maximum element size");
    elements_across_thickness =
      prm.get_double("Elements across the plate thickness");
    global_refinements  = prm.get_integer("Global refinements");
    contact_refinements = prm.get_integer("Contact refinements");
    polynomial_degree   = prm.get_integer("Polynomial degree");
    gmsh_executable     = prm.get("Gmsh executable");
    geometry_file       = prm.get("Geometry file");
    prm.leave_subsection();

    const double R = geometry.sphere_radius;
    AssertThrow(contact_element_size > 0,
                ExcMessage("Mesh/Contact element size must be positive, got " +
                           as_written(contact_element_size) + " m."));
    AssertThrow(contact_element_size < R,
                ExcMessage("Mesh/Contact element size (" +
                           as_written(contact_element_size) +
                           " m) is larger than the sphere radius (" +
                           as_written(R) + " m)."));
    AssertThrow(uniform_zone_radius >= 0,
                ExcMessage("Mesh/Uniform zone radius must not be negative."));
    AssertThrow(growth_factor >= 1 && growth_factor <= 3,
                ExcMessage("Mesh/Growth factor must lie in [1, 3], got " +
                           as_written(growth_factor) + "."));
    AssertThrow(maximum_element_size >= contact_element_size,
                ExcMessage("Mesh/Maximum element size must not be smaller "
                           "than the contact element size."));
    AssertThrow(elements_across_thickness >= 1 &&
                  elements_across_thickness <= 1000,
                ExcMessage("Mesh/Elements across the plate thickness must lie "
                           "in [1, 1000], got " +
                           as_written(elements_across_thickness) + "."));
    AssertThrow(contact_element_size <= far_field_element_size(),
                ExcMessage("Mesh/Contact element size (" +
                           as_written(contact_element_size) +
                           " m) exceeds the plate thickness / Elements across "
                           "the plate thickness (" +
                           as_written(far_field_element_size()) + " m)."));
    AssertThrow(contact_surface_radius > 0 && contact_surface_radius <= 0.5 * R,
                ExcMessage("Mesh/Contact surface radius must lie in (0, R/2] "
                           "= (0, " +
                           as_written(0.5 * R) + "] m, got " +
                           as_written(contact_surface_radius) + " m."));
    AssertThrow(contact_surface_radius < geometry.plate_radius,
                ExcMessage("Mesh/Contact surface radius must be smaller than "
                           "the plate radius."));
    AssertThrow(contact_element_size <= contact_surface_radius,
                ExcMessage("Mesh/Contact element size must not exceed the "
                           "contact surface radius."));
    AssertThrow(std::filesystem::exists(geometry_file),
                ExcMessage("Mesh/Geometry file <" + geometry_file +
                           "> does not exist."));
  }


  void
  SpherePlateMesh::create(
    parallel::distributed::Triangulation<2> &triangulation,
    const std::string                       &work_directory) const
  {
    const MPI_Comm    comm     = triangulation.get_communicator();
    const std::string msh_file = work_directory + "/mesh.msh";
    const std::string log_file = work_directory + "/gmsh.log";

    // gmsh runs on one rank; the others wait for its verdict.
    int status = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ostringstream command;
        command.precision(17);
        // The .geo halves its sizes once (subdivision of the recombined
        // mesh into quadrilaterals only), hence the factor 2.
        command << gmsh_executable << " -2 -v 2"
                << " -setnumber R " << geometry.sphere_radius
                << " -setnumber g0 " << geometry.initial_gap
                << " -setnumber Rp " << geometry.plate_radius
                << " -setnumber H " << geometry.plate_thickness
                << " -setnumber rc " << contact_surface_radius
                << " -setnumber hc " << contact_element_size
                << " -setnumber rz " << uniform_zone_radius
                << " -setnumber growth " << growth_factor << " -setnumber hmax "
                << far_field_element_size() << " -setnumber plate "
                << (geometry.plate_meshed ? 1 : 0) << " -setnumber hemisphere "
                << (geometry.hemisphere ? 1 : 0) << " \"" << geometry_file
                << "\" -o \"" << msh_file << "\" > \"" << log_file << "\" 2>&1";
        std::filesystem::remove(msh_file);
        const int rc = std::system(command.str().c_str());
        status       = WIFEXITED(rc) ? WEXITSTATUS(rc) : 255;
        if (status == 0 && !std::filesystem::exists(msh_file))
          status = 1;
      }
    status = Utilities::MPI::broadcast(comm, status, 0);
    AssertThrow(status != 127,
                ExcMessage("gmsh was not found (Mesh/Gmsh executable = <" +
                           gmsh_executable +
                           ">): install gmsh or give its path."));
    AssertThrow(status == 0,
                ExcMessage("gmsh failed to mesh <" + geometry_file +
                           "> (exit status " + std::to_string(status) +
                           "); its messages are in " + log_file + "."));

    GridIn<2> grid_in;
    grid_in.attach_triangulation(triangulation);
    std::ifstream input(msh_file);
    AssertThrow(input, ExcMessage("Cannot read the mesh file " + msh_file));
    grid_in.read_msh(input);

    // The whole surface of the sphere is round: its boundary faces follow a
    // spherical manifold (the higher-order mapping then curves the cells).
    constexpr types::manifold_id sphere_surface = 1;
    for (const auto &cell : triangulation.cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() &&
            (face->boundary_id() == boundary_ids::sphere_contact ||
             face->boundary_id() == boundary_ids::sphere_free_surface))
          face->set_manifold_id(sphere_surface);
    triangulation.set_manifold(sphere_surface,
                               SphericalManifold<2>(geometry.sphere_centre()));

    triangulation.refine_global(global_refinements);

    // Extra refinement of everything near the contact point: all cells
    // touching the contact surfaces are refined alike, so no hanging node
    // lies on a contact surface.
    const Point<2> contact_points[2] = {Point<2>(0, 0),
                                        Point<2>(0, geometry.initial_gap)};
    for (unsigned int cycle = 0; cycle < contact_refinements; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &contact_point : contact_points)
              if (cell->center().distance(contact_point) <
                  contact_surface_radius + cell->diameter())
                cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
    for (unsigned int cycle = 0; cycle < contact_surface_refinements; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              if (on_contact_surface(face))
                cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
  }
} // namespace impact_fem
