// The global adapter: a scene's conditions (basics/conditions.h) as constraints and loads of the
// enriched elasticity problem, at a load factor lambda.
//   displacement on a boundary -> Dirichlet data on its boundary id (the same on both crack faces)
//                  on a point  -> Dirichlet data on its vertices
//                  on a region -> Dirichlet data on every node of its cells
//   traction on a boundary     -> (tx, ty) - p n on its faces
//   point force on a point     -> a nodal force on its vertex (shared among its vertices)
#pragma once

#include "elasticity.h"
#include "conditions.h"

namespace pumpd::global
{
  void apply(const conditions::Conditions &conditions, EnrichedElasticity &problem, double lambda = 1.);
} // namespace pumpd::global
