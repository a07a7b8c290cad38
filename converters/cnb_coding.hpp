#pragma once
// The .cnb file of a scene as convert and report write it: every body coded the cheapest way within D
// (analysis/coding_choice/cheapest_coding: its NURBS as they are or a certified mesh), costed by the .cnb
// writer itself, then written with the meshes' certificate as their share of the bound.
#include <string>

#include "analysis/coding_choice/cheapest_coding.hpp"
#include "core/scene.hpp"
#include "formats/cnb/cnb_options.hpp"

namespace cadnurbs {

struct CnbCoding {
  Scene scene;                // as written: the chosen bodies meshed
  CnbOptions options;         // D, the trim share (= the meshes' share: 0.4, or where every body was meshed
                              // whichever of 0.4, 0.6 and 0.8 codes smallest), mesh_deviation = their
                              // certificate, quantisation_scale (below; for a scene without trimmed
                              // surfaces, whichever of 1, 0.99, ..., 0.8 codes smallest)
  CodingChoiceReport choice;  // what was meshed, and the candidates' bytes
  CnbWriteReport written;     // the writer's report for `bytes`; its deviation_bound() is within D
  std::string bytes;          // the file
};

// The quantisation scale: a file that its reader sews before meshing (sewn_when_meshed: polygon sets, or no
// shared-edge numbers, as from IGES and VRML) is sewn at D/4, while the quantisation at D may part two faces'
// edges by up to 2 D. So such a scene is written at the largest scale of 1, 1/√2, 1/2, ..., 1/64 (half
// octaves: capping-moulded.step at 1e-3 of its diagonal sews at 0.35, 664 bytes, not 1/4, 692; the muRATA
// 5100 toroid at 0.01 mm at 0.044, 30,677 bytes, where 1/8 left 218 pieces open) whose decoded
// file sews (at D/4, as certified_mesh does) with no longer an open boundary in no more pieces than the
// scene itself (1% allowed, and D of length), if that file also meshes at D as convert meshes it with no
// more uncertified triangles, no more unshared edge uses and no longer an open boundary than the scene;
// else at the scale that moves every boundary by at most half the tolerance within which sewing first
// merges vertices (1e-5 of the diagonal), so that it finds the scene's own vertices. The mesh is checked
// because sewing alone reported wing.iges's compact form closed at 1/4 and 1/8, where its mesh had 28 open
// edges, then 23,988 uncertified triangles; only the first scale that sews alike is meshed, since such
// meshes can take minutes. hammer.iges at 1 mm takes 1/4 (7,168 bytes instead of 6,450; 4 open pieces,
// the part's own, instead of 127).
//
// `max_deviation` = D > 0 in scene units. `exact` (may be null): the part `scene` is the compact form of
// (compact_scene), whose every body meshed is one more candidate (cheapest_coding.hpp). Candidates are
// costed by write_cnb with the meshes' certificate as mesh_deviation (the header states the bound), so
// `bytes` is the size the choice was made on; a candidate the writer refuses is not chosen.
// mesh_where_cheaper = false writes the scene as it is (convert --exact-nurbs), `choice` then holding its
// bytes as every candidate's and no body. Throws as write_cnb (for the scene as it is) and cheapest_coding do.
CnbCoding cnb_coding(const Scene& scene, double max_deviation, const Scene* exact = nullptr,
                     bool mesh_where_cheaper = true);

// How the bound of a .cnb written by cnb_coding is made up, for deviation bases: "" when no body was
// meshed, else "; it includes the certificate X of the N bodies (F faces, P polygons) written as meshes".
std::string meshed_bodies_basis(const CodingChoiceReport& choice);

}  // namespace cadnurbs
