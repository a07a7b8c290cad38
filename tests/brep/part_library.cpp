#include "part_library.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "formats/step/step_reader.hpp"

namespace cadnurbs::test {

const std::vector<std::string>& library_parts() {
  static const std::vector<std::string> parts = {
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
  return parts;
}

std::string library_file(const std::string& part, const std::string& ext) {
  std::string cache;
  if (const char* c = std::getenv("CADNURBS_CACHE")) cache = c;
  else if (const char* x = std::getenv("XDG_CACHE_HOME")) cache = std::string(x) + "/cadnurbs";
  else cache = std::string(std::getenv("HOME") ? std::getenv("HOME") : "") + "/.cache/cadnurbs";
  const std::string family = part.substr(0, part.find('/'));
  return cache + "/kicad-packages3d-6.0.10-1/" + family + ".3dshapes/" + library_part_name(part) + ext;
}

Scene read_library_step(const std::string& part) {
  const std::string path = library_file(part, ".step");
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path + " does not exist (scripts/fetch-part-library.sh fetches it)");
  return read_step(path).scene;
}

std::string library_part_name(const std::string& part) { return part.substr(part.find('/') + 1); }

}  // namespace cadnurbs::test
