#include "nucleation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>

#include "boundary_transfer.h"
#include "box_policy.h"
#include "csv.h"
#include "error.h"
#include "exchange.h"
#include "path_metrics.h"
#include "vtu_output.h"

namespace pumpd::coupling
{
  using geometry::Point;

  namespace
  {
    /// The no-fail band along the boundary layer [horizons] (header comment, 2).
    const double layer_clearance = 2.;

    /// The point of a boundary piece nearest p.
    Point nearest_on(const geometry::Piece &piece, Point p)
    {
      if (piece.arc && piece.spans(p) && geometry::norm(p - piece.centre) > 0.)
        return piece.centre + (piece.radius / geometry::norm(p - piece.centre)) * (p - piece.centre);
      if (piece.arc)
        return geometry::norm(p - piece.a) < geometry::norm(p - piece.b) ? piece.a : piece.b;
      const Point  e  = piece.b - piece.a;
      const double ee = geometry::dot(e, e);
      return piece.a + (ee > 0. ? std::clamp(geometry::dot(p - piece.a, e) / ee, 0., 1.) : 0.) * e;
    }

    /// The largest bond stretch over its critical stretch, Z, of a state and the node it is at.
    std::pair<double, Point> largest_stretch_ratio(const local::PdModel &model, const local::State &s)
    {
      const auto  z    = model.stretch_ratio(s);
      std::size_t best = model.nodes().front();
      for (std::size_t i : model.nodes())
        if (z[i] > z[best])
          best = i;
      return {z[best], model.lattice().position(best)};
    }

    /// No-fail zones along the box's boundary layer: per box side with layer nodes of its own
    /// (within a horizon of it and of no other side), the bounding box of the layer nodes within a
    /// horizon of it (they are prescribed already), its bonds and those within `margin` linear.
    std::vector<local::PrescribedRegion> layer_no_fail_zones(const local::PdModel &probe, double horizon,
                                                             double margin)
    {
      const auto &box  = probe.region().box;
      const auto  near = [&](Point p) {
        const double distance[4] = {p.x - box.x_min, box.x_max - p.x, p.y - box.y_min, box.y_max - p.y};
        std::array<bool, 4> sides{};
        for (int side = 0; side < 4; ++side)
          sides[side] = distance[side] < horizon;
        return sides;
      };
      std::array<bool, 4> own{};
      for (std::size_t i : probe.boundary_layer())
        {
          const auto sides = near(probe.lattice().position(i));
          if (std::count(sides.begin(), sides.end(), true) == 1)
            own[std::find(sides.begin(), sides.end(), true) - sides.begin()] = true;
        }
      std::vector<local::PrescribedRegion> zones;
      for (int side = 0; side < 4; ++side)
        {
          if (!own[side])
            continue;
          std::optional<geometry::Box> strip;
          for (std::size_t i : probe.boundary_layer())
            if (const Point p = probe.lattice().position(i); near(p)[side])
              strip = strip ? geometry::Box{std::min(strip->x_min, p.x), std::min(strip->y_min, p.y),
                                            std::max(strip->x_max, p.x), std::max(strip->y_max, p.y)}
                            : geometry::Box{p.x, p.y, p.x, p.y};
          zones.push_back(local::PrescribedRegion::box("Boundary layer", *strip, true, true));
          zones.back().elastic_margin = margin;
        }
      return zones;
    }

    void write_nucleation(const Scene &scene, const NucleatedCrack &crack, const local::PdModel &model,
                          const local::State &state)
    {
      if (scene.output_directory.empty())
        return;
      std::filesystem::create_directories(scene.output_directory);
      CsvFile csv(scene.output_directory + "/nucleation.csv", "vertex,x_m,y_m,lambda,lambda_over_lambda_i");
      for (std::size_t k = 0; k < crack.path.size(); ++k)
        csv.row(k, crack.path[k].x, crack.path[k].y, crack.load_factor, crack.load_factor / crack.site.load_factor);
      local::write_vtu(scene.output_directory + "/nucleation_pd.vtu", model, state);
    }
  } // namespace

  Point nearest_boundary_point(const geometry::Body &body, Point p)
  {
    Point      best;
    double     best_distance = std::numeric_limits<double>::infinity();
    const auto visit         = [&](const geometry::Loop &loop) {
      for (const auto &piece : loop.pieces)
        if (const Point q = nearest_on(piece, p); geometry::norm(q - p) < best_distance)
          {
            best          = q;
            best_distance = geometry::norm(q - p);
          }
    };
    visit(body.outline());
    for (const auto &hole : body.holes())
      visit(hole);
    return best;
  }

  Point nucleation_mouth(const geometry::Body &body, Point site, double horizon)
  {
    const double depth = body.clearance(site);
    if (depth > horizon)
      throw InvalidParameter("Initial cracks", "none",
                             "the first initiation site " + geometry::to_text(site) + " lies " + pumpd::to_text(depth, 4) +
                               " m inside the body, more than a horizon (" + pumpd::to_text(horizon, 4) +
                               " m) from its outline and holes: a crack starting there would have two tips, and "
                               "nucleation forms edge cracks only (from a mouth on the boundary); give the crack to "
                               "grow as Initial cracks");
    return nearest_boundary_point(body, site);
  }

  Point opening_direction(const geometry::Body &body, Point mouth, Point sigma1, double horizon)
  {
    const Point t{-sigma1.y, sigma1.x};
    const auto  depth = [&](Point e) {
      const Point x = mouth + horizon * e;
      return body.contains(x) ? body.clearance(x) : -1.;
    };
    return depth(t) >= depth(-1. * t) ? t : -1. * t;
  }

  NucleatedCrack nucleate(const Scene &scene, const GlobalLocalSettings &settings, const InitiationSettings &initiation,
                          const InitiationSite &site, std::ostream &out)
  {
    const auto  &pd    = settings.pd;
    const Point  mouth = nucleation_mouth(scene.body, site.position, pd.horizon);
    const Point  t     = opening_direction(scene.body, mouth, site.direction, pd.horizon);

    GlobalProblem global(scene, settings.global);
    global.solve_uncracked();
    // Centred at the mouth, with room for the longest crack between the mouth and the no-fail band
    // of every layer: half a side at least the layer, the band and the Maximum advance.
    BoxSettings box = settings.cycle.box;
    box.horizon     = pd.horizon;
    box.spacing     = pd.spacing();
    box.behind      = 0.5;
    box.size        = std::max(box.size, 2. * ((1. + layer_clearance) * pd.horizon + settings.cycle.exchange.max_advance));
    box.max_size    = std::max(box.max_size, box.size);
    BoxPolicy boxes(scene.body, box);

    NucleatedCrack crack;
    crack.site = site;
    crack.box  = boxes.place(mouth, t);
    const local::Region    region{scene.body, crack.box, {{mouth, mouth + pd.spacing() * t}}};
    const auto             material = pd.material(scene.material);
    const local::PdModel   model(material, pd.horizon, pd.horizon_over_spacing, region,
                                 layer_no_fail_zones(local::PdModel(material, pd.horizon, pd.horizon_over_spacing, region),
                                                     pd.horizon, layer_clearance * pd.horizon));
    const BoundaryTransfer transfer(global, model);
    crack.pd_nodes = model.nodes().size();

    ExchangeSettings exchange  = settings.cycle.exchange;
    exchange.first_load_factor = initiation.first_load_factor;
    exchange.start_below_accepted = false;
    ExchangeController controller(exchange);
    // The material node next to the mouth, where the ridge is traced from (header comment, 3).
    const Point start = [&] {
      const Point x    = mouth + 0.5 * pd.spacing() * t;
      std::size_t best = model.nodes().front();
      for (std::size_t i : model.nodes())
        if (geometry::norm(model.lattice().position(i) - x) < geometry::norm(model.lattice().position(best) - x))
          best = i;
      return model.lattice().position(best);
    }();
    TipState at_mouth;
    at_mouth.position             = start;
    at_mouth.direction            = t;
    at_mouth.critical_load_factor = site.load_factor;
    const double allowed = std::min(exchange.max_advance, settings.growth.length_limit());
    // The path has its mouth on the boundary; it arrives where its far end comes within a
    // horizon of the outline or a hole.
    const auto arrives = [&](const geometry::Polyline &path) {
      return geometry::norm(path.back() - mouth) > pd.horizon && scene.body.clearance(path.back()) < pd.horizon;
    };

    out << "nucleation at site 1 " << geometry::to_text(site.position) << ": mouth " << geometry::to_text(mouth)
        << ", the crack along " << geometry::to_text(t, 4) << " (perpendicular to sigma_1); PD box [" << crack.box.x_min
        << ", " << crack.box.x_max << "] x [" << crack.box.y_min << ", " << crack.box.y_max << "], delta "
        << pd.horizon << " m, " << crack.pd_nodes << " PD nodes; states from " << exchange.first_load_factor
        << " lambda_i, lambda_i = " << site.load_factor << std::endl;
    const auto outcome = run_exchange(model, transfer, controller, {at_mouth}, {allowed}, arrives, pd, out, "lambda_i");
    crack.states     = outcome.states;
    crack.iterations = outcome.iterations;
    if (!outcome.branching.empty())
      throw InvalidParameter("Initial cracks", "none",
                             "the damage that formed at the first initiation site " + geometry::to_text(site.position) +
                               " branches, refused: " + outcome.branching);
    if (outcome.decision == ExchangeController::Decision::too_small)
      {
        if (!scene.output_directory.empty())
          local::write_vtu(scene.output_directory + "/nucleation_pd.vtu", model, outcome.state);
        const auto [z, at] = largest_stretch_ratio(model, outcome.state);
        throw InvalidParameter("Maximum load factor", pumpd::to_text(exchange.max_load_factor),
                               "no crack formed at the first initiation site " + geometry::to_text(site.position) +
                                 " up to this many times lambda_i = " + pumpd::to_text(site.load_factor, 4) +
                                 ": the elastic sigma_1 / sigma_s there reached " +
                                 pumpd::to_text(outcome.load_factor, 4) + ", the largest bond stretch over its critical one " +
                                 pumpd::to_text(z, 4) + " at " + geometry::to_text(at, 4) + " (the scene does not break)");
      }
    auto path         = outcome.increments.front().path;
    path[0]           = mouth;
    crack.path        = truncate(path, allowed);
    crack.load_factor = outcome.load_factor * site.load_factor;
    write_nucleation(scene, crack, model, outcome.state);
    out << "nucleation: a crack of " << geometry::length(crack.path) << " m formed at lambda = " << crack.load_factor
        << " (" << outcome.load_factor << " lambda_i): " << geometry::to_text(crack.path) << std::endl;
    return crack;
  }

  GlobalLocalResult run_global_local_from_initiation(const Scene &scene, const GlobalLocalSettings &settings,
                                                     const InitiationSettings &initiation, std::ostream &out)
  {
    const auto found = find_initiation(scene, settings.global, settings.pd, initiation);
    report_initiation(found, scene, out);
    if (found.sites.size() > 1)
      out << "nucleation: the first site only; the other " << found.sites.size() - 1
          << " candidate site" << (found.sites.size() == 2 ? " is" : "s are") << " not tried\n";
    const auto crack = nucleate(scene, settings, initiation, found.sites.front(), out);
    Scene      cracked = scene;
    cracked.cracks     = {crack.path};
    return run_global_local(cracked, settings, out);
  }
} // namespace pumpd::coupling
