#pragma once
// The check that our own NURBS files mesh as watertight as the B-rep they came from (issue 9): `source`
// (read from STEP/IGES, with the B-rep's shared edges) is meshed at D = 0.01 x its bounding-box diagonal
// and welded by exact position; then written as X3D classic (compact and as the exact NURBS), VRML97 and
// X3D XML (compact), each read back, sewn (sew_faces at sewing_tolerance) and meshed the same way:
//  - every use of a sewn edge finds the edge on its face (no unshared edge uses);
//  - where the B-rep's mesh is closed (no boundary, no non-manifold edge), every read-back mesh is too;
//  - and the exact NURBS read back, where sewing needed no cut and found no edge shorter than its
//    tolerance, gives exactly the B-rep's shared edges (count of edges used twice or more, per
//    placement). Otherwise (open B-reps, whose open edges depend on the sampling; cut or tiny edges)
//    the counts are printed.
// Reports failures through GoogleTest and prints one line of figures per form.
#include <string>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/scene.hpp"
#include "formats/vrml/vrml_writer.hpp"

namespace cadnurbs::test {

void check_read_back_watertight(const Scene& source, const std::string& name);

// One form of it: `source` written (compact_scene first when `compact`) at the writer's default
// precision, read back, its loops repaired (as `convert` does to every input), sewn and meshed at `deviation`; the welded mesh's edge counts (sewing and
// tessellation reports to the pointers given).
EdgeCounts read_back_edges(const Scene& source, VrmlEncoding encoding, bool compact, double deviation,
                           SewingReport* sewing = nullptr, TessellationReport* report = nullptr);

}  // namespace cadnurbs::test
