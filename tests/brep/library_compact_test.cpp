// The compact writer against --exact-nurbs on 20 parts of the real part library (compact_exactness.hpp),
// fetched by scripts/fetch-part-library.sh (the ctest fixture library_fetch runs it first).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "compact_exactness.hpp"
#include "corpus_manifest.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs::test {
namespace {

// The library parts: a spread over the nine families, fixed so that results compare across runs.
const std::vector<std::string> kLibraryParts = {
    "Connector_PinHeader_2.54mm/PinHeader_1x05_P2.54mm_Vertical",
    "Connector_PinHeader_2.54mm/PinHeader_2x08_P2.54mm_Horizontal",
    "Package_DIP/DIP-8_W7.62mm",
    "Package_DIP/SMDIP-18_W9.53mm_Clearance8mm",
    "Package_DIP/DIP-28_W15.24mm_Socket",
    "Package_DFN_QFN/DFN-8-1EP_2x2mm_P0.5mm_EP0.7x1.3mm",
    "Package_DFN_QFN/QFN-32-1EP_4x4mm_P0.4mm_EP2.65x2.65mm",
    "Package_QFP/LQFP-48_7x7mm_P0.5mm",
    "Package_QFP/TQFP-32_7x7mm_P0.8mm",
    "Package_BGA/BGA-100_9.0x9.0mm_Layout10x10_P0.8mm",
    "Package_BGA/BGA-100_6.0x6.0mm_Layout11x11_P0.5mm_Ball0.3mm_Pad0.25mm_NSMD",
    "Resistor_THT/R_Axial_DIN0207_L6.3mm_D2.5mm_P10.16mm_Horizontal",
    "Resistor_THT/R_Axial_DIN0207_L6.3mm_D2.5mm_P2.54mm_Vertical",
    "Inductor_THT/L_Axial_L11.0mm_D4.5mm_P15.24mm_Horizontal_Fastron_MECC",
    "Inductor_THT/Choke_EPCOS_B82722A",
    "LED_THT/LED_D5.0mm",
    "LED_THT/LED_D3.0mm",
    "LED_THT/LED_Rectangular_W3.0mm_H2.0mm",
    "Connector_Phoenix_MC/PhoenixContact_MC_1,5_4-G-3.81_1x04_P3.81mm_Horizontal",
    "Connector_Phoenix_MC/PhoenixContact_MCV_1,5_3-G-3.5_1x03_P3.50mm_Vertical",
};

// Where scripts/fetch-part-library.sh puts the library (its own default, or CADNURBS_CACHE).
std::string library_folder() {
  std::string cache;
  if (const char* c = std::getenv("CADNURBS_CACHE")) cache = c;
  else if (const char* x = std::getenv("XDG_CACHE_HOME")) cache = std::string(x) + "/cadnurbs";
  else cache = std::string(std::getenv("HOME") ? std::getenv("HOME") : "") + "/.cache/cadnurbs";
  return cache + "/kicad-packages3d-6.0.10-1";
}

class LibraryCompact : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryCompact, SameSurfacesAsExactNurbs) {
  const std::string& part = GetParam();
  const std::string family = part.substr(0, part.find('/')), name = part.substr(part.find('/') + 1);
  const std::string path = library_folder() + "/" + family + ".3dshapes/" + name + ".step";
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " (scripts/fetch-part-library.sh fetches it)";
  check_compact_is_exact(read_step(path).scene, name);
}

INSTANTIATE_TEST_SUITE_P(Library, LibraryCompact, ::testing::ValuesIn(kLibraryParts),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
