// Every STEP file of the shared corpus (../shared/corpus, read by path) parses, with as many instances
// and references as the pre-check counts in the same file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/common/file_io.hpp"
#include "formats/step/part21/parse_part21.hpp"
#include "formats/step/step_precheck.hpp"

namespace cadnurbs::part21 {
namespace {

std::vector<std::string> corpus_step_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(CADNURBS_SHARED_DIR) + "/corpus/step")) {
    const std::string extension = file_extension(entry.path().string());
    if (extension == ".step" || extension == ".stp") files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class CorpusStep : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusStep, CountsMatchThePrecheck) {
  const std::string path = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/" + GetParam();
  const std::string bytes = read_file(path);
  const StepPrecheckFigures figures = precheck_step(bytes, path);
  const Model model = parse_part21(bytes, path);
  EXPECT_GT(model.size(), 0u);
  EXPECT_EQ(model.size(), figures.entities);
  EXPECT_EQ(model.reference_count(), figures.references);
  EXPECT_FALSE(model.file_schemas().empty());
  // Every reference lands on an instance whose #number is the one written.
  std::size_t checked = 0;
  for (EntityId id = 0; id < model.size(); ++id)
    for (const Record& record : model.records(id))
      for (std::size_t k = 0; k < record.count; ++k) {
        const Value value = model.parameter(record, k);
        if (value.kind() != ValueKind::reference) continue;
        ASSERT_EQ(model.number(value.reference()), value.reference_number());
        ++checked;
      }
  EXPECT_GT(checked, 0u);
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusStep, ::testing::ValuesIn(corpus_step_files()), test_name);

TEST(CorpusStepFiles, AllFifteenAreThere) { EXPECT_EQ(corpus_step_files().size(), 15u); }

}  // namespace
}  // namespace cadnurbs::part21
