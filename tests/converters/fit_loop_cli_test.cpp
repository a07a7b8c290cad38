// `cadnurbs fit-loop`: a saved control mesh, read back, gives the same limit surface and the same
// measured distances; bad input is refused with one line and nothing written.
#include <gtest/gtest.h>

#include <set>

#include "command_fixture.hpp"
#include "formats/obj/control_mesh_obj.hpp"

namespace fs = std::filesystem;
using namespace cadnurbs;

namespace {

const std::string kPlate = CADNURBS_SHARED_DIR "/corpus/stl/plate_holes.STL";

class FitLoopCommand : public test::CommandTest {
 protected:
  std::set<std::string> files() const {
    std::set<std::string> out;
    for (const auto& entry : fs::directory_iterator(dir_)) out.insert(entry.path().filename().string());
    return out;
  }
  static std::string line_starting(const std::string& text, const std::string& start) {
    const size_t at = text.find("\n" + start);
    return at == std::string::npos ? "" : text.substr(at + 1, text.find('\n', at + 1) - at - 1);
  }
};

TEST_F(FitLoopCommand, SavedControlMeshGivesTheSameSurface) {
  const auto fitted = run("fit-loop " + kPlate + " -o " + path("control.obj") + " --surface " + path("fitted.obj") +
                          " --control-vertices 60");
  ASSERT_EQ(fitted.status, 0) << fitted.err;
  const auto again = run("fit-loop " + path("control.obj") + " --input " + kPlate + " --surface " + path("again.obj"));
  ASSERT_EQ(again.status, 0) << again.err;
  const SubdivisionControlMesh control = read_control_mesh_obj(path("control.obj"));
  EXPECT_EQ(control.positions.size(), 60u);
  EXPECT_FALSE(control.crease_edges.empty());
  const SubdivisionControlMesh a = read_control_mesh_obj(path("fitted.obj")), b = read_control_mesh_obj(path("again.obj"));
  EXPECT_EQ(a.positions, b.positions);  // bit-equal: the tags came back, so the rules did too
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangles.size(), control.triangles.size() * 64);
  const std::string measured = line_starting(fitted.out, "limit surface");
  EXPECT_NE(measured, "");
  EXPECT_EQ(measured, line_starting(again.out, "limit surface"));
}

TEST_F(FitLoopCommand, RefusesATruncatedStlAndWritesNothing) {
  write_file_atomically(path("cut.stl"), read_file(kPlate).substr(0, 84 + 50 * 10 + 7));
  const auto r = run("fit-loop " + path("cut.stl") + " -o " + path("control.obj") + " --surface " + path("s.obj"));
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(r.err.rfind("cadnurbs fit-loop: " + path("cut.stl") + ": binary STL", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_EQ(files(), (std::set<std::string>{"cut.stl", "stdout.txt", "stderr.txt"}));
}

TEST_F(FitLoopCommand, RefusesAControlMeshOutputThatIsNotObj) {
  const auto r = run("fit-loop " + kPlate + " -o " + path("control.wrl"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "cadnurbs fit-loop: " + path("control.wrl") + ": the control mesh is written as .obj\n");
}

}  // namespace
