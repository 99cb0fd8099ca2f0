// The PD adapter: a place of a scene's condition (basics/conditions.h) as a prescribed region of
// a PD body (model.h), fixing the components the condition names.
//   a point    -> the nodes within `point_radius` of each of its vertices (a support, a pad)
//   a boundary -> the nodes within `band_width` of its faces (a grip)
//   a region   -> the nodes in its cells
#pragma once

#include "conditions.h"
#include "model.h"

namespace pumpd::local
{
  PrescribedRegion prescribed_region(const conditions::Place &place, bool fix_x, bool fix_y, double point_radius,
                                     double band_width);
} // namespace pumpd::local
