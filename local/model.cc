#include "model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "error.h"
#include "fast_exp.h"
#include "memory.h"

namespace pumpd::local
{
  namespace
  {
    std::string box_text(const geometry::Box &b)
    {
      std::ostringstream s;
      s << "[" << b.x_min << ", " << b.x_max << "] x [" << b.y_min << ", " << b.y_max << "]";
      return s.str();
    }

    void validate(const Region &r)
    {
      const geometry::Box &o = r.body.bounding_box();
      if (!(o.width() > 0. && o.height() > 0.))
        throw InvalidParameter("Body outline", box_text(o), "must have positive width and height");
      if (!o.contains(r.box, 1e-9 * std::max(o.width(), o.height())))
        throw InvalidParameter("PD box", box_text(r.box),
                               "must lie inside the body " + box_text(o));
      for (const auto &crack : r.cracks)
        {
          if (crack.size() < 2)
            throw InvalidParameter("Crack", std::to_string(crack.size()) + " vertices",
                                   "a crack polyline needs at least 2 vertices");
          for (const auto &p : crack)
            if (!o.contains(p, 1e-9 * std::max(o.width(), o.height())))
              throw InvalidParameter("Crack vertex",
                                     "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")",
                                     "must lie inside the body " + box_text(o));
        }
    }

    /// Box edges inside the body's bounding box: 0 left, 1 right, 2 bottom, 3 top.
    std::array<bool, 4> interior_edges(const geometry::Box &box, const geometry::Box &outline, double tol)
    {
      return {box.x_min > outline.x_min + tol, box.x_max < outline.x_max - tol,
              box.y_min > outline.y_min + tol, box.y_max < outline.y_max - tol};
    }

    /// The body with only the holes near the box (within `reach`): the only ones a bond of the
    /// box can pass through.
    geometry::Body near_box(const geometry::Body &body, const geometry::Box &box, double reach)
    {
      const auto near = [&](const geometry::Piece &p) {
        const geometry::Box b = p.bounding_box();
        return b.x_max >= box.x_min - reach && b.x_min <= box.x_max + reach && b.y_max >= box.y_min - reach &&
               b.y_min <= box.y_max + reach;
      };
      std::vector<geometry::Loop> holes;
      for (const auto &hole : body.holes())
        if (std::any_of(hole.pieces.begin(), hole.pieces.end(), near))
          holes.push_back(hole);
      return {body.outline(), holes};
    }

    /// The segments of the cracks whose bounding box comes within `reach` of the box: no bond of
    /// the box's lattice can cross the others.
    std::vector<std::array<geometry::Point, 2>> crack_segments_near(const std::vector<geometry::Polyline> &cracks,
                                                                    const geometry::Box &box, double reach)
    {
      std::vector<std::array<geometry::Point, 2>> near;
      for (const auto &c : cracks)
        for (std::size_t s = 0; s + 1 < c.size(); ++s)
          if (std::max(c[s].x, c[s + 1].x) >= box.x_min - reach && std::min(c[s].x, c[s + 1].x) <= box.x_max + reach &&
              std::max(c[s].y, c[s + 1].y) >= box.y_min - reach && std::min(c[s].y, c[s + 1].y) <= box.y_max + reach)
            near.push_back({c[s], c[s + 1]});
      return near;
    }

    /// h = delta / m, with m checked first so that m <= 0 is reported as m, not as h.
    double spacing_for(double horizon, int m)
    {
      if (m < 2)
        throw InvalidParameter("Horizon over spacing (m)", std::to_string(m),
                               "must be an integer >= 2 (the horizon spans at least two spacings)");
      return horizon / m;
    }
  } // namespace

  double estimated_model_bytes(const Lattice &grid, const Stencil &st)
  {
    const double n = double(grid.storage_size());
    return n * 24. * 8. + 5. * double(st.size()) * n / 8.;
  }

  ModelMemory model_memory(const Lattice &grid, const Stencil &st)
  {
    return {estimated_model_bytes(grid, st), 0.8 * available_memory()};
  }

  PrescribedRegion PrescribedRegion::disk(std::string name, geometry::Point centre, double radius, bool fix_x,
                                          bool fix_y)
  {
    PrescribedRegion r;
    r.name   = std::move(name);
    r.centre = centre;
    r.radius = radius;
    r.area   = {centre.x - radius, centre.y - radius, centre.x + radius, centre.y + radius};
    r.fix_x  = fix_x;
    r.fix_y  = fix_y;
    return r;
  }

  PrescribedRegion PrescribedRegion::box(std::string name, const geometry::Box &area, bool fix_x, bool fix_y)
  {
    PrescribedRegion r;
    r.name   = std::move(name);
    r.area   = area;
    r.centre = {0.5 * (area.x_min + area.x_max), 0.5 * (area.y_min + area.y_max)};
    r.fix_x  = fix_x;
    r.fix_y  = fix_y;
    return r;
  }

  PrescribedRegion PrescribedRegion::band(std::string name, std::vector<std::array<geometry::Point, 2>> edges,
                                          double width, bool fix_x, bool fix_y)
  {
    PrescribedRegion r;
    r.name   = std::move(name);
    r.radius = width;
    r.area   = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const auto &e : edges)
      for (const auto &x : e)
        r.area = {std::min(r.area.x_min, x.x - width), std::min(r.area.y_min, x.y - width),
                  std::max(r.area.x_max, x.x + width), std::max(r.area.y_max, x.y + width)};
    r.centre = {0.5 * (r.area.x_min + r.area.x_max), 0.5 * (r.area.y_min + r.area.y_max)};
    r.edges  = std::move(edges);
    r.fix_x  = fix_x;
    r.fix_y  = fix_y;
    return r;
  }

  PrescribedRegion PrescribedRegion::shape(std::string name, const geometry::Box &area,
                                           std::function<bool(geometry::Point)> inside, bool fix_x, bool fix_y)
  {
    PrescribedRegion r = box(std::move(name), area, fix_x, fix_y);
    r.inside           = std::move(inside);
    return r;
  }

  bool PrescribedRegion::contains(geometry::Point p, double g) const
  {
    const geometry::Box grown{area.x_min - g, area.y_min - g, area.x_max + g, area.y_max + g};
    if (!grown.contains(p))
      return false;
    if (!edges.empty())
      return std::any_of(edges.begin(), edges.end(),
                         [&](const auto &e) { return geometry::distance_to_segment(p, e[0], e[1]) <= radius + g; });
    if (inside)
      return g > 0. || inside(p);
    return radius <= 0. || geometry::norm(p - centre) <= radius + g;
  }

  std::string PrescribedRegion::description() const
  {
    if (!edges.empty())
      return "band of width " + std::to_string(radius) + " m along " + std::to_string(edges.size()) + " edges";
    if (radius > 0.)
      return "disk of radius " + std::to_string(radius) + " m at (" + std::to_string(centre.x) + ", " +
             std::to_string(centre.y) + ")";
    return (inside ? "region in the box " : "box ") + box_text(area);
  }

  PdModel::PdModel(const MaterialParameters &material, double horizon, int horizon_ratio,
                   const Region &region, const std::vector<PrescribedRegion> &prescribed)
    : mat(material, horizon)
    , grid(region.box, spacing_for(horizon, horizon_ratio), horizon_ratio)
    , st(make_half_stencil(horizon_ratio, mat))
    , reg(region)
    , regions(prescribed)
  {
    validate(reg);
    const double h = grid.spacing();
    volume         = h * h;
    // Refuse a lattice this machine cannot hold before allocating it; memory grows like m^4 at a
    // fixed horizon (nodes and bonds per node each like m^2).
    const auto [bytes, available] = model_memory(grid, st);
    if (bytes > available)
      {
        const int m_max = int(std::floor(horizon_ratio * std::pow(available / bytes, 0.25)));
        std::ostringstream why;
        why << "the PD lattice of " << grid.nx() * grid.ny() << " nodes (spacing " << h << " m) with " << 2 * st.size()
            << " bonds each needs about " << bytes / 1073741824. << " GiB, more than the " << available / 1073741824.
            << " GiB this machine can give it: use m <= " << std::max(2, m_max)
            << " for this box and horizon, or a larger horizon or a smaller box";
        throw InvalidParameter("Horizon over spacing", std::to_string(horizon_ratio), why.str());
      }

    stiffness = 0.;
    for (std::size_t k = 0; k < st.size(); ++k)
      {
        const double q = st.weight[k] * h * h;
        force_coeff.push_back(4. * mat.C() * mat.beta() * q * mat.normalisation());
        energy_coeff.push_back(mat.C() * q * mat.normalisation());
        stiffness += 2. * force_coeff.back() / (st.length[k] * h); // both halves of the stencil
      }

    const std::size_t n = grid.storage_size();
    plane_words         = (n + 63) / 64;
    exists.assign(st.size() * plane_words, 0);
    precrack.assign(st.size() * plane_words, 0);
    free.assign(n, 0.);

    std::vector<char> material_at(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      if (grid.is_real(i) && reg.body.contains(grid.position(i)))
        {
          material_at[i] = 1;
          active_nodes.push_back(i);
        }

    // Boundary layer: nodes closer than one horizon to a box edge inside the body, where the
    // body goes on across the edge (the outline holds the node's foot on the edge strictly inside;
    // a box edge across a re-entrant cut-out, or along the outline, as at an L-panel's corner, has
    // free surface, not more material, beyond it).
    const auto &box  = reg.box;
    const auto  edge = interior_edges(box, reg.body.bounding_box(), 0.25 * h);
    const auto  beyond = [&](geometry::Point foot) {
      return reg.body.outline().distance(foot) > 1e-9 * h && reg.body.outline().encloses(foot);
    };
    for (std::size_t i : active_nodes)
      {
        const auto p        = grid.position(i);
        const bool in_layer = (edge[0] && p.x - box.x_min < horizon && beyond({box.x_min, p.y})) ||
                              (edge[1] && box.x_max - p.x < horizon && beyond({box.x_max, p.y})) ||
                              (edge[2] && p.y - box.y_min < horizon && beyond({p.x, box.y_min})) ||
                              (edge[3] && box.y_max - p.y < horizon && beyond({p.x, box.y_max}));
        if (in_layer)
          layer_nodes.push_back(i);
        else
          free[i] = 1.;
      }
    free_x = free;
    free_y = free;

    // Prescribed regions: each fixes its components on the material nodes it contains.
    for (const auto &r : regions)
      {
        const std::string name = r.name.empty() ? std::string("Prescribed region") : r.name;
        if (!r.fix_x && !r.fix_y)
          throw InvalidParameter(name, "neither component fixed", "a prescribed region fixes ux, uy or both");
        if (!std::isfinite(r.radius) || r.radius < 0. || !std::isfinite(r.area.x_min) ||
            !std::isfinite(r.area.x_max) || !std::isfinite(r.area.y_min) || !std::isfinite(r.area.y_max))
          throw InvalidParameter(name, "radius " + std::to_string(r.radius) + ", area " + box_text(r.area),
                                 "must be finite, with radius >= 0");
        std::vector<std::size_t> in;
        for (std::size_t i : active_nodes)
          if (r.contains(grid.position(i)))
            {
              in.push_back(i);
              if (r.fix_x)
                free_x[i] = 0.;
              if (r.fix_y)
                free_y[i] = 0.;
              free[i] = 0.;
            }
        if (in.empty())
          throw InvalidParameter(name,
                                 r.description(),
                                 "holds no PD node (spacing " + std::to_string(h) +
                                   " m): make it larger or move it onto the body");
        region_nodes.push_back(std::move(in));
      }
    for (std::size_t i : active_nodes)
      if (free_x[i] == 0. || free_y[i] == 0.)
        constrained.push_back(i);

    // Bonds: exist between material nodes unless the segment leaves the body (through a hole or
    // across a re-entrant part of the outline).
    // A bond can leave the body or cross a crack segment only where its node lies within a bond
    // length of them: the tests run for those nodes alone (the margin covers the rounding of the
    // node positions x0 + c h).
    const geometry::Body boundary = near_box(reg.body, box, 2. * horizon);
    const auto           crack_segments = crack_segments_near(reg.cracks, box, 2. * horizon);
    double               longest_bond   = 0.;
    for (std::size_t k = 0; k < st.size(); ++k)
      longest_bond = std::max(longest_bond, st.length[k] * h);
    longest_bond *= 1. + 1e-9;
    std::vector<char> near_boundary(n, 0), near_crack(n, 0);
    for (std::size_t i : active_nodes)
      {
        const auto a     = grid.position(i);
        near_boundary[i] = boundary.clearance(a) <= longest_bond;
        near_crack[i]    = std::any_of(crack_segments.begin(), crack_segments.end(), [&](const auto &c) {
          return geometry::distance_to_segment(a, c[0], c[1]) <= longest_bond;
        });
      }
    for (std::size_t k = 0; k < st.size(); ++k)
      {
        const std::ptrdiff_t off = st.dx[k] + std::ptrdiff_t(grid.stride()) * st.dy[k];
        for (std::size_t i : active_nodes)
          {
            const std::size_t j = i + off;
            if (!material_at[j])
              continue;
            const auto a = grid.position(i), b = grid.position(j);
            if (near_boundary[i] && boundary.crosses_boundary(a, b))
              continue;
            const std::size_t w = k * plane_words + i / 64;
            exists[w] |= std::uint64_t(1) << (i % 64);
            if (near_crack[i] && std::any_of(crack_segments.begin(), crack_segments.end(), [&](const auto &c) {
                  return geometry::segments_intersect(a, b, c[0], c[1]);
                }))
              precrack[w] |= std::uint64_t(1) << (i % 64);
          }
      }

    // No-fail zones: bonds with an end near a region with elastic_margin >= 0 stay linear.
    std::vector<char> zone(n, 0);
    bool              any_zone = false;
    for (const auto &r : regions)
      if (r.elastic_margin >= 0.)
        {
          if (!std::isfinite(r.elastic_margin))
            throw InvalidParameter(r.name + " elastic margin", std::to_string(r.elastic_margin), "must be finite");
          any_zone = true;
          for (std::size_t i : active_nodes)
            if (r.contains(grid.position(i), r.elastic_margin))
              zone[i] = 1;
        }
    if (any_zone)
      {
        linear_bits.assign(exists.size(), 0);
        for (std::size_t k = 0; k < st.size(); ++k)
          {
            const std::ptrdiff_t off = st.dx[k] + std::ptrdiff_t(grid.stride()) * st.dy[k];
            for (std::size_t i : active_nodes)
              if (bond_exists(k, i) && !bit(precrack, k * plane_words, i) && (zone[i] || zone[i + off]))
                {
                  linear_bits[k * plane_words + i / 64] |= std::uint64_t(1) << (i % 64);
                  linear_k.push_back(std::uint32_t(k));
                  linear_i.push_back(i);
                }
          }
      }
  }

  State PdModel::initial_state() const
  {
    const std::size_t n = grid.storage_size();
    State             s;
    s.ux.assign(n, 0.);
    s.uy.assign(n, 0.);
    s.vx.assign(n, 0.);
    s.vy.assign(n, 0.);
    s.fx.assign(n, 0.);
    s.fy.assign(n, 0.);
    s.broken.resize(exists.size());
    for (std::size_t w = 0; w < exists.size(); ++w)
      s.broken[w] = ~exists[w] | precrack[w];
    return s;
  }

  // The hot loop. For one row and one stencil offset, 64 consecutive nodes i and their partners
  // j = i + off are contiguous, so the bond stretch, failure test and force vectorise; the
  // forces go to a small buffer first and are then added to i and subtracted from j (Newton 3).
  // A shortened bond under the linear law in compression is softened by nothing (x = 0).
  // Only the lanes of a word that hold a column of the box are computed, in whole vectors of
  // 8: the ghost columns' bonds do not exist and would only add zeros (a box 65 nodes wide has
  // 65 real lanes in 2 words of 64).
  template <bool linear_in_compression>
  void PdModel::forces_in_rows(State &s, std::size_t row_begin, std::size_t row_end,
                               double &dissipated) const
  {
    const double  h       = grid.spacing();
    const double  x_break = 0.5 * mat.parameters().break_factor * mat.parameters().break_factor;
    const double *ux = s.ux.data(), *uy = s.uy.data();
    double       *fx = s.fx.data(), *fy = s.fy.data();
    const std::size_t m          = grid.reach();
    const std::size_t first_word = m / 64, last_word = (m + grid.nx() + 63) / 64;
    const auto        lanes = [&](std::size_t w) { // [begin, end) of word w's real columns, in 8s
      const std::size_t first = 64 * w, begin = std::max(first, m) - first;
      const std::size_t end = std::min(first + 64, m + grid.nx()) - first;
      return std::pair{begin / 8 * 8, (end + 7) / 8 * 8};
    };

    alignas(64) double gx[64], gy[64];
    for (std::size_t iy = row_begin; iy < row_end; ++iy)
      for (std::size_t k = 0; k < st.size(); ++k)
        {
          const std::ptrdiff_t off = st.dx[k] + std::ptrdiff_t(grid.stride()) * st.dy[k];
          const double ex = st.ex[k], ey = st.ey[k], inv_r = 1. / (st.length[k] * h);
          const double beta_r = mat.beta() * st.length[k] * h, a = force_coeff[k];
          std::uint64_t *bits = s.broken.data() + k * plane_words + iy * grid.stride() / 64;
          for (std::size_t w = first_word; w < last_word; ++w)
            {
              const std::size_t   i0    = iy * grid.stride() + 64 * w;
              const std::uint64_t dead  = bits[w];
              std::uint64_t       fresh = 0;
              const auto [l0, l1]       = lanes(w);
#pragma omp simd reduction(| : fresh) aligned(gx, gy : 64)
              for (std::uint64_t l = l0; l < l1; ++l) // 64-bit lanes and masks: vectorises
                {
                  const std::size_t   i = i0 + l, j = i0 + l + off;
                  const double        S = ((ux[j] - ux[i]) * ex + (uy[j] - uy[i]) * ey) * inv_r;
                  const double        x = linear_in_compression && S < 0. ? 0. : beta_r * S * S;
                  const std::uint64_t gone  = (dead >> l) & 1u;
                  const std::uint64_t fails = x > x_break ? 1u : 0u;
                  fresh |= (fails & ~gone) << l;
                  const double F = (gone | fails) ? 0. : a * S * exp_negative(x);
                  gx[l] = F * ex;
                  gy[l] = F * ey;
                }
#pragma omp simd
              for (std::size_t l = l0; l < l1; ++l)
                {
                  fx[i0 + l] += gx[l];
                  fy[i0 + l] += gy[l];
                }
#pragma omp simd
              for (std::size_t l = l0; l < l1; ++l)
                {
                  fx[i0 + l + off] -= gx[l];
                  fy[i0 + l + off] -= gy[l];
                }
              if (fresh)
                {
                  bits[w] |= fresh;
                  // Rare path: the energy the failing bonds held is dissipated.
                  for (int l = 0; l < 64; ++l)
                    if ((fresh >> l) & 1u)
                      {
                        const std::size_t i = i0 + l, j = i + off;
                        const double S = ((ux[j] - ux[i]) * ex + (uy[j] - uy[i]) * ey) * inv_r;
                        dissipated += 2. * volume * energy_coeff[k] *
                                      (1. - exp_negative(beta_r * S * S));
                      }
                }
            }
        }
  }

  void PdModel::compute_forces(State &s) const
  {
    // Row blocks at least m + 1 rows high: block b adds into its own rows and the first m + 1
    // rows of block b + 1 only (m rows of reach, one more where a ghost lane wraps past the row
    // end), so all even blocks can run at once, then all odd blocks. An even block first clears
    // its own rows and those of the odd block after it, which no other even block touches: the
    // threads meet once between the phases and once at the end. The layout depends on the
    // lattice alone (the sums, and so the results, not on the thread count): at most 16 blocks,
    // a multiple of 4 where there are 4 or more, so that two threads share each phase evenly.
    const std::size_t ny       = grid.ny();
    const std::size_t possible = std::clamp<std::size_t>(ny / (grid.reach() + 1), 1, 16);
    const std::size_t blocks   = possible >= 4 ? possible / 4 * 4 : possible;
    const auto        first    = [&](std::size_t b) { return b * ny / blocks; }; // rows [first(b), first(b + 1))
    const std::size_t row      = grid.stride();
    const std::size_t n        = s.fx.size();
    std::vector<double> dissipated(blocks, 0.);
    const auto          forces = [&](std::size_t b) {
      if (mat.parameters().compression == Compression::linear)
        forces_in_rows<true>(s, first(b), first(b + 1), dissipated[b]);
      else
        forces_in_rows<false>(s, first(b), first(b + 1), dissipated[b]);
    };
#pragma omp parallel
    {
#pragma omp for schedule(static)
      for (std::size_t b = 0; b < blocks; b += 2)
        {
          const std::size_t cleared_end = b + 2 < blocks ? first(b + 2) * row : n;
          std::fill(s.fx.begin() + first(b) * row, s.fx.begin() + cleared_end, 0.);
          std::fill(s.fy.begin() + first(b) * row, s.fy.begin() + cleared_end, 0.);
          forces(b);
        }
#pragma omp for schedule(static) nowait
      for (std::size_t b = 1; b < blocks; b += 2)
        forces(b);
    }
    for (double d : dissipated)
      s.dissipated += d;
    if (!linear_k.empty())
      correct_linear_bonds(s);
  }

  // The kernel gave a S exp(-x) (or 0 where it found the bond broken, failing it now and
  // dissipating its energy); a no-fail bond gets a S: the difference is added, a failure undone.
  void PdModel::correct_linear_bonds(State &s) const
  {
    const double h = grid.spacing();
    for (std::size_t b = 0; b < linear_k.size(); ++b)
      {
        const std::size_t    k = linear_k[b], i = linear_i[b];
        const std::ptrdiff_t off = st.dx[k] + std::ptrdiff_t(grid.stride()) * st.dy[k];
        const std::size_t    j   = i + off;
        // S and x as the kernel computes them (the same rounding: the undone dissipation cancels).
        const double inv_r = 1. / (st.length[k] * h), beta_r = mat.beta() * st.length[k] * h;
        const double S = ((s.ux[j] - s.ux[i]) * st.ex[k] + (s.uy[j] - s.uy[i]) * st.ey[k]) * inv_r;
        const double x = mat.softens(S) ? beta_r * S * S : 0.;
        std::uint64_t &word = s.broken[k * plane_words + i / 64];
        const std::uint64_t mask = std::uint64_t(1) << (i % 64);
        double         kernel = 0.;
        if (word & mask)
          {
            word &= ~mask; // failed in this call (no-fail bonds are never left broken)
            s.dissipated -= 2. * volume * energy_coeff[k] * (1. - exp_negative(x));
          }
        else
          kernel = force_coeff[k] * S * exp_negative(x);
        const double dF = force_coeff[k] * S - kernel;
        s.fx[i] += dF * st.ex[k];
        s.fy[i] += dF * st.ey[k];
        s.fx[j] -= dF * st.ex[k];
        s.fy[j] -= dF * st.ey[k];
      }
  }

  geometry::Point PdModel::reaction(const State &s, std::size_t r) const
  {
    geometry::Point f;
    for (std::size_t i : region_nodes.at(r))
      {
        f.x -= s.fx[i];
        f.y -= s.fy[i];
      }
    return volume * f;
  }

  std::size_t PdModel::nearest_node(geometry::Point x) const
  {
    std::size_t best = active_nodes.front();
    for (std::size_t i : active_nodes)
      if (geometry::norm(grid.position(i) - x) < geometry::norm(grid.position(best) - x))
        best = i;
    return best;
  }

  double PdModel::stable_time_step() const
  {
    return std::sqrt(2. * mat.parameters().density / stiffness);
  }

  template <class BondVisitor>
  void PdModel::for_each_existing_bond(BondVisitor &&visit) const
  {
    for (std::size_t k = 0; k < st.size(); ++k)
      {
        const std::ptrdiff_t off = st.dx[k] + std::ptrdiff_t(grid.stride()) * st.dy[k];
        for (std::size_t i : active_nodes)
          if (bond_exists(k, i))
            visit(k, i, i + off);
      }
  }

  double PdModel::elastic_energy(const State &s) const
  {
    const double h = grid.spacing();
    double       e = 0.;
    for_each_existing_bond([&](std::size_t k, std::size_t i, std::size_t j) {
      if (bit(s.broken, k * plane_words, i))
        return;
      const double S = ((s.ux[j] - s.ux[i]) * st.ex[k] + (s.uy[j] - s.uy[i]) * st.ey[k]) /
                       (st.length[k] * h);
      const double x = mat.beta() * st.length[k] * h * S * S;
      e += 2. * volume * energy_coeff[k] * (is_linear(k, i) || !mat.softens(S) ? x : 1. - std::exp(-x));
    });
    return e;
  }

  double PdModel::kinetic_energy(const State &s) const
  {
    double e = 0.;
    for (std::size_t i : active_nodes)
      e += free_x[i] * s.vx[i] * s.vx[i] + free_y[i] * s.vy[i] * s.vy[i];
    return 0.5 * mat.parameters().density * volume * e;
  }

  std::vector<double> PdModel::inflection_stretches() const
  {
    std::vector<double> s;
    for (std::size_t k = 0; k < st.size(); ++k)
      s.push_back(mat.inflection_stretch(st.length[k] * grid.spacing()));
    return s;
  }

  std::vector<double> PdModel::damage(const State &s) const
  {
    const double        h          = grid.spacing();
    const auto          inflection = inflection_stretches();
    std::vector<double> lost(grid.storage_size(), 0.), all(grid.storage_size(), 0.);
    for_each_existing_bond([&](std::size_t k, std::size_t i, std::size_t j) {
      const double w = st.weight[k];
      all[i] += w;
      all[j] += w;
      const double r = st.length[k] * h;
      const double S = ((s.ux[j] - s.ux[i]) * st.ex[k] + (s.uy[j] - s.uy[i]) * st.ey[k]) / r;
      if (bit(s.broken, k * plane_words, i) || (std::abs(S) > inflection[k] && !is_linear(k, i) && mat.softens(S)))
        {
          lost[i] += w;
          lost[j] += w;
        }
    });
    for (std::size_t i = 0; i < lost.size(); ++i)
      lost[i] = all[i] > 0. ? lost[i] / all[i] : 0.;
    return lost;
  }

  std::vector<double> PdModel::stretch_ratio(const State &s) const
  {
    return largest_stretch_ratio(s, false);
  }

  std::vector<double> PdModel::compressive_stretch_ratio(const State &s) const
  {
    return largest_stretch_ratio(s, true);
  }

  std::vector<double> PdModel::largest_stretch_ratio(const State &s, bool shortening_only) const
  {
    const double        h          = grid.spacing();
    const auto          inflection = inflection_stretches();
    std::vector<double> z(grid.storage_size(), 0.);
    for_each_existing_bond([&](std::size_t k, std::size_t i, std::size_t j) {
      const double r       = st.length[k] * h;
      const double S       = ((s.ux[j] - s.ux[i]) * st.ex[k] + (s.uy[j] - s.uy[i]) * st.ey[k]) / r;
      const bool   counted = mat.softens(S) && (!shortening_only || (S < 0. && !is_linear(k, i)));
      const double ratio   = counted ? std::abs(S) / inflection[k] : 0.;
      z[i]                 = std::max(z[i], ratio);
      z[j]                 = std::max(z[j], ratio);
    });
    return z;
  }

  std::vector<double> PdModel::energy_density(const State &s) const
  {
    const double        h = grid.spacing();
    std::vector<double> w(grid.storage_size(), 0.);
    for_each_existing_bond([&](std::size_t k, std::size_t i, std::size_t j) {
      if (bit(s.broken, k * plane_words, i))
        return;
      const double r = st.length[k] * h;
      const double S = ((s.ux[j] - s.ux[i]) * st.ex[k] + (s.uy[j] - s.uy[i]) * st.ey[k]) / r;
      const double x = mat.beta() * r * S * S;
      const double g = energy_coeff[k] * (is_linear(k, i) || !mat.softens(S) ? x : 1. - std::exp(-x));
      w[i] += g;
      w[j] += g;
    });
    return w;
  }

  std::size_t PdModel::intact_bonds(const State &s) const
  {
    std::size_t n = 0;
    for_each_existing_bond([&](std::size_t k, std::size_t i, std::size_t) {
      n += !bit(s.broken, k * plane_words, i);
    });
    return n;
  }
} // namespace pumpd::local
