// The coder prior (formats/cnb/cnb_coder_prior.hpp, coder 3 of format version 4): small files code smaller
// from it, the writer keeps whichever coder codes smallest, and files of the earlier coders and versions
// still read. The capping samples are not among the prior's training files.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_stream.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "tests/cnb/cnb_file_header.hpp"

namespace cadnurbs {
namespace {

std::string sample(const std::string& file) { return std::string(CADNURBS_SOURCE_DIR) + "/samples/" + file; }

std::string written(const Scene& scene, double deviation, CnbOptions::Coder coder, CnbWriteReport* report = nullptr) {
  CnbOptions options;
  options.max_deviation = deviation;
  options.coder = coder;
  return write_cnb(scene, options, report);
}

constexpr uint8_t deflate_id = 1, arithmetic_id = 2, arithmetic_prior_id = 3, two_rates_id = 4;  // the header's coder byte

// The four cappings' NURBS at D = 1 mm are payloads of 300 to 3,400 bytes: each codes smaller from the
// prior than from ½, and all together by at least 3% (measured 1,516 -> 1,457 bytes).
TEST(CnbCoderPrior, SmallFilesCodeSmallerFromThePrior) {
  size_t uniform_total = 0, prior_total = 0;
  for (const char* name : {"capping-90", "capping-end", "capping-moulded", "capping-post"}) {
    const Scene scene = read_vrml(sample(std::string(name) + ".x3dv"));
    CnbWriteReport report;
    written(scene, 1.0, CnbOptions::Coder::smallest, &report);
    std::cout << name << ": payload " << report.payload_bytes << ", coded from 1/2 " << report.arithmetic_bytes
              << ", from the prior " << report.arithmetic_prior_bytes << ", deflated " << report.deflate_bytes << "\n";
    EXPECT_LT(report.arithmetic_prior_bytes, report.arithmetic_bytes) << name;
    uniform_total += report.arithmetic_bytes;
    prior_total += report.arithmetic_prior_bytes;
  }
  EXPECT_LT(static_cast<double>(prior_total), 0.97 * static_cast<double>(uniform_total));
}

// Every rational surface's first weight a little off, so that its weights are no outer product (weight
// mode 3, version 6 on) and are written as a table or rounded, as versions 3 to 5 wrote them.
void break_weight_products(SceneNode& node) {
  for (auto& shape : node.shapes)
    if (auto* t = std::get_if<TrimmedSurface>(&shape.geometry); t && !t->surface.weights.empty())
      t->surface.weights[0] *= 1.001;
  for (auto& child : node.children) break_weight_products(child);
}

// The writer keeps the smallest of the four coders: the prior with two rates (coder 4, version 7) for a
// capping's NURBS at 1 mm, deflate for the moulded capping's NURBS at 1 mm with its weights rounded (whose
// repeated runs of bytes deflate finds).
TEST(CnbCoderPrior, WriterKeepsTheSmallestCoder) {
  const Scene nurbs = read_vrml(sample("capping-90.x3dv"));
  Scene moulded = read_vrml(sample("capping-moulded.x3dv"));
  break_weight_products(moulded.root);
  const struct {
    const Scene* scene;
    double deviation;
    uint8_t expected_coder;
  } cases[] = {{&nurbs, 1.0, two_rates_id}, {&moulded, 1.0, deflate_id}};
  for (const auto& [scene, deviation, expected_coder] : cases) {
    CnbWriteReport report;
    const std::string smallest = written(*scene, deviation, CnbOptions::Coder::smallest, &report);
    std::cout << "deflated " << report.deflate_bytes << ", coded from 1/2 " << report.arithmetic_bytes
              << ", from the prior " << report.arithmetic_prior_bytes << "\n";
    size_t forced = SIZE_MAX;
    for (auto coder : {CnbOptions::Coder::deflate, CnbOptions::Coder::arithmetic, CnbOptions::Coder::arithmetic_prior,
                       CnbOptions::Coder::arithmetic_two_rates})
      forced = std::min(forced, written(*scene, deviation, coder).size());
    EXPECT_EQ(smallest.size(), forced);
    EXPECT_EQ(static_cast<uint8_t>(smallest[5]), expected_coder);
  }
}

// Without colours (whose coding version 4 changed), meshes (whose contexts it changed:
// CnbTraversalMesh.VersionThreeContextsStillRead) and factored weights (version 6), a version 6 payload
// is a version 3 one, and coder 2
// codes it alike: so a version 3 file coded from ½ still reads. Version 3 knew no coder 3, so a version 3
// file naming it is refused.
void drop_colours(SceneNode& node) {
  node.colour.reset();
  for (auto& shape : node.shapes) shape.colour.reset();
  for (auto& child : node.children) drop_colours(child);
}

TEST(CnbCoderPrior, VersionThreeFilesStillReadAndKnowNoPrior) {
  Scene scene = read_vrml(sample("capping-end.x3dv"));
  drop_colours(scene.root);
  break_weight_products(scene.root);
  const std::string uniform = written(scene, 1.0, CnbOptions::Coder::arithmetic);
  const std::string prior = written(scene, 1.0, CnbOptions::Coder::arithmetic_prior);
  ASSERT_EQ(static_cast<uint8_t>(uniform[5]), arithmetic_id);
  ASSERT_EQ(static_cast<uint8_t>(prior[5]), arithmetic_prior_id);
  const CnbPayload from_v4 = read_cnb_payload(uniform, "end.cnb");
  const CnbPayload from_v3 = read_cnb_payload(with_version(uniform, 3), "end.cnb");
  EXPECT_EQ(from_v3.version, 3);
  EXPECT_EQ(from_v3.bytes, from_v4.bytes);
  // (The prior file's payload may differ: the writer picks trim predictors by the coded size.)
  EXPECT_EQ(read_cnb(prior, "end.cnb").root.children.size(), read_cnb(uniform, "end.cnb").root.children.size());
  try {
    read_cnb(with_version(prior, 3), "end.cnb");
    ADD_FAILURE() << "a version 3 file with coder 3 was read";
  } catch (const FileError& e) {
    EXPECT_STREQ(e.what(), "end.cnb: byte 5: unknown entropy coder 3");
  }
}

// read_cnb_payload gives the payload the header promises, with a context for each byte, and says which
// coder the file used.
TEST(CnbCoderPrior, PayloadsReadWithTheirContexts) {
  const Scene scene = read_vrml(sample("capping-post.x3dv"));
  for (auto coder : {CnbOptions::Coder::deflate, CnbOptions::Coder::arithmetic_prior}) {
    CnbWriteReport report;
    const std::string file = written(scene, 0.01, coder, &report);
    const CnbPayload payload = read_cnb_payload(file, "post.cnb");
    EXPECT_EQ(payload.bytes.size(), report.payload_bytes);
    EXPECT_EQ(payload.contexts.size(), payload.bytes.size());
    EXPECT_EQ(payload.arithmetic, coder != CnbOptions::Coder::deflate);
    EXPECT_EQ(payload.version, cnb::format_version);
  }
}

}  // namespace
}  // namespace cadnurbs
