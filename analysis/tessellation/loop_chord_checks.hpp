#pragma once
// Step 2 of tessellate_to_deviation, its last part: which chords of a face's sampled loops must be
// split (on their model curve, for every face that uses it) before the face can be meshed (internal).
//
// In: a face whose loop points are collected (Face::points), and D. Out: spans of model curves added
// to `out`; chords of a face's own samples (no model curve span) are never reported.
#include <set>

#include "analysis/tessellation/tessellation_face.hpp"

namespace cadnurbs::tessellation {

// Chords that properly cross another chord of the face's loops in (u,v), and every chord of a loop of
// fewer than 3 distinct points (coarse chords of nearby loops, a small hole near an outer boundary,
// may cross; a small closed edge may come out as too few points). Chords that touch or overlap are
// left alone: they follow loops that touch or overlap themselves in the file, which no split can undo.
void crossing_chords(const Face& face, std::set<CurveSpan>& out);

// Chords this face's surface does not follow within D (criterion (2) of sample_trim_segment, between
// this face's own points at the chord's ends), or that cross more than one line of its grid. A curve is
// sampled on its first face; on the others, triangles along such a chord could never be certified, and
// refining towards it only makes slivers.
void coarse_chords(const Face& face, double max_deviation, std::set<CurveSpan>& out);

}  // namespace cadnurbs::tessellation
