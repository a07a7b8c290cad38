#pragma once
// A trimmed face with its normal turned round, for a Brep face whose m_bRev says its normal is the
// opposite of its surface's (and for Extrusion faces built the other way round).
//
// In:  a trimmed surface whose loops follow the VRML/X3D rule.
// Out: the surface with u and v swapped (normal Su x Sv reversed) and every loop's points mirrored the
//      same way, then traversed backwards so that the rule still holds (TrimEdgeRef::reversed flipped
//      with it). Exact: points, weights and knots are only moved, never recomputed.
#include "core/trimmed_surface.hpp"

namespace cadnurbs::rhino {

TrimmedSurface flipped(const TrimmedSurface& face);

}  // namespace cadnurbs::rhino
