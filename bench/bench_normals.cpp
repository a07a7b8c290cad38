// bench_normals: `cadnurbs normals`' pipeline (read_stl without facet normals, weld_vertices, orient_faces, crease_normals at
// 30 degrees: a normal per corner group and an index per corner) against OpenMesh (IO::read_mesh, which merges equal points, then face and vertex normals by
// update_normals) and assimp (ReadFile with JoinIdenticalVertices and GenSmoothNormals at a maximum
// smoothing angle of 30 degrees) on one generated binary STL of about two million triangles.
// Ours runs twice per round: with the machine's threads (our parallel stages) and with one; the peers use one.
// Each is run three times, each time in a fresh process (this program re-executed with --run NAME), so
// that its peak resident memory (the child's ru_maxrss from wait4) is its own; the time is the child's
// own wall time from opening the file to the normals, the best of the three.
//
//   bench_normals [--cache DIR]     (default /tmp/cadnurbs-bench-normals; the STL is written there once)
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "analysis/normals/crease_normals.hpp"
#include "analysis/normals/orient_faces.hpp"
#include "analysis/mesh/weld_vertices.hpp"
#include "core/worker_threads.hpp"
#include "formats/stl/stl_reader.hpp"
#include "formats/stl/stl_writer.hpp"

namespace {

using namespace cadnurbs;
constexpr double kCreaseDegrees = 30;

// ---------------------------------------------------------------------------------------------
// The input: a torus (smooth), a capped cylinder (smooth side, sharp rims) and a box (sharp), disjoint,
// closed and outward, 2,000,012 triangles.

void add_quad(TriangleMesh& m, int a, int b, int c, int d) {
  m.triangles.push_back({a, b, c});
  m.triangles.push_back({a, c, d});
}

void add_torus(TriangleMesh& m, double big, double small, int around, int across) {
  const int first = static_cast<int>(m.positions.size());
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const double u = 2 * std::numbers::pi * i / around, v = 2 * std::numbers::pi * j / across;
      const double r = big + small * std::cos(v);
      m.positions.emplace_back(r * std::cos(u), r * std::sin(u), small * std::sin(v));
    }
  auto at = [&](int i, int j) { return first + (i % around) * across + j % across; };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) add_quad(m, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
}

void add_cylinder(TriangleMesh& m, const Eigen::Vector3d& base, double radius, double height, int segments, int rows) {
  const int first = static_cast<int>(m.positions.size());
  for (int row = 0; row <= rows; ++row)
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * std::numbers::pi * i / segments;
      m.positions.push_back(base + Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), height * row / rows));
    }
  auto at = [&](int row, int i) { return first + row * segments + i % segments; };
  for (int row = 0; row < rows; ++row)
    for (int i = 0; i < segments; ++i) add_quad(m, at(row, i), at(row, i + 1), at(row + 1, i + 1), at(row + 1, i));
  const int bottom = static_cast<int>(m.positions.size());
  m.positions.push_back(base);
  m.positions.push_back(base + Eigen::Vector3d(0, 0, height));
  for (int i = 0; i < segments; ++i) {
    m.triangles.push_back({bottom, at(0, i + 1), at(0, i)});
    m.triangles.push_back({bottom + 1, at(rows, i), at(rows, i + 1)});
  }
}

void add_box(TriangleMesh& m, const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  const int first = static_cast<int>(m.positions.size());
  for (int i = 0; i < 8; ++i)
    m.positions.emplace_back(i & 1 ? high.x() : low.x(), i & 2 ? high.y() : low.y(), i & 4 ? high.z() : low.z());
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) add_quad(m, first + f[0], first + f[1], first + f[2], first + f[3]);
}

std::string input_stl(const std::filesystem::path& cache) {
  const std::filesystem::path path = cache / "normals-2M.stl";
  TriangleMesh m;
  add_torus(m, 50, 15, 1000, 960);
  add_cylinder(m, {100, 0, -20}, 10, 40, 500, 79);
  add_box(m, {-130, -20, -20}, {-90, 20, 20});
  const std::uintmax_t bytes = 84 + 50 * m.triangles.size();
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) != bytes) {
    std::filesystem::create_directories(cache);
    write_stl(path.string(), m, StlEncoding::binary, "bench_normals");
  }
  return path.string();
}

// ---------------------------------------------------------------------------------------------
// The three contenders, each run in a child. Each prints "seconds vertices normals" on stdout.

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// threads: worker_threads() for our parallel stages (0: the machine's count).
int run_ours(const std::string& path, int threads) {
  if (threads > 0) set_worker_threads(threads);
  const auto start = std::chrono::steady_clock::now();
  std::fprintf(stderr, " ours (%d threads):", worker_threads());
  auto stage = [&, last = start](const char* name) mutable {  // each stage's time on stderr
    const auto now = std::chrono::steady_clock::now();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::fprintf(stderr, " %s %.3f s (peak %.0f MiB)", name, std::chrono::duration<double>(now - last).count(),
                 usage.ru_maxrss / 1024.0);
    last = now;
  };
  // Corners with equal coordinates merged as they are read (the weld then sees each point once), no facet
  // normals (with_crease_normals makes its own).
  TriangleMesh soup = read_stl(path, {.facet_normals = false, .merge_equal_points = true});
  stage("read_stl");
  const double tolerance = default_weld_tolerance(soup);
  TriangleMesh welded = weld_vertices(std::move(soup), tolerance);
  stage("weld");
  SidePartners partners;
  TriangleMesh oriented = orient_faces(std::move(welded), nullptr, nullptr, &partners);
  stage("orient");
  CreaseNormalsReport report;
  const CornerNormals shared =
      crease_normals(oriented, kCreaseDegrees * std::numbers::pi / 180, &report, &partners);
  stage("creases");
  std::fprintf(stderr, "\n");
  const double seconds = seconds_since(start);
  std::printf("%.6f %zu %zu\n", seconds, oriented.positions.size(), shared.normals.size());
  return 0;
}

int run_openmesh(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  OpenMesh::TriMesh_ArrayKernelT<> mesh;
  ::omerr().disable();
  if (!OpenMesh::IO::read_mesh(mesh, path)) return 1;
  mesh.request_face_normals();
  mesh.request_vertex_normals();
  mesh.update_normals();  // face normals, then each vertex's from its faces
  const double seconds = seconds_since(start);
  std::printf("%.6f %zu %zu\n", seconds, mesh.n_vertices(), mesh.n_vertices());
  return 0;
}

int run_assimp(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  Assimp::Importer importer;
  importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, static_cast<float>(kCreaseDegrees));
  // assimp's STL importer gives every vertex its facet's normal; GenSmoothNormals keeps normals that exist
  // (and JoinIdenticalVertices joins only vertices whose normals are equal too) unless they are removed.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals);
  if (!scene || scene->mNumMeshes == 0 || !scene->mMeshes[0]->mNormals) return 1;
  const double seconds = seconds_since(start);
  std::size_t vertices = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) vertices += scene->mMeshes[i]->mNumVertices;
  std::printf("%.6f %zu %zu\n", seconds, vertices, vertices);  // a vertex per distinct (position, normal)
  return 0;
}

// ---------------------------------------------------------------------------------------------
// The parent: runs each contender three times in a child and prints the table.

struct Run {
  double seconds = 0;
  long peak_kib = 0;
  std::size_t vertices = 0, normals = 0;
};

// The 1-minute load average, as /proc/loadavg gives it (-1 where there is none).
double load_average() {
  double load = -1;
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = -1;
    std::fclose(f);
  }
  return load;
}

Run run_child(const std::string& self, const std::string& name, const std::string& path) {
  int out[2];
  if (pipe(out) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    close(out[1]);
    execl(self.c_str(), self.c_str(), "--run", name.c_str(), path.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out[1]);
  std::string text;
  char buffer[256];
  for (ssize_t n; (n = read(out[0], buffer, sizeof buffer)) > 0;) text.append(buffer, n);
  close(out[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);  // this child's own peak, not the largest of all children so far
  Run run;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
      std::sscanf(text.c_str(), "%lf %zu %zu", &run.seconds, &run.vertices, &run.normals) != 3)
    throw std::runtime_error(name + " failed: " + text);
  run.peak_kib = usage.ru_maxrss;
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 3 && args[0] == "--run") {
    if (args[1] == "ours") return run_ours(args[2], 0);
    if (args[1] == "ours-1-thread") return run_ours(args[2], 1);
    if (args[1] == "openmesh") return run_openmesh(args[2]);
    if (args[1] == "assimp") return run_assimp(args[2]);
    return 2;
  }
  std::filesystem::path cache = "/tmp/cadnurbs-bench-normals";
  if (args.size() == 2 && args[0] == "--cache") cache = args[1];
  const std::string path = input_stl(cache);
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::printf("input: %s, %ju triangles, %ju bytes; each run in a fresh process, best of 3; %u hardware threads\n",
              path.c_str(), (std::filesystem::file_size(path) - 84) / 50, std::filesystem::file_size(path),
              std::thread::hardware_concurrency());

  struct Row {
    const char* name;
    const char* what;
    Run best;
  };
  std::vector<Row> rows = {
      {"ours", "read_stl + weld_vertices + orient_faces + crease_normals 30 deg, worker_threads() threads", {}},
      {"ours-1-thread", "the same, 1 thread", {}},
      {"openmesh", "IO::read_mesh + update_normals (face and vertex normals, no crease)", {}},
      {"assimp", "ReadFile: JoinIdenticalVertices + GenSmoothNormals 30 deg", {}},
  };
  const double load_before = load_average();
  for (int round = 0; round < 3; ++round)
    for (Row& row : rows) {  // interleaved, so that a busy moment does not fall on one contender only
      const Run run = run_child(self, row.name, path);
      std::fprintf(stderr, "  %-8s round %d: %.3f s, %.1f MiB\n", row.name, round + 1, run.seconds, run.peak_kib / 1024.0);
      if (round == 0 || run.seconds < row.best.seconds) row.best.seconds = run.seconds;
      row.best.peak_kib = std::max(row.best.peak_kib, run.peak_kib);
      row.best.vertices = run.vertices;
      row.best.normals = run.normals;
    }
  std::printf("1-minute load average before the runs: %.2f\n", load_before);
  std::printf("1-minute load average after the runs: %.2f\n", load_average());
  const Run& ours = rows[0].best;
  std::printf("\n| | what runs | vertices out | normals out | wall time (s), best of 3 | / ours | peak RSS (MiB) | / ours |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const Row& row : rows)
    std::printf("| %s | %s | %zu | %zu | %.3f | %.2f | %.1f | %.2f |\n", row.name, row.what, row.best.vertices,
                row.best.normals, row.best.seconds, row.best.seconds / ours.seconds, row.best.peak_kib / 1024.0,
                static_cast<double>(row.best.peak_kib) / ours.peak_kib);
  return 0;
}
