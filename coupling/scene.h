// A scene describes a specimen; a method computes it (DESIGN.md, "The scene and the methods").
// The scene is built from the .prm section `Scene` and the mesh it names:
//   - the body: the mesh's own domain (outline and holes of any shape, basics/body.h);
//   - boundary conditions on named places of the mesh (gmsh physical names), values as functions
//     of x, y and the load factor lambda (deal.II FunctionParser), linear in lambda:
//       Displacement = <place>: ux = <f>, uy = <f>; ...      (either or both components)
//       Traction     = <boundary>: tx = <f>, ty = <f>, p = <f>; ...  (p: pressure, t = -p n)
//       Point force  = <point>: fx = <f>, fy = <f>; ...
//   - initial cracks: polylines; an end on the outline or a hole's rim is a mouth, the others tips;
//   - what to report as load and displacement (load_displacement.csv);
//   - the material.
// Reading it checks everything a method relies on before any long work: names that exist, values
// finite and linear in lambda wherever a method takes them, a body held against rigid motion, no two conditions fighting over a vertex,
// cracks inside the body with their mouths on its boundary.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "body.h"
#include "conditions.h"

namespace dealii
{
  class ParameterHandler;
  template <int dim, int spacedim>
  class Triangulation;
} // namespace dealii

namespace pumpd::coupling
{
  /// The elastic and fracture properties of the specimen.
  struct Material
  {
    double youngs_modulus  = 2.4e9;  ///< E [Pa]
    double poisson_ratio   = 0.25;   ///< nu
    double fracture_energy = 500.;   ///< G_c [J/m^2]
    double density         = 1200.;  ///< rho [kg/m^3]
    bool   plane_strain    = true;

    /// E' = E / (1 - nu^2) in plane strain, E in plane stress.
    double effective_modulus() const;
    /// K_c = sqrt(E' G_c).
    double critical_sif() const;
  };

  /// What load_displacement.csv reports: the load (lambda, or the reaction force component on a
  /// place holding a displacement condition) against the displacement (a component at a point,
  /// or its mean over a boundary; or the work-conjugate displacement 2 U / lambda).
  struct Report
  {
    bool                    load_is_lambda = true;
    conditions::Place       load_place;
    int                     load_component = 1; ///< 0: x, 1: y
    double                  load_sign      = 1.;
    bool                    work_conjugate = true;
    conditions::Place       displacement_place;
    int                     displacement_component = 1;
    double                  displacement_sign      = 1.;
    std::string             load_name = "lambda", displacement_name = "2 U / lambda";
  };

  struct Scene
  {
    std::string                                        mesh_file;
    std::shared_ptr<const dealii::Triangulation<2, 2>> mesh;  ///< as read (the methods refine copies)
    geometry::Body                                     body;
    conditions::Conditions                             conditions;
    std::vector<geometry::Polyline>                    cracks;
    Material                                           material;
    Report                                             report;
    std::string                                        output_directory;
    geometry::Polyline                                 reference_path; ///< empty: none

    /// The one crack (InvalidParameter naming "Initial cracks" unless there is exactly one).
    const geometry::Polyline &crack() const;
  };

  /// The section `Scene` of a scene file, bound to its entries (ParameterHandler::add_parameter).
  struct SceneSettings
  {
    std::string mesh_file;
    double      mesh_size         = 0.;
    double      max_cells         = 5e5;
    std::string displacement;
    std::string traction;
    std::string point_force;
    std::string initial_cracks;
    std::string report_load         = "lambda";
    std::string report_displacement = "";
    std::string length_defaults     = "scene"; ///< scene | absolute (scene_lengths.h)
    std::string output_directory    = "out";
    std::string reference_path      = "";
    Material    material;

    void add_parameters(dealii::ParameterHandler &prm);
  };

  /// Creates the folder `directory` (nothing if it is empty: a run that writes nothing) before any
  /// work and reserves it for this run (basics/output.h: the first file written into it locks it
  /// against other pumpd processes); throws InvalidParameter naming `entry` if it cannot be
  /// created or written to.
  void make_output_directory(const std::string &entry, const std::string &directory);

  /// Reads the mesh and builds the scene. Throws InvalidParameter naming the entry and what is
  /// allowed for every check in the header comment. With `progress`, meshing a .geo reports there
  /// while gmsh runs (global::read_mesh).
  Scene build_scene(const SceneSettings &settings, std::ostream *progress = nullptr);

  /// A hash (FNV-1a) of what makes the scene's geometry: the mesh's vertices and cells and the
  /// initial cracks. A cycle checkpoint keeps it, so that a run resumes only the scene that wrote
  /// it.
  std::uint64_t geometry_fingerprint(const Scene &scene);

  /// Reference path (x, y per line; lines starting with '#' or a letter are skipped). Throws
  /// InvalidParameter("Reference path", ...) if it cannot be read or is not a regular file (a FIFO
  /// or a device is not opened).
  geometry::Polyline read_path(const std::string &file);
} // namespace pumpd::coupling
