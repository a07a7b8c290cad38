#include "converters/cnb_coding.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "converters/scene_preparation.hpp"
#include "core/bounding_box.hpp"
#include "core/number_format.hpp"
#include "formats/cnb/cnb_quantisation.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"

namespace cadnurbs {

namespace {
// The share of D that trims (in (u,v)) and meshes (their certificate) may use; points get the rest.
constexpr double kMeshShare = 0.4;
// Where that share meshed every body, these are tried too: a coarser mesh on a finer grid is smaller on
// small curved parts (90 KiCad parts at 1 mm, the best of 0.4, 0.6 and 0.8 per part: 73,764 -> 72,063
// bytes before mesh groups), while 0.6 or 0.8 for all was larger (77,510 and 80,860). 0.5 and 0.7 as well
// helped dense curved meshes by about 1.5% (Ventilator.stp at 3e-4 of its diagonal 19,326 -> 19,047 bytes,
// linkrods.step at 1e-4 5,975 -> 5,902) and 50 DFN and Phoenix parts at 0.01 mm by 0.04%, for twice the
// CPU of a wholly meshed part (io1-tu-203.stp at 1 mm, with the coarser grids below at up to 1.4x): not
// tried.
constexpr double kWholeMeshShares[] = {0.6, 0.8};
// They are tried, too, where the NURBS were chosen but a wholly meshed candidate came within this factor:
// the Phoenix MC 1,5/2-GF MountHole at 0.01 mm codes its NURBS in 3,509 bytes (at 561b8b1), its meshes in
// 3,732 at 0.4 and in 2,468 at 0.8.
constexpr double kMeshedWithin = 1.5;
// Where the chosen meshes crack (the part's own faces lie farther apart than the share along a shared
// edge), this share is tried too, and fewer cracks win over fewer bytes: Ventilator.stp at 1e-4 of its
// diagonal meshes with 36 open edges at 0.4, 0.6 and 0.8 of D and closed at 0.95, as at D (its NURBS,
// their approximated pcurves refit, now cost less than either).
constexpr double kClosingShare = 0.95;
// The scales at which a decoded file that sews alike is meshed to see whether it meshes alike too. One was
// a cliff: sunglasses_lens.igs at D = 3e-4 of its diagonal meshed alike at 1/sqrt(2) but not at 1, and went
// to the safe scale (NURBS 9,971 bytes against 3,533 at 0.0222572 mm, where 1 meshed alike).
constexpr int kMeshChecks = 3;
// A grid a little finer than the bound needs can code smaller: where a part's pitches fall in whole steps,
// its repeats predict exactly. A scene without trimmed surfaces (every face meshed) is written at whichever
// of 1, 0.99, ..., 0.80 of the step codes smallest (90 KiCad parts at 1 mm: 60,937 -> 58,822 bytes with
// steps of 0.005; TQFP-52 977 -> 809). A finer grid only tightens the bound; trims, whose sewing was
// checked at one scale, are not moved. Every wholly meshed share is written on these grids, not only the
// one that cost least at the step itself: the grids reorder them. PinHeader_1x21 SMD Pin1Right at 1 mm:
// 698 bytes at a share whose file cost more at the step itself, against 926 at the cheapest as costed; DFN-10-1EP 2x3mm at 0.01 mm costs 622 bytes at 0.4 and 629 at 0.8, which the
// grids take to 620 and 566.
constexpr int kFinerGrids = 20;
constexpr double kFinerGridStep = 0.01;

// A grid coarser than the worst rounding allows can still keep every vertex within the points' share:
// the writer then states their largest move as decoded (CnbOptions::measured_point_step). Tried on
// wholly meshed scenes: steps up to kCoarserGrids·kCoarserGridStep coarser than the worst case's (to 1.4x
// cost more CPU and saved nothing more on 50 DFN and Phoenix parts at 0.01 mm), and
// the decimal steps (1, 2, 2.5 and 5 times a power of ten) up to kCoarsestDecimal times it, on which parts
// drawn on decimal dimensions keep their corners exactly.
constexpr int kCoarserGrids = 4;
constexpr double kCoarserGridStep = 0.05;
constexpr double kCoarsestDecimal = 64;

// The steps above whose largest move is within the points' share and that collapse no more faces than
// the worst case's step: each as the float32 the writer stores.
std::vector<double> coarser_steps(const Scene& scene, const CnbOptions& options) {
  const double q = cnb::point_step(scene, options);
  const double share = cnb::point_share(options);
  std::vector<double> candidates;
  for (int i = 1; i <= kCoarserGrids; ++i) candidates.push_back(q * (1.0 + kCoarserGridStep * i));
  for (double decade = std::pow(10.0, std::floor(std::log10(q))); decade <= kCoarsestDecimal * q; decade *= 10.0)
    for (double mantissa : {1.0, 2.0, 2.5, 5.0})
      if (mantissa * decade > q && mantissa * decade <= kCoarsestDecimal * q) candidates.push_back(mantissa * decade);
  std::vector<double> steps;
  long collapsed = -1;
  for (double candidate : candidates) {
    const double step = static_cast<float>(candidate);
    try {
      if (cnb::largest_point_move(scene, step) > share) continue;
      if (collapsed < 0) collapsed = cnb::collapsed_faces(scene, static_cast<float>(q));
      if (cnb::collapsed_faces(scene, step) > collapsed) continue;
    } catch (const std::invalid_argument&) {
      continue;  // a coordinate too far from 0 for the grid
    }
    steps.push_back(step);
  }
  return steps;
}

// How a scene meshes as convert meshes a .cnb of it (certified_mesh: sewn first where it sews).
struct MeshedAsRead {
  long uncertified = 0;
  int unshared = 0;
  double open_length = 0;
};

MeshedAsRead meshed_as_read(const Scene& scene, double d) {
  const CertifiedMesh meshed = certified_mesh(BrepTranslation{}, scene, d);
  return {meshed.report.uncertified_triangles, meshed.report.unshared_edge_uses,
          count_boundary_edges(weld_exact(scene_triangles(meshed.meshes))).boundary_length};
}

// The quantisation scale of the header's rule for `scene` (written with `options`), a scene the reader sews.
double scale_keeping_sewn(const Scene& scene, const CnbOptions& options) {
  const double d = options.max_deviation;
  const SewingTolerance tolerance = sewing_tolerance(scene_bounding_box(scene).diagonal().norm(), d);
  // Last, boundaries moved by at most half the tolerance within which sewing merges vertices first.
  const double safe = std::min(0.125, 0.5 * tolerance.first / d);
  SewingReport own;
  sew_faces(scene, tolerance, &own);
  std::optional<MeshedAsRead> mine;
  int mesh_checks = 0;
  auto safe_codes_smaller = [&](size_t bytes) {
    CnbOptions at_safe = options;
    at_safe.quantisation_scale = safe;
    try {
      return write_cnb(scene, at_safe).size() < bytes;
    } catch (const std::invalid_argument&) {
      return false;
    }
  };
  for (int half_octaves = 0; half_octaves <= 12; ++half_octaves) {
    const double scale = std::exp2(-0.5 * half_octaves);
    if (scale <= safe) break;
    try {
      CnbOptions trial = options;
      trial.quantisation_scale = scale;
      const std::string written = write_cnb(scene, trial);
      const Scene decoded = read_cnb(written, "the scene as written");
      SewingReport sewn;
      sew_faces(decoded, tolerance, &sewn);
      if (sewn.open_length > 1.01 * own.open_length + d ||
          sewn.open_pieces > own.open_pieces + (own.open_pieces + 99) / 100)
        continue;
      // Sewn alike; meshed alike too? (At most kMeshChecks scales: a mesh of pieces sewn across moved
      // vertices can take minutes, so after that a failure goes straight to the safe scale.) Most scales
      // that do not mesh alike fail already on their shared edges, which are sampled before any face is
      // meshed: DIP-18_W8.89mm_SMDSocket at 1e-3 of its diagonal meshed its file at 1/45 of D in 13.8 s,
      // to 19,240 uncertified triangles and 170 unshared edge uses against the part's 0 and 0.
      if (!mine) mine = meshed_as_read(scene, d);
      if (certified_scene_unshared_edge_uses(decoded, d, EdgeSource::file) > mine->unshared) {
        if (++mesh_checks == kMeshChecks) return safe;
        continue;
      }
      const MeshedAsRead back = meshed_as_read(decoded, d);
      // An open part's rim meshed finer is longer (its chords approach the curves from below): the rim
      // is compared with the longer of the scene's mesh rim and its rim as sewing samples it, as
      // cnb_read_back compares them (sunglasses_lens.igs at 3e-4 of its diagonal: 373.6 against 367.6).
      const double rim = std::max(mine->open_length, own.open_length);
      const bool alike = back.uncertified <= mine->uncertified && back.unshared <= mine->unshared &&
                         back.open_length <= 1.01 * rim + d;
      // A finer grid can code smaller where the part's dimensions fall on it (R_Array_SIP10 at 0.01 mm:
      // 1,911 bytes at 1/32 of D, 1,886 at the safe 1/74.5): the smaller of the two.
      if (alike) return safe_codes_smaller(written.size()) ? safe : scale;
      if (++mesh_checks == kMeshChecks) return safe;
    } catch (const std::exception&) {
      continue;  // the writer refuses this scale, or its file does not mesh; a finer one may do
    }
  }
  return safe;
}

}  // namespace

CnbCoding cnb_coding(const Scene& scene, double max_deviation, const Scene* exact, bool mesh_where_cheaper) {
  CnbCoding out;
  out.options.max_deviation = max_deviation;
  out.options.trim_share = kMeshShare;
  const bool sewn = sewn_when_meshed(scene);
  const double scale = sewn ? scale_keeping_sewn(scene, out.options) : 1.0;
  const CnbOptions base = out.options;
  auto options_for = [&](const Scene& s) {  // meshes alone are not sewn on reading
    CnbOptions options = base;
    options.quantisation_scale = sewn_when_meshed(s) ? scale : 1.0;
    return options;
  };
  // The exact part's meshes join where its faces meet only if its loops say where: a part that names no shared
  // edges (IGES, VRML) is sewn first, for meshes within the share (sewing at a quarter of it).
  Scene sewn_exact;
  if (mesh_where_cheaper && exact && sewn_when_meshed(*exact)) {
    sewn_exact =
        sew_faces(*exact, sewing_tolerance(scene_bounding_box(*exact).diagonal().norm(), kMeshShare * max_deviation));
    exact = &sewn_exact;
  }
  // The cheapest coding with trims and meshes within `share`·D. A candidate the writer refuses
  // (std::invalid_argument: options it cannot meet for that scene) is never the cheapest; the scene as it
  // is, if refused too, fails in the last write below with the writer's message.
  // `meshes_only`: a candidate that keeps a trimmed surface is not costed (nor chosen).
  auto cheapest = [&](double share, CodingChoiceReport& choice, bool meshes_only) {
    auto coded_bytes = [&](const Scene& s, double mesh_deviation) {
      if (meshes_only && count_entities(s).trimmed_surfaces > 0) return std::numeric_limits<size_t>::max();
      CnbOptions options = options_for(s);
      options.trim_share = share;
      options.mesh_deviation = mesh_deviation;  // the header states the bound it makes part of
      try {
        return write_cnb(s, options).size();
      } catch (const std::invalid_argument&) {
        return std::numeric_limits<size_t>::max();
      }
    };
    return cheapest_coding(scene, {max_deviation, share, !sewn}, coded_bytes, &choice, exact);
  };
  // A coding at one share, written: the trim share is the meshes' share. A scene without trimmed surfaces
  // is also written on the finer grids and on the coarser ones (coarser_steps); the smallest file is kept.
  auto finish = [&](Scene chosen, const CodingChoiceReport& choice, double share) {
    CnbCoding c;
    c.scene = std::move(chosen);
    c.choice = choice;
    c.options = options_for(c.scene);
    c.options.trim_share = share;
    c.options.mesh_deviation = choice.certified_deviation;
    c.bytes = write_cnb(c.scene, c.options, &c.written);
    if (mesh_where_cheaper && count_entities(c.scene).trimmed_surfaces == 0) {
      const CnbOptions first = c.options;
      // Writes at `options` and keeps the file if smaller; false where the writer refuses them.
      const auto keep_if_smaller = [&](const CnbOptions& options) {
        CnbWriteReport written;
        std::string bytes;
        try {
          bytes = write_cnb(c.scene, options, &written);
        } catch (const std::invalid_argument&) {
          return false;
        }
        if (bytes.size() < c.bytes.size()) c.bytes = std::move(bytes), c.options = options, c.written = written;
        return true;
      };
      for (int i = 1; i <= kFinerGrids; ++i) {
        CnbOptions finer = first;
        finer.quantisation_scale *= 1.0 - kFinerGridStep * i;
        if (!keep_if_smaller(finer)) break;  // a grid too fine for the model's coordinates; finer ones are too
      }
      // Coarser grids keep the same bound on every point's move. Not tried where trimmed surfaces are
      // kept: their writes cost seconds each (capping-end.step at 0.01 mm: 78 CPU-seconds became over 200
      // with them), and a sewn file's faces join as the sewing scale's check saw them on the step itself.
      for (double step : coarser_steps(c.scene, first)) {
        CnbOptions coarser = first;
        coarser.measured_point_step = step;
        keep_if_smaller(coarser);
      }
      c.choice.set_bytes(c.bytes.size());
    }
    return c;
  };
  struct Contender {
    Scene scene;
    CodingChoiceReport choice;
    double share;
  };
  std::vector<Contender> contenders;
  contenders.push_back({mesh_where_cheaper ? Scene() : scene, {}, kMeshShare});
  if (mesh_where_cheaper) contenders[0].scene = cheapest(kMeshShare, contenders[0].choice, false);
  const CodingChoiceReport first = contenders[0].choice;
  // Other shares where every body was meshed, or where a wholly meshed candidate came within
  // kMeshedWithin of the choice; and only wholly meshed candidates: the sewing scale above was checked for
  // the first share's trims. (Were the NURBS costed there too, at a larger trim share they could win and
  // hide a smaller mesh: a Phoenix MCV 1,5/10-GF MountHole at 0.01 mm, NURBS 4,083 bytes at 0.4 against
  // meshes of 4,006 at 0.8.)
  size_t meshed_whole = 0;
  for (size_t bytes : {first.all_meshed_bytes, first.exact_meshed_bytes, first.merged_meshes_bytes})
    if (bytes > 0 && (meshed_whole == 0 || bytes < meshed_whole)) meshed_whole = bytes;
  const bool meshed_close =
      meshed_whole > 0 && static_cast<double>(meshed_whole) <= kMeshedWithin * static_cast<double>(first.bytes());
  std::vector<double> other_shares(std::begin(kWholeMeshShares), std::end(kWholeMeshShares));
  if (first.unshared_edge_uses > 0) other_shares.push_back(kClosingShare);
  auto better = [](const CodingChoiceReport& a, const CodingChoiceReport& b) {
    return std::pair(a.unshared_edge_uses, a.bytes()) < std::pair(b.unshared_edge_uses, b.bytes());
  };
  if (mesh_where_cheaper && ((first.bodies_meshed > 0 && first.bodies_kept == 0) || meshed_close))
    for (double other : other_shares) {
      Contender c{{}, {}, other};
      c.scene = cheapest(other, c.choice, true);
      c.choice.as_is_bytes = first.as_is_bytes;  // not costed at this share: the NURBS as the first share wrote them
      if (c.choice.bodies_kept == 0 && c.choice.bodies_meshed > 0) contenders.push_back(std::move(c));
    }
  size_t best = 0;
  for (size_t i = 1; i < contenders.size(); ++i)
    if (better(contenders[i].choice, contenders[best].choice)) best = i;
  // Every other wholly meshed coding with no more cracks is written on the finer grids too (kFinerGrids),
  // and the smallest file wins.
  const CodingChoiceReport costed = contenders[best].choice;
  out = finish(std::move(contenders[best].scene), costed, contenders[best].share);
  for (size_t i = 0; i < contenders.size(); ++i) {
    const CodingChoiceReport& c = contenders[i].choice;
    if (i == best || c.bodies_kept > 0 || c.bodies_meshed == 0 ||
        c.unshared_edge_uses > costed.unshared_edge_uses)
      continue;
    CnbCoding other = finish(std::move(contenders[i].scene), c, contenders[i].share);
    if (other.bytes.size() < out.bytes.size()) out = std::move(other);
  }
  if (!mesh_where_cheaper)
    out.choice.as_is_bytes = out.choice.per_body_bytes = out.choice.all_meshed_bytes = out.bytes.size();
  return out;
}

std::string meshed_bodies_basis(const CodingChoiceReport& choice) {
  if (choice.bodies_meshed == 0) return "";
  return "; it includes the certificate " + number_text(choice.certified_deviation, 4) + " of the " +
         std::to_string(choice.bodies_meshed) + " bodies (" + std::to_string(choice.faces_meshed) + " faces, " +
         std::to_string(choice.polygons_meshed) + " polygons) written as meshes";
}

}  // namespace cadnurbs
