#include "parameters.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

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
    entry(prm, "Type", "pd-edge-crack", Patterns::Selection("pd-edge-crack|lefm-growth|global-local|full-pd"),
                      "Which scene to run. pd-edge-crack: a PD box around a mode-I edge-crack tip, "
                      "its boundary layer driven by the Williams field of a rising K. lefm-growth: "
                      "LEFM crack growth in the Ingraffea beam (XFEM, maximum hoop stress; no PD). "
                      "global-local: the coupled cycle in the Ingraffea beam (XFEM drives a PD box at "
                      "the tip, the PD damage grows the crack; subsections Peridynamics and Global-local). "
                      "full-pd: the whole Ingraffea beam as one PD body, supports and load as prescribed "
                      "PD regions, displacement-controlled (subsections Peridynamics and Full PD).");
    entry(prm, "Output directory", "out", Patterns::DirectoryName(),
                      "Where VTU/PVD, load_steps.csv, checkpoint.h5, crack_path.csv go (created if "
                      "missing). Relative paths in a scene file (this one, Mesh file, Published path) "
                      "start at the current directory; make run runs from the repository root.");
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
                      "Dynamic relaxation stops when |f| / (k |u - u_rigid|) falls below this (u_rigid: the "
                      "best-fit rigid motion of the PD body), in [1e-14, 0.5].");
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

    const auto point = Patterns::List(Patterns::Double(), 2, 2, ",");
    prm.enter_subsection("LEFM growth");
    entry(prm, "Mesh file", "meshes/ingraffea-beam.geo", Patterns::FileName(),
                      "The beam: gmsh .geo (meshed by gmsh) or .msh, all quadrilaterals; boundary ids "
                      "1-4 on the outline (a rectangle), 5 on the holes. Relative to the current directory.");
    entry(prm, "Mesh size", "0.008", Patterns::Double(0., 1.),
                      "h passed to gmsh for a .geo [m], in [0, 1]; 0: the file's default. "
                      "meshes/ingraffea-beam*.geo: cells of h, h/2 in the crack band.");
    entry(prm, "Initial crack", "0.1016,0; 0.1016,0.0254", Patterns::List(point, 2, Patterns::List::max_int_value, ";"),
                      "Crack polyline \"x1,y1; x2,y2; ...\" [m], at least 2 points inside the body; an end "
                      "on the outline is the mouth, the other ends are tips. Ingraffea Cases I, II: "
                      "0.1016,0; 0.1016,0.0254; Case III: 0.127,0; 0.127,0.0381.");
    entry(prm, "Poisson's ratio", "0.35", Patterns::Double(0., 0.5),
                      "nu of the linear elastic body, in [0, 0.5) (PMMA: 0.35). Plane strain or stress "
                      "and Young's modulus from the Material subsection.");
    entry(prm, "Pin support", "0.0254,0", point, "x,y [m] of the mesh vertex with both displacements fixed.");
    entry(prm, "Roller support", "0.4826,0", point, "x,y [m] of the mesh vertex with the vertical displacement fixed.");
    entry(prm, "Load point", "0.254,0.2032", point, "x,y [m] of the mesh vertex where the point load acts (downwards).");
    entry(prm, "Load", "1e5", Patterns::Double(0.),
                      "Point load [N per m of thickness], > 0. K scales with it; the LEFM growth direction "
                      "does not depend on it.");
    entry(prm, "Growth increment", "0.004", Patterns::Double(0.), "Crack advance da per step [m], > 0.");
    entry(prm, "Increment halving angle", "0", Patterns::Double(0., 90.),
                      "Adaptive increment: da / (1 + |theta_c| / this) for the kink angle theta_c [deg], in "
                      "[0, 90]; 0: every increment is da.");
    entry(prm, "Maximum steps", "100", Patterns::Integer(1), "Growth increments at most, >= 1.");
    entry(prm, "Maximum crack length", "0.3", Patterns::Double(0.),
                      "Stop when the crack polyline is this long [m], > 0.");
    entry(prm, "Linear solver", "direct", Patterns::Selection("direct|cg-amg"),
          "direct: UMFPACK; cg-amg: conjugate gradients with AMG (Trilinos ML, rigid-body modes) on the "
          "standard unknowns and a direct solve on the enriched ones, for large meshes.");
    entry(prm, "Tip enrichment radius", "0.01", Patterns::Double(0.),
                      "Nodes within this distance of a tip carry the branch functions [m]; at least the "
                      "diameter of the cell at the tip (default mesh: 2.5 band cells). The interaction "
                      "integral uses the same radius.");
    entry(prm, "Refinement levels near the tip", "1", Patterns::Integer(0, 6),
                      "Cells near a tip are refined to this level (each level halves them), in [0, 6]; "
                      "the refinement stays along the path.");
    entry(prm, "Refinement radius", "0.012", Patterns::Double(0.), "Refine the cells within this distance of a tip [m], > 0.");
    entry(prm, "Hole margin", "0.001", Patterns::Double(0., 1.),
                      "A tip that would enter a hole stops this far [m] from the hole's circle, in [0, 1].");
    entry(prm, "Output interval", "5", Patterns::Integer(1), "Write global_NNN.vtu every n steps (and the last), >= 1.");
    entry(prm, "Published path", "", Patterns::Anything(),
                      "Optional CSV of a reference crack path (x,y [m] per line, # comments), copied to "
                      "reference_path.csv and compared (the largest distance of its points from our path); "
                      "empty: none. Relative to the current directory.");
    prm.leave_subsection();

    prm.enter_subsection("Global-local");
    entry(prm, "Mesh file", "meshes/ingraffea-beam-holes.geo", Patterns::FileName(),
          "The beam, as in LEFM growth: gmsh .geo or .msh, all quadrilaterals, ids 1-4 outline, 5 holes.");
    entry(prm, "Mesh size", "0.008", Patterns::Double(0., 1.), "h passed to gmsh for a .geo [m], in [0, 1]; 0: the file's default.");
    entry(prm, "Initial crack", "0.1016,0; 0.1016,0.0254", Patterns::List(point, 2, Patterns::List::max_int_value, ";"),
          "Edge crack polyline \"x1,y1; x2,y2; ...\" [m]: one end on the outline (the mouth), the other the "
          "tip; inside the body and clear of the holes.");
    entry(prm, "Poisson's ratio", "0.25", Patterns::Double(0., 0.5),
          "nu of the global body, in [0, 0.5). Bond-based PD has nu = 1/4 (plane strain), 1/3 (plane stress): "
          "use the same here so that the two models describe one material.");
    entry(prm, "Pin support", "0.0254,0", point, "x,y [m] of the mesh vertex with both displacements fixed.");
    entry(prm, "Roller support", "0.4826,0", point, "x,y [m] of the mesh vertex with the vertical displacement fixed.");
    entry(prm, "Load point", "0.254,0.2032", point, "x,y [m] of the mesh vertex where the point load acts (downwards).");
    entry(prm, "Reference load", "1e5", Patterns::Double(0.),
          "P_ref [N/m], > 0: the global solve's load; the load of each exchange is lambda P_c with the "
          "critical load P_c (G = G_c at the tip) scaled from it.");
    entry(prm, "Linear solver", "direct", Patterns::Selection("direct|cg-amg"), "direct: UMFPACK; cg-amg: CG with AMG.");
    entry(prm, "Tip enrichment radius", "0.006", Patterns::Double(0.), "Branch-function radius around the tip [m], > 0.");
    entry(prm, "Refinement levels near the tip", "2", Patterns::Integer(0, 6), "Cells near the tip are refined to this level, in [0, 6].");
    entry(prm, "Refinement radius", "0.008", Patterns::Double(0.), "Refine the cells within this distance of the tip [m], > 0.");
    entry(prm, "Box size", "0.032", Patterns::Double(0.),
          "Side of the square PD box [m]: at least 4 horizons plus the box margin, at most the body's smaller side.");
    entry(prm, "Box tip position", "0.3", Patterns::Double(0., 1.),
          "The tip sits this fraction of the box side from the box's rear (along the crack), in [0.05, 0.95].");
    entry(prm, "Box margin", "0.008", Patterns::Double(0.),
          "The box moves ahead once the tip has less than this much free lattice ahead [m], > 0.");
    entry(prm, "Maximum box size", "0.064", Patterns::Double(0.),
          "A box grows to take in a nearby hole up to this side [m], >= Box size.");
    entry(prm, "Crack damage threshold", "0.3", Patterns::Double(0., 1.),
          "A node with PD damage above this lies on the crack, in [0.05, 0.95] (crack faces reach ~0.41).");
    entry(prm, "First load factor", "0.9", Patterns::Double(0., 100.),
          "lambda = load / P_c of the first PD state of the first exchange, in [0.05, 10].");
    entry(prm, "Load increment", "0.05", Patterns::Double(0., 1.), "dlambda between PD states, in [1e-4, 1].");
    entry(prm, "Minimum load increment", "0.0125", Patterns::Double(0., 1.),
          "A too-long advance halves dlambda down to this, then the advance is truncated; in [1e-6, Load increment].");
    entry(prm, "Maximum load factor", "3", Patterns::Double(0., 100.),
          "No growth up to lambda = this: the run stops (the load is too small), in [First load factor, 100].");
    entry(prm, "Maximum advance", "0.008", Patterns::Double(0.), "da_max: the longest crack advance per exchange [m], > 0.");
    entry(prm, "Minimum advance", "0.004", Patterns::Double(0.),
          "An advance below this is no growth [m], at least two PD spacings and at most da_max / 2. A short "
          "advance is mostly straight ahead: the increment must be long enough for the PD crack to turn.");
    entry(prm, "Near distance", "0.008", Patterns::Double(0., 1.),
          "Within this of a hole or the outline the advance per exchange is da_max / 2 [m], in [0, 1].");
    entry(prm, "Start below the last load", "false", Patterns::Bool(),
          "false: every exchange's PD states start at the First load factor (below P_c), so the rebuilt box "
          "forms its process zone before the crack grows; true: one Load increment below the last accepted "
          "load (fewer PD states, but the crack then runs within one relaxation and turns less).");
    entry(prm, "Maximum exchanges", "200", Patterns::Integer(1), "Global-local exchanges at most, >= 1.");
    entry(prm, "Maximum crack length", "0.3", Patterns::Double(0.), "Stop when the crack polyline is this long [m], > 0.");
    entry(prm, "Hole margin", "0.001", Patterns::Double(0., 1.), "A tip stops this far [m] from a hole's circle, in [0, 1].");
    entry(prm, "Reference box area", "0.02258", Patterns::Double(0.),
          "Area of the fixed PD box the moving box is compared with [m^2]; default: Ni et al. (2019), "
          "(2, 0)-(7, 7) in = 0.127 m x 0.1778 m.");
    entry(prm, "Output interval", "1", Patterns::Integer(1), "Write global and PD VTU every n exchanges (and the last), >= 1.");
    entry(prm, "Published path", "", Patterns::Anything(),
          "Optional CSV of a published path (x,y [m] per line): copied to reference_path.csv and compared "
          "(symmetric mean and Hausdorff distance over its length). Relative to the current directory.");
    entry(prm, "Resume", "false", Patterns::Bool(),
          "true: continue from checkpoint.h5 in the output directory (written after every exchange).");
    prm.leave_subsection();

    // Full PD (coupling/full_pd.h): Material and Peridynamics are shared with the other scenes.
    prm.enter_subsection("Full PD");
    entry(prm, "Beam outline", "0,0; 0.508,0.2032", Patterns::List(point, 2, 2, ";"),
          "Lower-left and upper-right corner \"x1,y1; x2,y2\" [m] of the rectangular body; it is also the PD "
          "box (no boundary layer: every edge is a free surface). meshes/ingraffea-beam-holes.geo: 0,0; 0.508,0.2032.");
    entry(prm, "Holes", "0.1524,0.06985,0.00635; 0.1524,0.12065,0.00635; 0.1524,0.17145,0.00635",
          Patterns::List(Patterns::List(Patterns::Double(), 3, 3, ","), 0, Patterns::List::max_int_value, ";"),
          "Circular holes \"x,y,r; ...\" [m], inside the outline, radius > 0; empty: none. The default is the "
          "geometry of meshes/ingraffea-beam-holes.geo (Cases II, III).");
    entry(prm, "Initial crack", "0.1016,0; 0.1016,0.0254", Patterns::List(point, 2, Patterns::List::max_int_value, ";"),
          "Pre-crack polyline \"x1,y1; x2,y2; ...\" [m] inside the outline (bonds across it start broken); its last "
          "vertex is the tip the crack is traced from, along its last segment.");
    entry(prm, "Pin support", "0.0254,0", point, "x,y [m]: the nodes within the support radius have ux = uy = 0.");
    entry(prm, "Roller support", "0.4826,0", point, "x,y [m]: the nodes within the support radius have uy = 0 (ux free).");
    entry(prm, "Load point", "0.254,0.2032", point,
          "x,y [m]: the nodes within the support radius take the prescribed downward displacement d (ux free).");
    entry(prm, "Support radius", "0", Patterns::Double(0.),
          "Radius [m] of the pin, roller and load regions, in [0, half the beam's smaller side]; 0: one horizon.");
    entry(prm, "No-fail radius", "0.04", Patterns::Double(0.),
          "Bonds within this distance [m] of the pin, roller and load point stay linear elastic (no softening, "
          "no failure); 0: none, else in [Support radius, half the beam's smaller side]. A point load P gives the "
          "Flamant stress 2 P / (pi r), above the PD strength (~K_c / sqrt(pi delta), ~10 MPa at delta = 4 mm) "
          "within a few cm at the beam's failure load: without the zone the pads crush first.");
    entry(prm, "Crack damage threshold", "0.3", Patterns::Double(0., 1.),
          "A node with PD damage above this lies on the crack, in [0.05, 0.95] (crack faces reach ~0.41).");
    entry(prm, "Onset stretch ratio", "0.9", Patterns::Double(0., 1.),
          "Elastic phase: while no bond near the tip passed its inflection stretch, the relaxed state is "
          "scaled (linear response) so that the largest stretch ratio Z near the tip reaches this, in [0.001, 1].");
    entry(prm, "First increment", "0.02", Patterns::Double(0., 1.),
          "Displacement increment dd / d once bonds soften, in [Minimum increment, Maximum increment].");
    entry(prm, "Minimum increment", "0.002", Patterns::Double(0., 1.),
          "Smallest dd / d, in [1e-6, 1]: a step that grows the crack by more than the maximum advance is "
          "repeated with dd / 2 down to this.");
    entry(prm, "Maximum increment", "0.05", Patterns::Double(0., 1.), "Largest dd / d, in [Minimum increment, 1].");
    entry(prm, "Target advance", "0", Patterns::Double(0.),
          "Crack advance per step the increment aims at [m]: dd <- dd clamp(a_t / growth, 1/2, 2), doubled "
          "after a step without growth; 0: one horizon.");
    entry(prm, "Maximum advance", "0", Patterns::Double(0.),
          "A step growing the crack by more than this [m] is undone and repeated with half the increment; "
          "0 or at least the target advance; 0: four horizons.");
    entry(prm, "Maximum displacement", "0.005", Patterns::Double(0.), "Stop at this load-point displacement [m], > 0.");
    entry(prm, "Maximum steps", "400", Patterns::Integer(1), "Displacement steps at most, >= 1.");
    entry(prm, "Control", "crack mouth opening", Patterns::Selection("crack mouth opening|load point"),
          "What the steps increase once bonds soften: the crack-mouth opening (stable through the snap-back "
          "of the load-displacement curve; a servo in the relaxation moves the load pad) or the load-point "
          "displacement (the crack may run unstably).");
    entry(prm, "Servo gain", "1", Patterns::Double(0., 1.),
          "Crack-mouth control: the fraction of the opening error a servo correction removes (it moves the pad and "
          "the body along the last state's secant mode), in [1e-6, 1].");
    entry(prm, "Gauge distance", "0", Patterns::Double(0.),
          "Crack-mouth control: the opening is read between the nodes this far [m] either side of the crack "
          "mouth, in [0, a quarter of the beam's width]; 0: one horizon.");
    entry(prm, "Stall steps", "15", Patterns::Integer(1),
          "Once the crack has grown, stop after this many steps in a row without growth (the crack stopped), >= 1.");
    entry(prm, "Hole margin", "0.001", Patterns::Double(0., 1.),
          "The run stops when the crack comes within this distance [m] of a hole, in [0, 0.1].");
    entry(prm, "Output interval", "10", Patterns::Integer(1), "Write pd_NNN.vtu every n steps (and the last), >= 1.");
    entry(prm, "Published path", "", Patterns::Anything(),
          "Optional CSV of a published path (x,y [m] per line): copied to reference_path.csv and compared "
          "(symmetric mean and Hausdorff distance over its length). Relative to the current directory.");
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

  namespace
  {
    geometry::Point to_point(const std::string &text)
    {
      const auto xy = dealii::Utilities::split_string_list(text, ',');
      return {dealii::Utilities::string_to_double(xy[0]), dealii::Utilities::string_to_double(xy[1])};
    }

    /// The subsections Material and Peridynamics, shared by the PD scenes.
    void read_peridynamics(ParameterHandler &prm, local::MaterialParameters &material, double &horizon,
                           int &horizon_ratio, double &tolerance, std::size_t &max_iterations)
    {
      prm.enter_subsection("Material");
      material.youngs_modulus  = prm.get_double("Young's modulus");
      material.fracture_energy = prm.get_double("Fracture energy");
      material.density         = prm.get_double("Density");
      material.plane_strain    = prm.get_bool("Plane strain");
      prm.leave_subsection();
      prm.enter_subsection("Peridynamics");
      horizon                = prm.get_double("Horizon");
      horizon_ratio          = prm.get_integer("Horizon over spacing");
      material.influence     = local::influence_from_string(prm.get("Influence function"));
      material.break_factor  = prm.get_double("Bond break factor");
      tolerance              = prm.get_double("Relaxation tolerance");
      max_iterations         = prm.get_integer("Relaxation max iterations");
      prm.leave_subsection();
    }
  } // namespace

  LefmGrowthParameters read_lefm_growth(ParameterHandler &prm)
  {
    LefmGrowthParameters p;
    p.output_directory = output_directory(prm);
    prm.enter_subsection("Material");
    p.youngs_modulus = prm.get_double("Young's modulus");
    p.plane_strain   = prm.get_bool("Plane strain");
    prm.leave_subsection();
    prm.enter_subsection("LEFM growth");
    p.mesh_file = prm.get("Mesh file");
    p.mesh_size = prm.get_double("Mesh size");
    for (const auto &point : dealii::Utilities::split_string_list(prm.get("Initial crack"), ';'))
      p.initial_crack.push_back(to_point(point));
    p.poisson_ratio     = prm.get_double("Poisson's ratio");
    p.pin               = to_point(prm.get("Pin support"));
    p.roller            = to_point(prm.get("Roller support"));
    p.load_point        = to_point(prm.get("Load point"));
    p.load              = prm.get_double("Load");
    p.growth_increment  = prm.get_double("Growth increment");
    p.halving_angle     = prm.get_double("Increment halving angle");
    p.max_steps         = prm.get_integer("Maximum steps");
    p.max_crack_length  = prm.get_double("Maximum crack length");
    p.tip_radius        = prm.get_double("Tip enrichment radius");
    p.iterative_solver  = prm.get("Linear solver") == "cg-amg";
    p.refinement_levels = prm.get_integer("Refinement levels near the tip");
    p.refinement_radius = prm.get_double("Refinement radius");
    p.hole_margin       = prm.get_double("Hole margin");
    p.output_interval   = prm.get_integer("Output interval");
    p.published_path    = prm.get("Published path");
    prm.leave_subsection();
    return p;
  }

  EdgeCrackParameters read_edge_crack(ParameterHandler &prm)
  {
    EdgeCrackParameters p;
    p.output_directory = output_directory(prm);
    read_peridynamics(prm, p.material, p.horizon, p.horizon_ratio, p.tolerance, p.max_iterations);
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

namespace pumpd::coupling
{
  GlobalLocalParameters read_global_local(ParameterHandler &prm)
  {
    GlobalLocalParameters p;
    p.output_directory = output_directory(prm);
    read_peridynamics(prm, p.material, p.horizon, p.horizon_ratio, p.tolerance, p.max_iterations);
    prm.enter_subsection("Global-local");
    p.mesh_file = prm.get("Mesh file");
    p.mesh_size = prm.get_double("Mesh size");
    for (const auto &point : dealii::Utilities::split_string_list(prm.get("Initial crack"), ';'))
      p.initial_crack.push_back(to_point(point));
    p.poisson_ratio                 = prm.get_double("Poisson's ratio");
    p.pin                           = to_point(prm.get("Pin support"));
    p.roller                        = to_point(prm.get("Roller support"));
    p.load_point                    = to_point(prm.get("Load point"));
    p.reference_load                = prm.get_double("Reference load");
    p.iterative_solver              = prm.get("Linear solver") == "cg-amg";
    p.tip_radius                    = prm.get_double("Tip enrichment radius");
    p.refinement_levels             = prm.get_integer("Refinement levels near the tip");
    p.refinement_radius             = prm.get_double("Refinement radius");
    p.box.size                      = prm.get_double("Box size");
    p.box.behind                    = prm.get_double("Box tip position");
    p.box.margin                    = prm.get_double("Box margin");
    p.box.max_size                  = prm.get_double("Maximum box size");
    p.crack_damage                  = prm.get_double("Crack damage threshold");
    p.exchange.first_load_factor    = prm.get_double("First load factor");
    p.exchange.load_increment       = prm.get_double("Load increment");
    p.exchange.min_load_increment   = prm.get_double("Minimum load increment");
    p.exchange.max_load_factor      = prm.get_double("Maximum load factor");
    p.exchange.max_advance          = prm.get_double("Maximum advance");
    p.exchange.min_advance          = prm.get_double("Minimum advance");
    p.exchange.near_distance        = prm.get_double("Near distance");
    p.exchange.start_below_accepted = prm.get_bool("Start below the last load");
    p.max_exchanges                 = prm.get_integer("Maximum exchanges");
    p.max_crack_length              = prm.get_double("Maximum crack length");
    p.hole_margin                   = prm.get_double("Hole margin");
    p.reference_box_area            = prm.get_double("Reference box area");
    p.output_interval               = prm.get_integer("Output interval");
    p.published_path                = prm.get("Published path");
    p.resume                        = prm.get_bool("Resume");
    prm.leave_subsection();
    return p;
  }
} // namespace pumpd::coupling

namespace pumpd::coupling
{
  FullPdParameters read_full_pd(ParameterHandler &prm)
  {
    FullPdParameters p;
    p.output_directory = output_directory(prm);
    read_peridynamics(prm, p.material, p.horizon, p.horizon_ratio, p.tolerance, p.max_iterations);
    prm.enter_subsection("Full PD");
    const auto corners = dealii::Utilities::split_string_list(prm.get("Beam outline"), ';');
    const auto lo = to_point(corners[0]), hi = to_point(corners[1]);
    p.outline = {lo.x, lo.y, hi.x, hi.y};
    p.holes.clear();
    for (const auto &hole : dealii::Utilities::split_string_list(prm.get("Holes"), ';'))
      {
        const auto v = dealii::Utilities::split_string_list(hole, ',');
        p.holes.push_back({{dealii::Utilities::string_to_double(v[0]), dealii::Utilities::string_to_double(v[1])},
                           dealii::Utilities::string_to_double(v[2])});
      }
    p.initial_crack.clear();
    for (const auto &point : dealii::Utilities::split_string_list(prm.get("Initial crack"), ';'))
      p.initial_crack.push_back(to_point(point));
    p.pin                 = to_point(prm.get("Pin support"));
    p.roller              = to_point(prm.get("Roller support"));
    p.load_point          = to_point(prm.get("Load point"));
    p.support_radius      = prm.get_double("Support radius");
    p.no_fail_radius      = prm.get_double("No-fail radius");
    p.crack_damage        = prm.get_double("Crack damage threshold");
    p.onset_stretch_ratio = prm.get_double("Onset stretch ratio");
    p.first_increment     = prm.get_double("First increment");
    p.min_increment       = prm.get_double("Minimum increment");
    p.max_increment       = prm.get_double("Maximum increment");
    p.target_advance      = prm.get_double("Target advance");
    p.max_advance         = prm.get_double("Maximum advance");
    p.max_displacement    = prm.get_double("Maximum displacement");
    p.control             = prm.get("Control") == "load point" ? FullPdParameters::Control::load_point
                                                               : FullPdParameters::Control::crack_mouth_opening;
    p.servo_gain          = prm.get_double("Servo gain");
    p.gauge_distance      = prm.get_double("Gauge distance");
    p.max_steps           = prm.get_integer("Maximum steps");
    p.stall_steps         = prm.get_integer("Stall steps");
    p.hole_margin         = prm.get_double("Hole margin");
    p.output_interval     = prm.get_integer("Output interval");
    p.published_path      = prm.get("Published path");
    prm.leave_subsection();
    return p;
  }
} // namespace pumpd::coupling
