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
  CnbOptions options;         // D, the trim share (= the meshes' share), mesh_deviation = their certificate,
                              // quantisation_scale (below)
  CodingChoiceReport choice;  // what was meshed, and the candidates' bytes
  CnbWriteReport written;     // the writer's report for `bytes`; its deviation_bound() is within D
  std::string bytes;          // the file
};

// The quantisation scale: a file that its reader sews before meshing (sewn_when_meshed: polygon sets, or no
// shared-edge numbers, as from IGES and VRML) is sewn at D/4, while the quantisation at D may part two faces'
// edges by up to 2 D. So such a scene is written at the largest scale of 1, 1/2, 1/4 and 1/8 whose decoded
// file, sewn as certified_mesh sews it for a mesh at D, leaves no longer a boundary open, in no more pieces,
// than the scene itself sewn the same way (1% allowed, and D of length: sampled); else at the scale that
// moves every boundary by at most half the tolerance within which sewing first merges vertices and cuts
// pieces (1e-5 of the diagonal), so that it finds the scene's own vertices. hammer.iges at 1 mm: 127 open
// pieces at 1, 48 at 1/2, 4 (the part's own) at 1/4, for 7,169 bytes instead of 6,450; at 1e-3 of its
// diagonal (41 mm) 1/8 still left 19 open pieces (the exact faces: 0), and meshing them took 268,430
// triangles, 6,339 of them uncertified; at 1/200, 1,128 triangles, none uncertified.
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
