// Double cantilever beam (prm/double-cantilever-beam.prm, meshes/double-cantilever-beam.geo): arms
// of height h = 0.01 m, length L = 0.12 m, opened by P = lambda per m of thickness as uniform
// shear tractions on the arms' end faces, held by three support components that carry no load.
//
// Compliance against corrected beam theory: each arm a cantilever of length a, lengthened by the
// rotation of its root on the uncracked beam (Kanninen 1973, "An augmented double cantilever beam
// model for studying crack propagation and arrest", Int. J. Fract. 9: the arm on an elastic
// foundation of stiffness 2 E' / h, decay length 6^(-1/4) h):
//   C = Delta / P = 8 (a + chi h)^3 / (E' B h^3),  chi = 6^(-1/4) = 0.639,
// Delta the opening at the load (here 2 U / P, the mean opening of the end faces), B = 1, E' the
// plane-strain modulus. The corrected beam theory of the DCB test standards (ISO 15024, ASTM
// D5528) has this form with chi measured. The model leaves out the arms' shear; plane elasticity
// gives chi = 0.673 (below) and a compliance up to 1.8 % above the formula at a/h = 5: the
// tolerance is 3 %. The critical load from that compliance: G = P^2 / (2 B) dC/da = 12 P^2 (a +
// chi h)^2 / (E' B^2 h^3) = G_c gives P_c = B h^(3/2) sqrt(E' G_c) / (2 sqrt(3) (a + chi h)),
// against the code's lambda_c (from K by the interaction integral).
// Cross-check: the plane-elasticity K of the long DCB (Fichter 1983; Foote & Buchwald 1985,
// Int. J. Fract. 29), K = 2 sqrt(3) P (a + 0.673 h) / (B h^(3/2)) for long arms and ligament
// (here a/h = 5 to 7, a ligament of at least 5 h).
#include <gtest/gtest.h>

#include <deal.II/grid/tria.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "metric.h"
#include "scene_file.h"
#include "specimen.h"

using namespace pumpd;

TEST(DoubleCantileverBeam, ComplianceAndCriticalLoadAgainstCorrectedBeamTheory)
{
  const double h = 0.01, chi = std::pow(6., -0.25);
  double       worst_compliance = 0., worst_load = 0., worst_k = 0.;
  const auto   worse = [](double e, double &worst) { worst = e > worst || std::isnan(e) ? e : worst; };
  for (const double a : {0.05, 0.06, 0.07})
    {
      auto               p = test::scene_file("prm/double-cantilever-beam.prm", "");
      std::ostringstream crack;
      crack << "0,0; " << a << ",0";
      p.scene.initial_cracks = crack.str();
      const auto scene       = coupling::build_scene(p.scene);
      const auto solution    = test::solve(scene, p.global);
      EXPECT_EQ(solution.load, 1.); // Report: Load = lambda

      const double e_prime    = scene.material.effective_modulus();
      const double compliance = solution.displacement; // (2 U / lambda) / lambda
      const double beam       = 8. * std::pow(a + chi * h, 3) / (e_prime * h * h * h);
      const double p_c = std::pow(h, 1.5) * scene.material.critical_sif() / (2. * std::sqrt(3.) * (a + chi * h));
      const double k_exact = 2. * std::sqrt(3.) * (a + 0.673 * h) / std::pow(h, 1.5);
      std::cout << "a / h = " << a / h << ": compliance " << compliance << " m/N, beam theory " << beam
                << "; critical load " << solution.tip.critical_load_factor << " N/m, beam theory " << p_c << "; K "
                << solution.tip.k1 << ", exact " << k_exact << "; K_II / K_I " << solution.tip.k2 / solution.tip.k1
                << "\n";
      worse(std::abs(compliance / beam - 1.), worst_compliance);
      worse(std::abs(solution.tip.critical_load_factor / p_c - 1.), worst_load);
      worse(std::abs(solution.tip.k1 / k_exact - 1.), worst_k);
      EXPECT_LT(std::abs(solution.tip.k2), 1e-3 * solution.tip.k1);
    }
  test::metric("scene.dcb.compliance_rel_err", worst_compliance);
  test::metric("scene.dcb.critical_load_rel_err", worst_load);
  test::metric("scene.dcb.k_rel_err_exact", worst_k);
  EXPECT_LT(worst_compliance, 0.03);
  EXPECT_LT(worst_load, 0.03);
  EXPECT_LT(worst_k, 0.01);
}

// Study (ctest -L study): a = 0.06 m on meshes of 2, 1 and 0.5 mm (the tip cells refined twice
// more); compliance against corrected beam theory and K against the exact value per mesh.
TEST(DoubleCantileverBeamStudy, DISABLED_MeshRefinement)
{
  const double h = 0.01, a = 0.06, chi = std::pow(6., -0.25);
  for (const double size : {0.002, 0.001, 0.0005})
    {
      auto p                 = test::scene_file("prm/double-cantilever-beam.prm", "");
      p.scene.mesh_size      = size;
      const auto scene       = coupling::build_scene(p.scene);
      const auto solution    = test::solve(scene, p.global);
      const double beam      = 8. * std::pow(a + chi * h, 3) / (scene.material.effective_modulus() * h * h * h);
      const double k_exact   = 2. * std::sqrt(3.) * (a + 0.673 * h) / std::pow(h, 1.5);
      std::cout << "mesh size " << size << " m, " << scene.mesh->n_active_cells() << " cells: compliance "
                << solution.displacement << " m/N, beam theory " << beam << "; K " << solution.tip.k1 << ", exact "
                << k_exact << "\n";
      const std::string at = "_at_h_" + std::to_string(int(std::round(size * 1e6))) + "um";
      test::metric("scene.dcb.compliance_rel_err" + at, std::abs(solution.displacement / beam - 1.));
      test::metric("scene.dcb.k_rel_err_exact" + at, std::abs(solution.tip.k1 / k_exact - 1.));
    }
}
