// Tessellation at a given maximum deviation D: our tessellate_to_deviation against OCCT's
// BRepMesh_IncrementalMesh (deflection D, absolute, angular deflection 1.5 rad so that only D drives
// it, single-threaded like ours), on the same models in the same run. Both meshes are measured
// against the exact trimmed NURBS with measure_deviation. Timing by Google Benchmark; the table at
// the end gathers triangles, times and deviations.
#include <benchmark/benchmark.h>

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/measure/measure_deviation.hpp"
#include "analysis/eval/sample_trim_segment.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/bounding_box.hpp"
#include "formats/brep/occt_setup.hpp"
#include "formats/brep/trimmed_surface_to_face.hpp"
#include "formats/step/step_reader.hpp"
#include "samples/capping.hpp"
#include "samples/capping_edges.hpp"
#include "samples/capping_shapes.hpp"
#include "tests/brep/occt_mesh.hpp"

namespace cadnurbs {
namespace {

using test::occt_mesh;
using test::occt_triangles;

struct Model {
  std::string name;
  Scene scene;        // our exact trimmed NURBS (millimetres)
  TopoDS_Shape shape;  // the same model for OCCT
  double deviation;   // D
  int faces = 0;
  int fallbacks = 0;  // faces read_step could only give as meshes (not measured, not tessellated)
};



// Cappings: our NURBS, and OCCT faces built from them (B-spline surface + pcurves), sewn.
Model capping_model(const std::string& name, double d) {
  Model m;
  m.name = name + " D=" + std::to_string(d).substr(0, std::to_string(d).find_last_not_of('0') + 1);
  m.scene = capping_nurbs(bundled_capping(name));
  share_capping_edges(m.scene);
  m.deviation = d;
  BRepBuilderAPI_Sewing sewing(1e-4);
  for (const auto& shape : m.scene.root.shapes) {
    sewing.Add(trimmed_surface_to_face(std::get<TrimmedSurface>(shape.geometry), shape.name, 1e-7));
    ++m.faces;
  }
  sewing.Perform();
  m.shape = sewing.SewedShape();
  return m;
}

// Corpus STEP files: ours through read_step (formats/brep), OCCT's through its own STEPControl_Reader.
Model step_model(const std::string& file, double relative) {
  Model m;
  const std::string path = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/" + file;
  BrepTranslation t = read_step(path);
  m.scene = std::move(t.scene);
  m.faces = t.face_count;
  m.fallbacks = static_cast<int>(t.fallbacks.size());
  const double diagonal = scene_bounding_box(m.scene).diagonal().norm();
  m.deviation = relative * diagonal;
  char label[200];
  std::snprintf(label, sizeof label, "%s D=%.3g", file.c_str(), m.deviation);
  m.name = label;
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error(path + ": OCCT cannot read it");
  reader.TransferRoots();
  m.shape = reader.OneShape();
  return m;
}

struct Row {
  std::string model;
  int faces = 0, fallbacks = 0;
  double d = 0;
  long ours_triangles = 0, occt_triangles = 0;
  double ours_seconds = 0, occt_seconds = 0;
  double ours_deviation = 0, occt_deviation = 0;
  long ours_boundary = 0, uncertified = 0;
  int unshared = 0;
};

// Collects the mean real time per iteration of every benchmark run.
class Collector : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> seconds;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs)
      if (r.run_type == Run::RT_Iteration) seconds[r.benchmark_name()] = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace
}  // namespace cadnurbs

int main(int argc, char** argv) {
  using namespace cadnurbs;
  prepare_occt();
  std::vector<Model> models;
  for (double d : {1.0, 0.1, 0.01}) models.push_back(capping_model("capping-90", d));
  models.push_back(capping_model("capping-post", 0.1));
  for (const char* file : {"io1-cm-214.stp", "io1-tu-203.stp", "as1-oc-214.stp", "dm1-id-214.stp", "screw.step",
                           "linkrods.step", "featuretype.STEP", "Ventilator.stp"}) {
    try {
      models.push_back(step_model(file, 0.001));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "skipped %s: %s\n", file, e.what());
    }
  }
  for (auto& m : models) {
    benchmark::RegisterBenchmark(("ours/" + m.name).c_str(), [&m](benchmark::State& state) {
      try {
        for (auto _ : state) benchmark::DoNotOptimize(tessellate_to_deviation(m.scene, m.deviation));
      } catch (const std::exception& e) {
        state.SkipWithError(e.what());
      }
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("occt/" + m.name).c_str(), [&m](benchmark::State& state) {
      for (auto _ : state) {
        state.PauseTiming();
        BRepTools::Clean(m.shape);
        state.ResumeTiming();
        occt_mesh(m.shape, m.deviation);
      }
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  std::vector<Row> rows;
  for (auto& m : models) try {
    Row r;
    r.model = m.name;
    r.faces = m.faces;
    r.fallbacks = m.fallbacks;
    r.d = m.deviation;
    TessellationReport report;
    const TriangleMesh ours = scene_triangles(tessellate_to_deviation(m.scene, m.deviation, &report));
    BRepTools::Clean(m.shape);
    occt_mesh(m.shape, m.deviation);
    const TriangleMesh theirs = occt_triangles(m.shape);
    r.ours_triangles = static_cast<long>(ours.triangles.size());
    r.occt_triangles = static_cast<long>(theirs.triangles.size());
    r.ours_seconds = collector.seconds["ours/" + m.name];
    r.occt_seconds = collector.seconds["occt/" + m.name];
    r.ours_deviation = measure_deviation(ours, m.scene).overall.max;
    r.occt_deviation = measure_deviation(theirs, m.scene).overall.max;
    r.ours_boundary = count_boundary_edges(weld_exact(ours)).boundary;
    r.uncertified = report.uncertified_triangles;
    r.unshared = report.unshared_edge_uses;
    rows.push_back(r);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", m.name.c_str(), e.what());
  }
  std::printf("\n| model | faces (fallback) | D (mm) | triangles ours | triangles OCCT | ours/OCCT | time ours (ms) | "
              "time OCCT (ms) | ours/OCCT | max dev. ours / D | max dev. OCCT / D | open edges ours | uncertified / "
              "unshared ours |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& r : rows)
    std::printf("| %s | %d (%d) | %.4g | %ld | %ld | %.2f | %.2f | %.2f | %.2f | %.3f | %.3f | %ld | %ld / %d |\n",
                r.model.c_str(), r.faces, r.fallbacks, r.d, r.ours_triangles, r.occt_triangles,
                double(r.ours_triangles) / r.occt_triangles, 1e3 * r.ours_seconds, 1e3 * r.occt_seconds,
                r.ours_seconds / r.occt_seconds, r.ours_deviation / r.d, r.occt_deviation / r.d, r.ours_boundary,
                r.uncertified, r.unshared);
  return 0;
}
