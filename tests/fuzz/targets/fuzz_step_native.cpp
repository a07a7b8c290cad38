// libFuzzer target over our own STEP reader, parser and builder together (formats/step/part21 and
// formats/step/native): every byte string goes to read_step_native, which must return a scene or throw one
// of its refusals (FileError for the exchange structure, OutsideNativeSubset for what it hands to
// OpenCASCADE, GeometryError from core) in time and memory the input bounds; the scene it returns must pass
// core's validate. Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.step_native).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"
#include "formats/step/native/read_step_native.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const cadnurbs::BrepTranslation read = cadnurbs::read_step_native(bytes, "fuzz.step");
    cadnurbs::validate(read.scene);
  } catch (const cadnurbs::FileError&) {
  } catch (const cadnurbs::step::OutsideNativeSubset&) {
  } catch (const cadnurbs::GeometryError&) {
  }
  return 0;
}
