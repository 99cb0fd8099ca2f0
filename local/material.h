// Lipton's bond-based softening peridynamic material (reference, Sec. 2.2; Lipton 2014, 2016).
//
// Pair potential of a bond xi = y - x with stretch S (linearised, S = (u(y)-u(x)).e / |xi|):
//   psi(xi, S) = J(|xi|/delta) g(|xi| S^2) / (delta |B_delta|),   g(r) = C (1 - exp(-beta r)),
// energy density W(x) = int_{B_delta(x)} psi dy (each bond counted at both of its ends, as in
// Lipton and the PeriHPX decks), force density its variation:
//   f(x) = int 4 J S g'(|xi| S^2) / (delta |B_delta|) e dy.
// Small strain: W = (C beta M / 4)((tr eps)^2 + 2 eps:eps), so lambda = mu = C beta M / 2.
// Separation: G = 4 C M / pi.  With M = int_0^1 J(r) r^2 dr this gives
//   C = pi G_c / (4 M)   (as the decks)    and    beta = 2 lambda / (C M).
// The decks and Lipton's papers write beta = 4 lambda / (C M): Lipton's elastic energy is
// int 2 mu |eps|^2 + lambda (div u)^2 (no factor 1/2), so with the usual Lame constants the decks'
// beta doubles the stiffness (checked in tests/local/calibration_test.cc). The reference paper's
// own formulas (C = pi G_c / 4, beta = 4 E nu / (C (1-nu)(1-2nu)), nu = 1/3 "for plane strain")
// omit M and mix up the two cases: bond-based 2D fixes nu = 1/4 in plane strain and 1/3 in plane
// stress; lambda below is the in-plane Lame constant of that case.
//
// A bond fails for good when |S| exceeds break_factor times the inflection stretch
// S_c(r) = 1 / sqrt(2 beta r) (where the bond force peaks); the decks use 10.
//
// Lipton's g depends on S^2: a bond softens and fails when shortened as when stretched. With
// Compression::linear a shortened bond (S < 0) keeps the force and energy of the linearised law,
// psi = J C beta |xi| S^2 / (delta |B_delta|) (g(r) ~ C beta r), and never fails, as bonds
// do in Silling's prototype microelastic brittle model.
#pragma once

#include <string>

namespace pumpd::local
{
  enum class Influence
  {
    constant, ///< J(r) = 1 on [0, 1)
    linear    ///< J(r) = 12 (1 - r), normalised to M = 1 (the decks' type 1)
  };

  Influence   influence_from_string(const std::string &name);
  std::string to_string(Influence influence);

  /// The bond law of a shortened bond (S < 0).
  enum class Compression
  {
    softening, ///< Lipton's g(|xi| S^2), as in tension
    linear     ///< the linearised law; the bond never fails
  };

  Compression compression_from_string(const std::string &name);

  struct MaterialParameters
  {
    double    youngs_modulus  = 2.4e9; ///< E [Pa]
    double    fracture_energy = 500.;  ///< G_c [J/m^2]
    double    density         = 1200.; ///< rho [kg/m^3]
    bool      plane_strain    = true;  ///< nu = 1/4 (plane strain) or 1/3 (plane stress)
    Influence influence       = Influence::linear;
    double    break_factor    = 10.;   ///< bond fails at break_factor * S_c
    Compression compression   = Compression::softening;
  };

  class LiptonMaterial
  {
  public:
    /// Throws InvalidParameter for E, G_c, rho, delta <= 0 or break_factor < 1.
    LiptonMaterial(const MaterialParameters &parameters, double horizon);

    const MaterialParameters &parameters() const { return p; }
    double horizon() const { return delta; }
    double poisson_ratio() const { return p.plane_strain ? 0.25 : 1. / 3.; }
    /// In-plane Lame constants (lambda = mu for bond-based PD).
    double lame_lambda() const { return lambda; }
    double shear_modulus() const { return lambda; }
    /// E' = E / (1 - nu^2) in plane strain, E in plane stress.
    double effective_modulus() const;
    /// Critical stress intensity factor sqrt(E' G_c).
    double critical_sif() const;

    double moment() const { return M; }   ///< M = int_0^1 J(r) r^2 dr
    double C() const { return c; }
    double beta() const { return b; }
    /// J(r / delta), zero outside the horizon.
    double influence(double r_over_delta) const;
    /// S_c(r) = 1 / sqrt(2 beta r), the stretch of peak bond force.
    double inflection_stretch(double r) const;
    /// Whether a bond at stretch S follows Lipton's softening law (else the linear one).
    bool softens(double S) const { return S > 0. || p.compression == Compression::softening; }
    /// 1 / (delta |B_delta|) = 1 / (pi delta^3).
    double normalisation() const { return norm; }

    /// Linear-elastic energy density 1/2 sigma:eps of an in-plane strain.
    double elastic_energy_density(double exx, double eyy, double exy) const;

  private:
    MaterialParameters p;
    double             delta, lambda, M, c, b, norm;
  };
} // namespace pumpd::local
