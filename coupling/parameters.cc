#include "parameters.h"

#include <deal.II/base/parameter_handler.h>

namespace pumpd::coupling
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  namespace
  {
    /// declare_entry with the default appended to the documentation, so that
    /// `pumpd --print-parameters` lists value range, documentation and default together.
    void entry(ParameterHandler &prm, const std::string &name, const std::string &default_value,
               const Patterns::PatternBase &pattern, const std::string &documentation)
    {
      prm.declare_entry(name, default_value, pattern, documentation + " Default: " + default_value + ".");
    }
  } // namespace

  void declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    entry(prm, "Type", "pd-edge-crack", Patterns::Selection("pd-edge-crack"),
                      "Which scene to run. pd-edge-crack: a PD box around a mode-I edge-crack tip, "
                      "its boundary layer driven by the Williams field of a rising K.");
    entry(prm, "Output directory", "out", Patterns::DirectoryName(),
                      "Where VTU/PVD, load_steps.csv and checkpoint.h5 go (created if missing).");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    entry(prm, "Young's modulus", "2.4e9", Patterns::Double(0.), "E [Pa], > 0.");
    entry(prm, "Fracture energy", "500", Patterns::Double(0.), "Critical energy release rate G_c [J/m^2], > 0.");
    entry(prm, "Density", "1200", Patterns::Double(0.), "rho [kg/m^3], > 0.");
    entry(prm, "Plane strain", "true", Patterns::Bool(),
                      "true: plane strain (bond-based PD fixes nu = 1/4); false: plane stress (nu = 1/3).");
    prm.leave_subsection();

    prm.enter_subsection("Peridynamics");
    entry(prm, "Horizon", "0.004", Patterns::Double(0.), "delta [m], > 0.");
    entry(prm, "Horizon over spacing", "4", Patterns::Integer(2, 64),
                      "m = delta / h, an integer in [2, 64]: the lattice spacing is h = delta / m.");
    entry(prm, "Influence function", "linear", Patterns::Selection("constant|linear"),
                      "J(r): constant 1, or linear 12 (1 - r) (the published decks).");
    entry(prm, "Bond break factor", "10", Patterns::Double(1.),
                      "A bond fails for good beyond this multiple (>= 1) of its inflection stretch "
                      "S_c = 1 / sqrt(2 beta |xi|); the decks use 10.");
    entry(prm, "Relaxation tolerance", "1e-6", Patterns::Double(1e-14, 0.5),
                      "Dynamic relaxation stops when |f| / (k |u|) falls below this, in [1e-14, 0.5].");
    entry(prm, "Relaxation max iterations", "200000", Patterns::Integer(1),
                      "Upper bound on dynamic relaxation iterations per load step, >= 1.");
    prm.leave_subsection();

    prm.enter_subsection("Edge crack");
    entry(prm, "Box size", "0.096", Patterns::Double(0.),
                      "Side of the square PD box [m], >= 4 horizons; the crack tip is at its centre.");
    entry(prm, "First K over K_c", "0.6", Patterns::Double(0., 1000.),
                      "K of the first load step, as a multiple of K_c = sqrt(E' G_c).");
    entry(prm, "Last K over K_c", "1.4", Patterns::Double(0., 1000.),
                      "K of the last load step, >= the first.");
    entry(prm, "Load steps", "17", Patterns::Integer(1), "Number of K levels, equally spaced, >= 1.");
    entry(prm, "Crack damage threshold", "0.3", Patterns::Double(0., 1.),
                      "A node with damage above this lies on the crack. A node on the face of a "
                      "straight crack has damage ~0.41 (the bonds across the crack of one side).");
    entry(prm, "Stop after growth", "0", Patterns::Double(0.),
                      "Stop the load steps once the crack grew this far [m]; 0 runs all steps.");
    entry(prm, "Output interval", "1", Patterns::Integer(1), "Write the PD state every n load steps.");
    prm.leave_subsection();
  }

  std::string scene_type(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    const std::string t = prm.get("Type");
    prm.leave_subsection();
    return t;
  }

  std::string output_directory(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    const std::string d = prm.get("Output directory");
    prm.leave_subsection();
    return d;
  }

  EdgeCrackParameters read_edge_crack(ParameterHandler &prm)
  {
    EdgeCrackParameters p;
    p.output_directory = output_directory(prm);
    prm.enter_subsection("Material");
    p.material.youngs_modulus  = prm.get_double("Young's modulus");
    p.material.fracture_energy = prm.get_double("Fracture energy");
    p.material.density         = prm.get_double("Density");
    p.material.plane_strain    = prm.get_bool("Plane strain");
    prm.leave_subsection();
    prm.enter_subsection("Peridynamics");
    p.horizon                = prm.get_double("Horizon");
    p.horizon_ratio          = prm.get_integer("Horizon over spacing");
    p.material.influence     = local::influence_from_string(prm.get("Influence function"));
    p.material.break_factor  = prm.get_double("Bond break factor");
    p.tolerance              = prm.get_double("Relaxation tolerance");
    p.max_iterations         = prm.get_integer("Relaxation max iterations");
    prm.leave_subsection();
    prm.enter_subsection("Edge crack");
    p.box_size        = prm.get_double("Box size");
    p.k_start         = prm.get_double("First K over K_c");
    p.k_end           = prm.get_double("Last K over K_c");
    p.load_steps      = prm.get_integer("Load steps");
    p.crack_damage    = prm.get_double("Crack damage threshold");
    p.growth_to_stop  = prm.get_double("Stop after growth");
    p.output_interval = prm.get_integer("Output interval");
    prm.leave_subsection();
    return p;
  }
} // namespace pumpd::coupling
