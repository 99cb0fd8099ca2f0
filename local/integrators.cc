#include "integrators.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "error.h"

namespace pumpd::local
{
  void check_finite(const PdModel &model, const State &s)
  {
    double sum = 0.;
    for (std::size_t i : model.nodes())
      sum += s.ux[i] * s.ux[i] + s.uy[i] * s.uy[i] + s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] +
             s.fx[i] * s.fx[i] + s.fy[i] * s.fy[i];
    if (!std::isfinite(sum))
      {
        std::ostringstream m;
        m << "non-finite displacement, velocity or force in the PD state at step " << s.step << " (time "
          << s.time << " s)";
        throw NonFiniteState(m.str());
      }
  }

  VelocityVerlet::VelocityVerlet(const PdModel &m, double time_step)
    : pd(m)
    , dt(time_step)
  {
    const double bound = pd.stable_time_step();
    if (!(dt > 0.) || dt > bound)
      {
        std::ostringstream allowed;
        allowed << "must be in (0, " << bound
                << "] s, the Silling-Askari bound sqrt(2 rho / sum_j c_ij / |xi_ij|) of this lattice";
        std::ostringstream value;
        value << dt << " s";
        throw InvalidParameter("PD time step", value.str(), allowed.str());
      }
  }

  void VelocityVerlet::initialise(State &s) const
  {
    pd.compute_forces(s);
    check_finite(pd, s);
  }

  void VelocityVerlet::step(State &s, const BoundaryLayer &layer, double ramp_end,
                            const std::vector<const RegionDisplacement *> &regions) const
  {
    const auto  &free_x = pd.free_mask_x();
    const auto  &free_y = pd.free_mask_y();
    const auto  &cn     = pd.constrained_nodes();
    const double k      = 0.5 * dt / pd.material().parameters().density;

    std::vector<double> fx0(cn.size()), fy0(cn.size()), ux0(cn.size()), uy0(cn.size());
    for (std::size_t n = 0; n < cn.size(); ++n)
      {
        fx0[n] = s.fx[cn[n]];
        fy0[n] = s.fy[cn[n]];
        ux0[n] = s.ux[cn[n]];
        uy0[n] = s.uy[cn[n]];
      }

    const std::size_t n = s.ux.size();
    for (std::size_t i = 0; i < n; ++i)
      {
        s.vx[i] = free_x[i] * (s.vx[i] + k * s.fx[i]);
        s.vy[i] = free_y[i] * (s.vy[i] + k * s.fy[i]);
        s.ux[i] += dt * s.vx[i];
        s.uy[i] += dt * s.vy[i];
      }
    layer.apply(s, ramp_end);
    for (const auto *r : regions)
      r->apply(s, ramp_end);
    pd.compute_forces(s);
    for (std::size_t i = 0; i < n; ++i)
      {
        s.vx[i] = free_x[i] * (s.vx[i] + k * s.fx[i]);
        s.vy[i] = free_y[i] * (s.vy[i] + k * s.fy[i]);
      }

    // Work of the constraints: the force they apply is minus the bond force on the prescribed
    // components (a free component's share is zero: it is not prescribed).
    double work = 0.;
    for (std::size_t m = 0; m < cn.size(); ++m)
      {
        const std::size_t i = cn[m];
        work -= 0.5 * ((1. - free_x[i]) * (fx0[m] + s.fx[i]) * (s.ux[i] - ux0[m]) +
                       (1. - free_y[i]) * (fy0[m] + s.fy[i]) * (s.uy[i] - uy0[m]));
      }
    s.external_work += pd.node_volume() * work;
    s.time += dt;
    ++s.step;
    check_finite(pd, s);
  }

  DynamicRelaxation::DynamicRelaxation(const PdModel &m, double tolerance, std::size_t max_iterations)
    : model(m)
    , tol(tolerance)
    , max_it(max_iterations)
  {
    require_range("Relaxation tolerance", tol, 1e-14, 0.5, "must be in [1e-14, 0.5]");
    if (max_it < 1)
      throw InvalidParameter("Relaxation iterations", "0", "must be >= 1");
  }

  namespace
  {
    /// |u - u_rigid|^2 over the nodes, u_rigid the least-squares rigid motion t + omega e_z x (x - x_c):
    /// the part of u that strains the body. A box cut out of a deflecting body moves and turns
    /// far more than it deforms, so a residual relative to |u| itself would stop too early.
    /// The node offsets from the centroid are fixed: computed once per relaxation.
    class DeformationNorm
    {
    public:
      explicit DeformationNorm(const PdModel &model)
        : nodes(model.nodes())
      {
        double xc = 0., yc = 0.;
        for (std::size_t i : nodes)
          {
            const auto x = model.lattice().position(i);
            xc += x.x, yc += x.y;
          }
        const double n = std::max<double>(1., nodes.size());
        for (std::size_t i : nodes)
          {
            const auto x = model.lattice().position(i);
            dx.push_back(x.x - xc / n), dy.push_back(x.y - yc / n);
            polar += dx.back() * dx.back() + dy.back() * dy.back();
          }
      }

      double squared(const State &s) const
      {
        if (nodes.empty())
          return 0.;
        double tx = 0., ty = 0., turn = 0.;
        for (std::size_t k = 0; k < nodes.size(); ++k)
          {
            tx += s.ux[nodes[k]], ty += s.uy[nodes[k]];
            turn += dx[k] * s.uy[nodes[k]] - dy[k] * s.ux[nodes[k]];
          }
        tx /= nodes.size(), ty /= nodes.size();
        const double omega = polar > 0. ? turn / polar : 0.; // sum dx = sum dy = 0: t drops out
        double       u2    = 0.;
        for (std::size_t k = 0; k < nodes.size(); ++k)
          {
            const double rx = s.ux[nodes[k]] - tx + omega * dy[k], ry = s.uy[nodes[k]] - ty - omega * dx[k];
            u2 += rx * rx + ry * ry;
          }
        return u2;
      }

    private:
      const std::vector<std::size_t> &nodes;
      std::vector<double>             dx, dy;
      double                          polar = 0.;
    };
  } // namespace

  // Kilic & Madenci (2010) with time step 1: adaptive damping c = 2 sqrt(u.K1 u / u.u) from the
  // local diagonal stiffness K1_ii = -(f_i^n - f_i^{n-1}) / (rho v_i^{n-1/2}).
  // Fictitious density rho = Lambda / 4, the least the step allows: central differences are stable
  // for lambda_max(K) <= 4 rho, and lambda_max(K) <= Lambda, since no bond's tangent exceeds its
  // linear stiffness c = a / |xi| and u.K u = sum_bonds c (e.(u_j - u_i))^2 <= 2 sum_i u_i.(sum_j c
  // e e^T) u_i <= Lambda |u|^2 (over the full stencil, sum_j c e e^T = Lambda / 2 I).
  RelaxationResult DynamicRelaxation::solve(State &s, const Servo &servo) const
  {
    const auto       &nodes  = model.nodes();
    const auto       &free_x = model.free_mask_x();
    const auto       &free_y = model.free_mask_y();
    const double      lambda = model.stiffness_scale();
    const double      rho    = 0.25 * lambda;
    const std::size_t n      = s.ux.size();
    std::vector<double> fx_old(n, 0.), fy_old(n, 0.);

    const DeformationNorm deformation(model);
    RelaxationResult      result;
    if (servo.correct)
      result.servo_error = servo.correct(s);
    model.compute_forces(s);
    check_finite(model, s);
    double damping = 0.;
    for (std::size_t it = 0;; ++it)
      {
        double f2 = 0.;
        for (std::size_t i : nodes)
          f2 += free_x[i] * s.fx[i] * s.fx[i] + free_y[i] * s.fy[i] * s.fy[i];
        const double u2   = deformation.squared(s);
        result.iterations = it;
        result.residual   = std::sqrt(f2) / (lambda * std::sqrt(u2) + 1e-300);
        result.converged  = (result.residual < tol || f2 == 0.) && result.servo_error < servo.tolerance;
        if (result.converged || it == max_it)
          break;
        for (std::size_t i : nodes)
          {
            if (it == 0) // v^{1/2} = F^0 / (2 rho)
              {
                s.vx[i] = free_x[i] * s.fx[i] / (2. * rho);
                s.vy[i] = free_y[i] * s.fy[i] / (2. * rho);
              }
            else
              {
                s.vx[i] = free_x[i] * ((2. - damping) * s.vx[i] + 2. * s.fx[i] / rho) / (2. + damping);
                s.vy[i] = free_y[i] * ((2. - damping) * s.vy[i] + 2. * s.fy[i] / rho) / (2. + damping);
              }
            s.ux[i] += s.vx[i];
            s.uy[i] += s.vy[i];
            fx_old[i] = s.fx[i];
            fy_old[i] = s.fy[i];
          }
        if (servo.correct)
          result.servo_error = servo.correct(s);
        model.compute_forces(s);
        check_finite(model, s);
        double num = 0., den = 0.;
        for (std::size_t i : nodes)
          {
            const auto local = [&](double f, double f0, double v, double u) {
              if (v == 0.)
                return;
              const double k1 = -(f - f0) / (rho * v);
              num += u * k1 * u;
              den += u * u;
            };
            if (free_x[i] != 0.)
              local(s.fx[i], fx_old[i], s.vx[i], s.ux[i]);
            if (free_y[i] != 0.)
              local(s.fy[i], fy_old[i], s.vy[i], s.uy[i]);
          }
        damping = (den > 0. && num > 0.) ? std::min(1.9, 2. * std::sqrt(num / den)) : 0.;
      }
    std::fill(s.vx.begin(), s.vx.end(), 0.);
    std::fill(s.vy.begin(), s.vy.end(), 0.);
    return result;
  }
} // namespace pumpd::local
