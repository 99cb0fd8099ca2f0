#include "full_pd.h"

#include <deal.II/base/parameter_handler.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <tuple>
#include <utility>

#include "arrival.h"
#include "boundary_layer.h"
#include "crack_extraction.h"
#include "crack_traces.h"
#include "error.h"
#include "exchange.h"
#include "integrators.h"
#include "model.h"
#include "nucleation.h"
#include "path_metrics.h"
#include "pd_conditions.h"
#include "recorder.h"

namespace pumpd::coupling
{
  using geometry::Point;
  using Clock        = std::chrono::steady_clock;
  namespace Patterns = dealii::Patterns;

  void FullPdControlSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Full PD");
    prm.add_parameter("Support radius", support_radius,
                      "Point conditions and loading pads act on the nodes within this radius [m] of their point; 0: "
                      "one horizon. At most half the body's smaller side.",
                      Patterns::Double(0.));
    prm.add_parameter("No-fail radius in horizons", no_fail_horizons,
                      "Bonds within this many horizons of a point condition or pad stay linear elastic (a no-fail "
                      "zone: the pads would crush otherwise), at most a quarter of the body's smaller side (so "
                      "that a crack can still run towards the pad of a slender beam); 0: none.",
                      Patterns::Double(0., 1000.));
    prm.add_parameter("Onset stretch ratio", onset_stretch_ratio,
                      "The elastic phase jumps to the displacement where the largest stretch ratio Z near the tip "
                      "reaches this (the state scaled: linear response).",
                      Patterns::Double(1e-3, 1.));
    prm.add_parameter("First increment", first_increment,
                      "dd / d once bonds soften, in [Minimum increment, Maximum increment].", Patterns::Double(1e-6, 1.));
    prm.add_parameter("Minimum increment", min_increment,
                      "Smallest dd / d: a step that grows the crack by more than the maximum advance is repeated with "
                      "dd / 2 down to this.",
                      Patterns::Double(1e-6, 1.));
    prm.add_parameter("Maximum increment", max_increment, "Largest dd / d, at least the minimum increment.",
                      Patterns::Double(1e-6, 1.));
    prm.add_parameter("Target advance", target_advance,
                      "Crack advance per step the increment aims at [m]: dd <- dd clamp(a_t / growth, 1/2, 2), doubled "
                      "after a step without growth; 0: one horizon.",
                      Patterns::Double(0.));
    prm.add_parameter("Maximum advance", max_advance,
                      "A step growing the crack by more than this [m] is undone and repeated with half the increment; "
                      "0 (four horizons) or at least the target advance.",
                      Patterns::Double(0.));
    prm.add_parameter("Maximum displacement", max_displacement,
                      "Stop when the control displacement d (the largest prescribed displacement) reaches this [m]; "
                      "0: no limit.",
                      Patterns::Double(0.));
    prm.add_parameter("Maximum steps", max_steps, "Displacement steps at most.", Patterns::Integer(1));
    prm.add_parameter("Control", control,
                      "What the steps increase once bonds soften: the crack-mouth opening (stable through the "
                      "snap-back of the load-displacement curve; a servo in the relaxation moves the driven "
                      "displacements; needs a crack with a mouth: without an initial crack, the one that forms, "
                      "from when it forms) or the control displacement d (the crack may run unstably).",
                      Patterns::Selection("crack mouth opening|load point"));
    prm.add_parameter("Servo gain", servo_gain,
                      "Crack-mouth control: the fraction of the opening error a servo correction removes.",
                      Patterns::Double(1e-6, 1.));
    prm.add_parameter("Gauge distance", gauge_distance,
                      "Crack-mouth control: the opening is read between the nodes this far [m] either side of the "
                      "crack's mouth, at most a quarter of the body's width; 0: one horizon across an initial "
                      "crack's mouth, four across a crack that forms (out of its softening zone; at most a quarter "
                      "of the body's smaller side).",
                      Patterns::Double(0.));
    prm.add_parameter("Stall steps", stall_steps,
                      "Once the crack has grown, stop after this many steps in a row without growth (once the "
                      "steps are taken in the crack-mouth opening, only when the drive has also risen by (1 + "
                      "Maximum increment)^n since the last growth).",
                      Patterns::Integer(1));
    prm.add_parameter("Output interval", output_interval, "Write pd_NNN.vtu every n steps (and the last).",
                      Patterns::Integer(1));
    prm.add_parameter("Equilibrium error", equilibrium_error,
                      "Dynamic relaxation of the whole body stops when its residual |f| / (k |u - u_rigid|) is below "
                      "this times (h / L)^2 (L the larger side of the body, h the spacing; the body's slowest mode is "
                      "about (h / L)^2 as stiff as a bond, so this bounds the displacement error relative to the "
                      "deformation), or below the Peridynamics section's Relaxation tolerance where that is smaller.",
                      Patterns::Double(1e-12, 1.));
    prm.leave_subsection();
  }

  double FullPdControlSettings::relaxation_tolerance(double tolerance, double spacing, double size) const
  {
    return std::min(tolerance, equilibrium_error * (spacing / size) * (spacing / size));
  }

  namespace
  {
    double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

    std::string text(double v)
    {
      std::ostringstream s;
      s << v;
      return s.str();
    }

    void validate(const Scene &scene, const FullPdControlSettings &p)
    {
      const auto &o = scene.body.bounding_box();
      if (p.support_radius > 0.5 * std::min(o.width(), o.height()))
        throw InvalidParameter("Support radius", text(p.support_radius),
                               "must be in [0, half the body's smaller side] m (0: one horizon)");
      require_range("Maximum increment", p.max_increment, p.min_increment, 1., "must be in [Minimum increment, 1]");
      require_range("First increment", p.first_increment, p.min_increment, p.max_increment,
                    "must be in [Minimum increment, Maximum increment]");
      if (p.gauge_distance > 0.25 * o.width())
        throw InvalidParameter("Gauge distance", text(p.gauge_distance),
                               "must be in [0, a quarter of the body's width] m (0: one horizon across an "
                               "initial crack, four across a crack that forms)");
      if (!scene.conditions.tractions.empty())
        throw InvalidParameter("Traction", scene.conditions.tractions.front().place.name,
                               "full PD drives a scene by one displacement: tractions cannot be applied (prescribe a "
                               "displacement, or load through a point force, which becomes a loading pad)");
      const double on_face = 1e-8 * std::max(o.width(), o.height());
      for (std::size_t a = 0; a < scene.cracks.size(); ++a)
        for (std::size_t b = 0; b < scene.cracks.size(); ++b)
          for (const Point end : {scene.cracks[a].front(), scene.cracks[a].back()})
            if (a != b && distance_to_polyline(end, scene.cracks[b]) <= on_face)
              throw InvalidParameter("Initial cracks", to_text(scene.cracks[a]) + " | " + to_text(scene.cracks[b]),
                                     "full PD traces a crack from its tips: an end on another crack's face (a "
                                     "junction) is grown by lefm-growth and global-local; give the cracks apart");
    }

    /// The prescribed regions of the scene, with the displacement of each per unit control
    /// displacement d (zero for supports), and the load factor of a state at d.
    struct Drive
    {
      std::vector<local::PrescribedRegion>                     regions;
      std::vector<std::function<Point(Point)>>                 unit;       ///< per region
      std::vector<std::string>                                 place_name; ///< per region
      std::vector<bool>                                        at_point;   ///< per region: a point's disk
      bool                                                     pad = false; ///< d is a pad's displacement
      Point                                                    force;       ///< the pad's force per unit lambda
      double                                                   largest = 1.; ///< lambda-scaled displacements: d / lambda

      Drive(const Scene &scene, double radius, double band)
      {
        for (const auto &d : scene.conditions.displacements)
          {
            regions.push_back(local::prescribed_region(d.place, d.ux.has_value(), d.uy.has_value(), radius, band));
            place_name.push_back(d.place.name);
            at_point.push_back(d.place.kind == conditions::Place::Kind::point);
            unit.push_back([d](Point x) { return Point{d.ux ? (*d.ux)(x) : 0., d.uy ? (*d.uy)(x) : 0.}; });
          }
        double g = 0.;
        for (std::size_t r = 0; r < regions.size(); ++r)
          for (const auto &x : scene.conditions.displacements[r].place.points)
            g = std::max(g, geometry::norm(unit[r](x)));
        if (scene.conditions.forces.size() > 1 || (!scene.conditions.forces.empty() && g > 0.))
          throw InvalidParameter("Point force", scene.conditions.forces.front().place.name,
                                 "full PD drives a scene by one displacement: one point force (a loading pad), or "
                                 "displacement conditions that lambda scales, not both or several forces");
        if (!scene.conditions.forces.empty())
          {
            const auto &f = scene.conditions.forces.front();
            pad           = true;
            force         = f.force;
            const Point e = (1. / geometry::norm(f.force)) * f.force;
            regions.push_back(local::prescribed_region(f.place, f.force.x != 0., f.force.y != 0., radius, band));
            place_name.push_back(f.place.name);
            at_point.push_back(true);
            unit.push_back([e](Point) { return e; });
            return;
          }
        largest = g;
        for (auto &u : unit)
          u = [u, g](Point x) { return (1. / g) * u(x); };
      }
    };

    /// Where a crack forms in a body without one: its mouth on the outline or a hole's rim, the
    /// material node next to it the ridge is traced from, and the direction it leaves the mouth in.
    struct Seed
    {
      Point mouth, start, direction;
    };

    /// The seed of the crack in `field` (per node the damage): at the most damaged node within a
    /// spacing of the boundary whose damage reaches `threshold`, among the nodes `eligible`; its
    /// mouth the nearest boundary point, its direction towards the damage-weighted centroid of the
    /// nodes above the threshold within three horizons of the mouth. None while no node qualifies.
    std::optional<Seed> seed_crack(const local::PdModel &model, const DamageField &field,
                                   const std::vector<char> &eligible, double threshold, double horizon)
    {
      const auto &lattice = model.lattice();
      const auto &body    = model.region().body;
      const auto  damage  = [&](std::size_t i) { return field.values[lattice.row(i) * field.nx + lattice.column(i)]; };
      std::optional<std::size_t> best;
      for (std::size_t i : model.nodes())
        if (eligible[i] && damage(i) >= threshold && body.clearance(lattice.position(i)) < lattice.spacing() &&
            (!best || damage(i) > damage(*best)))
          best = i;
      if (!best)
        return std::nullopt;
      const Point  mouth  = nearest_boundary_point(body, lattice.position(*best));
      const double radius = 3. * horizon;
      Point        moment;
      double       mass = 0.;
      for (std::size_t i : model.nodes())
        {
          const Point x = lattice.position(i);
          if (eligible[i] && damage(i) >= threshold && geometry::norm(x - mouth) < radius)
            {
              moment = moment + (damage(i) - threshold) * (x - mouth);
              mass += damage(i) - threshold;
            }
        }
      if (mass <= 0. || geometry::norm(moment) < 1e-3 * lattice.spacing() * mass)
        return std::nullopt;
      return Seed{mouth, lattice.position(*best), (1. / geometry::norm(moment)) * moment};
    }

    /// A crack formed inside the body, with no mouth on the boundary.
    struct InteriorCrack
    {
      Point              site; ///< its most damaged node
      geometry::Polyline path; ///< from one tip through the site to the other
      std::string        ends; ///< why each way's trace ended
    };

    /// The crack in `field` at the most damaged of the nodes `eligible` that lie at least a horizon
    /// inside the body and whose damage reaches the threshold: traced both ways from that node
    /// along the principal axis of the damage above the threshold within three horizons of it
    /// (the direction of its second moment's largest eigenvalue), each way until its ridge ends or
    /// splits. None while no node qualifies.
    std::optional<InteriorCrack> interior_crack(const local::PdModel &model, const DamageField &field,
                                                const std::vector<char> &eligible, ExtractionSettings extraction)
    {
      const auto &lattice = model.lattice();
      const auto  damage  = [&](std::size_t i) { return field.values[lattice.row(i) * field.nx + lattice.column(i)]; };
      const auto  cracked = [&](std::size_t i) { return eligible[i] && damage(i) >= extraction.threshold; };
      std::optional<std::size_t> best;
      for (std::size_t i : model.nodes())
        if (cracked(i) && model.region().body.clearance(lattice.position(i)) >= extraction.horizon &&
            (!best || damage(i) > damage(*best)))
          best = i;
      if (!best)
        return std::nullopt;
      const Point site = lattice.position(*best);
      double      sxx = 0., sxy = 0., syy = 0.;
      for (std::size_t i : model.nodes())
        if (const Point r = lattice.position(i) - site; cracked(i) && geometry::norm(r) < 3. * extraction.horizon)
          {
            const double weight = damage(i) - extraction.threshold;
            sxx += weight * r.x * r.x;
            sxy += weight * r.x * r.y;
            syy += weight * r.y * r.y;
          }
      const double angle = 0.5 * std::atan2(2. * sxy, sxx - syy);
      const Point  axis{std::cos(angle), std::sin(angle)};
      extraction.branch_ends_trace = true;
      const auto ahead  = extract_crack(field, site, axis, extraction);
      const auto behind = extract_crack(field, site, -1. * axis, extraction);
      InteriorCrack crack{site, {behind.path.rbegin(), behind.path.rend()}, ahead.stop_reason + "; " + behind.stop_reason};
      crack.path.insert(crack.path.end(), ahead.path.begin() + 1, ahead.path.end());
      return crack;
    }

    /// Thrown by the servo when the drive it needs leaves the range a softening body allows.
    struct ServoLost
    {};

    double peak_rss_mb()
    {
      rusage usage{};
      getrusage(RUSAGE_SELF, &usage);
      return double(usage.ru_maxrss) / 1024.; // kB on Linux
    }
  } // namespace

  local::ModelMemory full_pd_memory(const Scene &scene, const PeridynamicsSettings &pd)
  {
    const local::Lattice        grid(scene.body.bounding_box(), pd.spacing(), pd.horizon_over_spacing);
    const local::LiptonMaterial material(pd.material(scene.material), pd.horizon);
    return local::model_memory(grid, local::make_half_stencil(pd.horizon_over_spacing, material));
  }

  FullPdResult run_full_pd(const Scene &scene, const FullPdSettings &settings, std::ostream &out)
  {
    const auto &p  = settings.full_pd;
    const auto &pd = settings.pd;
    validate(scene, p);
    const auto   t0     = Clock::now();
    const double h      = pd.spacing();
    const double radius = p.support_radius > 0. ? p.support_radius : pd.horizon;
    const double a_t    = p.target_advance > 0. ? p.target_advance : pd.horizon;
    const double a_max  = p.max_advance > 0. ? p.max_advance : 4. * pd.horizon;
    const double d_max  = p.max_displacement > 0. ? p.max_displacement : std::numeric_limits<double>::infinity();
    for (const auto &[name, length] : {std::pair{"Support radius", p.support_radius}, {"Gauge distance", p.gauge_distance}})
      if (length > 0. && length < h)
        throw InvalidParameter(name, text(length), "must be 0 or at least the PD spacing h = " + text(h) + " m");
    if (p.max_advance > 0. && p.max_advance < a_t)
      throw InvalidParameter("Maximum advance", text(p.max_advance),
                             "must be 0 or at least the target advance (" + text(a_t) + " m)");

    // The cracks, each its mouth first: they are traced from their tips (the first crack's mouth
    // holds the gauges). Without one, the crack is traced from the seed (seed_crack) of the damage;
    // the mouth is not known before the crack forms, so the steps are taken in the control
    // displacement.
    const double on_boundary = 1e-8 * scene.body.bounding_box().width();
    CrackTraces  traces(scene.cracks, scene.body, on_boundary);
    const geometry::Polyline initial   = scene.cracks.empty() ? geometry::Polyline{} : traces.paths().front();
    const bool               has_mouth = !initial.empty() && scene.body.clearance(initial.front()) <= on_boundary;
    const bool by_mouth = p.control == "crack mouth opening";
    if (by_mouth && !initial.empty() && !has_mouth)
      throw InvalidParameter("Control", p.control,
                             "crack-mouth control needs a crack with a mouth on the outline or a hole's rim; use load point");

    Drive        drive(scene, radius, pd.horizon);
    const double no_fail_radius =
      std::min(p.no_fail_horizons * pd.horizon,
               0.25 * std::min(scene.body.bounding_box().width(), scene.body.bounding_box().height()));
    if (no_fail_radius > 0.)
      for (std::size_t r = 0; r < drive.regions.size(); ++r)
        if (drive.at_point[r])
          drive.regions[r].elastic_margin = std::max(0., no_fail_radius - radius);
    const local::PdModel model(pd.material(scene.material), pd.horizon, pd.horizon_over_spacing,
                               local::Region{scene.body, scene.body.bounding_box(), scene.cracks}, drive.regions);
    std::vector<local::RegionDisplacement> prescribed;
    std::vector<std::vector<Point>>        unit_at_node;
    for (std::size_t r = 0; r < drive.regions.size(); ++r)
      {
        prescribed.emplace_back(model, r);
        std::vector<Point> u;
        for (std::size_t i : prescribed.back().nodes())
          u.push_back(drive.unit[r](model.lattice().position(i)));
        unit_at_node.push_back(u);
      }
    // The prescribed displacements at control displacement d.
    const auto drive_to = [&](double d, local::State &st) {
      for (std::size_t r = 0; r < prescribed.size(); ++r)
        {
          std::vector<double> ux, uy;
          for (const auto &u : unit_at_node[r])
            {
              ux.push_back(d * u.x);
              uy.push_back(d * u.y);
            }
          prescribed[r].set_target(ux, uy);
          prescribed[r].apply(st, 1.);
        }
    };
    // The scene's load factor, load and displacement of a state at control displacement d.
    const auto lambda_of = [&](double d, const local::State &st) {
      if (!drive.pad)
        return d / drive.largest;
      const Point f = prescribed.back().reaction(st);
      return geometry::dot(f, drive.force) / geometry::dot(drive.force, drive.force);
    };
    const auto report = [&](double lambda, const local::State &st) {
      const auto &r     = scene.report;
      const auto  pick  = [](Point v, int c) { return c == 0 ? v.x : v.y; };
      double      load  = lambda, displacement = 0.;
      if (!r.load_is_lambda)
        {
          Point f;
          for (std::size_t k = 0; k < prescribed.size(); ++k)
            if (drive.place_name[k] == r.load_place.name)
              f = f + prescribed[k].reaction(st);
          load = r.load_sign * pick(f, r.load_component);
        }
      if (r.work_conjugate)
        displacement = lambda != 0. ? 2. * model.elastic_energy(st) / lambda : 0.;
      else if (r.displacement_place.kind == conditions::Place::Kind::point)
        {
          const std::size_t i = model.nearest_node(r.displacement_place.points.front());
          displacement        = r.displacement_sign * pick(Point{st.ux[i], st.uy[i]}, r.displacement_component);
        }
      else
        {
          Point       sum;
          std::size_t n = 0;
          for (std::size_t i : model.nodes())
            for (const auto &e : r.displacement_place.edges)
              if (geometry::distance_to_segment(model.lattice().position(i), e[0], e[1]) < h)
                {
                  sum = sum + Point{st.ux[i], st.uy[i]};
                  ++n;
                  break;
                }
          displacement = n > 0 ? r.displacement_sign * pick((1. / n) * sum, r.displacement_component) : 0.;
        }
      return std::pair<double, double>{load, displacement};
    };
    const auto                    &extent = scene.body.bounding_box();
    const double                   tolerance =
      p.relaxation_tolerance(pd.tolerance, h, std::max(extent.width(), extent.height()));
    const local::DynamicRelaxation relax(model, tolerance, pd.max_iterations);
    const double                   n_nodes = double(model.nodes().size());

    // Nodes a crack may seed at: a horizon clear of every prescribed region and no-fail zone.
    std::vector<char> seedable(model.lattice().storage_size(), 0);
    for (std::size_t i : model.nodes())
      seedable[i] = std::none_of(drive.regions.begin(), drive.regions.end(), [&](const local::PrescribedRegion &r) {
        return r.contains(model.lattice().position(i), std::max(0., r.elastic_margin) + pd.horizon);
      });
    std::optional<Seed> seed;
    ExtractionSettings  extraction;
    extraction.threshold = pd.crack_damage;
    extraction.horizon   = pd.horizon;
    const double length0 = traces.length();

    // Crack-mouth opening w: the relative displacement of two gauge nodes either side of the
    // mouth, along the normal to the crack's first segment: the initial crack's, or a seeded
    // crack's once it forms (none before). The default gauge distance is one horizon across a
    // notch; across a crack that has just formed, whose softening zone still reaches a horizon or
    // two from its mouth, four horizons (at most a quarter of the body's smaller side), so that
    // the opening the servo holds is the body's elastic response, not that of softening bonds.
    Point       normal;
    std::size_t gauge_minus = model.nodes().front(), gauge_plus = gauge_minus;
    const auto  place_gauges = [&](Point mouth, Point direction, double default_gauge) {
      const double gauge = p.gauge_distance > 0. ? p.gauge_distance : default_gauge;
      normal             = {direction.y, -direction.x};
      gauge_minus        = model.nearest_node(mouth - gauge * normal);
      gauge_plus         = model.nearest_node(mouth + gauge * normal);
    };
    if (by_mouth && !initial.empty())
      place_gauges(initial[0], (1. / geometry::norm(initial[1] - initial[0])) * (initial[1] - initial[0]), pd.horizon);
    const auto mouth_opening = [&](const local::State &st) {
      return (st.ux[gauge_plus] - st.ux[gauge_minus]) * normal.x + (st.uy[gauge_plus] - st.uy[gauge_minus]) * normal.y;
    };

    // Nodes near the initial tips (without a crack: every node a crack may seed at): their stretch
    // ratio decides the elastic jump (the pads' own stress concentrations do not).
    const auto               tips0 = traces.initial_tips();
    std::vector<std::size_t> near_tip;
    for (std::size_t i : model.nodes())
      if (initial.empty() ? bool(seedable[i]) : std::any_of(tips0.begin(), tips0.end(), [&](Point tip) {
            return geometry::norm(model.lattice().position(i) - tip) < 2. * pd.horizon;
          }))
        near_tip.push_back(i);

    Recorder recorder(scene);
    CsvFile  table = recorder.table("load_steps.csv", "step,control_displacement_m,crack_mouth_opening_m,lambda,load,"
                                                     "displacement,crack_length_m,tip_x_m,tip_y_m,dr_iterations,"
                                                     "dr_converged,repeats,seconds");
    // The cracks are traced from their tips: the initial ones, or one that formed inside the
    // body (interior_crack); else the crack is traced from its seed.
    bool from_tips = !initial.empty();
    // Every crack as accepted (without cracks traced from tips, the crack the seed forms).
    const auto paths = [&](const geometry::Polyline &seeded) {
      return from_tips ? traces.paths() : std::vector<geometry::Polyline>{seeded};
    };
    recorder.crack_paths(paths(initial));
    std::size_t prescribed_nodes = 0;
    for (const auto &r : prescribed)
      prescribed_nodes += r.size();
    out << "full PD: " << scene.mesh_file << ", " << scene.body.holes().size() << " holes, initial cracks "
        << scene.cracks.size() << " (tips " << tips0.size() << ", " << length0 << " m); delta " << pd.horizon
        << " m, m = " << pd.horizon_over_spacing << ", h = " << h << " m: " << model.nodes().size() << " nodes; "
        << prescribed.size() << " prescribed regions (" << prescribed_nodes << " nodes), "
        << (drive.pad ? "a loading pad" : "lambda-scaled displacements") << ", no-fail radius "
        << no_fail_radius << " m (" << model.linear_bond_count()
        << " linear bonds); relaxation tolerance " << tolerance << "; K_c = " << model.material().critical_sif()
        << " Pa m^1/2" << std::endl;
    if (initial.empty())
      out << "full PD: no initial crack: it is traced from where the damage first reaches the boundary (or, where "
             "a crack forms inside the body, from its two tips), under load-point control"
          << (by_mouth ? " until it forms, then under the opening of its mouth (if the gauges across it open)" : "")
          << std::endl;

    FullPdResult result;
    result.nodes   = model.nodes().size();
    result.path    = initial;
    local::State s = model.initial_state();
    // The damage the crack is traced through: per node the largest of the accepted states.
    DamageField         traced;
    std::vector<double> ux_prev(s.ux.size(), 0.), uy_prev(s.uy.size(), 0.); // last accepted state
    // d: the controlled displacement (the drive, or the crack-mouth opening once the servo is on);
    // pad: the drive's displacement.
    double      d = 0., dd_prev = 0., pad = 0., pad_prev = 0.;
    bool        servo_on   = false;
    bool        gauges_tried = false; // across a seeded crack's mouth
    double      pad_over_w = 0.; // (d/w)_0 of the servo
    double      dd = 0.01 * (p.max_displacement > 0. ? p.max_displacement : 1e-2 * scene.body.bounding_box().width());
    bool        elastic   = true;
    bool        grown     = false;
    std::size_t stalled   = 0;
    double      pad_grown = 0.; // the drive at the last growth
    double      length    = length0;
    double      growth_t0 = 0.;
    // From here on d is the crack-mouth opening of state st: the servo holds it, with the drive's
    // displacement per unit opening (d/w)_0 of st, and the increments are taken in it.
    const auto steps_in_opening = [&](const local::State &st) {
      servo_on   = true;
      pad_over_w = pad / mouth_opening(st);
      d          = mouth_opening(st);
      dd /= pad_over_w;
      dd_prev /= pad_over_w;
    };

    // A tip within half a horizon of a no-fail zone has reached it: the zone's bonds do not break.
    const auto no_fail_arrival = [&](const std::vector<geometry::Polyline> &cracks) -> std::string {
      for (const auto &crack : cracks)
        for (std::size_t end = 0; crack.size() > 1 && end < 2; ++end)
          if (const Point tip = end == 0 ? crack.front() : crack.back(); scene.body.clearance(tip) > on_boundary)
            for (std::size_t r = 0; r < drive.regions.size(); ++r)
              if (drive.regions[r].elastic_margin >= 0. &&
                  drive.regions[r].contains(tip, drive.regions[r].elastic_margin + 0.5 * pd.horizon))
                return "a tip reached the no-fail zone of " + drive.place_name[r] + " at " + to_text(tip) +
                       " (its bonds do not break: No-fail radius in horizons)";
      return {};
    };
    // Bond-based PD's potential is even in the stretch: where bonds soften in compression too, the
    // compressed side of a body without a notch (a bending specimen's) softens about as soon as the
    // stretched side. Said when the crack forms, where bonds have softened in compression by then.
    const auto note_compression = [&](const local::State &st) {
      const auto  zc = model.compressive_stretch_ratio(st);
      double      z  = 0.;
      std::size_t at = 0;
      for (std::size_t i : near_tip)
        if (zc[i] > z)
          std::tie(z, at) = std::pair{zc[i], i};
      if (z >= 1.)
        out << "  note: bonds have softened in compression too, up to Z = " << z << " at "
            << to_text(model.lattice().position(at))
            << " (Bond law in compression = softening): the crack may have started where the body is compressed, "
               "or been drawn there; Bond law in compression = linear fails bonds in tension only"
            << std::endl;
    };
    // Back to the drive's displacement d, for good, from a state whose opening the servo could not
    // hold.
    const auto steps_in_drive = [&] {
      servo_on = false;
      d        = pad;
      dd *= pad_over_w;
      dd_prev *= pad_over_w;
    };

    for (std::size_t n = 1;; ++n)
      {
        if (n > p.max_steps)
          {
            result.stop_reason = "maximum steps";
            break;
          }
        if (pad >= d_max * (1. - 1e-12))
          {
            result.stop_reason = "maximum displacement";
            break;
          }
        if (!servo_on)
          dd = std::min(dd, d_max - d);
        const auto   t_step = Clock::now();
        FullPdStep   step;
        step.step = n;
        const local::State saved = s;
        CrackIncrement              increment;  // of the seeded crack
        std::vector<CrackIncrement> increments; // of every tip of the initial cracks
        DamageField                 field;
        std::string                 branching;
        double             d_new = d + dd, pad_new = pad, growth = 0., last_growth = 0., traced_length = 0.;
        for (;;)
          {
            d_new = d + dd;
            // Predictor: elastic, the state scaled to the new displacement; later the last
            // increment extrapolated.
            pad_new = d_new;
            if (elastic && d > 0.)
              for (std::size_t i : model.nodes())
                {
                  s.ux[i] *= d_new / d;
                  s.uy[i] *= d_new / d;
                }
            else if (dd_prev > 0.)
              {
                const double r = dd / dd_prev;
                for (std::size_t i : model.nodes())
                  {
                    const double ux = s.ux[i], uy = s.uy[i];
                    s.ux[i] += r * (ux - ux_prev[i]);
                    s.uy[i] += r * (uy - uy_prev[i]);
                  }
                if (servo_on)
                  pad_new = pad + r * (pad - pad_prev);
              }
            else if (servo_on)
              pad_new = pad + pad_over_w * dd;
            drive_to(pad_new, s);
            local::Servo servo;
            if (servo_on)
              {
                // The opening misses its target by e: move the drive by (d/w) e and, with it, the
                // whole body along the secant mode saved / pad (the last accepted state per unit
                // drive displacement), so that the body follows the drive at once instead of over
                // the relaxation's slowest period; the relaxation then settles the rest.
                servo.tolerance = 0.1 * dd / d_new;
                servo.correct   = [&](local::State &st) {
                  const double error = d_new - mouth_opening(st);
                  if (std::abs(error) < servo.tolerance * d_new)
                    return std::abs(error) / d_new;
                  const double move  = p.servo_gain * pad_over_w * error;
                  const double share = move / pad; // of the secant mode saved / pad
                  for (std::size_t i : model.nodes())
                    {
                      st.ux[i] += share * saved.ux[i];
                      st.uy[i] += share * saved.uy[i];
                    }
                  pad_new += move;
                  // In a softening body the drive that holds a slightly larger opening stays
                  // positive and below twice the last one; outside, the servo chases a state with
                  // no equilibrium at this opening and would diverge.
                  if (!(pad_new > 0. && pad_new < 2. * pad))
                    throw ServoLost{};
                  drive_to(pad_new, st);
                  return std::abs(d_new - mouth_opening(st)) / d_new;
                };
              }
            local::RelaxationResult relaxed;
            try
              {
                relaxed = relax.solve(s, servo);
              }
            catch (const ServoLost &)
              {
                out << "  step " << n << ": the servo lost the opening (the drive left (0, " << 2e3 * pad
                    << "] mm): from here on the steps are taken in the drive's displacement, repeated\n";
                s = saved;
                steps_in_drive();
                continue;
              }
            step.iterations += relaxed.iterations;
            step.converged = relaxed.converged;
            result.node_steps += n_nodes * double(relaxed.iterations);
            if (!relaxed.converged)
              out << "  warning: dynamic relaxation stopped at residual " << relaxed.residual << " after "
                  << relaxed.iterations << " iterations\n";
            try
              {
                field = damage_field(model, s);
                if (!traced.values.empty())
                  for (std::size_t k = 0; k < field.values.size(); ++k)
                    field.values[k] = std::max(field.values[k], traced.values[k]);
                // Without an initial crack the seed follows the damage until the crack is a
                // horizon long.
                if (!from_tips && length < pd.horizon)
                  seed = seed_crack(model, field, seedable, pd.crack_damage, pd.horizon);
                if (from_tips)
                  {
                    increments    = traces.extract(field, extraction, 0.5 * pd.horizon);
                    traced_length = traces.traced_length(increments);
                  }
                else
                  {
                    if (seed)
                      {
                        increment         = extract_crack(field, seed->start, seed->direction, extraction);
                        increment.path[0] = seed->mouth;
                      }
                    else
                      increment = CrackIncrement{};
                    traced_length = length0 + increment.length();
                  }
              }
            catch (const CrackBranching &e)
              {
                branching = e.what();
                break;
              }
            growth = std::max(0., traced_length - length);
            // Repeat a too-long advance with half the increment, unless halving did not shorten it
            // (unstable growth, a snap-back: the crack runs at any increment; accepted as it is).
            const bool shorter = step.repeats == 0 || growth < 0.75 * last_growth;
            last_growth        = growth;
            if (growth > a_max && shorter && dd > p.min_increment * d * (1. + 1e-9) && !elastic)
              {
                out << "  step " << n << ": d " << d_new << " m grew the crack by " << 1e3 * growth
                    << " mm (> maximum advance): repeated with half the increment\n";
                s  = saved;
                dd = std::max(0.5 * dd, p.min_increment * d);
                ++step.repeats;
                continue;
              }
            break;
          }
        result.seconds_relaxation += seconds_since(t_step);

        // Accept the state.
        for (std::size_t i : model.nodes())
          {
            ux_prev[i] = saved.ux[i];
            uy_prev[i] = saved.uy[i];
          }
        traced   = field;
        dd_prev  = dd;
        d        = d_new;
        pad_prev = pad;
        pad      = pad_new;
        if (servo_on)
          pad_over_w = pad / mouth_opening(s);
        std::string stop;
        if (!branching.empty())
          stop = "crack branching, refused: " + branching;
        else if (from_tips)
          {
            stop        = traces.accept(increments, scene.body, settings.growth.hole_margin, pd.horizon);
            result.path = traces.paths().front();
          }
        else
          {
            const geometry::Polyline &path = increment.path;
            // A seeded crack's first segment leaves the boundary: from a hole's rim it is not an
            // arrival at that hole.
            const bool from_rim = !path.empty() && scene.body.hole_clearance(path[0]) < 1e-3 * h;
            auto arrival = arrive(path, scene.body, settings.growth.hole_margin, pd.horizon, from_rim ? 2 : 1);
            result.path  = arrival.path;
            stop         = arrival.reason;
          }
        if (stop.empty())
          stop = no_fail_arrival(paths(result.path));
        // A crack a horizon long or more that forms inside the body is traced on from its two tips,
        // as an initial interior crack is.
        if (stop.empty() && !from_tips && !seed)
          if (const auto inside = interior_crack(model, field, seedable, extraction);
              inside && geometry::length(inside->path) >= pd.horizon)
            {
              traces                = CrackTraces({inside->path}, scene.body, on_boundary);
              from_tips             = true;
              result.interior_crack = inside->site;
              result.path           = traces.paths().front();
              increment.stop_reason = inside->ends;
              out << "  a crack formed inside the body at " << to_text(inside->site) << ", from "
                  << to_text(inside->path.front()) << " to " << to_text(inside->path.back()) << " (" << inside->ends
                  << "): from here on it is traced from its two tips" << std::endl;
            }
        const double new_length = from_tips ? traces.length() : geometry::length(result.path);
        if (initial.empty() && length == 0. && new_length > 0.)
          note_compression(s);
        growth                  = std::max(0., new_length - length);
        length                  = new_length;
        // A seeded crack has a mouth once it forms: from here on d is its opening, read at gauges
        // placed across its first direction. Tried once, in the step it forms in: where the gauges
        // did not open over that step, the run stays under load-point control.
        if (by_mouth && !gauges_tried && initial.empty() && seed && length > 0.)
          {
            gauges_tried = true;
            place_gauges(seed->mouth, seed->direction,
                         std::min(4. * pd.horizon, 0.25 * std::min(extent.width(), extent.height())));
            if (mouth_opening(s) <= std::max(0., mouth_opening(saved)))
              out << "  the crack formed at " << to_text(seed->mouth)
                  << ", but the gauges across its mouth did not open: it grows under load-point control"
                  << std::endl;
            else
              {
                steps_in_opening(s);
                out << "  the crack formed at its mouth " << to_text(seed->mouth)
                    << ": from here on the steps are taken in the mouth's opening" << std::endl;
              }
          }

        // Next increment (the rule in full_pd.h).
        double z_tip = 0.;
        if (elastic)
          {
            const auto z = model.stretch_ratio(s);
            for (std::size_t i : near_tip)
              z_tip = std::max(z_tip, z[i]);
            if (z_tip >= p.onset_stretch_ratio * (1. - 1e-3) || growth > 0.)
              {
                elastic = false;
                if (by_mouth && !initial.empty())
                  steps_in_opening(s); // w = d / (d/w)_0 in the elastic phase
                dd = p.first_increment * d;
              }
            else
              dd = std::max(d * (p.onset_stretch_ratio / std::max(z_tip, 1e-12) - 1.), p.first_increment * d);
          }
        else if (growth > 0.)
          dd *= std::clamp(a_t / growth, 0.5, 2.);
        else
          dd *= 2.;
        if (!elastic)
          dd = std::clamp(dd, p.min_increment * d, p.max_increment * d);
        if (growth > 0. && !grown)
          {
            grown     = true;
            growth_t0 = std::chrono::duration<double>(t_step - t0).count(); // the growth rate counts this step
          }
        stalled = grown && growth == 0. ? stalled + 1 : 0;
        if (growth > 0.)
          pad_grown = pad;
        // Under the servo the opening also grows by softening alone: the crack has stopped only
        // once the drive, too, has risen as far as that many of the largest steps would take it.
        const bool drive_rose =
          !servo_on || pad >= pad_grown * std::pow(1. + p.max_increment, double(p.stall_steps));
        if (stop.empty() && stalled >= p.stall_steps && drive_rose)
          stop = "the crack stopped growing (" + std::to_string(stalled) + " steps without growth)";

        step.displacement  = pad;
        step.mouth_opening = mouth_opening(s);
        step.lambda        = lambda_of(pad, s);
        std::tie(step.load, step.reported_displacement) = report(step.lambda, s);
        step.crack_length = length;
        step.tip          = result.path.empty() ? Point{} : result.path.back();
        step.seconds      = seconds_since(t_step);
        result.steps.push_back(step);
        table.row(n, pad, step.mouth_opening, step.lambda, step.load, step.reported_displacement, length, step.tip.x,
                  step.tip.y, step.iterations, step.converged, step.repeats, step.seconds);
        recorder.load_displacement(n, step.lambda, step.load, step.reported_displacement, length, step.tip);
        recorder.crack_paths(paths(result.path));
        const bool last = !stop.empty() || n >= p.max_steps || pad >= d_max * (1. - 1e-12);
        if (n % p.output_interval == 0 || last)
          recorder.pd_state(model, s);

        std::string tracing = increment.stop_reason;
        for (const auto &inc : increments)
          tracing += (tracing.empty() ? "" : "; ") + inc.stop_reason;

        // ETA: growth rate against the tip's clearance once the crack grows, else the
        // displacement still to go (unknown without a largest displacement).
        const double elapsed = seconds_since(t0);
        double       eta     = pad > 0. && std::isfinite(d_max) ? elapsed / pad * std::max(0., d_max - pad)
                                                                : std::numeric_limits<double>::quiet_NaN();
        if (grown && length > length0)
          {
            const double left = std::max(0., scene.body.clearance(result.path.back()) - settings.growth.hole_margin);
            eta = std::isfinite(d_max) ? std::min(eta, (elapsed - growth_t0 + 1e-9) / (length - length0) * left)
                                       : (elapsed - growth_t0 + 1e-9) / (length - length0) * left;
          }
        out << "step " << std::setw(3) << n << "  d " << std::setprecision(4) << std::setw(9) << 1e3 * pad << " mm  w "
            << std::setw(9) << 1e3 * step.mouth_opening << " mm  lambda " << std::setw(9) << step.lambda << "  crack "
            << std::setw(7) << 1e3 * length << " mm (+" << 1e3 * growth << ")  tip " << to_text(step.tip) << "  DR "
            << step.iterations << (step.converged ? "" : " (not converged)")
            << (step.repeats ? "  repeats " + std::to_string(step.repeats) : "")
            << (elastic ? "  elastic, Z_tip " + text(z_tip) : "") << "  " << std::fixed << std::setprecision(1)
            << step.seconds << " s  ETA " << std::setprecision(0)
            << (std::isfinite(eta) ? "~" + std::to_string(std::lround(eta)) + " s"
                                   : std::string("unknown before growth"))
            << std::defaultfloat
            << std::setprecision(6) << (growth > 0. ? "  (tracing: " + tracing + ")" : "") << std::endl;
        if (!stop.empty())
          {
            result.stop_reason = stop;
            break;
          }
      }

    result.paths       = paths(result.path);
    result.joined      = traces.joined();
    result.seconds     = seconds_since(t0);
    result.peak_rss_mb = peak_rss_mb();
    std::size_t iterations = 0;
    for (const auto &st : result.steps)
      iterations += st.iterations;
    out << "end: " << result.stop_reason << "; " << grown_cracks_text(scene.cracks, result.paths, scene.body, on_boundary)
        << ", control displacement "
        << pad << " m, " << result.steps.size() << " steps, " << result.seconds << " s\n";
    out << "pumpd-metric fullpd.nodes " << model.nodes().size() << "\n"
        << "pumpd-metric fullpd.node_steps " << result.node_steps << "\n"
        << "pumpd-metric fullpd.dr_iterations " << iterations << "\n"
        << "pumpd-metric fullpd.ns_per_node_iteration "
        << (result.node_steps > 0. ? 1e9 * result.seconds_relaxation / result.node_steps : 0.) << "\n"
        << "pumpd-metric fullpd.seconds_total " << result.seconds << "\n"
        << "pumpd-metric fullpd.peak_rss_mb " << result.peak_rss_mb << "\n"
        << "pumpd-metric fullpd.crack_length_m " << geometry::length(result.path) << "\n";
    if (!scene.reference_path.empty())
      {
        const auto dist            = published_distance(result.path, scene.reference_path, 0.1 * h);
        result.reference_mean      = dist.mean;
        result.reference_hausdorff = dist.hausdorff;
        out << "pumpd-metric fullpd.mean_dev_mm " << 1e3 * dist.mean << "\n"
            << "pumpd-metric fullpd.hausdorff_mm " << 1e3 * dist.hausdorff << "\n";
      }
    return result;
  }
} // namespace pumpd::coupling
