// A crack that starts where there was none (README, "Where a crack starts"): the PD body at an
// initiation site (initiation.h) is loaded by the uncracked body's displacement until its damage
// forms a crack, which then grows as an initial crack would.
//  1. The sites checked: every candidate site, largest ratio first, except one that lies within
//     half a nucleation box's side of a site already checked (the same site: it lies in that
//     site's box, clear of its layer, where that box's crack forms). Each is checked on its own
//     (steps 2-4), with its own box and load ladder.
//  2. An edge site (within a horizon of the outline or a hole's rim): the mouth is the boundary
//     point nearest the site; the crack opens against sigma_1: it leaves the mouth along t
//     perpendicular to sigma_1's direction, the sense that leads into the material. An interior
//     site (deeper than a horizon from every boundary) starts an interior crack with two tips: its
//     centre is the site, and it runs both ways along t.
//  3. The PD box: BoxPolicy's box centred at the mouth or the centre (clipped to the body, grown
//     to take in a nearby hole), a side of at least 2 (3 delta + Maximum advance) so that the
//     longest crack stays clear of the layer's no-fail band below. The boundary transfer maps the
//     uncracked global displacement per unit load factor onto its boundary layer and onto the
//     places of the scene's conditions it takes in (held_places, boundary_transfer.h). The bonds within
//     two horizons of the layer stay linear elastic (a no-fail zone, as at full PD's pads): where
//     the layer, held to the elastic field, meets a free surface of the softer PD body (its surface
//     nodes lack bonds), the strain concentrates, and in a box whose stress hardly varies, such as
//     a beam's tension face, the crack would form there instead of at the site. A box that holds no
//     point of the outline or a hole's rim (an interior site's, away from them) has no such band:
//     its layer meets no free surface, and the crack has two horizons more room. The body starts
//     with a flaw of one lattice spacing along t (bonds across it broken), from the mouth, or
//     centred at the interior site: below the lattice's resolution as a crack, it is the
//     imperfection the damage localises at, where the stress hardly varies over the box (without
//     it, the box's own imperfections take that role), and so the most damaged place.
//  4. Quasi-static PD states along lambda = (first, first + dlambda, ...) lambda_i, lambda_i of
//     the site (sigma_1 = sigma_s), judged by the ExchangeController as an exchange is (exchange.h,
//     lambda_i in place of lambda_c): the damage ridge is traced from the flaw's end, along t from
//     the mouth, or both ways (t and -t) from the two ends of the interior flaw, two tips judged as
//     the tips of one box are (crack_extraction.h); a state whose ridge (the longer one) is at
//     least the Minimum advance long is a crack; one longer than the Maximum advance is repeated
//     at a lower load, then truncated. The ridge of an edge crack is traced from the material node
//     next to the mouth (at a re-entrant corner the mouth's own cell may have its node outside the
//     body); the path then starts at the mouth. No crack up to the Maximum load factor: the site
//     does not break (InvalidParameter naming it, with the largest sigma_1 / sigma_s of the elastic
//     field and the largest bond stretch seen). A ridge that branches is refused (a crack with
//     more than two tips).
//  5. The initial cracks: the cracks of the sites that formed one at a load factor within one
//     Load increment (times the lambda_i of that site) of the lowest; the sites that formed
//     later would have been unloaded by the first cracks, so they are reported, not grown. No
//     site forms a crack: the first site's refusal is thrown.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <vector>

#include "error.h"
#include "global_local.h"
#include "initiation.h"

namespace pumpd::coupling
{
  struct NucleatedCrack
  {
    geometry::Polyline path; ///< edge crack: mouth first, tip last; interior: tip, the flaw's ends, tip
    InitiationSite     site;
    double             load_factor = 0.;  ///< lambda of the state that formed it
    double             onset_load_factor = 0.; ///< lambda of the onset of its growth (exchange.h)
    geometry::Box      box;
    std::size_t        pd_nodes = 0, states = 0, iterations = 0;
    std::optional<InvalidParameter> refusal; ///< why no crack formed at the site (then no path)
  };

  /// The point of the body's outline or a hole's rim nearest p.
  geometry::Point nearest_boundary_point(const geometry::Body &body, geometry::Point p);

  /// The mouth of a crack nucleated at `site`: the nearest point of the body's outline or a hole's
  /// rim; none when the site lies more than `horizon` from every boundary (an interior site: a
  /// crack with two tips).
  std::optional<geometry::Point> nucleation_mouth(const geometry::Body &body, geometry::Point site, double horizon);

  /// The unit direction along which a crack leaves `mouth`: perpendicular to `sigma1` (unit), the
  /// sense whose point a horizon in lies deeper in the material.
  geometry::Point opening_direction(const geometry::Body &body, geometry::Point mouth, geometry::Point sigma1,
                                    double horizon);

  /// Forms the crack at `site` (header comment, 2-4) in the uncracked solution `global`; progress
  /// to `out`, the site named by `number`. Writes nucleation_pd.vtu (the first site),
  /// nucleation_pd_<number>.vtu (the others: the last PD state) to the scene's output directory.
  /// No crack (a branching ridge, none up to the Maximum load factor): the refusal, no path.
  NucleatedCrack nucleate(const Scene &scene, GlobalProblem &global, const GlobalLocalSettings &settings,
                          const InitiationSettings &initiation, const InitiationSite &site, std::size_t number,
                          std::ostream &out);

  /// The sites checked (header comment, 1): indices into `sites`, closer than `same_site` to no
  /// site before them in the list.
  std::vector<std::size_t> distinct_sites(const std::vector<InitiationSite> &sites, double same_site);

  /// The global-local method on a scene without a crack: its initiation sites (printed and written,
  /// initiation.h), a crack nucleated at each distinct one, the sites' outcomes (printed, and
  /// columns of initiation_sites.csv), the initial cracks written to nucleation.csv; then the cycle
  /// grows them together.
  GlobalLocalResult run_global_local_from_initiation(const Scene &scene, const GlobalLocalSettings &settings,
                                                     const InitiationSettings &initiation, std::ostream &out);
} // namespace pumpd::coupling
